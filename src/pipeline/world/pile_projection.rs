//! Objects that a step left inside each other while hands pushed them are
//! moved apart by position.
//!
//! **Why.** Giving way (`give_way`) takes the hands out of a jammed pile,
//! but the pile's pieces still arrive at each other with the hands' speed:
//! two swept fronts meet closing at 0.4 m/s, 6.7 mm a 60 Hz step, three
//! times rapier's 2 mm contact prediction, so a pair can begin a step apart
//! with no contact and end it millimetres deep. The velocity solver takes
//! such an overlap out only over later steps, at a speed that soft contacts
//! bound, while the sweep goes on pressing; and the give-way tests judge a
//! step from the last one's pushes, so they see a closing a step late.
//! With giving way alone, the hand-edge and forearm gathers of `surfacelab
//! behaviours` (`gather_hand_edges`, `gather_forearms`) leave pieces deeper
//! in each other than the suite's 3 mm limit for piles with Joint, Particle
//! and Hybrid; with this projection as well they stay within it, and no
//! other case changes.
//!
//! **Model.** `Box2D`'s position solver (nonlinear Gauss-Seidel): after the
//! step, every pair of movable objects deeper in each other than [`SLOP`]
//! is moved apart along the level part of its contact normal, the move
//! shared by inverse mass, over a few sweeps so a squeezed row passes its
//! corrections along. Velocities are kept; the next step's contacts, now
//! within prediction, stop the closing. Hands are not part of it: where
//! they close on a pile they have given way, and where they push one
//! object into another the lighter one is moved back into the hand, whose
//! contact pushes again in the next step. Pairs stacked on each other (a
//! level part of the normal under half) are left to the solver, which
//! lifts the upper one against gravity instead of pressing the lower one
//! into the table.
//!
//! **When.** Only in steps where a hand pushes an object across the table
//! (a press from above is no push) or a pile is jammed: free objects
//! collide with finite momentum, which their contacts absorb within a
//! step, while a hand's bodies drive on with whatever impulse it takes.
//! Every other step is bit for bit what it would be without it.
//!
//! Design: docs/design/pile-projection.md.

use super::magnified::MagnifiedDispatcher;
use glam::Vec3;
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d::parry::query::QueryDispatcher;
use rapier3d::prelude::*;

/// Overlap (m) two objects may keep: the hands' [`super::give_way::GIVE`],
/// a sixth of the behaviour suite's 3 mm limit for piles and about what an
/// ordinary push of one object into another holds them at.
const SLOP: f32 = super::give_way::GIVE;

/// Gauss-Seidel sweeps over the pairs: a row of pieces squeezed end to end
/// passes a correction on by about one neighbour a sweep.
const SWEEPS: usize = 4;

/// How far apart (m) two objects' boxes may be and still be tested in a
/// later sweep: moves of a few millimetres (about the deepest overlap a
/// `gather` sweep leaves for the projection) can bring pieces that did not
/// touch into each other; anything further waits a step.
const REACH: f32 = 0.005;

/// Moves apart the movable objects (`objects`: every object's body and
/// collider, in object order) that overlap deeper than [`SLOP`], and their
/// colliders with them.
pub(super) fn separate(physics: &mut PhysicsWorld, objects: &[(RigidBodyHandle, ColliderHandle)]) {
    let (colliders, bodies) = (&physics.colliders, &physics.bodies);
    // (index, collider, inverse mass, bounding box before any move) of each
    // movable object.
    let live: Vec<(usize, &Collider, f32, Aabb)> = objects
        .iter()
        .enumerate()
        .filter_map(|(i, &(b, c))| {
            let body = bodies.get(b).filter(|b| b.is_dynamic() && b.is_enabled())?;
            let collider = colliders.get(c)?;
            Some((i, collider, body.mass_properties().local_mprops.inv_mass, collider.compute_aabb()))
        })
        .collect();
    // Pairs whose boxes, widened by [`REACH`], meet: sorted along x and
    // swept, so a thousand objects cost a sort rather than half a million
    // box tests a sweep; then taken in object order, as a nested loop
    // would, so the result does not depend on the sort.
    let mut order: Vec<usize> = (0..live.len()).collect();
    order.sort_by(|&p, &q| live[p].3.mins.x.total_cmp(&live[q].3.mins.x));
    let mut pairs = Vec::new();
    for (k, &p) in order.iter().enumerate() {
        let a = live[p].3.loosened(REACH);
        for &q in &order[k + 1..] {
            let b = live[q].3.loosened(REACH);
            if b.mins.x > a.maxs.x {
                break;
            }
            if a.intersects(&b) {
                pairs.push((p.min(q), p.max(q)));
            }
        }
    }
    pairs.sort_unstable();
    let mut shift = vec![Vec3::ZERO; objects.len()];
    let at = |c: &Collider, s: Vec3| Pose::from_parts(c.position().translation + s, c.position().rotation);
    for _ in 0..SWEEPS {
        let mut moved = false;
        for &(p, q) in &pairs {
            let ((i, a, wa, box_a), (j, b, wb, box_b)) = (live[p], live[q]);
            if wa + wb <= 0.0 || !box_a.translated(shift[i]).intersects(&box_b.translated(shift[j])) {
                continue;
            }
            let (pa, pb) = (at(a, shift[i]), at(b, shift[j]));
            let Ok(Some(c)) = MagnifiedDispatcher.contact(&pa.inv_mul(&pb), a.shape(), b.shape(), 0.0) else {
                continue;
            };
            let depth = -c.dist - SLOP;
            if depth <= 0.0 {
                continue;
            }
            // Out of a towards b; a move by s along its level part takes
            // s * |level| off the depth.
            let n = pa.rotation * c.normal1;
            let level = Vec3::new(n.x, n.y, 0.0);
            let across = level.length();
            if across < 0.5 {
                continue;
            }
            let step = level * (depth / (across * across));
            shift[i] -= step * (wa / (wa + wb));
            shift[j] += step * (wb / (wa + wb));
            moved = true;
        }
        if !moved {
            break;
        }
    }
    let mut any = false;
    for (i, s) in shift.iter().enumerate() {
        if *s != Vec3::ZERO
            && let Some(b) = physics.bodies.get_mut(objects[i].0)
        {
            let t = b.translation();
            b.set_translation(t + *s, true);
            any = true;
        }
    }
    if any {
        physics.bodies.propagate_modified_body_positions_to_colliders(&mut physics.colliders);
    }
}
