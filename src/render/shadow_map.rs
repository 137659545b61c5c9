//! The shadow map: depth of the casters seen from the light, sampled with a
//! comparison sampler by every lit shader.
//!
//! Why a shadow map and not planar projected shadows: shadows here fall on
//! several receivers (the table, the raised steering platform, other objects,
//! draped cloth), and planar shadows need one projection (and a stencil pass
//! against double blending) per receiving plane and cannot shadow curved
//! receivers at all. The map's projection (see [`crate::render::light`]) is
//! aligned with the table, and its 1024² depth-only pass costs about a
//! millisecond on lavapipe (see `benches/render.rs`).

use crate::render::targets::DEPTH_FORMAT;
use crate::render::texture::texture_2d;

#[derive(Debug)]
pub struct ShadowMap {
    pub view: wgpu::TextureView,
    pub sampler: wgpu::Sampler,
}

impl ShadowMap {
    pub fn new(device: &wgpu::Device, size: u32) -> Self {
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let texture = texture_2d(device, "shadow map", [size, size], DEPTH_FORMAT, usage);
        let view =
            texture.create_view(&wgpu::TextureViewDescriptor { label: Some("shadow map view"), ..Default::default() });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow comparison sampler"),
            address_mode_u: wgpu::AddressMode::ClampToEdge,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            address_mode_w: wgpu::AddressMode::ClampToEdge,
            // Linear filtering of the comparison results: 2x2 PCF for free.
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..Default::default()
        });
        Self { view, sampler }
    }
}
