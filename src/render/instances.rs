//! Per-instance GPU records and how draw-list items become them. Pure.
//!
//! Each record's layout matches the `ObjectInstance`/`DecalIn`/`LineIn`/`CubeIn`
//! struct of its shader; the `@location`s are listed beside each field.

use bytemuck::{Pod, Zeroable};
use glam::{Mat3, Mat4, Vec3};

use crate::render::draw_list::{ContactOverlay, Decal, FeedbackDraw, ObjectDraw, Rgba, TableDraw};
use crate::render::gpu_record::GpuRecord;

/// Thickness of the table slab below z = 0 (metres): enough for its front
/// edge to read as a solid object, thin enough not to fill the frame.
pub const TABLE_THICKNESS: f32 = 0.03;

/// Specular strength of objects; the table is matte.
const OBJECT_SPECULAR: f32 = 0.35;

/// A mesh instance (`struct ObjectInstance` in `shaders/frame.wgsl`,
/// locations 2..=10; the flat and shadow shaders read a subset).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct ObjectInstance {
    pub model: [[f32; 4]; 4],
    pub normal: [[f32; 4]; 3],
    pub color: [f32; 4],
    /// y: specular strength (x, z, w unused).
    pub params: [f32; 4],
}

impl GpuRecord for ObjectInstance {
    const ATTRIBUTES: &'static [wgpu::VertexAttribute] = &wgpu::vertex_attr_array![
        2 => Float32x4, 3 => Float32x4, 4 => Float32x4, 5 => Float32x4,
        6 => Float32x4, 7 => Float32x4, 8 => Float32x4,
        9 => Float32x4, 10 => Float32x4,
    ];
}

impl ObjectInstance {
    pub fn new(model: Mat4, color: Rgba, params: [f32; 4]) -> Self {
        // Normals transform with the inverse transpose; a singular model
        // (a zero scale) gets the plain rotation part instead of NaNs.
        let linear = Mat3::from_mat4(model);
        let normal = if linear.determinant().abs() > 1e-12 { linear.inverse().transpose() } else { linear };
        let col = |v: Vec3| [v.x, v.y, v.z, 0.0];
        Self {
            model: model.to_cols_array_2d(),
            normal: [col(normal.x_axis), col(normal.y_axis), col(normal.z_axis)],
            color,
            params,
        }
    }

    /// The table slab: a box whose top face is z = 0.
    pub fn table(table: &TableDraw) -> Self {
        let model = Mat4::from_translation(Vec3::new(0.0, 0.0, -0.5 * TABLE_THICKNESS))
            * Mat4::from_scale(Vec3::new(table.width, table.depth, TABLE_THICKNESS));
        Self::new(model, table.color, [0.0; 4])
    }

    pub fn object(object: &ObjectDraw) -> Self {
        Self::new(object.transform, object.color, [0.0, OBJECT_SPECULAR, 0.0, 0.0])
    }

    /// A deformable: its vertices are already in world space.
    pub fn deformable(color: Rgba) -> Self {
        Self::new(Mat4::IDENTITY, color, [0.0, 0.1, 0.0, 0.0])
    }
}

/// A decal (`shaders/decal.wgsl`, locations 0..=2).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct DecalInstance {
    /// x, y: centre; z: plane height; w: rotation about z.
    pub place: [f32; 4],
    /// x, y: half extents (x = radius); z: stroke width (0 = filled); w: 0 disc, 1 rect.
    pub shape: [f32; 4],
    pub color: [f32; 4],
}

impl GpuRecord for DecalInstance {
    const ATTRIBUTES: &'static [wgpu::VertexAttribute] =
        &wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4, 2 => Float32x4];
}

impl DecalInstance {
    pub fn new(decal: &Decal) -> Self {
        match *decal {
            Decal::Disc { center, z, radius, color, ring } => {
                Self { place: [center.x, center.y, z, 0.0], shape: [radius, radius, stroke(ring), 0.0], color }
            }
            Decal::Rect { center, z, half, angle, color, outline } => {
                Self { place: [center.x, center.y, z, angle], shape: [half.x, half.y, stroke(outline), 1.0], color }
            }
        }
    }
}

/// A stroke width for the shader: 0 means filled, so a non-positive or
/// non-finite width is treated as filled too.
fn stroke(width: Option<f32>) -> f32 {
    width.filter(|w| w.is_finite() && *w > 0.0).unwrap_or(0.0)
}

/// Spacing of the grid lines on the table top (metres).
pub const GRID_SPACING: f32 = 0.05;
/// Width of the darker rim around the table top (metres).
pub const RIM_WIDTH: f32 = 0.012;

/// A strip painted on the table top (`shaders/grid.wgsl`, locations 0..=1).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct StripInstance {
    /// xy: one end; z: height; w: half width (pixels or metres).
    pub a: [f32; 4],
    /// xy: the other end; z: 1 when the width is in pixels; w: darkness.
    pub b: [f32; 4],
}

impl GpuRecord for StripInstance {
    const ATTRIBUTES: &'static [wgpu::VertexAttribute] = &wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4];
}

