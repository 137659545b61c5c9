//! Proxy: one persistent rigid body per tracked contact.
//!
//! Placed by a ray cast, then driven each step by the velocity that brings it
//! to the contact's position within the step (for a body of known mass this
//! *is* the force `m·Δv/dt`). Only the tangential (x, y) velocity is imposed:
//! gravity presses the proxy into whatever it stands on, so static and kinetic
//! friction move objects, and from the side it collides. A contact whose
//! centroid misses every movable object but whose outline overlaps one
//! puts its proxy over that object (`hit_test = "outline"`, the default);
//! the paper's proxy stands under the centroid only (`"centroid"`).

use super::hit_test;
use super::surface_point::{at_height, clamp_len, support_below, table_point, table_velocity};
use super::{Feedback, HitTest, PressureMode, ProxyShape, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput};
use crate::pipeline::vision::{Contact, ContactId};
use crate::pipeline::world::prelude::*;
use crate::pipeline::world::{Layer, TechniqueBody, TechniqueWorld, World, WorldError};
use glam::{Vec2, Vec3};
use std::collections::BTreeMap;

#[derive(Debug, Clone, Copy)]
struct Proxy {
    body: TechniqueBody,
    /// Spawned on a soft body, with its small inertia (see [`soft_mass`]).
    light: bool,
    /// Its press (N) and half height (m), for a light proxy's support test.
    weight: f32,
    half_height: f32,
    /// Where on the glass it stands from the contact's centroid (m): zero
    /// unless the centroid missed what the outline overlaps (see `landing`).
    offset: Vec2,
}

#[derive(Debug)]
pub struct ProxyTechnique {
    config: TechniqueConfig,
    /// By contact id; a `BTreeMap` keeps creation order deterministic.
    proxies: BTreeMap<ContactId, Proxy>,
    contacts: usize,
}

impl ProxyTechnique {
    pub fn new(config: TechniqueConfig) -> Self {
        ProxyTechnique { config, proxies: BTreeMap::new(), contacts: 0 }
    }

    fn half_height(&self, world: &World, surface_z: f32) -> f32 {
        match self.config.proxy_shape {
            ProxyShape::Cube | ProxyShape::Sphere => self.config.proxy_size,
            // From the camera's near plane (10 cm below the eye) down to the surface.
            ProxyShape::Capsule => ((world.eye().z - 0.1 - surface_z) / 2.0).max(self.config.proxy_size),
        }
    }

    fn spawn(&self, world: &mut TechniqueWorld<'_>, target: Vec2, velocity: Vec2, weight: f32) -> Proxy {
        let hit = support_below(world, target);
        let light = hit.is_some_and(|h| h.soft.is_some());
        let mass = if light { soft_mass(weight) } else { self.config.proxy_mass };
        let surface_z = hit.map_or(0.0, |h| h.point.z);
        let target = hit.map_or(target, |h| h.point.truncate());
        let r = self.config.proxy_size;
        let hh = self.half_height(world, surface_z);
        let collider = match self.config.proxy_shape {
            ProxyShape::Cube => ColliderBuilder::cuboid(r, r, r),
            ProxyShape::Sphere => ColliderBuilder::ball(r),
            ProxyShape::Capsule => ColliderBuilder::capsule_z(hh - r, r),
        };
        let center = target.extend(surface_z + hh + 0.0005);
        let body = RigidBodyBuilder::dynamic()
            .translation(center)
            // Free to yaw: rapier's twist friction over a face contact would
            // otherwise pin the object's rotation to a non-rotating proxy
            // (a two-finger twist could never turn anything). No tipping.
            .enabled_rotations(false, false, true)
            // A light proxy starts pressing from its second frame, once it
            // is known to stand on something (see `apply`).
            .gravity_scale(if light { 1.0 } else { gravity_scale_for(mass, weight) })
            .linvel(velocity.extend(0.0))
            .can_sleep(false)
            .build();
        let collider = collider
            .mass(mass)
            .friction(self.config.friction)
            .friction_combine_rule(CoefficientCombineRule::Max)
            .restitution(0.0)
            .collision_groups(Layer::Proxy.groups())
            .build();
        let body = world.spawn_body(body, collider);
        Proxy { body, light, weight, half_height: hh, offset: Vec2::ZERO }
    }

    /// Where a new contact's proxy stands on the glass: under its centroid,
    /// unless that misses every movable object and its outline overlaps
    /// one; then over the object it overlaps most, at the overlap point
    /// nearest the centroid (`hit_test`) moved in towards the object's
    /// middle by the cube's half width, so that the cube's face still
    /// covers that point. At the overlap point itself the cube would stand
    /// on a ball's steep flank and slide off it, and a flat hand whose
    /// fingers lie over a 6 cm ball would barely move it sideways
    /// (`tests/techniques.rs`, `a_flat_hand_whose_centre_misses_a_ball_still_moves_it`).
    fn landing(&self, world: &World, c: &Contact, input: &TechniqueInput<'_>, centroid: Vec2) -> Vec2 {
        if self.config.hit_test != HitTest::Outline
            || world
                .cast_contact_ray(centroid)
                .is_some_and(|h| h.soft.is_some() || h.object.is_some_and(|id| world.is_movable(id)))
        {
            return centroid;
        }
        let outline = hit_test::outline(c, input.sensor);
        hit_test::overlaps(world, &outline, centroid)
            .first()
            .map_or(centroid, |o| o.point + (o.centre - o.point).clamp_length_max(self.config.proxy_size))
    }
}

