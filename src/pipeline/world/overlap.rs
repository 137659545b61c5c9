//! Overlap of scene objects, from their shapes and poses alone (not from
//! the solver's contact cache, which lags a step and keeps only pairs the
//! broad phase paired): how deeply pushed pieces pile into each other, and
//! whether a technique body would be created inside a movable object (it
//! would be shoved out at once, with whatever speed the solver needs).

use super::magnified::MagnifiedDispatcher;
use super::world::World;
use crate::scene::ObjectId;
use glam::Vec3;
use rapier3d::parry::bounding_volume::BoundingVolume;
use rapier3d::parry::query::{self, QueryDispatcher};
use rapier3d::parry::shape::Capsule;
use rapier3d::prelude::{Pose, RigidBody};

impl World {
    /// Deepest overlap (m, ≥ 0) between any two active scene objects now.
    /// Pairs are pre-filtered by their bounding boxes, so a 40-piece scene
    /// costs a few hundred box tests and a handful of shape queries.
    pub fn max_object_overlap(&self) -> f32 {
        let colliders = &self.physics().colliders;
        let live: Vec<_> = self
            .object_ids()
            .filter(|&id| self.is_active(id))
            .filter_map(|id| colliders.get(self.object_collider(id)))
            .map(|c| (c, c.compute_aabb()))
            .collect();
        let mut deepest = 0.0f32;
        for (i, (a, box_a)) in live.iter().enumerate() {
            for (b, box_b) in &live[i + 1..] {
                if !box_a.intersects(box_b) {
                    continue;
                }
                let pos12 = a.position().inv_mul(b.position());
                if let Ok(Some(c)) = MagnifiedDispatcher.contact(&pos12, a.shape(), b.shape(), 0.0) {
                    deepest = deepest.max(-c.dist);
                }
            }
        }
        deepest
    }

    /// Whether scene object `id` is active and dynamic (can be pushed).
    pub fn is_movable(&self, id: ObjectId) -> bool {
        id.index() < self.object_count()
            && self.is_active(id)
            && self.physics().bodies.get(self.object_body(id)).is_some_and(RigidBody::is_dynamic)
    }

    /// Whether an upright capsule (segment half-length `half`, radius `r`)
    /// centred at `center` overlaps any movable scene object.
    pub fn capsule_overlaps_movable(&self, center: Vec3, half: f32, r: f32) -> bool {
        let capsule = Capsule::new_z(half, r);
        let pose = Pose::from_translation(center);
        self.object_ids().filter(|&id| self.is_movable(id)).any(|id| {
            self.physics().colliders.get(self.object_collider(id)).is_some_and(|c| {
                query::intersection_test(&pose, &capsule, c.position(), c.shape()).map_or(true, |s| s.intersecting)
            })
        })
    }
}
