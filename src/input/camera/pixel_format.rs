//! A frame's bytes as a V4L2 camera delivers them, and their grey levels.
//!
//! The vision stage wants one grey level a pixel, so only formats that
//! carry luminance as such are taken: GREY and Y16 (infrared cameras, FTIR
//! and DI rigs), Z16 (depth cameras such as `RealSense` through `uvcvideo`,
//! millimetres), and YUYV / UYVY, the packed 4:2:2 formats every UVC
//! webcam offers, whose luma is read and chroma dropped. Compressed MJPG is
//! refused: decoding it would cost a JPEG decoder and a frame's time, and
//! the same cameras offer YUYV at the sizes a table needs.
//!
//! Rows may be padded (`stride` ≥ width × bytes a pixel), as drivers do
//! to align lines; 16-bit formats are little-endian, as V4L2 defines them.

use super::CameraError;
use crate::input::images::{CameraImage, CameraKind, Pixels};

/// The pixel formats taken, by their V4L2 four-character codes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PixelFormat {
    /// `GREY`: 8-bit luminance.
    Grey,
    /// `Y16 `: 16-bit luminance, little-endian.
    Y16,
    /// `Z16 `: 16-bit depth, little-endian (millimetres on the cameras
    /// that offer it through V4L2).
    Z16,
    /// `YUYV`: Y0 U Y1 V, two pixels in four bytes.
    Yuyv,
    /// `UYVY`: U Y0 V Y1.
    Uyvy,
}

impl PixelFormat {
    /// Every format, in the order a camera's offers are preferred: grey
    /// first (no conversion), depth, then the packed webcam formats.
    pub const PREFERENCE: [PixelFormat; 5] =
        [PixelFormat::Grey, PixelFormat::Y16, PixelFormat::Z16, PixelFormat::Yuyv, PixelFormat::Uyvy];

    /// The formats to ask a camera for, best first: a depth calibration
    /// needs millimetres (Z16, then Y16); infrared wants 8-bit grey, then
    /// the packed webcam formats, then 16-bit grey; with no calibration
    /// yet, [`PixelFormat::PREFERENCE`].
    pub fn preference(kind: Option<CameraKind>) -> &'static [PixelFormat] {
        match kind {
            None => &Self::PREFERENCE,
            Some(CameraKind::Depth) => &[PixelFormat::Z16, PixelFormat::Y16],
            Some(CameraKind::Ir) => &[PixelFormat::Grey, PixelFormat::Yuyv, PixelFormat::Uyvy, PixelFormat::Y16],
        }
    }

    pub fn fourcc(self) -> [u8; 4] {
        match self {
            PixelFormat::Grey => *b"GREY",
            PixelFormat::Y16 => *b"Y16 ",
            PixelFormat::Z16 => *b"Z16 ",
            PixelFormat::Yuyv => *b"YUYV",
            PixelFormat::Uyvy => *b"UYVY",
        }
    }

    pub fn from_fourcc(code: [u8; 4]) -> Option<PixelFormat> {
        Self::PREFERENCE.into_iter().find(|f| f.fourcc() == code)
    }

    /// The code as text, for messages (`"YUYV"`, `"Z16"`).
    pub fn name(self) -> &'static str {
        match self {
            PixelFormat::Grey => "GREY",
            PixelFormat::Y16 => "Y16",
            PixelFormat::Z16 => "Z16",
            PixelFormat::Yuyv => "YUYV",
            PixelFormat::Uyvy => "UYVY",
        }
    }

    /// Bytes a pixel takes in a row (the packed formats: two a pixel on
    /// average, four for each pair).
    pub fn bytes_per_pixel(self) -> u32 {
        match self {
            PixelFormat::Grey => 1,
            PixelFormat::Y16 | PixelFormat::Z16 | PixelFormat::Yuyv | PixelFormat::Uyvy => 2,
        }
    }

    /// Whether its grey levels are 16-bit (a depth camera's millimetres, or
    /// a high-bit infrared camera).
    pub fn is_16_bit(self) -> bool {
        matches!(self, PixelFormat::Y16 | PixelFormat::Z16)
    }
}

/// What the driver agreed to deliver.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RawFormat {
    pub width: u32,
    pub height: u32,
    /// Bytes from one row's start to the next's.
    pub stride: u32,
    pub pixel: PixelFormat,
}

impl RawFormat {
    /// Rows without padding.
    pub fn packed(width: u32, height: u32, pixel: PixelFormat) -> RawFormat {
        RawFormat { width, height, stride: width * pixel.bytes_per_pixel(), pixel }
    }

    /// Bytes a whole frame needs: every row but the last with its padding.
    pub fn frame_bytes(&self) -> usize {
        let row = self.width as usize * self.pixel.bytes_per_pixel() as usize;
        if self.height == 0 { 0 } else { (self.height as usize - 1) * self.stride as usize + row }
    }