/// Weight (N) for a contact, scaled by grey level when pressure is on
/// (full grey presses twice the configured weight, a light touch less).
pub(super) fn pressure_weight(config: &TechniqueConfig, base: f32, grey: f32) -> f32 {
    match config.pressure {
        PressureMode::Off => base,
        PressureMode::Weight => base * (grey / 255.0).clamp(0.1, 1.0) * 2.0,
    }
}

/// The mass of a technique body standing on a soft body. Its weight (the
/// press) is kept through the gravity scale; only its inertia changes.
/// rapier's soft solver cannot hold a heavy body on light particles: a
/// 0.2 kg box pressing 2 N sinks into a 30 g, 256-particle cloth (0.12 g
/// particles) and a 1 kg one goes through. Too light, and a per-frame
/// particle carries too little momentum to drag the sheet under it. Four
/// fingertips sliding over the flat 50 g task cloth drag it furthest at a
/// few tens of grams a particle and hardly at all at 50 g (the particles
/// push into the sheet); heavier particles also make two hands smoothing it
/// outwards stretch it for good, so 10 g balances the two
/// (`tests/soft_bodies.rs`).
pub(super) fn soft_mass(weight: f32) -> f32 {
    SOFT_CONTACT_MASS.max(weight / (9.81 * SOFT_MAX_GRAVITY_SCALE))
}

/// Inertia (kg) of a proxy or particle standing on a soft body...
const SOFT_CONTACT_MASS: f32 = 0.01;
/// ...unless its press would need a gravity scale above this: a body
/// falling at 8 g still moves only 2 cm in a step if its support gives way.
const SOFT_MAX_GRAVITY_SCALE: f32 = 8.0;
/// Fastest fall (m/s) of a light proxy: a finger never comes down faster.
const LIGHT_MAX_FALL: f32 = 0.5;
/// A light proxy whose bottom is more than this (m) above the surface under
/// its centre is falling, not pressing.
const LIGHT_SUPPORT_GAP: f32 = 0.003;

/// The gravity scale that makes a body of `mass` press with `weight` newtons.
pub(super) fn gravity_scale_for(mass: f32, weight: f32) -> f32 {
    weight / (mass * 9.81)
}

impl Technique for ProxyTechnique {
    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError> {
        self.contacts = input.frame.contacts.len();
        let dt = input.dt;
        let mut seen = Vec::with_capacity(input.frame.contacts.len());
        for c in &input.frame.contacts {
            seen.push(c.id);
            let target = table_point(input.sensor, c.blob.centroid);
            let v_hand = clamp_len(table_velocity(input.sensor, c.velocity_px, dt), self.config.max_contact_speed);
            if let Some(p) = self.proxies.get(&c.id).copied() {
                let Some(pos) = world.technique_body(p.body).map(RigidBody::translation) else { continue };
                // Where the finger appears at the proxy's own height.
                let target = at_height(world, target + p.offset, pos.z);
                // A light proxy presses only while it stands on something:
                // its press comes from a gravity scale of tens of g, which
                // would throw it through the table in one step should the
                // cloth under it slide away.
                let supported = !p.light
                    || world
                        .cast_ray(pos, Vec3::NEG_Z, 1.0)
                        .is_some_and(|h| h.toi <= p.half_height + LIGHT_SUPPORT_GAP);
                let Some(b) = world.technique_body_mut(p.body) else { continue };
                if p.light {
                    let scale = if supported { gravity_scale_for(b.mass(), p.weight) } else { 1.0 };
                    let scale = scale.min(SOFT_MAX_GRAVITY_SCALE);
                    b.set_gravity_scale(scale, true);
                }
                // The velocity that reaches the target this step, capped: a
                // contact that jumps (lost tracking) is followed, never teleported to.
                let v = clamp_len((target - pos.truncate()) / dt, self.config.max_contact_speed);
                let mut vz = b.linvel().z;
                if p.light {
                    vz = vz.max(-LIGHT_MAX_FALL);
                }
                // Driven through the world, which predicts the cube's
                // contacts along a sudden fast start: a fingertip flicked
                // from rest at 3 m/s moves it 5 cm in a step, six times its
                // half width, into a box's side and through it
                // (`World::drive`).
                world.drive(p.body, Vec3::new(v.x, v.y, vz));
            } else {
                let weight = pressure_weight(&self.config, self.config.proxy_weight, c.blob.mean_grey);
                let at = self.landing(world, c, input, target);
                let mut p = self.spawn(world, at, v_hand, weight);
                p.offset = at - target;
                self.proxies.insert(c.id, p);
            }
        }
        // Contacts that lifted: their proxies go.
        let gone: Vec<ContactId> = self.proxies.keys().copied().filter(|id| !seen.contains(id)).collect();
        for id in gone {
            if let Some(p) = self.proxies.remove(&id) {
                world.remove_body(p.body);
            }
        }
        Ok(())
    }

    fn feedback(&self, world: &World) -> Feedback {
        let cubes = self
            .proxies
            .values()
            .filter_map(|p| world.technique_body(p.body))
            .map(|b| (b.translation(), self.config.proxy_size))
            .collect();
        Feedback { lines: Vec::new(), edges: Vec::new(), cubes }
    }

    fn counts(&self) -> TechniqueCounts {
        TechniqueCounts { contacts: self.contacts, bodies: self.proxies.len(), joints: 0 }
    }

    fn clear(&mut self, world: &mut TechniqueWorld<'_>) {
        for (_, p) in std::mem::take(&mut self.proxies) {
            world.remove_body(p.body);
        }
    }

    fn config_mut(&mut self) -> &mut TechniqueConfig {
        &mut self.config
    }
}
