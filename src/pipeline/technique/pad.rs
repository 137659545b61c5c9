//! A resting hand's pad: the particles a contact lays on the object it
//! rests on, moved as one rigid body.
//!
//! **Why.** The paper's particles are independent bodies, each pressing with
//! its own weight wherever it is. A fingertip is one pad of flesh over a
//! bone, held by the arm: when the surface under it tilts, its higher side
//! takes the press. That decides a drag at the top of something tall. The
//! steering cylinder (5 cm tall, 2.5 cm radius, 150 g) dragged by its top
//! starts to tip about its front rim, which raises the back of its top; a
//! finger held at its height presses that back harder, and the press there,
//! behind the axis, holds the cylinder upright while its base slides (the
//! Proxy's cube does the same, its rotations locked). Independent particles
//! each keep their own small press where they are, near the axis, and the
//! cylinder tips or the finger slides over its top (`surfacelab behaviours`,
//! `cylinder_top_drag`; test
//! `a_fingertip_pad_drags_the_steering_cylinder_upright_by_its_top`).
//!
//! **How.** Each frame, the particles of a contact that rests on an object
//! (see `rest`) and land on that object become the colliders of one dynamic
//! body. Each keeps its shape, mass and friction, so friction still acts at
//! every particle; the body weighs what its particles weigh, so the hand
//! presses as hard as its particles alone do. The body moves by the mean of
//! its particles' velocities (the hand's move over the object along its
//! surface, its skin's slip included) and turns about the vertical through
//! the particles' centroid as the hand turns on the glass (see
//! `rigid_fit`). Vertically it follows the
//! surface down (the arm presses the hand there), and it gives way up only
//! as fast as the surface rises under every one of its particles: an
//! object lifting under the whole hand lifts it, one tilting under it
//! presses its raised side. Across the table it gives way to a surface
//! coming at it as its particles would (a ball rolling into a fingertip on
//! its far flank). Particles on anything else (the table, a second object,
//! a soft body) are the paper's.
//!
//! The alternatives fail (`surfacelab behaviours` and the light touches of
//! `a_light_touch_rolls_a_ball_forward_wherever_it_ends`): held level (no
//! vertical speed), a light fingertip sliding fast past a ball's top leaves
//! its surface within the step and barely rolls it; following the surface
//! up as well, some top drags of the steering cylinder tip it, even with
//! more solver iterations; giving way in no direction, a fingertip on a
//! ball's far flank stops the ball rolling into it dead.
//!
//! **Solver.** A pad touches its object through many contacts at once, all
//! acting on the same two bodies, and rapier's 4 iterations do not
//! converge them. Pads persist while their contact rests (as pooled
//! particles do, `Pads::place`), so their contacts warm-start, and their
//! islands get [`SOLVER_ITERATIONS`] more. Created afresh every step (the
//! paper's create/destroy variant) they get [`FRESH_SOLVER_ITERATIONS`].
//!
//! Design: docs/design/resting-pad.md.

use super::surface_point::least_squares_turn;
use crate::pipeline::vision::ContactId;
use crate::pipeline::world::prelude::*;
use crate::pipeline::world::{TechniqueBody, TechniqueWorld};
use glam::Vec3;
use std::collections::BTreeMap;

/// Extra solver iterations for the island of a persistent pad. With none,
/// a pad's many contacts do not converge: pin-and-spin and flat-hand turns
/// fall short and some top drags of the steering cylinder tip it. With 4,
/// Particle passes `surfacelab behaviours` and holds the cylinder upright
/// in top drags, though a sudden start to 0.2 m/s (which tips the cylinder
/// over with Joint) sits at the edge. More iterations buy nothing here and
/// cost frame time, which must stay well under the paper's create/destroy
/// (`cargo bench --bench frame`).
pub const SOLVER_ITERATIONS: usize = 4;

/// Extra solver iterations for the island of a pad created afresh this
/// step, with no warm start (the paper's create/destroy variant). With
/// fewer, the suite's pin and spin on the small box with fresh pads sinks
/// the box into the table and turns it well short of 90 degrees; each
/// doubling roughly halves the sink
/// (`a_pad_does_not_press_what_it_rests_on_into_the_table`).
pub const FRESH_SOLVER_ITERATIONS: usize = 16;

