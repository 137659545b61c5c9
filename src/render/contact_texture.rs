//! The contact image on the GPU: one R8 texture, re-uploaded each frame it
//! is shown, recreated when its size changes.

use crate::render::draw_list::ContactOverlay;
use crate::render::texture::texture_2d;

#[derive(Debug)]
pub struct ContactTexture {
    size: [u32; 2],
    texture: wgpu::Texture,
    pub bind_group: wgpu::BindGroup,
}

impl ContactTexture {
    pub fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, sampler: &wgpu::Sampler, size: [u32; 2]) -> Self {
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
        let texture = texture_2d(device, "contact image", size, wgpu::TextureFormat::R8Unorm, usage);
        let view = texture
            .create_view(&wgpu::TextureViewDescriptor { label: Some("contact image view"), ..Default::default() });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("contact image bind group"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(sampler) },
            ],
        });
        Self { size, texture, bind_group }
    }

    pub fn size(&self) -> [u32; 2] {
        self.size
    }

    /// Uploads `overlay` (already validated: `pixels.len() == width * height`).
    pub fn upload(&self, queue: &wgpu::Queue, overlay: &ContactOverlay) {
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &self.texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            &overlay.pixels,
            // Queue writes have no row-alignment requirement (copies inside
            // a command encoder do).
            wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(overlay.width), rows_per_image: None },
            wgpu::Extent3d { width: overlay.width, height: overlay.height, depth_or_array_layers: 1 },
        );
    }
}
