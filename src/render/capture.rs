//! Off-screen rendering to an image: screenshots, golden tests, videos of
//! study runs. The same [`Renderer`] as the window draws into an RGBA8
//! texture, which is read back (see `readback`).

use crate::render::texture::texture_2d;
use std::path::Path;

use image::RgbaImage;

use crate::render::draw_list::DrawList;
use crate::render::error::RenderError;
use crate::render::gpu::GpuContext;
use crate::render::readback::{Alpha, Readback, readable};
use crate::render::renderer::{Renderer, RendererOptions};

/// Format of captured frames: sRGB-encoded RGBA8, what PNG files hold.
pub const CAPTURE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// A renderer with its own off-screen target and readback buffer, reused
/// from frame to frame (creating one costs pipeline compilation, far more
/// than a captured frame; `cargo bench --bench render`).
#[derive(Debug)]
pub struct Capture {
    renderer: Renderer,
    device: wgpu::Device,
    queue: wgpu::Queue,
    size: [u32; 2],
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    readback: Readback,
}

impl Capture {
    pub fn new(gpu: &GpuContext, width: u32, height: u32) -> Result<Self, RenderError> {
        Self::with_options(gpu, width, height, RendererOptions::default())
    }

    pub fn with_options(
        gpu: &GpuContext,
        width: u32,
        height: u32,
        options: RendererOptions,
    ) -> Result<Self, RenderError> {
        Self::with_format(gpu, width, height, CAPTURE_FORMAT, options)
    }

    /// Renders through a target of another 8-bit RGBA/BGRA format, e.g. the
    /// `Bgra8Unorm` a window surface may have, to check what a window shows.
    /// The image is always RGBA in sRGB encoding.
    pub fn with_format(
        gpu: &GpuContext,
        width: u32,
        height: u32,
        format: wgpu::TextureFormat,
        options: RendererOptions,
    ) -> Result<Self, RenderError> {
        if !readable(format) {
            return Err(RenderError::InvalidOptions(format!("capture format {format:?} is not 8-bit RGBA/BGRA")));
        }
        let max = gpu.device.limits().max_texture_dimension_2d;
        if !(1..=max).contains(&width) || !(1..=max).contains(&height) {
            return Err(RenderError::TargetSize { width, height, max });
        }
        let renderer = Renderer::new(&gpu.device, &gpu.queue, format, options)?;
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC;
        let texture = texture_2d(&gpu.device, "capture target", [width, height], format, usage);
        let view = texture
            .create_view(&wgpu::TextureViewDescriptor { label: Some("capture target view"), ..Default::default() });
        let readback = Readback::new(&gpu.device, [width, height], format, "capture readback");
        Ok(Self {
            renderer,
            device: gpu.device.clone(),
            queue: gpu.queue.clone(),
            size: [width, height],
            texture,
            view,
            readback,
        })
    }

    pub fn size(&self) -> [u32; 2] {
        self.size
    }

    pub fn renderer(&self) -> &Renderer {
        &self.renderer
    }

    /// Renders `list` and waits for the pixels.
    pub fn render(&mut self, list: &DrawList) -> Result<RgbaImage, RenderError> {
        self.renderer.prepare(list, self.size)?;
        let mut encoder =
            self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("capture encoder") });
        self.renderer.paint(&mut encoder, &self.view);
        self.readback.record(&mut encoder, &self.texture);
        self.queue.submit([encoder.finish()]);
        self.readback.read(&self.device, Alpha::Kept)
    }
}

/// One frame off-screen: builds a renderer, renders, reads back. For many
/// frames keep a [`Capture`] instead.
pub fn render_to_image(gpu: &GpuContext, list: &DrawList, width: u32, height: u32) -> Result<RgbaImage, RenderError> {
    Capture::new(gpu, width, height)?.render(list)
}

/// Writes `image` as a PNG, creating parent folders.
pub fn save_png(image: &RgbaImage, path: impl AsRef<Path>) -> Result<(), RenderError> {
    let path = path.as_ref();
    let error = |source| RenderError::Png { path: path.to_path_buf(), source };
    let mut png = std::io::Cursor::new(Vec::new());
    image.write_to(&mut png, image::ImageFormat::Png).map_err(error)?;
    // Atomic: a full disk leaves no 0-byte PNG and no temporary file.
    crate::files::write_output(path, png.get_ref()).map_err(|e| error(image::ImageError::IoError(e)))
}
