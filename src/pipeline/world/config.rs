//! Which effects a world simulates, derived once from the scene's declaration.

use crate::scene::{Effect, EffectSet, Scene};
use glam::Vec3;

/// The switches a [`super::World`] was built with. Tests read this to check
/// that undeclared effects are really off; benchmarks build the same scene
/// with [`EffectSet::all`] to measure what ignoring the declaration costs.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(clippy::struct_excessive_bools)] // one switch per effect, read by tests
pub struct WorldConfig {
    pub effects: EffectSet,
    pub gravity: Vec3,
    pub dt: f32,
    /// `IntegrationParameters::max_ccd_substeps`; 0 turns all CCD off.
    pub ccd_substeps: usize,
    /// Whether bodies may fall asleep.
    pub sleeping: bool,
    /// Whether colliders keep their friction coefficients (else all are 0).
    pub friction: bool,
    /// Whether impulse joints may be created at all.
    pub joints: bool,
    /// Whether soft bodies (volumes, cloth, tearing) may be created.
    pub soft_bodies: bool,
    pub solver_iterations: usize,
    pub pgs_iterations: usize,
    pub length_unit: f32,
    pub max_speed: f32,
    pub contact_hz: f32,
    /// Hands give way where they close on a pile (`give_way.rs`).
    pub give_way: bool,
}

impl WorldConfig {
    /// The configuration for `scene` simulating exactly `effects`.
    pub fn new(scene: &Scene, effects: EffectSet) -> Self {
        let p = scene.physics;
        WorldConfig {
            effects,
            gravity: if effects.contains(Effect::Gravity) { Vec3::new(0.0, 0.0, -9.81) } else { Vec3::ZERO },
            dt: p.dt,
            ccd_substeps: if effects.contains(Effect::Ccd) { p.ccd_substeps.max(1) } else { 0 },
            sleeping: effects.contains(Effect::Sleeping),
            friction: effects.contains(Effect::Friction),
            joints: effects.contains(Effect::Joints),
            soft_bodies: effects.any_soft(),
            solver_iterations: p.solver_iterations,
            pgs_iterations: p.pgs_iterations,
            length_unit: p.length_unit,
            max_speed: p.max_speed,
            contact_hz: p.contact_hz,
            give_way: p.give_way,
        }
    }
}
