//! Hybrid: the paper's suggested extension for grasping (Discussion:
//! "extend the particle approach to allow proxies to persist at a given
//! depth ... or a hybrid approach in which both the particle and single
//! proxy techniques are used simultaneously").
//!
//! Per-frame particles do what [`ParticleTechnique`] does: friction from
//! the top, collision from the side, as the outline moves. On top of them,
//! each outline point of a contact that touched down on *fixed* ground (the
//! table, a platform) becomes a **grip**: a persistent body that stays at
//! the depth where it touched for as long as its contact persists, and
//! follows the contact's rigid motion (its tracked centroid and turn). A
//! grip never re-lands on top of what it meets, so two hands, or a pinch,
//! closing on an object from its sides squeeze it between their grips and
//! carry it; when the contact lifts, its grips go and the object is free.
//!
//! Choices, each for a reason:
//! - A contact that landed on a movable object anywhere under it rests on
//!   it and makes no grips (see `touch_down` and `rest`); it is a Particle
//!   contact.
//! - A gripping contact's particles are balls, not line-of-sight capsules:
//!   its grips are its contact from the side, and capsules standing beside
//!   a pinched ball push it out of the grip and throw it on release
//!   (`tests/hybrid.rs`, `a_pinch_grasps_a_ball_with_hybrid_and_lets_it_go`).
//! - Grips are made only where the touch landed on fixed ground. A grip
//!   made on a movable object's top would hang in the air at that height as
//!   soon as the object moved from under it; the per-frame particles already
//!   press on tops.
//! - A grip is a vertical capsule [`GRIP_HEIGHT`] tall standing on its
//!   ground: a finger's side, not its tip. A small sphere at table height
//!   meets a ball below its equator, where the contact normal points up, and
//!   squeezing pops the ball out of the hands.
//! - No grip is made where its capsule would overlap a body: it would shove
//!   that body away the moment it appeared.
//! - A grip that falls more than [`GRIP_SLIP`] behind its target has been
//!   stopped by something it cannot move (a wall, a platform's side): it
//!   lets go, as a finger slides off.
//!
//! Design: docs/design/techniques.md.

use super::particle::{ParticleTechnique, REFERENCE_SPACING};
use super::proxy::{gravity_scale_for, pressure_weight};
use super::surface_point::{at_height, clamp_len, table_point};
use super::{Feedback, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput};
use crate::pipeline::surface::Sensor;
use crate::pipeline::vision::{Contact, ContactId, FlowInterest};
use crate::pipeline::world::prelude::*;
use crate::pipeline::world::{Layer, TechniqueBody, TechniqueWorld, World, WorldError};
use glam::{Vec2, Vec3};
use std::collections::BTreeMap;

/// Height (m) of a grip capsule: above the equator of the largest ball in
/// the project's scenes (3 cm radius), so a squeeze meets it side-on.
pub const GRIP_HEIGHT: f32 = 0.04;

/// Most grips one contact keeps (dropped evenly along its outline): a flat
/// hand's outline has about 130 samples at the default stride, and the
/// grip of its side facing an object needs far fewer.
const MAX_GRIPS_PER_CONTACT: usize = 48;

/// A grip further than this (m) from where its contact puts it has let go.
const GRIP_SLIP: f32 = 0.04;

#[derive(Debug, Clone, Copy)]
struct Grip {
    body: TechniqueBody,
    /// Offset from the contact's weighted centroid on the table plane (m),
    /// in the contact's frame at touch-down.
    offset: Vec2,
    /// Height (m) of the ground it touched.
    depth: f32,
}

#[derive(Debug, Default)]
struct Held {
    grips: Vec<Grip>,
    /// The contact's turn since touch-down (rad, table orientation).
    turned: f32,
}

#[derive(Debug)]
pub struct HybridTechnique {
    particles: ParticleTechnique,
    /// By contact id; a `BTreeMap` keeps creation order deterministic.
    held: BTreeMap<ContactId, Held>,
    grip_positions: Vec<Vec3>,
}

impl HybridTechnique {
    pub fn new(config: TechniqueConfig) -> Self {
        let particles = ParticleTechnique::new(config);
        HybridTechnique { particles, held: BTreeMap::new(), grip_positions: Vec::new() }
    }

    fn config(&self) -> &TechniqueConfig {
        self.particles.config()
    }

    /// Where a grip of `contact` should stand this frame (world x, y).
    fn target(world: &World, sensor: &Sensor, contact: &Contact, held: &Held, grip: &Grip) -> Vec2 {
        let c = table_point(sensor, contact.blob.weighted_centroid);
        let local = Vec2::from_angle(held.turned).rotate(grip.offset);
        at_height(world, c + local, grip.depth + GRIP_HEIGHT * 0.5)
    }

