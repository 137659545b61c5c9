//! One frame as a camera delivers it: 8-bit grey (an infrared camera) or
//! 16-bit grey (a depth camera's millimetres), read from and written to PNG.

use super::ImagesError;
use image::{ColorType, DynamicImage, ImageDecoder, ImageReader};
use std::path::Path;

/// A camera frame's grey levels, row after row, row 0 at the top of the
/// camera's picture.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Pixels {
    Grey8(Vec<u8>),
    Grey16(Vec<u16>),
}

/// Bits per grey level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BitDepth {
    Eight,
    Sixteen,
}

impl BitDepth {
    pub fn bits(self) -> u32 {
        match self {
            BitDepth::Eight => 8,
            BitDepth::Sixteen => 16,
        }
    }
}

/// A decoded camera frame. Invariant: `pixels` holds `width * height` levels.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CameraImage {
    pub width: u32,
    pub height: u32,
    pub pixels: Pixels,
}

impl CameraImage {
    pub fn depth(&self) -> BitDepth {
        match self.pixels {
            Pixels::Grey8(_) => BitDepth::Eight,
            Pixels::Grey16(_) => BitDepth::Sixteen,
        }
    }

    /// The median of a depth frame's readings, 0 (no reading) left out: the
    /// table's distance when the table fills most of the camera's view.
    /// `None` for an 8-bit frame or one without readings.
    pub fn median_reading(&self) -> Option<f32> {
        let Pixels::Grey16(mm) = &self.pixels else {
            return None;
        };
        let mut valid: Vec<u16> = mm.iter().copied().filter(|&d| d > 0).collect();
        if valid.is_empty() {
            return None;
        }
        let mid = valid.len() / 2;
        Some(f32::from(*valid.select_nth_unstable(mid).1))
    }

    /// The PNG's size and bit depth from its header alone, without decoding
    /// the pixels: what a sequence checks of every frame before it starts,
    /// so a bad frame 300 stops the run before frame 1. Colour or alpha is
    /// refused here.
    pub fn probe(path: &Path) -> Result<(u32, u32, BitDepth), ImagesError> {
        let decoder = open(path)?;
        let (w, h) = decoder.dimensions();
        Ok((w, h, grey_depth(path, decoder.color_type())?))
    }

    /// Decodes an 8- or 16-bit grey PNG.
    pub fn read(path: &Path) -> Result<CameraImage, ImagesError> {
        let decoder = open(path)?;
        grey_depth(path, decoder.color_type())?;
        let image = DynamicImage::from_decoder(decoder).map_err(|source| decode_error(path, source))?;
        let (width, height) = (image.width(), image.height());
        let pixels = match image {
            DynamicImage::ImageLuma8(b) => Pixels::Grey8(b.into_raw()),
            DynamicImage::ImageLuma16(b) => Pixels::Grey16(b.into_raw()),
            other => {
                return Err(ImagesError::Frame {
                    path: path.display().to_string(),
                    problem: format!("{:?} pixels; expected 8- or 16-bit grey", other.color()),
                });
            }
        };
        Ok(CameraImage { width, height, pixels })
    }

    /// Encodes as a grey PNG of the frame's own bit depth.
    pub fn to_png(&self, path: &Path) -> Result<Vec<u8>, ImagesError> {
        let mut out = std::io::Cursor::new(Vec::new());
        let encoded = match &self.pixels {
            Pixels::Grey8(p) => image::GrayImage::from_raw(self.width, self.height, p.clone())
                .map(|b| DynamicImage::ImageLuma8(b).write_to(&mut out, image::ImageFormat::Png)),
            Pixels::Grey16(p) => {
                image::ImageBuffer::<image::Luma<u16>, _>::from_raw(self.width, self.height, p.clone())
                    .map(|b| DynamicImage::ImageLuma16(b).write_to(&mut out, image::ImageFormat::Png))
            }
        };
        match encoded {
            Some(Ok(())) => Ok(out.into_inner()),
            Some(Err(source)) => Err(ImagesError::Encode { path: path.display().to_string(), source }),
            None => Err(ImagesError::Frame {
                path: path.display().to_string(),
                problem: "pixel count is not width x height".into(),
            }),
        }
    }

    /// Writes the PNG atomically (a reader never sees half a frame).
    pub fn write(&self, path: &Path) -> Result<(), ImagesError> {
        let bytes = self.to_png(path)?;
        crate::files::write_output(path, &bytes)
            .map_err(|source| ImagesError::Write { path: path.display().to_string(), source })
    }
}

fn open(path: &Path) -> Result<impl ImageDecoder, ImagesError> {
    let reader = ImageReader::open(path)
        .map_err(|source| ImagesError::Io { path: path.display().to_string(), source })?
        .with_guessed_format()
        .map_err(|source| ImagesError::Io { path: path.display().to_string(), source })?;
    if reader.format() != Some(image::ImageFormat::Png) {
        return Err(ImagesError::Frame { path: path.display().to_string(), problem: "not a PNG file".into() });
    }
    reader.into_decoder().map_err(|source| decode_error(path, source))
}

fn decode_error(path: &Path, source: image::ImageError) -> ImagesError {
    ImagesError::Decode { path: path.display().to_string(), source }
}

fn grey_depth(path: &Path, color: ColorType) -> Result<BitDepth, ImagesError> {
    match color {
        ColorType::L8 => Ok(BitDepth::Eight),
        ColorType::L16 => Ok(BitDepth::Sixteen),
        other => Err(ImagesError::Frame {
            path: path.display().to_string(),
            problem: format!("{other:?} pixels; frames must be 8- or 16-bit grey"),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sixteen_bit_frames_round_trip_and_colour_is_refused() {
        let dir = tempfile::tempdir().expect("dir");
        let path = dir.path().join("d.png");
        let frame = CameraImage { width: 3, height: 2, pixels: Pixels::Grey16(vec![0, 1, 1200, 65535, 7, 300]) };
        frame.write(&path).expect("write");
        assert_eq!(CameraImage::probe(&path).expect("probe"), (3, 2, BitDepth::Sixteen));
        assert_eq!(CameraImage::read(&path).expect("read"), frame);

        let rgb = dir.path().join("rgb.png");
        image::RgbImage::new(4, 4).save(&rgb).expect("save");
        let e = CameraImage::read(&rgb).expect_err("colour");
        assert!(e.to_string().ends_with("rgb.png: Rgb8 pixels; frames must be 8- or 16-bit grey"), "{e}");

        let junk = dir.path().join("junk.png");
        std::fs::write(&junk, b"\x89PNG\r\n\x1a\nnot really").expect("write");
        let e = CameraImage::read(&junk).expect_err("corrupt");
        assert!(e.to_string().ends_with("junk.png: not a readable PNG image"), "{e}");
        assert_eq!(crate::error::Kind::kind(&e), crate::error::ErrorKind::BadInput);
    }
}