/// The table top's markings: grid lines through the centre every
/// [`GRID_SPACING`] (1 px wide, 7% darker) inside a rim [`RIM_WIDTH`] wide
/// (25% darker). The rim's side strips stop short of the corners so no
/// pixel is darkened twice.
pub fn table_markings(table: &TableDraw) -> Vec<StripInstance> {
    let (hw, hd) = (0.5 * table.width, 0.5 * table.depth);
    let (iw, id) = (hw - RIM_WIDTH, hd - RIM_WIDTH);
    let mut strips = Vec::new();
    let line = |a: [f32; 2], b: [f32; 2]| StripInstance { a: [a[0], a[1], 0.0, 0.5], b: [b[0], b[1], 1.0, 0.07] };
    let count = |half: f32| (half / GRID_SPACING - 1e-3).floor().max(0.0) as i32;
    for k in -count(iw)..=count(iw) {
        let x = k as f32 * GRID_SPACING;
        strips.push(line([x, -id], [x, id]));
    }
    for k in -count(id)..=count(id) {
        let y = k as f32 * GRID_SPACING;
        strips.push(line([-iw, y], [iw, y]));
    }
    let r = 0.5 * RIM_WIDTH;
    let rim = |a: [f32; 2], b: [f32; 2]| StripInstance { a: [a[0], a[1], 0.0, r], b: [b[0], b[1], 0.0, 0.25] };
    strips.push(rim([-hw, hd - r], [hw, hd - r]));
    strips.push(rim([-hw, -hd + r], [hw, -hd + r]));
    strips.push(rim([-hw + r, -id], [-hw + r, id]));
    strips.push(rim([hw - r, -id], [hw - r, id]));
    strips
}

/// The drawn part of a contact image (`shaders/overlay.wgsl`, location 0):
/// texture coordinates of its non-zero pixels' bounding box, grown by a
/// texel for the filtering; `None` when the image is empty.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct OverlayRegion {
    /// xy: min, zw: max.
    pub uv_rect: [f32; 4],
}

impl GpuRecord for OverlayRegion {
    const ATTRIBUTES: &'static [wgpu::VertexAttribute] = &wgpu::vertex_attr_array![0 => Float32x4];
}

impl OverlayRegion {
    pub fn of(overlay: &ContactOverlay) -> Option<Self> {
        let (w, h) = (overlay.width as usize, overlay.height as usize);
        let (mut lo, mut hi) = ([usize::MAX; 2], [0usize; 2]);
        for (row, pixels) in overlay.pixels.chunks_exact(w.max(1)).take(h).enumerate() {
            if let (Some(first), Some(last)) = (pixels.iter().position(|&p| p > 0), pixels.iter().rposition(|&p| p > 0))
            {
                lo = [lo[0].min(first), lo[1].min(row)];
                hi = [hi[0].max(last), hi[1].max(row)];
            }
        }
        (lo[0] != usize::MAX).then(|| {
            let u = |c: usize| (c as f32 / w as f32).clamp(0.0, 1.0);
            let v = |r: usize| (r as f32 / h as f32).clamp(0.0, 1.0);
            Self { uv_rect: [u(lo[0].saturating_sub(1)), v(lo[1].saturating_sub(1)), u(hi[0] + 2), v(hi[1] + 2)] }
        })
    }
}

/// A feedback line (`shaders/feedback.wgsl` `vs_line`, locations 0..=2).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct LineInstance {
    /// xyz: end point; w: width in pixels.
    pub a: [f32; 4],
    pub b: [f32; 4],
    pub color: [f32; 4],
}

impl GpuRecord for LineInstance {
    const ATTRIBUTES: &'static [wgpu::VertexAttribute] =
        &wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4, 2 => Float32x4];
}

/// A feedback cube (`shaders/feedback.wgsl` `vs_cube`, locations 2..=3).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct CubeInstance {
    /// xyz: centre; w: half the side.
    pub center_half: [f32; 4],
    pub color: [f32; 4],
}

impl GpuRecord for CubeInstance {
    const ATTRIBUTES: &'static [wgpu::VertexAttribute] = &wgpu::vertex_attr_array![2 => Float32x4, 3 => Float32x4];
}

/// Splits feedback into line and cube instances; lines get `line_px` width.
/// Width of an end dot, in line widths.
pub const DOT_PER_LINE_WIDTH: f32 = 2.5;