    /// Grips for a contact seen for the first time.
    fn touch_down(&self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>, contact: &Contact) -> Held {
        let config = self.config();
        let r = config.particle_radius;
        let share = config.particle_stride as f32 * input.sensor.metres_per_pixel() / REFERENCE_SPACING;
        let centroid = table_point(input.sensor, contact.blob.weighted_centroid);
        // A contact that landed on a movable object rests on it (a fingertip
        // pinning a box's corner, a flat hand on a ball): the part of its
        // outline beyond the object's silhouette is a finger hanging over the
        // edge, not flesh at table depth, so it makes no grips. Gripped
        // there, a pinning fingertip would cage the corner it overhung and
        // the box would slide along its grips instead of pivoting. What it
        // landed on decides, not its centroid's ray: a flat hand laid 2 cm
        // off a ball's centre has its centroid up among the fingers, and
        // gripping with its outline on the table it would push the ball
        // nearly its whole slide, where a real ball rolls about half
        // (`ball_under_hand_off_centre`).
        let rests_on_movable = super::rest::lands_on_movable(contact, input.sensor, world);
        if rests_on_movable {
            return Held::default();
        }
        let samples: Vec<_> = input.frame.edges.iter().filter(|e| e.contact_id == contact.id).collect();
        let n = samples.len();
        let keep = n.min(MAX_GRIPS_PER_CONTACT);
        let mut held = Held::default();
        for k in 0..keep {
            let e = samples[k * n / keep];
            let p = table_point(input.sensor, e.px);
            let Some(hit) = world.cast_contact_ray(p) else { continue };
            let on_ground = hit.soft.is_none() && hit.object.is_none_or(|i| !world.is_movable(i)) && hit.normal.z > 0.7;
            if !on_ground {
                continue;
            }
            let half = GRIP_HEIGHT * 0.5 - r;
            let center = Vec3::new(hit.point.x, hit.point.y, hit.point.z + GRIP_HEIGHT * 0.5 + 0.0005);
            if world.capsule_overlaps_movable(center, half, r) {
                continue;
            }
            let weight = pressure_weight(config, config.particle_weight, f32::from(e.grey)) * share;
            let mass = config.particle_mass * share;
            let body = RigidBody::from(
                RigidBodyBuilder::dynamic()
                    .translation(center)
                    .gravity_scale(gravity_scale_for(mass, weight))
                    .lock_rotations()
                    .can_sleep(false),
            );
            let col = ColliderBuilder::capsule_z(half, r)
                .mass(mass)
                .friction(config.friction)
                .friction_combine_rule(CoefficientCombineRule::Max)
                .restitution(0.0)
                .collision_groups(Layer::Particle.groups())
                .build();
            let body = world.spawn_body(body, col);
            held.grips.push(Grip { body, offset: p - centroid, depth: hit.point.z });
        }
        held
    }
}

impl Technique for HybridTechnique {
    fn flow_interest(&mut self, world: &World, sensor: &Sensor, dt: f32) -> FlowInterest {
        self.particles.flow_interest(world, sensor, dt)
    }

    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError> {
        let mut fresh = Vec::new();
        for c in &input.frame.contacts {
            if !self.held.contains_key(&c.id) {
                let held = self.touch_down(input, world, c);
                self.held.insert(c.id, held);
                fresh.push(c.id);
            }
        }
        // Ball particles for gripping contacts (module doc).
        let gripping = self.held.iter().filter(|(_, h)| !h.grips.is_empty()).map(|(id, _)| *id);
        self.particles.set_ball_contacts(gripping);
        self.particles.apply(input, world)?;
        let dt = input.dt;
        let max_speed = self.config().max_contact_speed;
        let mut seen = Vec::with_capacity(input.frame.contacts.len());
        for c in &input.frame.contacts {
            seen.push(c.id);
            if fresh.contains(&c.id) {
                continue;
            }
            let Some(held) = self.held.get_mut(&c.id) else { continue };
            // Image orientation to table orientation (see `Contact`).
            held.turned -= c.rotation_rad;
            let targets: Vec<Vec2> = held.grips.iter().map(|g| Self::target(world, input.sensor, c, held, g)).collect();
            let mut slipped = Vec::new();
            for (k, (g, target)) in held.grips.iter().zip(targets).enumerate() {
                let Some(b) = world.technique_body_mut(g.body) else { continue };
                let pos = b.translation().truncate();
                if (target - pos).length() > GRIP_SLIP {
                    slipped.push(k);
                    continue;
                }
                // The velocity that reaches the target within the step (the
                // paper's proxy force for a body of known mass), capped.
                let v = clamp_len((target - pos) / dt, max_speed);
                let vz = b.linvel().z;
                b.set_linvel(Vec3::new(v.x, v.y, vz), true);
            }
            for k in slipped.into_iter().rev() {
                let g = held.grips.remove(k);
                world.remove_body(g.body);
            }
        }
        let gone: Vec<ContactId> = self.held.keys().copied().filter(|id| !seen.contains(id)).collect();
        for id in gone {
            if let Some(held) = self.held.remove(&id) {
                for g in held.grips {
                    world.remove_body(g.body);
                }
            }
        }
        Ok(())
    }

    fn after_step(&mut self, world: &mut TechniqueWorld<'_>) {
        self.particles.after_step(world);
        self.grip_positions.clear();
        for g in self.held.values().flat_map(|h| &h.grips) {
            if let Some(b) = world.technique_body(g.body) {
                self.grip_positions.push(b.translation());
            }
        }
    }

    fn feedback(&self, world: &World) -> Feedback {
        let mut f = self.particles.feedback(world);
        let r = self.config().particle_radius;
        f.cubes.extend(self.grip_positions.iter().map(|p| (*p - Vec3::Z * (GRIP_HEIGHT * 0.5 - r), r)));
        f
    }

    fn counts(&self) -> TechniqueCounts {
        let mut c = self.particles.counts();
        c.bodies += self.grip_positions.len();
        c
    }

    fn clear(&mut self, world: &mut TechniqueWorld<'_>) {
        self.particles.clear(world);
        for (_, held) in std::mem::take(&mut self.held) {
            for g in held.grips {
                world.remove_body(g.body);
            }
        }
        self.grip_positions.clear();
    }

    fn config_mut(&mut self) -> &mut TechniqueConfig {
        self.particles.config_mut()
    }
}
