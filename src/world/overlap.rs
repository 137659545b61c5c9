//! Overlap tests against the scene's movable bodies: a technique must not
//! create a body inside one (it would be shoved out at once, with whatever
//! speed the solver needs to separate them).

use super::world::World;
use glam::Vec3;
use rapier3d::parry::query::intersection_test;
use rapier3d::parry::shape::Capsule;
use rapier3d::prelude::{Pose, RigidBody};

impl World {
    /// Whether scene object `i` is active and dynamic (can be pushed).
    pub fn is_movable(&self, i: usize) -> bool {
        i < self.object_count()
            && self.is_active(i)
            && self.physics().bodies.get(self.object_body(i)).is_some_and(RigidBody::is_dynamic)
    }

    /// Whether an upright capsule (segment half-length `half`, radius `r`)
    /// centred at `center` overlaps any movable scene object.
    pub fn capsule_overlaps_movable(&self, center: Vec3, half: f32, r: f32) -> bool {
        let capsule = Capsule::new_z(half, r);
        let pose = Pose::from_translation(center);
        (0..self.object_count()).filter(|&i| self.is_movable(i)).any(|i| {
            self.physics().colliders.get(self.object_collider(i)).is_some_and(|c| {
                intersection_test(&pose, &capsule, c.position(), c.shape()).map_or(true, |s| s.intersecting)
            })
        })
    }
}
