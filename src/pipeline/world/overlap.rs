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
use rapier3d::parry::shape::{Capsule, Shape};
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

    /// How far to move `shape` at `pose` across (in x and y) so that it no
    /// longer overlaps any movable scene object but `resting_on` (what it
    /// is placed on, pressing into it on purpose): zero when it overlaps
    /// none. Each overlap is cleared along its contact normal's level part,
    /// objects one after another, so two objects squeezing the shape from
    /// both sides leave it in the last one.
    pub fn clearance(&self, shape: &dyn Shape, pose: Pose, resting_on: Option<ObjectId>) -> Vec3 {
        let mut shift = Vec3::ZERO;
        let mut reach = shape.compute_aabb(&pose);
        for (h, object, aabb) in self.scene_colliders() {
            let Some(id) = object.map(ObjectId::new) else { continue };
            if Some(id) == resting_on || !reach.intersects(aabb) || !self.is_movable(id) {
                continue;
            }
            let Some(c) = self.physics().colliders.get(*h) else { continue };
            let at = Pose::from_parts(pose.translation + shift, pose.rotation);
            let pos12 = c.position().inv_mul(&at);
            // Most shapes near an object do not overlap it: GJK's yes or no
            // first, the depth (EPA, magnified) only for the few that do.
            if !MagnifiedDispatcher.intersection_test(&pos12, c.shape(), shape).is_ok_and(|t| t.intersecting) {
                continue;
            }
            let Ok(Some(contact)) = MagnifiedDispatcher.contact(&pos12, c.shape(), shape, 0.0) else { continue };
            if contact.dist >= 0.0 {
                continue;
            }
            // Normal out of the object, towards the shape, in world space.
            let n = c.position().rotation * contact.normal1;
            let level = Vec3::new(n.x, n.y, 0.0);
            let len = level.length();
            if len < 1e-3 {
                continue;
            }
            // Far enough across that the overlap along the normal is gone.
            shift += level / len * (-contact.dist / len.max(0.5));
            reach = shape.compute_aabb(&Pose::from_parts(pose.translation + shift, pose.rotation));
        }
        shift
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
