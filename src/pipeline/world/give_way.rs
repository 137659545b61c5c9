//! A hand gives way where what it pushes is already pressed into something.
//!
//! **Why.** A technique's bodies follow the user's hand, whose motion the
//! simulation cannot change: to the solver they push with whatever impulse
//! it takes (particles weigh 40 times a 10 g piece, Joint's prisms are
//! kinematic). Pieces swept into a pile leave the solver no way out once
//! the pile is jammed between two hands: rigid pieces cannot shrink, so it
//! pressed them 8-14 mm into each other (`gather_hand_edges`,
//! `gather_forearms`), while 8 or 16 iterations, stiffer contacts or
//! shorter steps left that at 5-24 mm (README, "Piles"). A real hand
//! sweeping real chips feels the pile and its skin gives, or the chips ride
//! up; either way what it presses them with is bounded by what the pile
//! holds.
//!
//! **Model.** Before each step, every movable object pressed deeper than
//! [`GIVE`] into another movable object is *jammed*. For that step the
//! contacts between technique bodies and a jammed object are dropped: the
//! hand passes into it instead of pressing it further into the pile, and
//! the pile's own contacts push its pieces apart. Once the piece is back
//! within [`GIVE`] the hand presses it again. Nothing changes for an
//! object that is not pressed into another: a lone box, a ball, the
//! steering cylinder, a gripped block. A hand is not stopped by a jam (it
//! never is on a real surface); its particles, created clear of movable
//! objects every frame, are re-placed beside the piece.
//!
//! **How.** The depth is asked of the pair's shapes now (the magnified
//! query, as `max_object_overlap` does), not read from rapier's manifold,
//! which keeps a recycled pair's separation frozen while it drifts. A
//! jammed object's collider gets rapier's contact-modification flag for
//! the step, so objects that are not jammed keep rapier's contact
//! recycling and every other behaviour is bit for bit what it was.

use super::face_friction::FaceFriction;
use super::groups::{Layer, collider_layer};
use super::magnified::MagnifiedDispatcher;
use glam::Vec2;
use rapier3d::parry::query::QueryDispatcher;
use rapier3d::prelude::*;

/// Overlap (m) between two movable objects beyond which a pile counts as
/// jammed however the hands press it: a sixth of the behaviour suite's 3 mm
/// limit for piles, five times rapier's allowed error at the default length
/// unit. Measured over 24 sweeps (below): 0.2 mm and 0.5 mm gave the same
/// mean deepest overlap within 0.3 mm, 1 mm 0.3-0.6 mm more.
pub const GIVE: f32 = 0.0005;

/// Gap (m) under which two objects touch, for grouping them into a pile,
/// after taking off what they close in the coming step at their present
/// speeds: pieces swept at 0.2 m/s close 3.3 mm a step, more than rapier's
/// 2 mm prediction distance, and meet within the step.
pub const TOUCH: f32 = 0.0005;

/// How far (m) beyond touching two objects' depth is asked for (the
/// magnified query's prediction): far enough for any closing speed below
/// 1.2 m/s at 60 Hz.
const QUERY_REACH: f32 = 0.02;

/// Cosine under which two hands' pushes are opposed (more than 120° apart).
const OPPOSED: f32 = -0.5;

/// Whether `c` belongs to a technique (proxy, particle, line of sight).
fn is_technique(c: &Collider) -> bool {
    matches!(collider_layer(c), Layer::Proxy | Layer::Particle | Layer::Sight)
}

/// The scene object index of a movable object's collider (its `user_data`,
/// see `World::scene_objects`), `None` for anything else.
fn movable_index(c: &Collider, bodies: &RigidBodySet) -> Option<usize> {
    (collider_layer(c) == Layer::Object && c.parent().and_then(|b| bodies.get(b)).is_some_and(RigidBody::is_dynamic))
        .then_some(c.user_data as usize)
}

/// Which way technique bodies pressed each scene object in the step just
/// taken, by object index: the sum of the level parts of the contact
/// normals, pointing into the object, of every technique body touching it
/// (contacts dropped by [`StepHooks`] included: they still touch). Zero for
/// an object no hand touched. Read after the step, while the narrow phase
/// still holds this frame's technique bodies.
pub(super) fn pushes(physics: &PhysicsWorld, objects: &[ColliderHandle]) -> Vec<Vec2> {
    let colliders = &physics.colliders;
    objects
        .iter()
        .map(|&h| {
            let mut sum = Vec2::ZERO;
            for pair in physics.narrow_phase.contact_pairs_with(h) {
                let (other, into) = if pair.collider1 == h { (pair.collider2, -1.0) } else { (pair.collider1, 1.0) };
                if !colliders.get(other).is_some_and(is_technique) {
                    continue;
                }
                let Some(c1) = colliders.get(pair.collider1) else { continue };
                for m in pair.manifolds().iter().filter(|m| m.points.iter().any(|p| p.dist < TOUCH)) {
                    let n = c1.position().rotation * m.local_n1 * into;
                    let level = Vec2::new(n.x, n.y);
                    // A press from above is not a push across.
                    if level.length() > 0.5 {
                        sum += level.normalize();
                    }
                }
            }
            sum
        })
        .collect()
}

