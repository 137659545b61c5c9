//! The one way a technique may act on a scene object's body: push it ([`ObjectPush`]), never remove,
//! disable or teleport it.

use super::push::Push;
use super::world::World;
use crate::scene::ObjectId;
use glam::Vec3;
use rapier3d::prelude::RigidBody;

/// A scene object's body, to push: forces, impulses and velocities. It
/// reads as a [`RigidBody`] but offers no pose, enable or removal.
pub type ObjectPush<'w> = Push<'w, RigidBody>;

impl ObjectPush<'_> {
    pub fn add_force(&mut self, force: Vec3) {
        self.0.add_force(force, true);
    }

    pub fn add_force_at_point(&mut self, force: Vec3, point: Vec3) {
        self.0.add_force_at_point(force, point, true);
    }

    pub fn apply_impulse(&mut self, impulse: Vec3) {
        self.0.apply_impulse(impulse, true);
    }

    pub fn set_linvel(&mut self, v: Vec3) {
        self.0.set_linvel(v, true);
    }

    pub fn set_angvel(&mut self, w: Vec3) {
        self.0.set_angvel(w, true);
    }

    /// Clears the forces and torques added this step (they persist in
    /// rapier until cleared), without waking the body.
    pub fn reset_forces(&mut self) {
        self.0.reset_forces(false);
        self.0.reset_torques(false);
    }
}

impl World {
    /// Scene object `id`'s body, to read (pose, mass, velocity at a point).
    pub fn object_rigid_body(&self, id: ObjectId) -> Option<&RigidBody> {
        self.physics().bodies.get(self.object_body(id))
    }

    /// Scene object `id`'s body, to push.
    pub fn push_object(&mut self, id: ObjectId) -> Option<ObjectPush<'_>> {
        let h = self.object_body(id);
        self.physics_mut().bodies.get_mut(h).map(Push)
    }
}
