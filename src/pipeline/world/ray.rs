//! The result of a scene ray cast.

use crate::scene::ObjectId;
use glam::Vec3;
use rapier3d::prelude::SoftBodyHandle;

/// Where a ray met the scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RayHit {
    /// The scene object hit, or `None` for the table, its walls or a fixed
    /// environment part with no object index.
    pub object: Option<ObjectId>,
    pub point: Vec3,
    /// Outward surface normal at `point`.
    pub normal: Vec3,
    /// Distance along the (unit) ray.
    pub toi: f32,
    /// The soft body hit (a cloth, a block or a torn piece of one) and its
    /// particle nearest to `point`; `object` is `None` then.
    pub soft: Option<(SoftBodyHandle, u32)>,
}
