//! The attachments sized to the output: depth, and the multisampled colour
//! buffer that is resolved into the caller's view when MSAA is on.

/// Depth format of the main pass and of the shadow map: 32-bit float gives
/// ample precision for a table seen from under a metre away.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

#[derive(Debug)]
pub struct RenderTargets {
    pub size: [u32; 2],
    pub depth: wgpu::TextureView,
    /// Present when `sample_count > 1`; the caller's view is the resolve target.
    pub msaa_color: Option<wgpu::TextureView>,
}

impl RenderTargets {
    pub fn new(device: &wgpu::Device, size: [u32; 2], color_format: wgpu::TextureFormat, sample_count: u32) -> Self {
        let extent = wgpu::Extent3d { width: size[0], height: size[1], depth_or_array_layers: 1 };
        let texture = |label: &str, format| {
            device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size: extent,
                    mip_level_count: 1,
                    sample_count,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                    view_formats: &[],
                })
                .create_view(&wgpu::TextureViewDescriptor { label: Some(label), ..Default::default() })
        };
        Self {
            size,
            depth: texture("main depth", DEPTH_FORMAT),
            msaa_color: (sample_count > 1).then(|| texture("main msaa colour", color_format)),
        }
    }
}