pub fn feedback_instances(feedback: &[FeedbackDraw], line_px: f32) -> (Vec<LineInstance>, Vec<CubeInstance>) {
    let mut lines = Vec::new();
    let mut cubes = Vec::new();
    for item in feedback {
        match *item {
            FeedbackDraw::Line { a, b, color } => {
                lines.push(LineInstance { a: [a.x, a.y, a.z, line_px], b: [b.x, b.y, b.z, line_px], color });
                // A square dot at each end (a zero-length line is a square
                // of its width), so a short joint line still reads as one.
                let dot = DOT_PER_LINE_WIDTH * line_px;
                for p in [a, b] {
                    lines.push(LineInstance { a: [p.x, p.y, p.z, dot], b: [p.x, p.y, p.z, dot], color });
                }
            }
            FeedbackDraw::Cube { center, half, color } => {
                cubes.push(CubeInstance { center_half: [center.x, center.y, center.z, half], color });
            }
        }
    }
    (lines, cubes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Quat, Vec2};

    #[test]
    fn normal_matrix_undoes_non_uniform_scale() {
        let model =
            Mat4::from_scale_rotation_translation(Vec3::new(4.0, 1.0, 0.5), Quat::from_rotation_z(0.3), Vec3::ONE);
        let instance = ObjectInstance::new(model, [1.0; 4], [0.0; 4]);
        let n = Mat3::from_cols(
            Vec3::from_slice(&instance.normal[0][..3]),
            Vec3::from_slice(&instance.normal[1][..3]),
            Vec3::from_slice(&instance.normal[2][..3]),
        );
        // A tangent transformed by the model stays orthogonal to the
        // normal transformed by the normal matrix.
        let (tangent, normal) = (Vec3::new(1.0, -1.0, 0.0), Vec3::new(1.0, 1.0, 0.0));
        let t = Mat3::from_mat4(model) * tangent;
        assert!((n * normal).dot(t).abs() < 1e-5);
    }

    #[test]
    fn degenerate_scale_gives_finite_normals() {
        let instance = ObjectInstance::new(Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0)), [1.0; 4], [0.0; 4]);
        assert!(instance.normal.iter().flatten().all(|v| v.is_finite()));
    }

    #[test]
    fn table_top_is_at_zero() {
        let table = TableDraw { width: 0.6, depth: 0.45, color: [1.0; 4] };
        let model = Mat4::from_cols_array_2d(&ObjectInstance::table(&table).model);
        let top = model.transform_point3(Vec3::new(0.5, 0.5, 0.5));
        assert!(top.abs_diff_eq(Vec3::new(0.3, 0.225, 0.0), 1e-6));
    }

    #[test]
    fn decals_encode_kind_and_stroke() {
        let ring =
            Decal::Disc { center: Vec2::new(0.1, 0.2), z: 0.05, radius: 0.03, color: [1.0; 4], ring: Some(0.004) };
        let d = DecalInstance::new(&ring);
        assert_eq!(d.place, [0.1, 0.2, 0.05, 0.0]);
        assert_eq!(d.shape, [0.03, 0.03, 0.004, 0.0]);
        let rect = Decal::Rect {
            center: Vec2::ZERO,
            z: 0.0,
            half: Vec2::new(0.1, 0.05),
            angle: 0.5,
            color: [1.0; 4],
            outline: Some(-1.0),
        };
        let r = DecalInstance::new(&rect);
        assert_eq!(r.shape, [0.1, 0.05, 0.0, 1.0], "a negative outline is a filled rect");
        assert_eq!(r.place[3], 0.5);
    }

    #[test]
    fn records_match_their_vertex_layouts() {
        let size =
            |attrs: &[wgpu::VertexAttribute]| attrs.iter().map(|a| a.offset + a.format.size()).max().unwrap_or(0);
        assert_eq!(size(ObjectInstance::ATTRIBUTES), std::mem::size_of::<ObjectInstance>() as u64);
        assert_eq!(size(DecalInstance::ATTRIBUTES), std::mem::size_of::<DecalInstance>() as u64);
        assert_eq!(size(LineInstance::ATTRIBUTES), std::mem::size_of::<LineInstance>() as u64);
        assert_eq!(size(CubeInstance::ATTRIBUTES), std::mem::size_of::<CubeInstance>() as u64);
        assert_eq!(size(StripInstance::ATTRIBUTES), std::mem::size_of::<StripInstance>() as u64);
        assert_eq!(size(OverlayRegion::ATTRIBUTES), std::mem::size_of::<OverlayRegion>() as u64);
    }

    #[test]
    fn overlay_region_bounds_the_contact() {
        let mut overlay = ContactOverlay { width: 10, height: 5, pixels: vec![0; 50] };
        assert_eq!(OverlayRegion::of(&overlay), None);
        overlay.pixels[2 * 10 + 3] = 9; // row 2, column 3
        overlay.pixels[3 * 10 + 6] = 200; // row 3, column 6
        let r = OverlayRegion::of(&overlay).expect("non-empty").uv_rect;
        assert_eq!(r, [0.2, 0.2, 0.8, 1.0]);
        overlay.pixels[0] = 1;
        overlay.pixels[49] = 1;
        assert_eq!(OverlayRegion::of(&overlay).expect("non-empty").uv_rect, [0.0, 0.0, 1.0, 1.0]);
    }

    #[test]
    fn markings_stay_on_the_table_top() {
        let table = TableDraw { width: 0.61, depth: 0.4575, color: [1.0; 4] };
        let strips = table_markings(&table);
        // 11 vertical and 9 horizontal lines inside the rim, plus 4 rim strips.
        assert_eq!(strips.len(), 11 + 9 + 4);
        for s in &strips {
            for p in [[s.a[0], s.a[1]], [s.b[0], s.b[1]]] {
                assert!(p[0].abs() <= 0.305 + 1e-6 && p[1].abs() <= 0.22875 + 1e-6, "{p:?}");
            }
        }
    }
}