/// One particle of a pad: where it touches and how it moves this step.
#[derive(Debug, Clone)]
pub struct PadParticle {
    /// The point it touches, lifted by its radius (a particle's centre).
    pub center: Vec3,
    /// Its velocity as a free particle would get it (the hand's move over
    /// the surface it touches, giving way across the table to a surface
    /// coming at it), less its giving way upwards.
    pub velocity: Vec3,
    /// How fast (m/s) the surface it touches comes up at it (its giving way
    /// upwards).
    pub rise: f32,
    /// How the hand moves it across the table (m/s): its outline point's
    /// flow over the glass, seen at its height. The pad turns as these
    /// points do (see `rigid_fit`).
    pub glass: glam::Vec2,
    /// Press (N).
    pub weight: f32,
    /// Inertia (kg).
    pub mass: f32,
    /// Its collider, placed relative to `center`.
    pub collider: ColliderBuilder,
}

/// The pads in the world, by contact id (in id order: deterministic).
#[derive(Debug, Default)]
pub struct Pads {
    pads: BTreeMap<ContactId, Pad>,
}

/// One contact's pad.
#[derive(Debug, Clone)]
struct Pad {
    body: TechniqueBody,
    /// Each particle's centre relative to the body's origin this step.
    offsets: Vec<Vec3>,
}

impl Pads {
    /// Places this frame's pads, one per contact in `by_contact` (each with
    /// at least one particle); `ccd` is the distance along which their
    /// contacts are predicted (as a particle's, see `new_body`). A pad
    /// whose contact had one last frame keeps its body and colliders, moved
    /// and reshaped to this frame's particles, so rapier keeps their pairs
    /// and warm-starts their contacts (as pooled particles do); the others'
    /// pads go. Not `pooled` (the paper's create/destroy, where the caller
    /// clears the pads after each step), every pad is fresh and is solved
    /// with [`FRESH_SOLVER_ITERATIONS`] more.
    pub fn place(
        &mut self,
        world: &mut TechniqueWorld<'_>,
        by_contact: BTreeMap<ContactId, Vec<PadParticle>>,
        ccd: f32,
        pooled: bool,
    ) {
        let gone: Vec<ContactId> = self.pads.keys().copied().filter(|id| !by_contact.contains_key(id)).collect();
        for id in gone {
            if let Some(pad) = self.pads.remove(&id) {
                world.remove_body(pad.body);
            }
        }
        for (id, particles) in by_contact {
            let n = particles.len().max(1) as f32;
            let origin = particles.iter().map(|p| p.center).sum::<Vec3>() / n;
            let (velocity, turn) = rigid_fit(&particles, origin);
            let mass: f32 = particles.iter().map(|p| p.mass).sum();
            let weight: f32 = particles.iter().map(|p| p.weight).sum();
            let offsets: Vec<Vec3> = particles.iter().map(|p| p.center - origin).collect();
            // rapier turns a body about its centre of mass, up its
            // line-of-sight capsules: the touched points' centroid moves at
            // the fitted velocity instead.
            let mut com = Vec3::ZERO;
            let colliders: Vec<ColliderBuilder> = particles
                .into_iter()
                .map(|p| {
                    let mut c = p.collider;
                    c.position = Pose::from_translation(p.center - origin) * c.position;
                    com += c.position.translation * p.mass;
                    c
                })
                .collect();
            let com = if mass > 0.0 { com / mass } else { Vec3::ZERO };
            let spin = Vec3::new(0.0, 0.0, turn);
            let linvel = velocity + spin.cross(com);
            let gravity = super::proxy::gravity_scale_for(mass, weight);
            let body = if let Some(pad) = self.pads.get(&id) {
                world.set_compound(pad.body, colliders);
                if let Some(b) = world.technique_body_mut(pad.body) {
                    b.set_position(Pose::from_translation(origin), true);
                    b.set_gravity_scale(gravity, true);
                }
                pad.body
            } else {
                let body = RigidBodyBuilder::dynamic()
                    .translation(origin)
                    // Upright and level, as the finger over its bone; free
                    // to turn about the vertical with the hand.
                    .enabled_rotations(false, false, true)
                    .gravity_scale(gravity)
                    .additional_solver_iterations(if pooled { SOLVER_ITERATIONS } else { FRESH_SOLVER_ITERATIONS })
                    .can_sleep(false)
                    .soft_ccd_prediction(ccd);
                let colliders = colliders.iter().map(ColliderBuilder::build).collect();
                world.spawn_compound(body, colliders)
            };
            if let Some(b) = world.technique_body_mut(body) {
                b.set_linvel(linvel, true);
                b.set_angvel(spin, true);
            }
            self.pads.insert(id, Pad { body, offsets });
        }
    }

