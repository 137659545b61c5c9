//! The light rig: one directional "sun" that casts the shadows, plus a
//! sky/ground ambient. Fixed, so every frame and every snapshot is lit alike.

use glam::{Mat4, Vec3, Vec4};

use crate::render::bounds::Aabb;

/// Unit vector towards the light: from above, a little to the left and far
/// side of the table, 60° above the horizon. Shadows fall to the right and
/// towards the viewer, in front of the objects, where they show how high an
/// object floats (a lifted object's shadow detaches from it) without hiding
/// much of the table.
pub fn light_direction() -> Vec3 {
    Vec3::new(-0.45, 0.35, 1.0).normalize()
}

/// Linear RGB of the direct light.
pub const LIGHT_COLOR: [f32; 3] = [0.72, 0.70, 0.66];
/// Ambient from above (cool) and below (warm bounce off the table).
pub const SKY_COLOR: [f32; 3] = [0.32, 0.34, 0.38];
pub const GROUND_COLOR: [f32; 3] = [0.20, 0.19, 0.18];
/// Share of the direct light an occluder removes (shadows are not black:
/// a lit room has fill light).
pub const SHADOW_STRENGTH: f32 = 0.85;
/// Width of the soft shadow edge (metres); the PCF kernel spans it.
pub const PENUMBRA: f32 = 0.004;

/// The shadow map's projection: an *oblique* orthographic projection along
/// the light onto the table plane. A point maps to where the light ray
/// through it meets z = 0 (the map's u, v) and to its height (the depth:
/// higher is nearer the light). So the map's texel rows and columns follow
/// the table's x and y axes whatever the light's direction, and the shadow
/// edges of the (mostly axis-aligned) boxes and platforms run along texel
/// rows instead of crossing them in stair-steps — which a one-tap shadow
/// lookup would show.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShadowProjection {
    pub view_proj: Mat4,
    /// Side of the (square) region of the table plane the map covers (metres).
    pub extent: f32,
}

impl ShadowProjection {
    pub fn fit(bounds: &Aabb, direction: Vec3) -> Self {
        // Shift per metre of height along the light onto z = 0. The light is
        // well above the horizon; keep it so if a caller's direction is not.
        let dz = direction.z.max(0.1);
        let (kx, ky) = (direction.x / dz, direction.y / dz);
        let (mut lo, mut hi) = (glam::Vec2::splat(f32::INFINITY), glam::Vec2::splat(f32::NEG_INFINITY));
        for c in bounds.corners() {
            let p = glam::Vec2::new(c.x - kx * c.z, c.y - ky * c.z);
            lo = lo.min(p);
            hi = hi.max(p);
        }
        // A square region keeps texels square; margins keep casters at the
        // very edge inside the map and off the depth range's ends.
        let margin = 0.01 * (hi - lo).max_element().max(1e-3);
        let centre = 0.5 * (lo + hi);
        let half = 0.5 * (hi - lo).max_element() + margin;
        let (z_low, z_high) = (bounds.min.z - margin, bounds.max.z + margin);
        // Columns: x' = (x - kx z - cx) / half, y' likewise, depth runs from
        // 0 at the top of the bounds to 1 at their bottom.
        let view_proj = Mat4::from_cols(
            Vec4::new(1.0 / half, 0.0, 0.0, 0.0),
            Vec4::new(0.0, 1.0 / half, 0.0, 0.0),
            Vec4::new(-kx / half, -ky / half, -1.0 / (z_high - z_low), 0.0),
            Vec4::new(-centre.x / half, -centre.y / half, z_high / (z_high - z_low), 1.0),
        );
        Self { view_proj, extent: 2.0 * half }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fitted_shadow_frustum_contains_the_bounds() {
        let bounds = Aabb { min: Vec3::new(-0.3, -0.2, -0.03), max: Vec3::new(0.3, 0.2, 0.15) };
        let s = ShadowProjection::fit(&bounds, light_direction());
        for c in bounds.corners() {
            let p = s.view_proj.project_point3(c);
            assert!(p.x.abs() <= 1.0 && p.y.abs() <= 1.0 && (0.0..=1.0).contains(&p.z), "{c} -> {p}");
        }
        // Higher points are nearer the light (smaller depth).
        let low = s.view_proj.project_point3(Vec3::ZERO).z;
        let high = s.view_proj.project_point3(Vec3::Z * 0.1).z;
        assert!(high < low);
        // Points on one light ray share a texel.
        let p = Vec3::new(0.05, -0.02, 0.0);
        let q = p + light_direction() * 0.1;
        let (a, b) = (s.view_proj.project_point3(p), s.view_proj.project_point3(q));
        assert!((a.x - b.x).abs() < 1e-6 && (a.y - b.y).abs() < 1e-6);
        // Table axes map to map axes.
        let r = s.view_proj.project_point3(p + Vec3::X * 0.1);
        assert!((r.y - a.y).abs() < 1e-6 && r.x > a.x);
    }
}
