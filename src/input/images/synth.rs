//! Camera frames as a real rig would record them, made from a gesture:
//! test data for the image path (`surfacelab synth-images`), with a known
//! answer (the same gesture's synthetic contact image).
//!
//! Each frame is the gesture's contact image ([`rasterize`], the session's
//! own drawing) seen through a keystoned camera: every camera pixel looks
//! up the table point the calibration's homography gives it. On top:
//!
//! - `ir`: the touch blurred by the diffuser (3×3), a dim glow of the hand
//!   above the glass (a wide blur, below the threshold), a background
//!   gradient of ambient infrared, vignetting (30% darker in the corners),
//!   uniform noise of ±5 levels; 8-bit. The view is mirrored, as a camera
//!   under the glass sees the table. The background image is written too.
//! - `depth`: a camera above the table, 1200 mm away; touching skin at the
//!   height the touch band gives its grey (a full touch 3 mm inside the
//!   band, so noise does not push it out), the rest of the hand hovering
//!   55 mm up, the table at 0; triangular noise of ±2 mm, whole
//!   millimetres; 16-bit.
//!
//! Noise comes from a `ChaCha8Rng` seeded with the seed and the frame
//! number, so a sequence is the same on every machine.

use super::{Background, Calibration, CameraImage, CameraKind, Conversion, ImagesError, Pixels};
use crate::input::Gesture;
use crate::pipeline::surface::{ContactImage, RasterParams, Sensor, TablePoint, rasterize};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::Path;

/// IR: grey levels a full touch adds above the background, at the centre.
const IR_SIGNAL: f32 = 225.0;
/// IR: the hovering hand's glow, levels at its brightest (under the 40 threshold).
const IR_GLOW: f32 = 24.0;
/// IR: noise amplitude, levels.
const IR_NOISE: f32 = 5.0;
/// IR: the threshold written into the calibration.
const IR_THRESHOLD: u8 = 40;
/// Depth: the table's distance and the touch band written into the calibration.
const TABLE_DEPTH_MM: f32 = 1200.0;
const TOUCH_BAND_MM: [f32; 2] = [4.0, 30.0];
/// Depth: height of the hand that does not touch.
const HOVER_MM: f32 = 55.0;
/// Depth: noise amplitude, millimetres (the sum of two uniforms of half this).
const DEPTH_NOISE_MM: f32 = 2.0;
/// Half-width of the glow's box blur, contact pixels (applied twice).
const GLOW_RADIUS: usize = 10;

/// Where the table's corners (far-left, far-right, near-right, near-left)
/// appear in a 640×480 camera: IR from below (mirrored, keystoned), depth
/// from above (nearly square on).
const IR_CORNERS: [[f64; 2]; 4] = [[566.0, 38.0], [84.0, 46.0], [26.0, 452.0], [616.0, 440.0]];
const DEPTH_CORNERS: [[f64; 2]; 4] = [[52.0, 40.0], [596.0, 44.0], [604.0, 446.0], [44.0, 442.0]];

/// A synthetic camera over a sensor's table.
#[derive(Debug)]
pub struct Synthesizer {
    calibration: Calibration,
    sensor: Sensor,
    /// For each camera pixel, the contact-image position it sees (NaN: off the table).
    looks_at: Vec<[f32; 2]>,
    /// IR: ambient level of each camera pixel, and its vignetting factor.
    background: Vec<f32>,
    vignette: Vec<f32>,
    seed: u64,
}

impl Synthesizer {
    pub fn new(kind: CameraKind, sensor: &Sensor, image_size: [u32; 2], seed: u64) -> Result<Synthesizer, ImagesError> {
        let [w, h] = image_size;
        let (hw, hd) = (f64::from(sensor.table_width_m) / 2.0, f64::from(sensor.table_depth_m) / 2.0);
        let table = [[-hw, hd], [hw, hd], [hw, -hd], [-hw, -hd]];
        let corners = match kind {
            CameraKind::Ir => IR_CORNERS,
            CameraKind::Depth => DEPTH_CORNERS,
        };
        let scale = [f64::from(w) / 640.0, f64::from(h) / 480.0];
        let image = corners.map(|[x, y]| [x * scale[0], y * scale[1]]);
        let (mut background, mut vignette) = (Vec::new(), Vec::new());
        let (wf, hf) = (w as f32, h as f32);
        for y in 0..h {
            for x in 0..w {
                let (u, v) = (x as f32 / wf, y as f32 / hf);
                background.push(18.0 + 28.0 * u + 14.0 * v);
                let r2 = ((u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5)) / 0.5;
                vignette.push(1.0 - 0.3 * r2);
            }
        }
        let conversion = match kind {
            CameraKind::Ir => {
                let levels = background.iter().map(|b| b.round() as u8).collect();
                let image = CameraImage { width: w, height: h, pixels: Pixels::Grey8(levels) };
                Conversion::Ir {
                    threshold: IR_THRESHOLD,
                    background: Some(Background { name: "background.png".into(), image }),
                }
            }
            CameraKind::Depth => Conversion::Depth { table_depth_mm: TABLE_DEPTH_MM, touch_band_mm: TOUCH_BAND_MM },
        };
        let calibration = Calibration::new(conversion, image_size, image, table, "synth-images")?;
        let to_table = calibration.image_to_table();
        let mut looks_at = Vec::with_capacity((w * h) as usize);
        for y in 0..h {
            for x in 0..w {
                let p = to_table.apply([f64::from(x), f64::from(y)]).filter(|p| p[0].abs() <= hw && p[1].abs() <= hd);
                looks_at.push(
                    p.map_or([f32::NAN; 2], |p| sensor.to_pixel(TablePoint::new(p[0] as f32, p[1] as f32)).to_array()),
                );
            }
        }
        Ok(Synthesizer { calibration, sensor: *sensor, looks_at, background, vignette, seed })
    }