    /// Whether the driver's answer can be read: a size, an even width for
    /// the packed pairs, a stride that holds a row.
    pub fn check(&self) -> Result<(), CameraError> {
        let row = u64::from(self.width) * u64::from(self.pixel.bytes_per_pixel());
        let problem = if self.width < 2 || self.height < 2 {
            Some(format!("{}x{} pixels is too small", self.width, self.height))
        } else if matches!(self.pixel, PixelFormat::Yuyv | PixelFormat::Uyvy) && self.width % 2 == 1 {
            Some(format!("an odd width ({}) cannot hold {} pixel pairs", self.width, self.pixel.name()))
        } else if u64::from(self.stride) < row {
            Some(format!("{} bytes a row cannot hold {} {} pixels", self.stride, self.width, self.pixel.name()))
        } else {
            None
        };
        problem.map_or(Ok(()), |problem| Err(CameraError::Format { problem }))
    }
}

/// The grey levels of one delivered frame: 8-bit for GREY and the packed
/// formats (their luma), 16-bit for Y16 and Z16. Extra bytes after the
/// frame (drivers hand out whole buffers) are ignored; too few are an error.
pub fn decode(format: &RawFormat, bytes: &[u8]) -> Result<CameraImage, CameraError> {
    format.check()?;
    let need = format.frame_bytes();
    if bytes.len() < need {
        return Err(CameraError::ShortFrame { got: bytes.len(), need, format: describe(format) });
    }
    let (w, h, stride) = (format.width as usize, format.height as usize, format.stride as usize);
    let row_bytes = w * format.pixel.bytes_per_pixel() as usize;
    let rows = || (0..h).map(|r| &bytes[r * stride..r * stride + row_bytes]);
    // Row by row into a vector sized up front, which the compiler
    // vectorizes: a 640x480 frame decodes several times faster this way than
    // as one iterator flattened over the rows, Z16 and YUYV alike
    // (`cargo bench --bench images`).
    let pixels = if format.pixel.is_16_bit() {
        let mut out = Vec::with_capacity(w * h);
        for row in rows() {
            out.extend(row.chunks_exact(2).map(|b| u16::from_le_bytes([b[0], b[1]])));
        }
        Pixels::Grey16(out)
    } else {
        // Luma is every byte (GREY), or every other byte from 0 (YUYV) or 1 (UYVY).
        let (step, first) = match format.pixel {
            PixelFormat::Yuyv => (2, 0),
            PixelFormat::Uyvy => (2, 1),
            _ => (1, 0),
        };
        let mut out = Vec::with_capacity(w * h);
        for row in rows() {
            if step == 1 {
                out.extend_from_slice(row);
            } else {
                out.extend(row.chunks_exact(2).map(|pair| pair[first]));
            }
        }
        Pixels::Grey8(out)
    };
    Ok(CameraImage { width: format.width, height: format.height, pixels })
}

/// A frame's bytes as a camera would deliver it in `format` (the inverse
/// of [`decode`]: mid-grey chroma, zero padding): how recorded frames are
/// turned into a camera's stream for tests and benchmarks. The image must
/// have the format's size and bit depth.
pub fn encode(image: &CameraImage, format: &RawFormat) -> Result<Vec<u8>, CameraError> {
    format.check()?;
    let fits = [image.width, image.height] == [format.width, format.height]
        && matches!(&image.pixels, Pixels::Grey16(_)) == format.pixel.is_16_bit();
    if !fits {
        let bits = if matches!(image.pixels, Pixels::Grey16(_)) { 16 } else { 8 };
        let problem =
            format!("a {}x{} {bits}-bit image cannot be sent as {}", image.width, image.height, describe(format));
        return Err(CameraError::Format { problem });
    }
    let (w, stride) = (format.width as usize, format.stride as usize);
    let mut out = vec![0u8; format.frame_bytes()];
    for (r, line) in out.chunks_mut(stride).enumerate() {
        let row = &mut line[..w * format.pixel.bytes_per_pixel() as usize];
        match (&image.pixels, format.pixel) {
            (Pixels::Grey8(p), PixelFormat::Grey) => row.copy_from_slice(&p[r * w..(r + 1) * w]),
            (Pixels::Grey16(p), _) => {
                for (b, v) in row.chunks_exact_mut(2).zip(&p[r * w..(r + 1) * w]) {
                    b.copy_from_slice(&v.to_le_bytes());
                }
            }
            (Pixels::Grey8(p), pixel) => {
                let luma = usize::from(pixel == PixelFormat::Uyvy);
                for (b, v) in row.chunks_exact_mut(2).zip(&p[r * w..(r + 1) * w]) {
                    b[luma] = *v;
                    b[1 - luma] = 128;
                }
            }
        }
    }
    Ok(out)
}