/// Which scene objects (by index) are in a jammed pile. A pile is a group
/// of movable objects linked by the pairs that touch (or will within the
/// step, see [`TOUCH`]); it is jammed when hands press two different
/// objects of it from opposed sides (`pushes`, from the last step), or when
/// two of its objects overlap deeper than [`GIVE`]. The whole pile, because
/// a hand pushing its near piece presses the far pair through the pieces
/// between. One object pressed from both sides (a grasp) is no pile.
pub(super) fn jammed(physics: &PhysicsWorld, objects: &[ColliderHandle], pushes: &[Vec2], dt: f32) -> Vec<bool> {
    let colliders = &physics.colliders;
    let bodies = &physics.bodies;
    let velocity = |c: &Collider| c.parent().and_then(|b| bodies.get(b)).map_or(Vector::ZERO, RigidBody::linvel);
    // Union-find over the objects.
    let mut parent: Vec<usize> = (0..objects.len()).collect();
    let mut deep = vec![false; objects.len()];
    for (i, &h) in objects.iter().enumerate() {
        let Some(a) = colliders.get(h).filter(|c| movable_index(c, bodies).is_some()) else { continue };
        for pair in physics.narrow_phase.contact_pairs_with(h) {
            let other = if pair.collider1 == h { pair.collider2 } else { pair.collider1 };
            let Some(b) = colliders.get(other) else { continue };
            let Some(j) = movable_index(b, bodies).filter(|&j| j > i && j < objects.len()) else { continue };
            let pos12 = a.position().inv_mul(b.position());
            let Ok(Some(c)) = MagnifiedDispatcher.contact(&pos12, a.shape(), b.shape(), QUERY_REACH) else {
                continue;
            };
            // Normal out of a towards b, and how fast they close along it.
            let n = a.position().rotation * c.normal1;
            let closing = (velocity(a) - velocity(b)).dot(n).max(0.0);
            if c.dist - closing * dt >= TOUCH {
                continue;
            }
            let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
            parent[ri] = rj;
            deep[rj] |= deep[ri] || -c.dist > GIVE;
        }
    }
    let mut dirs: Vec<Vec<Vec2>> = vec![Vec::new(); objects.len()];
    for (i, p) in pushes.iter().enumerate().take(objects.len()) {
        if p.length() > 0.5 {
            let r = root(&mut parent, i);
            dirs[r].push(p.normalize());
        }
    }
    let opposed = |d: &[Vec2]| d.iter().enumerate().any(|(k, a)| d[k + 1..].iter().any(|b| a.dot(*b) < OPPOSED));
    (0..objects.len())
        .map(|i| {
            let r = root(&mut parent, i);
            deep[r] || opposed(&dirs[r])
        })
        .collect()
}

/// The root of `i`'s group in a union-find forest, halving paths.
fn root(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// The hooks every step runs: torsional friction of faces on the table
/// (`face_friction`) and hands giving way at jammed piles.
#[derive(Debug, Clone, Copy)]
pub(super) struct StepHooks<'a> {
    /// By scene object index: whether it is in a jammed pile this step.
    pub jammed: &'a [bool],
}

impl PhysicsHooks for StepHooks<'_> {
    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        let colliders = context.colliders;
        let (Some(c1), Some(c2)) = (colliders.get(context.collider1), colliders.get(context.collider2)) else {
            return;
        };
        let jammed = |c: &Collider| {
            movable_index(c, context.bodies).is_some_and(|i| self.jammed.get(i).copied().unwrap_or(false))
        };
        if (jammed(c1) && is_technique(c2)) || (jammed(c2) && is_technique(c1)) {
            if let Some(rigid) = context.rigid_mut() {
                rigid.solver_contacts.clear();
            }
            return;
        }
        // The table is the only other collider with a hook (a jammed
        // object's pairs with other objects are left as rapier made them).
        if collider_layer(c1) == Layer::Environment || collider_layer(c2) == Layer::Environment {
            FaceFriction.modify_solver_contacts(context);
        }
    }
}