    pub fn calibration(&self) -> &Calibration {
        &self.calibration
    }

    /// The camera's view of `contact` as frame number `n`.
    pub fn frame(&self, contact: &ContactImage, n: u64) -> CameraImage {
        let [w, h] = self.calibration.image_size;
        let touch: Vec<f32> = contact.pixels.iter().map(|&g| f32::from(g) / 255.0).collect();
        let (cw, ch) = (contact.width, contact.height);
        let glow = box_blur(&box_blur(&touch, cw, ch, GLOW_RADIUS), cw, ch, GLOW_RADIUS);
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed ^ n.wrapping_mul(0x9E37_79B9_7F4A_7C15));
        let pixels = match &self.calibration.conversion {
            Conversion::Ir { .. } => {
                let touch = box_blur(&touch, cw, ch, 1);
                let levels = (0..self.looks_at.len())
                    .map(|i| {
                        let q = self.looks_at[i];
                        let lit = IR_SIGNAL * bilinear(&touch, cw, ch, q) + IR_GLOW * bilinear(&glow, cw, ch, q);
                        let noise = rng.random_range(-IR_NOISE..=IR_NOISE);
                        (self.background[i] + self.vignette[i] * lit + noise).round().clamp(0.0, 255.0) as u8
                    })
                    .collect();
                Pixels::Grey8(levels)
            }
            Conversion::Depth { table_depth_mm, touch_band_mm: [near, far] } => {
                let mm = self
                    .looks_at
                    .iter()
                    .map(|&q| {
                        let s = bilinear(&touch, cw, ch, q);
                        // The touch band's grey read backwards, full touch
                        // kept a noise's width inside the band's near edge
                        // (noise must not push skin out of the band).
                        let height = if s > 0.02 {
                            far - s * (far - near - DEPTH_NOISE_MM - 1.0)
                        } else if bilinear(&glow, cw, ch, q) > 0.08 {
                            HOVER_MM
                        } else {
                            0.0
                        };
                        let half = 0.5 * DEPTH_NOISE_MM;
                        let noise = rng.random_range(-half..=half) + rng.random_range(-half..=half);
                        (table_depth_mm - height + noise).round().clamp(1.0, 65535.0) as u16
                    })
                    .collect();
                Pixels::Grey16(mm)
            }
        };
        debug_assert_eq!(self.sensor.width_px as usize, cw);
        CameraImage { width: w, height: h, pixels }
    }
}

/// What [`write_sequence`] wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    pub frames: usize,
    pub duration_s: f64,
}

/// Writes the gesture as camera frames `frame_00000.png`, ... into `out`
/// (one per physics step of `dt`, at the times a replay samples, up to and
/// including its last key), with `calibration.toml` (and `background.png`
/// for IR) beside them: a folder `run --images` plays as it is. The
/// contact image is drawn as the session draws it (`raster`).
pub fn write_sequence(
    gesture: &Gesture,
    sensor: &Sensor,
    raster: &RasterParams,
    dt: f64,
    synth: &Synthesizer,
    out: &Path,
) -> Result<Written, ImagesError> {
    let mut n = 0u64;
    loop {
        let t = n as f64 * dt;
        if t > gesture.duration() {
            break;
        }
        let contact = rasterize(&gesture.sample(t), sensor, raster);
        synth.frame(&contact, n).write(&out.join(format!("frame_{n:05}.png")))?;
        n += 1;
    }
    if let Conversion::Ir { background: Some(b), .. } = &synth.calibration.conversion {
        b.image.write(&out.join(&b.name))?;
    }
    // Last, so a folder with a calibration is a whole sequence.
    let path = out.join("calibration.toml");
    crate::files::write_output(&path, synth.calibration.to_toml().as_bytes())
        .map_err(|source| ImagesError::Write { path: path.display().to_string(), source })?;
    Ok(Written { frames: n as usize, duration_s: n.saturating_sub(1) as f64 * dt })
}