/// `640x480 YUYV (1280 bytes a row)`.
pub fn describe(format: &RawFormat) -> String {
    format!("{}x{} {} ({} bytes a row)", format.width, format.height, format.pixel.name(), format.stride)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey8(w: u32, h: u32) -> CameraImage {
        CameraImage { width: w, height: h, pixels: Pixels::Grey8((0..w * h).map(|i| (i * 7 % 251) as u8).collect()) }
    }

    fn grey16(w: u32, h: u32) -> CameraImage {
        CameraImage {
            width: w,
            height: h,
            pixels: Pixels::Grey16((0..w * h).map(|i| (i * 977 % 65_521) as u16).collect()),
        }
    }

    #[test]
    fn fourcc_codes_are_v4l2s() {
        assert_eq!(PixelFormat::from_fourcc(*b"YUYV"), Some(PixelFormat::Yuyv));
        assert_eq!(PixelFormat::from_fourcc(*b"Z16 "), Some(PixelFormat::Z16));
        assert_eq!(PixelFormat::from_fourcc(*b"MJPG"), None);
        for f in PixelFormat::PREFERENCE {
            assert_eq!(PixelFormat::from_fourcc(f.fourcc()), Some(f));
        }
    }

    #[test]
    fn luma_is_read_from_its_place_in_the_packed_pairs() {
        // Two pixels, one row: Y0 = 10, Y1 = 20, chroma 200 and 100.
        let one_row = |pixel| RawFormat::packed(2, 2, pixel);
        let yuyv = [10, 200, 20, 100, 30, 200, 40, 100];
        let uyvy = [200, 10, 100, 20, 200, 30, 100, 40];
        let want = Pixels::Grey8(vec![10, 20, 30, 40]);
        assert_eq!(decode(&one_row(PixelFormat::Yuyv), &yuyv).expect("decodes").pixels, want);
        assert_eq!(decode(&one_row(PixelFormat::Uyvy), &uyvy).expect("decodes").pixels, want);
        // 16-bit: little-endian, 0x1234 as [0x34, 0x12].
        let z = decode(&RawFormat::packed(2, 2, PixelFormat::Z16), &[0x34, 0x12, 1, 0, 0, 1, 0xff, 0xff]).expect("z16");
        assert_eq!(z.pixels, Pixels::Grey16(vec![0x1234, 1, 256, 65_535]));
    }

    #[test]
    fn every_format_round_trips_with_padded_rows() {
        for pixel in PixelFormat::PREFERENCE {
            let image = if pixel.is_16_bit() { grey16(6, 4) } else { grey8(6, 4) };
            for pad in [0, 4, 10] {
                let format = RawFormat { stride: 6 * pixel.bytes_per_pixel() + pad, ..RawFormat::packed(6, 4, pixel) };
                let bytes = encode(&image, &format).expect("encodes");
                // Three padded rows and a last one without its padding.
                let (stride, row) = (format.stride as usize, 6 * pixel.bytes_per_pixel() as usize);
                assert_eq!(bytes.len(), 3 * stride + row, "{pixel:?} pad {pad}");
                assert_eq!(decode(&format, &bytes).expect("decodes"), image, "{pixel:?} pad {pad}");
                // A whole driver buffer, longer than the frame, reads the same.
                let mut long = bytes.clone();
                long.extend([9; 64]);
                assert_eq!(decode(&format, &long).expect("decodes"), image);
            }
        }
    }

    #[test]
    fn short_frames_and_unreadable_formats_are_named() {
        let format = RawFormat::packed(640, 480, PixelFormat::Yuyv);
        let e = decode(&format, &[0; 1000]).expect_err("short");
        assert_eq!(e.to_string(), "a frame of 1000 bytes; 640x480 YUYV (1280 bytes a row) needs 614400");
        let odd = RawFormat::packed(5, 4, PixelFormat::Uyvy);
        assert_eq!(
            decode(&odd, &[0; 64]).expect_err("odd").to_string(),
            "camera format: an odd width (5) cannot hold UYVY pixel pairs"
        );
        let thin = RawFormat { stride: 100, ..RawFormat::packed(640, 480, PixelFormat::Grey) };
        assert!(
            decode(&thin, &vec![0; 1 << 20])
                .expect_err("stride")
                .to_string()
                .contains("100 bytes a row cannot hold 640 GREY")
        );
        assert!(encode(&grey8(6, 4), &RawFormat::packed(6, 4, PixelFormat::Z16)).is_err(), "8-bit as Z16");
        assert!(encode(&grey16(6, 4), &RawFormat::packed(6, 4, PixelFormat::Yuyv)).is_err(), "16-bit as YUYV");
        assert!(encode(&grey8(6, 4), &RawFormat::packed(8, 4, PixelFormat::Grey)).is_err(), "size");
    }
}
