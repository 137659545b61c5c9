//! Axis-aligned bounds of what a frame shows: they fit the camera's depth
//! range and the shadow map's frustum to the scene. Pure.

use glam::{Mat4, Vec3};

use crate::render::draw_list::{Decal, DrawList, FeedbackDraw, MeshKind};
use crate::render::instances::TABLE_THICKNESS;

/// An axis-aligned box; `EMPTY` until something is added.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    pub const EMPTY: Self = Self { min: Vec3::splat(f32::INFINITY), max: Vec3::splat(f32::NEG_INFINITY) };

    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// Grows to contain `p`; non-finite points are ignored so one broken
    /// object cannot wreck the depth range.
    pub fn add_point(&mut self, p: Vec3) {
        if p.is_finite() {
            self.min = self.min.min(p);
            self.max = self.max.max(p);
        }
    }

    pub fn union(mut self, other: Self) -> Self {
        if !other.is_empty() {
            self.add_point(other.min);
            self.add_point(other.max);
        }
        self
    }

    pub fn center(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    pub fn corners(&self) -> [Vec3; 8] {
        let (a, b) = (self.min, self.max);
        [
            Vec3::new(a.x, a.y, a.z),
            Vec3::new(b.x, a.y, a.z),
            Vec3::new(a.x, b.y, a.z),
            Vec3::new(b.x, b.y, a.z),
            Vec3::new(a.x, a.y, b.z),
            Vec3::new(b.x, a.y, b.z),
            Vec3::new(a.x, b.y, b.z),
            Vec3::new(b.x, b.y, b.z),
        ]
    }

    /// The box of a local box `[-half, half]` under `transform`.
    pub fn of_transformed_box(transform: Mat4, half: Vec3) -> Self {
        let mut out = Self::EMPTY;
        for c in (Self { min: -half, max: half }).corners() {
            out.add_point(transform.transform_point3(c));
        }
        out
    }

    /// Clamps to `limit` (both must be non-empty).
    pub fn intersect(&self, limit: &Self) -> Self {
        Self { min: self.min.max(limit.min), max: self.max.min(limit.max) }
    }
}

/// Half extents of a unit mesh in its own frame.
pub fn mesh_half_extents(mesh: MeshKind) -> Vec3 {
    match mesh {
        MeshKind::Box => Vec3::splat(0.5),
        MeshKind::Sphere => Vec3::ONE,
        MeshKind::Cylinder => Vec3::new(1.0, 1.0, 0.5),
        MeshKind::Capsule { radius, half_height } => Vec3::new(radius, radius, half_height + radius),
    }
}

/// The table slab.
pub fn table_bounds(list: &DrawList) -> Aabb {
    let half = Vec3::new(0.5 * list.table.width, 0.5 * list.table.depth, 0.0);
    Aabb { min: -half - Vec3::Z * TABLE_THICKNESS, max: half }
}

/// What casts or receives shadows: table, objects, deformables — clamped to
/// a few table sizes around the table so a flung object does not spread the
/// shadow map over empty space.
pub fn shadow_bounds(list: &DrawList) -> Aabb {
    let table = table_bounds(list);
    let mut casters = table;
    for o in &list.objects {
        casters = casters.union(Aabb::of_transformed_box(o.transform, mesh_half_extents(o.mesh)));
    }
    for d in &list.deformables {
        for &p in &d.positions {
            casters.add_point(p);
        }
    }
    let reach = list.table.width.max(list.table.depth).max(0.01);
    let limit = Aabb { min: table.min - Vec3::splat(reach), max: table.max + Vec3::splat(reach) };
    casters.intersect(&limit)
}

/// Everything drawn (adds decals and feedback to the shadow bounds), clamped
/// to 50 table sizes: the camera's depth range.
pub fn view_bounds(list: &DrawList) -> Aabb {
    let mut all = shadow_bounds(list);
    for decal in &list.decals {
        let (c, z, r) = match *decal {
            Decal::Disc { center, z, radius, ring, .. } => (center, z, radius + ring.unwrap_or(0.0).abs()),
            Decal::Rect { center, z, half, outline, .. } => (center, z, half.length() + outline.unwrap_or(0.0).abs()),
        };
        all.add_point(c.extend(z) - Vec3::new(r, r, 0.0));
        all.add_point(c.extend(z) + Vec3::new(r, r, 0.0));
    }
    for f in &list.feedback {
        match *f {
            FeedbackDraw::Line { a, b, .. } => {
                all.add_point(a);
                all.add_point(b);
            }
            FeedbackDraw::Cube { center, half, .. } => {
                all.add_point(center - Vec3::splat(half));
                all.add_point(center + Vec3::splat(half));
            }
        }
    }
    let table = table_bounds(list);
    let reach = 50.0 * list.table.width.max(list.table.depth).max(0.01);
    all.intersect(&Aabb { min: table.min - Vec3::splat(reach), max: table.max + Vec3::splat(reach) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotated_box_bounds() {
        let t = Mat4::from_rotation_z(std::f32::consts::FRAC_PI_4);
        let b = Aabb::of_transformed_box(t, Vec3::splat(0.5));
        let r = std::f32::consts::FRAC_1_SQRT_2;
        assert!(b.max.abs_diff_eq(Vec3::new(r, r, 0.5), 1e-6));
        assert!(b.min.abs_diff_eq(-b.max, 1e-6));
    }

    #[test]
    fn non_finite_points_are_ignored() {
        let mut b = Aabb::EMPTY;
        assert!(b.is_empty());
        b.add_point(Vec3::new(f32::NAN, 0.0, 0.0));
        assert!(b.is_empty());
        b.add_point(Vec3::ONE);
        assert_eq!(b.min, Vec3::ONE);
    }
}