/// Bilinear sample of a `w × h` image at a (fractional) pixel position,
/// integers at pixel centres; 0 off the image or at NaN.
fn bilinear(img: &[f32], w: usize, h: usize, [x, y]: [f32; 2]) -> f32 {
    if !(x >= 0.0 && y >= 0.0 && x <= (w - 1) as f32 && y <= (h - 1) as f32) {
        return 0.0;
    }
    let (x0, y0) = ((x as usize).min(w - 2), (y as usize).min(h - 2));
    let (fx, fy) = (x - x0 as f32, y - y0 as f32);
    let i = y0 * w + x0;
    let top = img[i] + (img[i + 1] - img[i]) * fx;
    let bottom = img[i + w] + (img[i + w + 1] - img[i + w]) * fx;
    top + (bottom - top) * fy
}

/// Mean over a `(2r+1)²` box, rows then columns, by running sums; the
/// box shrinks at the border.
fn box_blur(img: &[f32], w: usize, h: usize, r: usize) -> Vec<f32> {
    let pass = |src: &[f32], len: usize, lines: usize, at: &dyn Fn(usize, usize) -> usize| {
        let mut dst = vec![0.0; src.len()];
        for line in 0..lines {
            let mut sum = 0.0f32;
            let (mut lo, mut hi) = (0usize, 0usize);
            for k in 0..len {
                let (want_lo, want_hi) = (k.saturating_sub(r), (k + r + 1).min(len));
                while hi < want_hi {
                    sum += src[at(line, hi)];
                    hi += 1;
                }
                while lo < want_lo {
                    sum -= src[at(line, lo)];
                    lo += 1;
                }
                dst[at(line, k)] = sum / (hi - lo) as f32;
            }
        }
        dst
    };
    let rows = pass(img, w, h, &|line, k| line * w + k);
    pass(&rows, h, w, &|line, k| k * w + line)
}

#[cfg(test)]
mod tests {
    use super::super::Rectifier;
    use super::*;
    use crate::pipeline::surface::{Hand, HandKind};

    #[test]
    fn box_blur_keeps_the_mean_inside_and_spreads_a_point() {
        let mut img = vec![0.0; 7 * 7];
        img[3 * 7 + 3] = 9.0;
        let b = box_blur(&img, 7, 7, 1);
        assert!((b[2 * 7 + 2] - 1.0).abs() < 1e-6 && (b[3 * 7 + 3] - 1.0).abs() < 1e-6 && b[7 + 1] == 0.0);
        assert!((b.iter().sum::<f32>() - 9.0).abs() < 1e-5);
    }

    /// A flat hand seen by each synthetic camera and rectified back covers
    /// nearly the same contact pixels as drawn: the camera, its noise and
    /// its calibration undo each other.
    #[test]
    fn rectified_frames_give_back_the_contact_image() {
        let sensor = Sensor::default();
        let hand = Hand::new(1, HandKind::FlatHand, 0.1, -0.05).with_angle(0.3).with_pressure(1.0);
        let contact = rasterize(&[hand], &sensor, &RasterParams::default());
        let drawn: Vec<bool> = contact.pixels.iter().map(|&g| g >= 48).collect();
        let area = drawn.iter().filter(|&&d| d).count();
        assert!(area > 5000, "a flat hand covers {area} pixels");
        for kind in [CameraKind::Ir, CameraKind::Depth] {
            let synth = Synthesizer::new(kind, &sensor, [640, 480], 7).expect("camera");
            let frame = synth.frame(&contact, 0);
            let mut back = ContactImage::default();
            assert!(Rectifier::new(synth.calibration(), &sensor).rectify(&frame, &mut back));
            let seen: Vec<bool> = back.pixels.iter().map(|&g| g >= 48).collect();
            let differ = drawn.iter().zip(&seen).filter(|(a, b)| a != b).count();
            let false_far = seen.iter().enumerate().filter(|&(i, &s)| s && contact.pixels[i] == 0).count();
            println!("{kind:?}: {differ} of {area} pixels differ, {false_far} lit where nothing was drawn");
            assert!(differ * 100 < area * 5, "{kind:?}: {differ} of {area} pixels differ");
            assert_eq!(false_far, 0, "{kind:?}: glow or noise read as touch");
        }
    }
}
