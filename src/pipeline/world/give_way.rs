//! Hands give way where they close on a pile.
//!
//! **Why.** A technique's bodies follow the user's hand, whose motion the
//! simulation cannot change: to the solver they push with whatever impulse
//! it takes (particles weigh 40 times a 10 g piece, Joint's prisms are
//! kinematic). Pieces swept into a pile leave the solver no way out once
//! two hands close on it: rigid pieces cannot shrink, so it presses them
//! about a centimetre into each other (`surfacelab behaviours`,
//! `gather_hand_edges`, `gather_forearms`), and more solver iterations,
//! stiffer contacts or shorter steps do not prevent it. A real hand
//! sweeping real chips feels the pile and its skin gives, or the chips
//! ride up; either way what it presses them with is bounded by what the
//! pile holds.
//!
//! **Model.** Before each step, movable objects that touch (or will within
//! the step at their present speeds, see [`TOUCH`]) form piles. A pile is
//! *jammed* when hands close on it: two different objects of it were
//! pushed in the last step from opposed sides (more than 120° apart) by
//! technique bodies closing on each other faster than the pile's contacts
//! take up ([`TOUCH`] a step); or when two of its objects overlap deeper
//! than [`GIVE`] while a hand presses on into one of them faster than it
//! moves ([`PRESSING`]: a push the closing test saw a step late). A hand
//! pushing a row of objects along moves them, and two hands holding two
//! blocks between them do not close on them (their corners, pushing the
//! blocks along, press on now and then, so such a grasp carries the blocks
//! most but not all of the way it does without giving way). For that step
//! the contacts between technique bodies and the jammed pile's objects are
//! dropped: the hand passes into the pile instead of pressing it. A hand
//! is not stopped (it
//! never is on a real surface); particles, created clear of movable
//! objects every frame, are re-placed beside the pile. One object pressed
//! from both sides (a grasp) is no pile.
//! What the step still leaves of pieces closing on each other faster than
//! contacts are predicted, `pile_projection` moves apart after it.
//!
//! **How.** Depths are asked of the pair's shapes each step (the magnified query,
//! as `max_object_overlap` does), not read from rapier's manifold, which
//! keeps a recycled pair's separation frozen while it drifts. Only a jammed
//! object's collider gets rapier's contact-modification flag, for the
//! step, so everything else keeps rapier's contact recycling and every
//! behaviour without a pile is bit for bit what it is without giving way.
//!
//! Design: docs/design/pile-projection.md.

use super::face_friction::FaceFriction;
use super::groups::{Layer, collider_layer};
use super::magnified::MagnifiedDispatcher;
use glam::Vec2;
use rapier3d::parry::query::QueryDispatcher;
use rapier3d::prelude::*;

/// Overlap (m) between two objects of a pile beyond which hands that press
/// on into it give way: the net for what the closing test misses (a push
/// seen a step late, a pile pressed against something fixed). A sixth of
/// the behaviour suite's 3 mm limit for piles; ordinary pushes of one
/// object into another hold them a millimetre or so into each other, but
/// move them at the hand's speed (see [`PRESSING`]).
pub const GIVE: f32 = 0.0005;

/// Speed (m/s) at which a hand moving into an object, relative to it,
/// presses on into it rather than pushing it along: half a sweep's
/// 0.2 m/s. Much lower, and the overlap net lets a fingertip pushing a
/// light box into a heavy one (Particle) pass through the small box
/// instead of pushing it on (test `a_fingertip_pushes_one_box_with_another`).
const PRESSING: f32 = 0.1;

/// Gap (m) under which two objects touch, for grouping them into a pile,
/// after taking off what they close in the coming step at their present
/// speeds: pieces swept at 0.2 m/s close 3.3 mm a step, more than rapier's
/// 2 mm prediction distance. Hands closing on a pile faster than this a
/// step squeeze it.
pub const TOUCH: f32 = 0.0005;

/// How far beyond touching (m) a pair's separation is asked for: enough for
/// any closing speed under 1.2 m/s at 60 Hz.
const QUERY_REACH: f32 = 0.02;

/// Cosine under which two pushes are opposed (more than 120° apart).
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

fn linvel(c: &Collider, bodies: &RigidBodySet) -> Vector {
    c.parent().and_then(|b| bodies.get(b)).map_or(Vector::ZERO, RigidBody::linvel)
}

