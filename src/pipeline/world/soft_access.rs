//! The world's soft bodies, as its users read them: each accessor forwards
//! to `soft.rs` with the world's physics (so `soft.rs` needs no `World`).

use super::error::WorldError;
use super::push::Push;
use super::soft::{self, SoftSurface};
use super::world::World;
use crate::scene::{SoftBodySpec, SoftId};
use glam::Vec3;
use rapier3d::prelude::{SoftBody, SoftBodyHandle};

impl World {
    /// Adds a soft body (beyond the scene's own); returns its id for the
    /// `soft_*` accessors. Refuses when its effect is off, naming the scene
    /// and the effect.
    pub fn add_soft_body(&mut self, spec: &SoftBodySpec) -> Result<SoftId, WorldError> {
        let config = *self.config();
        let (soft, physics) = self.soft_and_physics_mut();
        soft.add(spec, &config, physics).map(SoftId::new).map_err(|e| WorldError::EffectNotDeclared {
            scene: self.scene().name.clone(),
            effect: e,
            what: format!("the {} `{}`", spec.kind.name(), spec.name),
        })
    }

    /// Number of declared soft bodies (including those whose effect is off).
    pub fn soft_body_count(&self) -> usize {
        self.soft().len()
    }

    /// Every declared soft body (including those whose effect is off).
    pub fn soft_ids(&self) -> impl Iterator<Item = SoftId> + use<> {
        (0..self.soft().len()).map(SoftId::new)
    }

    pub fn soft_spec(&self, id: SoftId) -> &SoftBodySpec {
        self.soft().spec(id.index())
    }

    /// Whether the declared soft body `id` exists in this world.
    pub fn soft_exists(&self, id: SoftId) -> bool {
        self.soft().exists(id.index())
    }

    /// The rapier bodies soft body `id` is made of now: the body itself,
    /// or after tears the pieces it came apart into.
    pub fn soft_pieces(&self, id: SoftId) -> impl Iterator<Item = (SoftBodyHandle, &SoftBody)> {
        soft::pieces(self.physics(), id.index())
    }

    /// The mass of each piece of soft body `id`, largest first.
    pub fn soft_piece_masses(&self, id: SoftId) -> Vec<f32> {
        soft::piece_masses(self.physics(), id.index())
    }

    /// Centre of mass of soft body `id` (all its pieces).
    pub fn soft_center(&self, id: SoftId) -> Option<Vec3> {
        soft::center(self.physics(), id.index())
    }

    /// Fastest particle of soft body `id` (m/s); infinite if any is not finite.
    pub fn soft_max_speed(&self, id: SoftId) -> f32 {
        soft::max_speed(self.physics(), id.index())
    }

    /// Whether every particle of every soft body is finite.
    pub fn soft_all_finite(&self) -> bool {
        soft::all_finite(self.physics())
    }

    /// Volume enclosed by soft body `id` now, and at rest (m³; 0 for a cloth).
    pub fn soft_volume(&self, id: SoftId) -> (f32, f32) {
        soft::volume(self.physics(), id.index())
    }

    /// Share of its rest area that soft body `id` covers on the table,
    /// seen from above (the `cloth_flat` goal's measure).
    pub fn soft_coverage(&self, id: SoftId) -> f32 {
        soft::coverage(self.physics(), self.soft().spec(id.index()), id.index())
    }

    /// Every soft body's surface now, torn pieces included.
    pub fn soft_surfaces(&self) -> Vec<SoftSurface> {
        soft::surfaces(self.physics())
    }
}

/// A soft body (or torn piece), to push: per-particle forces. It reads as a
/// [`SoftBody`] but offers no way to move its particles directly.
pub type SoftPush<'w> = Push<'w, SoftBody>;

impl SoftPush<'_> {
    pub fn add_particle_force(&mut self, particle: u32, force: Vec3) {
        self.0.add_particle_force(particle as usize, force, true);
    }
}

impl World {
    /// Soft body (or piece) `h`, to push.
    pub fn push_soft(&mut self, h: SoftBodyHandle) -> Option<SoftPush<'_>> {
        self.physics_mut().soft_bodies.get_mut(h).map(Push)
    }

    /// Clears the particle forces added this step on every soft body and
    /// piece (a tear may have carried a force to a new piece).
    pub fn reset_soft_forces(&mut self) {
        for (_, b) in self.physics_mut().soft_bodies.iter_mut() {
            b.reset_forces(false);
        }
    }

    /// The position of particle `particle` of soft body (or piece) `h`.
    pub fn soft_particle_position(&self, h: SoftBodyHandle, particle: u32) -> Option<Vec3> {
        Some(self.physics().soft_bodies.get(h)?.particle_position(particle as usize))
    }
}
