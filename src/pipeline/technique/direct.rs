//! Direct Force: a force at the touched point from the contact's velocity.
//!
//! The paper piloted it and dropped it: it models kinetic friction only, so
//! an object keeps sliding after the hand stops and must be pushed back
//! (overshoot). Kept as a baseline condition.

use super::surface_point::{clamp_len, table_point, table_velocity};
use super::{Feedback, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput};
use crate::pipeline::surface::{Sensor, TablePoint};
use crate::pipeline::vision::Blob;
use crate::pipeline::world::prelude::SoftBodyHandle;
use crate::pipeline::world::{TechniqueWorld, World, WorldError};
use glam::Vec3;

#[derive(Debug)]
pub struct DirectForce {
    config: TechniqueConfig,
    /// Points where a force was applied this frame (feedback: a cube each).
    touched: Vec<Vec3>,
    /// Soft particles given a force this frame (cleared after the step).
    soft_touched: Vec<(SoftBodyHandle, u32)>,
    contacts: usize,
}

impl DirectForce {
    pub fn new(config: TechniqueConfig) -> Self {
        DirectForce { config, touched: Vec::new(), soft_touched: Vec::new(), contacts: 0 }
    }
}

/// Largest share of its slip a soft particle may make up in one step.
const MAX_SERVO: f32 = 1.5;

/// The soft particles that appear (seen from the camera) inside `blob`.
fn soft_particles_under(world: &World, sensor: &Sensor, blob: &Blob) -> Vec<(SoftBodyHandle, u32)> {
    let mut out = Vec::new();
    for (h, b) in world.physics().soft_bodies.iter() {
        for (i, p) in b.particle_positions().enumerate() {
            let [x, y] = sensor.to_pixel(TablePoint(world.screen_point(p))).to_array();
            if blob.contains(x.round() as i64, y.round() as i64) {
                out.push((h, i as u32));
            }
        }
    }
    out
}

impl Technique for DirectForce {
    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError> {
        self.touched.clear();
        self.contacts = input.frame.contacts.len();
        for c in &input.frame.contacts {
            let p = table_point(input.sensor, c.blob.centroid);
            let Some(hit) = world.cast_contact_ray(p) else { continue };
            // A contact that just appeared has no velocity yet.
            if c.age_frames == 0 {
                continue;
            }
            let v_hand =
                clamp_len(table_velocity(input.sensor, c.velocity_px, input.dt), self.config.max_contact_speed);
            if hit.soft.is_some() {
                // On a soft body the touched "point" is every particle that
                // appears under the contact's footprint. As on a rigid body,
                // the drag is the whole body's mass times the gain times the
                // slip (here the mean slip under the hand), shared among
                // those particles: a hand drags a sheet like it drags a box.
                let mut under = soft_particles_under(world, input.sensor, &c.blob);
                if under.is_empty() {
                    // A fingertip between particles: the one the ray landed nearest.
                    under.extend(hit.soft);
                }
                under.sort_unstable_by_key(|&(h, i)| (h.0.into_raw_parts(), i));
                for group in under.chunk_by(|a, b| a.0 == b.0) {
                    let Some(mut b) = world.push_soft(group[0].0) else { continue };
                    let slip = group.iter().fold(Vec3::ZERO, |acc, &(_, i)| {
                        let v = b.particles()[i as usize].velocity();
                        acc + v_hand.extend(0.0) - Vec3::new(v.x, v.y, 0.0)
                    }) / group.len() as f32;
                    // ...but never more than takes a particle 1.5 times its
                    // slip in one step: past 2 the servo overshoots more each
                    // frame, and a fingertip on one particle would fling it.
                    let share = self.config.direct_gain * b.mass() / group.len() as f32;
                    for &(_, i) in group {
                        let m = b.particles()[i as usize].mass();
                        b.add_particle_force(i, slip * share.min(MAX_SERVO * m / input.dt));
                    }
                }
                self.soft_touched.extend(under);
                self.touched.push(hit.point);
                continue;
            }
            let Some(obj) = hit.object else { continue };
            let Some(mut body) = world.push_object(obj) else { continue };
            if !body.is_dynamic() {
                continue;
            }
            let v_point = body.velocity_at_point(hit.point);
            // Kinetic friction only: drag the touched point toward the hand's
            // tangential velocity; no static grip, no normal force.
            let rel = v_hand.extend(0.0) - Vec3::new(v_point.x, v_point.y, 0.0);
            let force = rel * (self.config.direct_gain * body.mass());
            body.add_force_at_point(force, hit.point);
            self.touched.push(hit.point);
        }
        Ok(())
    }

    fn after_step(&mut self, world: &mut TechniqueWorld<'_>) {
        // Forces are per step: clear what we added so they do not accumulate.
        for id in world.object_ids() {
            if let Some(mut b) = world.push_object(id) {
                b.reset_forces();
            }
        }
        // Every piece: a tear this step may have carried a force to a new one.
        if !std::mem::take(&mut self.soft_touched).is_empty() {
            world.reset_soft_forces();
        }
    }

    fn feedback(&self, _world: &World) -> Feedback {
        Feedback { lines: Vec::new(), edges: Vec::new(), cubes: self.touched.iter().map(|p| (*p, 0.006)).collect() }
    }

    fn counts(&self) -> TechniqueCounts {
        TechniqueCounts { contacts: self.contacts, bodies: 0, joints: 0 }
    }

    fn clear(&mut self, _world: &mut TechniqueWorld<'_>) {
        self.touched.clear();
    }

    fn config_mut(&mut self) -> &mut TechniqueConfig {
        &mut self.config
    }
}
