//! Off-screen rendering to an image: screenshots, golden tests, videos of
//! study runs. The same [`Renderer`] as the window draws into an RGBA8
//! texture, which is copied to a buffer and read back.

use std::path::Path;
use std::sync::mpsc;

use image::RgbaImage;

use crate::render::draw_list::DrawList;
use crate::render::error::RenderError;
use crate::render::gpu::GpuContext;
use crate::render::renderer::{Renderer, RendererOptions};

/// Format of captured frames: sRGB-encoded RGBA8, what PNG files hold.
pub const CAPTURE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// Bytes per row of a texture-to-buffer copy: `width * 4` rounded up to
/// wgpu's `COPY_BYTES_PER_ROW_ALIGNMENT` (256).
pub fn padded_bytes_per_row(width: u32) -> u32 {
    (width * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
}

/// A renderer with its own off-screen target and readback buffer, reused
/// from frame to frame (creating one costs pipeline compilation, far more
/// than a captured frame; `cargo bench --bench render`).
#[derive(Debug)]
pub struct Capture {
    renderer: Renderer,
    device: wgpu::Device,
    queue: wgpu::Queue,
    size: [u32; 2],
    /// Channels come back as B, G, R, A and are swapped into RGBA.
    bgra: bool,
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    readback: wgpu::Buffer,
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
        use wgpu::TextureFormat::{Bgra8Unorm, Bgra8UnormSrgb, Rgba8Unorm, Rgba8UnormSrgb};
        if ![Rgba8Unorm, Rgba8UnormSrgb, Bgra8Unorm, Bgra8UnormSrgb].contains(&format) {
            return Err(RenderError::InvalidOptions(format!("capture format {format:?} is not 8-bit RGBA/BGRA")));
        }
        let max = gpu.device.limits().max_texture_dimension_2d;
        if !(1..=max).contains(&width) || !(1..=max).contains(&height) {
            return Err(RenderError::TargetSize { width, height, max });
        }
        let renderer = Renderer::new(&gpu.device, &gpu.queue, format, options)?;
        let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("capture target"),
            size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture
            .create_view(&wgpu::TextureViewDescriptor { label: Some("capture target view"), ..Default::default() });
        let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("capture readback"),
            size: u64::from(padded_bytes_per_row(width)) * u64::from(height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        Ok(Self {
            renderer,
            device: gpu.device.clone(),
            queue: gpu.queue.clone(),
            size: [width, height],
            bgra: matches!(format, Bgra8Unorm | Bgra8UnormSrgb),
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
        let [width, height] = self.size;
        self.renderer.prepare(list, self.size)?;
        let mut encoder =
            self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("capture encoder") });
        self.renderer.paint(&mut encoder, &self.view);
        let padded = padded_bytes_per_row(width);
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &self.texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &self.readback,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded), rows_per_image: None },
            },
            wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
        );
        self.queue.submit([encoder.finish()]);

        let (sender, receiver) = mpsc::channel();
        self.readback.map_async(wgpu::MapMode::Read, .., move |result| {
            // The receiver outlives the poll below; a failed send cannot happen.
            let _ = sender.send(result);
        });
        self.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| RenderError::Readback(e.to_string()))?;
        receiver
            .recv()
            .map_err(|e| RenderError::Readback(e.to_string()))?
            .map_err(|e| RenderError::Readback(e.to_string()))?;

        let row = (width * 4) as usize;
        let mut pixels = Vec::with_capacity(row * height as usize);
        {
            let mapped = self.readback.get_mapped_range(..).map_err(|e| RenderError::Readback(e.to_string()))?;
            for chunk in mapped.chunks_exact(padded as usize) {
                pixels.extend_from_slice(&chunk[..row]);
            }
        }
        self.readback.unmap();
        if self.bgra {
            for pixel in pixels.chunks_exact_mut(4) {
                pixel.swap(0, 2);
            }
        }
        RgbaImage::from_raw(width, height, pixels)
            .ok_or_else(|| RenderError::Readback("pixel count does not match the image size".into()))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_padded_to_256_bytes() {
        assert_eq!(padded_bytes_per_row(64), 256);
        assert_eq!(padded_bytes_per_row(65), 512);
        assert_eq!(padded_bytes_per_row(1024), 4096);
        assert_eq!(padded_bytes_per_row(1), 256);
        assert_eq!(padded_bytes_per_row(100), 512);
    }
}
