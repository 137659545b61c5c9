//! Reading back what the window shows (`--screenshot-after`): the frame's
//! texture (the surface's own when it allows copies, else an off-screen
//! twin the same frame was drawn into) is copied to a buffer and saved.

use crate::render::padded_bytes_per_row;
use anyhow::{Context, anyhow};
use image::RgbaImage;
use std::sync::mpsc;

/// A copy of a frame on its way to the CPU.
#[derive(Debug)]
pub struct Readback {
    buffer: wgpu::Buffer,
    size: [u32; 2],
    bgra: bool,
}

impl Readback {
    /// Records a copy of `texture` (8-bit RGBA or BGRA, `size` pixels)
    /// into `encoder`; [`Readback::finish`] after the encoder is submitted.
    pub fn record(device: &wgpu::Device, encoder: &mut wgpu::CommandEncoder, texture: &wgpu::Texture) -> Self {
        let size = [texture.width(), texture.height()];
        let padded = padded_bytes_per_row(size[0]);
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("window capture readback"),
            size: u64::from(padded) * u64::from(size[1]),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded), rows_per_image: None },
            },
            wgpu::Extent3d { width: size[0], height: size[1], depth_or_array_layers: 1 },
        );
        let bgra = matches!(texture.format(), wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb);
        Self { buffer, size, bgra }
    }

    /// Waits for the copy and returns the pixels as RGBA.
    pub fn finish(self, device: &wgpu::Device) -> anyhow::Result<RgbaImage> {
        let (sender, receiver) = mpsc::channel();
        self.buffer.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = sender.send(r);
        });
        device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| anyhow!("waiting for the GPU: {e}"))?;
        receiver.recv().context("the readback never finished")?.map_err(|e| anyhow!("mapping the readback: {e}"))?;
        let [w, h] = self.size;
        let row = (w * 4) as usize;
        let mut pixels = Vec::with_capacity(row * h as usize);
        {
            let mapped = self.buffer.get_mapped_range(..).map_err(|e| anyhow!("reading the readback: {e}"))?;
            for chunk in mapped.chunks_exact(padded_bytes_per_row(w) as usize) {
                pixels.extend_from_slice(&chunk[..row]);
            }
        }
        self.buffer.unmap();
        for p in pixels.chunks_exact_mut(4) {
            if self.bgra {
                p.swap(0, 2);
            }
            // A window has no transparency; some surfaces leave alpha undefined.
            p[3] = 255;
        }
        RgbaImage::from_raw(w, h, pixels).context("pixel count does not match the frame size")
    }
}

/// Whether frames of this format can be read back here (8-bit RGBA/BGRA).
pub fn readable(format: wgpu::TextureFormat) -> bool {
    use wgpu::TextureFormat::{Bgra8Unorm, Bgra8UnormSrgb, Rgba8Unorm, Rgba8UnormSrgb};
    matches!(format, Rgba8Unorm | Rgba8UnormSrgb | Bgra8Unorm | Bgra8UnormSrgb)
}
