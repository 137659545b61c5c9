//! Reading a rendered texture back to the CPU: a copy into a mappable
//! buffer recorded with the frame, then, once it is submitted, the rows
//! unpadded and the channels put in RGBA order. Off-screen captures and
//! the demo window's screenshots read frames back the same way.

use crate::render::error::RenderError;
use image::RgbaImage;
use std::sync::mpsc;

/// Bytes per row of a texture-to-buffer copy: `width * 4` rounded up to
/// wgpu's `COPY_BYTES_PER_ROW_ALIGNMENT` (256).
pub fn padded_bytes_per_row(width: u32) -> u32 {
    (width * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
}

/// Whether frames of this format can be read back (8-bit RGBA/BGRA).
pub fn readable(format: wgpu::TextureFormat) -> bool {
    use wgpu::TextureFormat::{Bgra8Unorm, Bgra8UnormSrgb, Rgba8Unorm, Rgba8UnormSrgb};
    matches!(format, Rgba8Unorm | Rgba8UnormSrgb | Bgra8Unorm | Bgra8UnormSrgb)
}

/// What a read-back does with the alpha channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Alpha {
    /// As rendered (an off-screen target's alpha is defined).
    Kept,
    /// Every pixel opaque: a window has no transparency, and some surfaces
    /// leave alpha undefined.
    Opaque,
}

/// A mappable buffer that frames of one size and format are copied into.
#[derive(Debug)]
pub struct Readback {
    buffer: wgpu::Buffer,
    size: [u32; 2],
    /// Channels come back as B, G, R, A and are swapped into RGBA.
    bgra: bool,
}

impl Readback {
    /// A buffer for frames of `size` pixels in `format` (one that
    /// [`readable`] accepts).
    pub fn new(device: &wgpu::Device, size: [u32; 2], format: wgpu::TextureFormat, label: &str) -> Self {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: u64::from(padded_bytes_per_row(size[0])) * u64::from(size[1]),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let bgra = matches!(format, wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb);
        Readback { buffer, size, bgra }
    }

    /// Records a copy of `texture` (this read-back's size and format) into
    /// `encoder`; [`Readback::read`] once the encoder is submitted.
    pub fn record(&self, encoder: &mut wgpu::CommandEncoder, texture: &wgpu::Texture) {
        let [width, height] = self.size;
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &self.buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_bytes_per_row(width)),
                    rows_per_image: None,
                },
            },
            wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
        );
    }

    /// Waits for the recorded copy and returns its pixels as RGBA.
    pub fn read(&self, device: &wgpu::Device, alpha: Alpha) -> Result<RgbaImage, RenderError> {
        let (sender, receiver) = mpsc::channel();
        self.buffer.map_async(wgpu::MapMode::Read, .., move |result| {
            // The receiver outlives the poll below; a failed send cannot happen.
            let _ = sender.send(result);
        });
        device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| RenderError::Readback(e.to_string()))?;
        receiver
            .recv()
            .map_err(|e| RenderError::Readback(e.to_string()))?
            .map_err(|e| RenderError::Readback(e.to_string()))?;
        let [width, height] = self.size;
        let row = (width * 4) as usize;
        let mut pixels = Vec::with_capacity(row * height as usize);
        {
            let mapped = self.buffer.get_mapped_range(..).map_err(|e| RenderError::Readback(e.to_string()))?;
            for chunk in mapped.chunks_exact(padded_bytes_per_row(width) as usize) {
                pixels.extend_from_slice(&chunk[..row]);
            }
        }
        self.buffer.unmap();
        if self.bgra || alpha == Alpha::Opaque {
            for pixel in pixels.chunks_exact_mut(4) {
                if self.bgra {
                    pixel.swap(0, 2);
                }
                if alpha == Alpha::Opaque {
                    pixel[3] = 255;
                }
            }
        }
        RgbaImage::from_raw(width, height, pixels)
            .ok_or_else(|| RenderError::Readback("pixel count does not match the image size".into()))
    }
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

    #[test]
    fn only_8_bit_rgba_and_bgra_read_back() {
        assert!(readable(wgpu::TextureFormat::Bgra8UnormSrgb) && readable(wgpu::TextureFormat::Rgba8Unorm));
        assert!(!readable(wgpu::TextureFormat::Rgba16Float));
    }
}