    /// Where the pads' particles are now (after the step, for feedback).
    pub fn positions<'a>(&'a self, world: &'a TechniqueWorld<'_>) -> impl Iterator<Item = Vec3> + 'a {
        self.pads.values().flat_map(move |pad| {
            let pose = world.technique_body(pad.body).map(|b| *b.position());
            pad.offsets.iter().filter_map(move |o| pose.map(|p| p * *o))
        })
    }

    /// Removes every pad from the world.
    pub fn clear(&mut self, world: &mut TechniqueWorld<'_>) {
        for (_, pad) in std::mem::take(&mut self.pads) {
            world.remove_body(pad.body);
        }
    }
}

/// The rigid motion that fits the particles' velocities about `origin`:
/// their mean velocity, following the surface down but up only as fast as
/// it rises under every particle (see the module doc), and the
/// least-squares turn about the vertical (rad/s) of the hand's motion over
/// the glass at the particles (`PadParticle::glass`).
///
/// The turn is the hand's, not a fit to the particles' velocities along
/// the surface: on a curved surface those are not a rigid motion. Each is
/// the hand's flow projected on the particle's own tangent plane and capped
/// in speed along it, so on a ball's flank the points slide down and apart
/// at rates set by the local slope, and an outline that covers the flank
/// unevenly (a palm's heel over a ball it has slid past) fits a turn the
/// hand never made. Fitted so, a flat hand sliding 30 cm forward over a
/// ball without turning turns its pad at up to 2.2 rad/s as its heel
/// passes over the ball's front; the pad spins the ball at 6 rad/s and
/// sends it off 23° to the side (6.4 cm sideways for 15.1 cm forward when the hand lifts:
/// `ball_under_hand_forward` in the behaviour suite). Turned as the hand
/// turns on the glass, the pad turns under 0.8 rad/s and the ball rolls
/// 19.6 cm forward, 0.6 cm sideways.
fn rigid_fit(particles: &[PadParticle], origin: Vec3) -> (Vec3, f32) {
    let n = particles.len().max(1) as f32;
    let mean = particles.iter().map(|p| p.velocity).sum::<Vec3>() / n;
    let glass = particles.iter().map(|p| p.glass).sum::<glam::Vec2>() / n;
    let turn =
        least_squares_turn(particles.iter().map(|p| ((p.center - origin).truncate(), p.glass - glass))).unwrap_or(0.0);
    let rise = particles.iter().map(|p| p.rise).reduce(f32::min).unwrap_or(0.0).max(0.0);
    (Vec3::new(mean.x, mean.y, mean.z.min(0.0) + rise), turn)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn particle(center: Vec3, velocity: Vec3) -> PadParticle {
        PadParticle {
            center,
            velocity,
            rise: 0.0,
            glass: velocity.truncate(),
            weight: 0.1,
            mass: 0.4,
            collider: ColliderBuilder::ball(0.003),
        }
    }

    #[test]
    fn the_fit_recovers_a_translation_and_a_turn() {
        // Four points 1 cm round (0.1, 0.2), moving at (0.05, -0.02) m/s
        // and turning at 2 rad/s, with some vertical speed the fit drops.
        let (origin, v, w) = (Vec3::new(0.1, 0.2, 0.05), Vec3::new(0.05, -0.02, 0.0), 2.0f32);
        let ps: Vec<_> = [(0.01, 0.0), (0.0, 0.01), (-0.01, 0.0), (0.0, -0.01)]
            .iter()
            .map(|&(x, y)| {
                let d = Vec3::new(x, y, 0.0);
                particle(origin + d, v + Vec3::new(-w * d.y, w * d.x, 0.03))
            })
            .collect();
        let (fit_v, fit_w) = rigid_fit(&ps, origin);
        assert!((fit_v - v).length() < 1e-6, "{fit_v:?}");
        assert!((fit_w - w).abs() < 1e-4, "{fit_w}");
        // One particle: its velocity, no turn.
        // Down with the surface, but up only as fast as it rises under
        // every particle.
        let falling: Vec<_> = ps
            .iter()
            .zip([0.01, 0.03, 0.02, 0.05])
            .map(|(p, rise)| PadParticle { velocity: p.velocity - Vec3::new(0.0, 0.0, 0.05), rise, ..p.clone() })
            .collect();
        let (down, _) = rigid_fit(&falling, origin);
        assert!((down.z - (-0.02 + 0.01)).abs() < 1e-6, "{down:?}");
        let (one_v, one_w) = rigid_fit(&ps[..1], ps[0].center);
        assert!((one_v - Vec3::new(0.05, 0.0, 0.0)).length() < 1e-6 && one_w == 0.0, "{one_v:?} {one_w}");
    }
}