/// How the hands pushed one scene object across the table in a step.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Push {
    /// Sum of the level parts (unit) of the contact normals, pointing into
    /// the object, of the technique bodies touching it. Zero for an object
    /// no hand touched (a press from above is no push across).
    dir: Vec2,
    /// Those bodies' mean velocity along `dir` (m/s). With another object's,
    /// how fast two hands close on a pile, whatever the pile itself does.
    speed: f32,
    /// The fastest any of them moved into the object along its normal,
    /// relative to the object (m/s): above [`PRESSING`], the hand presses
    /// on into it instead of moving it along.
    pressing: f32,
}

impl Push {
    /// Whether any technique body pushed the object across the table.
    pub(super) fn touched(&self) -> bool {
        self.dir.length() > 0.5
    }
}

/// How technique bodies pushed each scene object (in `objects`' order) in
/// the step just taken, contacts dropped by [`StepHooks`] included (they
/// still touch). Read right after the step, while the narrow phase still
/// holds this frame's technique bodies.
pub(super) fn pushes(physics: &PhysicsWorld, objects: &[ColliderHandle]) -> Vec<Push> {
    let colliders = &physics.colliders;
    let bodies = &physics.bodies;
    objects
        .iter()
        .map(|&h| {
            let Some(object) = colliders.get(h) else { return Push::default() };
            let v_object = linvel(object, bodies);
            let (mut dir, mut velocity, mut pressing, mut n) = (Vec2::ZERO, Vector::ZERO, f32::MIN, 0.0f32);
            for pair in physics.narrow_phase.contact_pairs_with(h) {
                let (other, into) = if pair.collider1 == h { (pair.collider2, -1.0) } else { (pair.collider1, 1.0) };
                let Some(body) = colliders.get(other).filter(|c| is_technique(c)) else { continue };
                let Some(c1) = colliders.get(pair.collider1) else { continue };
                // Touching when the step began, or pushed during it (a contact
                // predicted from a gap keeps the gap as its distance).
                let touched = |m: &&ContactManifold| m.points.iter().any(|p| p.dist < TOUCH || p.data.impulse > 0.0);
                for m in pair.manifolds().iter().filter(touched) {
                    let normal = c1.position().rotation * m.local_n1 * into;
                    let level = Vec2::new(normal.x, normal.y);
                    if level.length() > 0.5 {
                        dir += level.normalize();
                        velocity += linvel(body, bodies);
                        pressing = pressing.max((linvel(body, bodies) - v_object).dot(normal));
                        n += 1.0;
                    }
                }
            }
            if n == 0.0 {
                return Push::default();
            }
            let mean = velocity / n;
            Push { dir, speed: Vec2::new(mean.x, mean.y).dot(dir.normalize_or_zero()), pressing }
        })
        .collect()
}

/// Which scene objects (in `objects`' order) are in a jammed pile this step
/// (see the module doc), from the objects' poses and speeds now and the
/// hands' `pushes` in the last step.
pub(super) fn jammed(physics: &PhysicsWorld, objects: &[ColliderHandle], pushes: &[Push], dt: f32) -> Vec<bool> {
    // Both tests need an object that hands pushed: without one (most steps
    // of most scenes) no pair needs asking.
    if !pushes.iter().any(Push::touched) {
        return vec![false; objects.len()];
    }
    let colliders = &physics.colliders;
    let bodies = &physics.bodies;
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
            let closing = (linvel(a, bodies) - linvel(b, bodies)).dot(n).max(0.0);
            if c.dist - closing * dt >= TOUCH {
                continue;
            }
            let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
            parent[ri] = rj;
            deep[rj] |= deep[ri] || -c.dist > GIVE;
        }
    }
    // Per pile, each pushed object's push: direction and speed.
    let mut sides: Vec<Vec<(Vec2, f32)>> = vec![Vec::new(); objects.len()];
    let mut pressed = vec![false; objects.len()];
    for (i, p) in pushes.iter().enumerate().take(objects.len()) {
        if p.touched() {
            let r = root(&mut parent, i);
            sides[r].push((p.dir.normalize(), p.speed));
            pressed[r] |= p.pressing > PRESSING;
        }
    }
    let closing_on = |s: &[(Vec2, f32)]| {
        s.iter()
            .enumerate()
            .any(|(k, (da, va))| s[k + 1..].iter().any(|(db, vb)| da.dot(*db) < OPPOSED && va + vb > TOUCH / dt))
    };
    (0..objects.len())
        .map(|i| {
            let r = root(&mut parent, i);
            (deep[r] && pressed[r]) || closing_on(&sides[r])
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
