//! The per-frame uniform block (`struct Frame` in `shaders/frame.wgsl`).

use bytemuck::{Pod, Zeroable};

use crate::render::camera::CameraMatrices;
use crate::render::draw_list::DrawList;
use crate::render::light::{
    GROUND_COLOR, LIGHT_COLOR, PENUMBRA, SHADOW_STRENGTH, SKY_COLOR, ShadowProjection, light_direction,
};

/// The "hand shadow": a dark blue-grey at up to 62% opacity where contact is full.
pub const OVERLAY_TINT: [f32; 4] = [0.015, 0.02, 0.045, 0.62];
/// Opacity of feedback hidden behind other geometry.
pub const HIDDEN_FEEDBACK_ALPHA: f32 = 0.4;

/// Field order and meaning match `struct Frame` in `shaders/frame.wgsl`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct FrameUniforms {
    pub view_proj: [[f32; 4]; 4],
    pub light_view_proj: [[f32; 4]; 4],
    pub camera_position: [f32; 4],
    pub light_direction: [f32; 4],
    pub light_color: [f32; 4],
    pub sky_color: [f32; 4],
    pub ground_color: [f32; 4],
    pub shadow: [f32; 4],
    pub viewport: [f32; 4],
    pub table: [f32; 4],
    pub overlay_tint: [f32; 4],
    pub options: [f32; 4],
}

impl FrameUniforms {
    pub fn new(
        list: &DrawList,
        size: [u32; 2],
        camera: &CameraMatrices,
        shadow: &ShadowProjection,
        shadow_map_size: u32,
        encode_srgb: bool,
    ) -> Self {
        let rgb = |c: [f32; 3]| [c[0], c[1], c[2], 0.0];
        let texel = shadow.extent / shadow_map_size as f32;
        let tap = (PENUMBRA / 3.0).max(texel);
        let (w, h) = (size[0] as f32, size[1] as f32);
        Self {
            view_proj: camera.view_proj.to_cols_array_2d(),
            light_view_proj: shadow.view_proj.to_cols_array_2d(),
            camera_position: list.camera.eye.extend(1.0).to_array(),
            light_direction: light_direction().extend(0.0).to_array(),
            light_color: rgb(LIGHT_COLOR),
            sky_color: rgb(SKY_COLOR),
            ground_color: rgb(GROUND_COLOR),
            // PCF taps one penumbra-third apart, but at least a texel.
            shadow: [texel, tap / shadow.extent, SHADOW_STRENGTH, tap],
            viewport: [w, h, 1.0 / w, 1.0 / h],
            table: [0.5 * list.table.width, 0.5 * list.table.depth, 0.0, 0.0],
            overlay_tint: OVERLAY_TINT,
            options: [if encode_srgb { 1.0 } else { 0.0 }, HIDDEN_FEEDBACK_ALPHA, 0.0, 0.0],
        }
    }
}
