//! The view: camera matrices and the mapping between pixels and the world,
//! for the renderer, for picking in the app, and for tests that check where
//! something appears on screen. Pure.

use glam::{Mat4, Vec2, Vec3, Vec4Swizzles};

use crate::render::bounds::{Aabb, view_bounds};
use crate::render::draw_list::{Camera, DrawList};

/// Matrices of one frame's view (depth range 0..1, wgpu's convention).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraMatrices {
    pub view: Mat4,
    pub proj: Mat4,
    pub view_proj: Mat4,
    pub near: f32,
    pub far: f32,
}

impl CameraMatrices {
    /// Fits the near and far planes around `bounds` for depth precision.
    pub fn new(camera: &Camera, size: [u32; 2], bounds: &Aabb) -> Self {
        let aspect = size[0].max(1) as f32 / size[1].max(1) as f32;
        let forward = (camera.target - camera.eye).try_normalize().unwrap_or(Vec3::NEG_Z);
        let (mut nearest, mut farthest) = (f32::INFINITY, 0.0f32);
        if !bounds.is_empty() {
            for c in bounds.corners() {
                let d = (c - camera.eye).dot(forward);
                nearest = nearest.min(d);
                farthest = farthest.max(d);
            }
        }
        let far = (farthest * 1.05).max(0.1);
        // A 32-bit float depth buffer resolves a far/near ratio of a few
        // thousand easily; never let the near plane reach the eye.
        let near = (nearest * 0.9).clamp(far / 4000.0, far * 0.5);
        let fov = camera.fov_y_deg.clamp(1.0, 170.0).to_radians();
        let up = if camera.up.cross(forward).length_squared() > 1e-8 { camera.up } else { Vec3::Y };
        let view = glam::camera::rh::view::look_at_mat4(camera.eye, camera.target, up);
        let proj = glam::camera::rh::proj::directx::perspective(fov, aspect, near, far);
        Self { view, proj, view_proj: proj * view, near, far }
    }

    /// The matrices the renderer uses for `list` drawn at `size` pixels.
    pub fn for_draw_list(list: &DrawList, size: [u32; 2]) -> Self {
        Self::new(&list.camera, size, &view_bounds(list))
    }

    /// Pixel coordinates (x right, y down, origin at the top-left corner of
    /// the top-left pixel) of a world point, or `None` behind the eye.
    pub fn world_to_pixel(&self, size: [u32; 2], p: Vec3) -> Option<Vec2> {
        let clip = self.view_proj * p.extend(1.0);
        if clip.w <= 1e-6 {
            return None;
        }
        let ndc = clip.xy() / clip.w;
        Some(Vec2::new((ndc.x * 0.5 + 0.5) * size[0] as f32, (0.5 - ndc.y * 0.5) * size[1] as f32))
    }

    /// The ray (origin, unit direction) through a pixel position.
    pub fn pixel_ray(&self, size: [u32; 2], pixel: Vec2) -> (Vec3, Vec3) {
        let ndc = Vec2::new(2.0 * pixel.x / size[0].max(1) as f32 - 1.0, 1.0 - 2.0 * pixel.y / size[1].max(1) as f32);
        let inverse = self.view_proj.inverse();
        let near = inverse.project_point3(ndc.extend(0.0));
        let far = inverse.project_point3(ndc.extend(1.0));
        (near, (far - near).normalize_or_zero())
    }

    /// Where the ray through `pixel` meets the horizontal plane at height
    /// `z` (e.g. the table, z = 0): mouse picking.
    pub fn pixel_to_plane(&self, size: [u32; 2], pixel: Vec2, z: f32) -> Option<Vec3> {
        let (origin, dir) = self.pixel_ray(size, pixel);
        if dir.z.abs() < 1e-8 {
            return None;
        }
        let t = (z - origin.z) / dir.z;
        (t >= 0.0).then(|| origin + dir * t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera { eye: Vec3::new(0.0, -0.6, 0.8), target: Vec3::ZERO, up: Vec3::Z, fov_y_deg: 45.0 }
    }

    fn bounds() -> Aabb {
        Aabb { min: Vec3::new(-0.3, -0.25, -0.03), max: Vec3::new(0.3, 0.25, 0.1) }
    }

    #[test]
    fn target_projects_to_the_centre() {
        let m = CameraMatrices::new(&camera(), [1024, 768], &bounds());
        let p = m.world_to_pixel([1024, 768], Vec3::ZERO).expect("in front");
        assert!(p.abs_diff_eq(Vec2::new(512.0, 384.0), 1e-3), "{p}");
        // +x is to the right, +y (away from the viewer) is up the screen.
        let right = m.world_to_pixel([1024, 768], Vec3::X * 0.1).expect("in front");
        let far = m.world_to_pixel([1024, 768], Vec3::Y * 0.1).expect("in front");
        assert!(right.x > 512.0 && far.y < 384.0);
    }

    #[test]
    fn depth_range_covers_the_bounds() {
        let m = CameraMatrices::new(&camera(), [800, 600], &bounds());
        for c in bounds().corners() {
            let clip = m.view_proj * c.extend(1.0);
            let z = clip.z / clip.w;
            assert!((0.0..=1.0).contains(&z), "corner {c} has depth {z}");
        }
    }

    #[test]
    fn picking_inverts_projection() {
        let size = [640, 480];
        let m = CameraMatrices::new(&camera(), size, &bounds());
        let p = Vec3::new(0.12, -0.07, 0.0);
        let pixel = m.world_to_pixel(size, p).expect("in front");
        let back = m.pixel_to_plane(size, pixel, 0.0).expect("hits the table");
        assert!(back.abs_diff_eq(p, 1e-4), "{back} vs {p}");
    }
}
