//! Camera frame to contact image: each contact-image pixel's centre is
//! carried through the calibration's homography into the camera image,
//! sampled there bilinearly, and its level converted to contact grey (the
//! rules are in [`super::calibration`]).
//!
//! The taps (which four camera pixels, with what weights) and the
//! background under each contact pixel depend only on the calibration and
//! the sensor, so they are computed once; a frame then costs one pass of
//! four loads and a few multiplies per contact pixel.

use super::{Calibration, CameraImage, Conversion, Pixels};
use crate::pipeline::surface::{ContactImage, PixelPoint, Sensor};

/// Where a contact pixel samples the camera image: the top-left of its
/// four camera pixels and its position between them.
#[derive(Debug, Clone, Copy)]
struct Tap {
    index: u32,
    fx: f32,
    fy: f32,
}

/// A contact pixel the camera does not see.
const OUTSIDE: u32 = u32::MAX;

#[derive(Debug, Clone)]
enum Convert {
    /// `grey = (level − offset[i]) · gain`, with `offset` = the background
    /// under pixel i plus the threshold, on the 8-bit scale.
    Ir { offset: Vec<f32>, gain: f32 },
    /// Height above the table in the touch band, see the calibration.
    Depth { table_mm: f32, near_mm: f32, far_mm: f32, jump_mm: f32 },
}

/// The per-calibration, per-sensor map from camera frames to contact images.
#[derive(Debug, Clone)]
pub struct Rectifier {
    sensor: Sensor,
    camera: [u32; 2],
    taps: Vec<Tap>,
    convert: Convert,
}

impl Rectifier {
    pub fn new(calibration: &Calibration, sensor: &Sensor) -> Rectifier {
        let [cw, ch] = calibration.image_size;
        let to_image = calibration.image_to_table().inverse();
        // Table points on the far side of the map's vanishing line would
        // land in the image mirrored: they are not seen.
        let centre = calibration.table_points.iter().fold([0.0; 2], |a, p| [a[0] + p[0] / 4.0, a[1] + p[1] / 4.0]);
        let seen_side = to_image.depth_sign(centre).signum();
        let (w, h) = (sensor.width_px as usize, sensor.height_px as usize);
        let mut taps = Vec::with_capacity(w * h);
        for r in 0..h {
            for c in 0..w {
                let t = sensor.to_table(PixelPoint::new(c as f32, r as f32)).to_array();
                let t = [f64::from(t[0]), f64::from(t[1])];
                let tap = match to_image.apply(t) {
                    Some([x, y])
                        if to_image.depth_sign(t).signum() == seen_side
                            && (-0.5..=f64::from(cw) - 0.5).contains(&x)
                            && (-0.5..=f64::from(ch) - 0.5).contains(&y) =>
                    {
                        // Clamp so the 2×2 block stays inside; half a pixel
                        // past the outer centres repeats the edge.
                        let x0 = (x.floor().max(0.0) as u32).min(cw - 2);
                        let y0 = (y.floor().max(0.0) as u32).min(ch - 2);
                        let fx = (x - f64::from(x0)).clamp(0.0, 1.0) as f32;
                        let fy = (y - f64::from(y0)).clamp(0.0, 1.0) as f32;
                        Tap { index: y0 * cw + x0, fx, fy }
                    }
                    _ => Tap { index: OUTSIDE, fx: 0.0, fy: 0.0 },
                };
                taps.push(tap);
            }
        }
        let convert = match &calibration.conversion {
            Conversion::Ir { threshold, background } => {
                let t = f32::from(*threshold);
                let offset = match background {
                    Some(b) => taps.iter().map(|tap| sample_level(&b.image.pixels, cw, *tap) + t).collect(),
                    None => vec![t; taps.len()],
                };
                Convert::Ir { offset, gain: 255.0 / (255.0 - t) }
            }
            Conversion::Depth { table_depth_mm, touch_band_mm: [near, far] } => {
                Convert::Depth { table_mm: *table_depth_mm, near_mm: *near, far_mm: *far, jump_mm: 0.5 * (far - near) }
            }
        };
        Rectifier { sensor: *sensor, camera: calibration.image_size, taps, convert }
    }

    /// The sensor whose contact image this rectifier makes.
    pub fn sensor(&self) -> &Sensor {
        &self.sensor
    }

    /// Fills `out` (resized to the sensor) from `frame`. A frame of another
    /// size than the calibration's, or 8-bit for a depth calibration, gives
    /// `false` and a blank image: callers check frames where they can name
    /// the file (see `FrameList`).
    #[must_use]
    pub fn rectify(&self, frame: &CameraImage, out: &mut ContactImage) -> bool {
        let (w, h) = (self.sensor.width_px as usize, self.sensor.height_px as usize);
        if out.width != w || out.height != h || out.pixels.len() != w * h {
            *out = ContactImage::new(w, h);
        }
        if [frame.width, frame.height] != self.camera {
            out.clear();
            return false;
        }
        let cw = self.camera[0];
        match (&self.convert, &frame.pixels) {
            (Convert::Ir { offset, gain }, Pixels::Grey8(p)) => {
                for ((o, tap), off) in out.pixels.iter_mut().zip(&self.taps).zip(offset) {
                    *o = ir_grey(sample(p, cw, *tap), *off, *gain);
                }
            }
            (Convert::Ir { offset, gain }, Pixels::Grey16(p)) => {
                for ((o, tap), off) in out.pixels.iter_mut().zip(&self.taps).zip(offset) {
                    *o = ir_grey(sample(p, cw, *tap) / 257.0, *off, *gain);
                }
            }
            (Convert::Depth { table_mm, near_mm, far_mm, jump_mm }, Pixels::Grey16(p)) => {
                for (o, tap) in out.pixels.iter_mut().zip(&self.taps) {
                    *o = match depth_sample(p, cw, *tap, *jump_mm) {
                        Some(d) => depth_grey(table_mm - d, *near_mm, *far_mm),
                        None => 0,
                    };
                }
            }
            (Convert::Depth { .. }, Pixels::Grey8(_)) => {
                out.clear();
                return false;
            }
        }
        true
    }
}

fn ir_grey(level: f32, offset: f32, gain: f32) -> u8 {
    // Saturating float-to-int cast: negative levels give 0, overflow 255.
    ((level - offset) * gain + 0.5) as u8
}

/// Grey of a height `h` above the table: 255 at the band's near edge,
/// falling linearly to 0 at its far edge, 0 outside.
fn depth_grey(h: f32, near: f32, far: f32) -> u8 {
    if (near..=far).contains(&h) { (255.0 * (far - h) / (far - near) + 0.5) as u8 } else { 0 }
}

fn taps<T: Copy + Into<f32>>(p: &[T], cw: u32, tap: Tap) -> [f32; 4] {
    let i = tap.index as usize;
    let cw = cw as usize;
    [p[i].into(), p[i + 1].into(), p[i + cw].into(), p[i + cw + 1].into()]
}

fn blend([a, b, c, d]: [f32; 4], fx: f32, fy: f32) -> f32 {
    let top = a + (b - a) * fx;
    let bottom = c + (d - c) * fx;
    top + (bottom - top) * fy
}

fn sample<T: Copy + Into<f32>>(p: &[T], cw: u32, tap: Tap) -> f32 {
    if tap.index == OUTSIDE { 0.0 } else { blend(taps(p, cw, tap), tap.fx, tap.fy) }
}

/// A background level on the 8-bit scale, whatever its depth.
fn sample_level(p: &Pixels, cw: u32, tap: Tap) -> f32 {
    match p {
        Pixels::Grey8(p) => sample(p, cw, tap),
        Pixels::Grey16(p) => sample(p, cw, tap) / 257.0,
    }
}

/// A depth in millimetres, or `None` where the camera has no reading.
///
/// Why not always bilinear: blending across the edge of a hand mixes the
/// hand's height with the table's and invents heights in between, which
/// would light a ring of false touch round every hovering hand. Where the
/// four readings differ by more than `jump_mm` (half the touch band) or one
/// of them is missing (0), the nearest reading is taken instead.
fn depth_sample(p: &[u16], cw: u32, tap: Tap, jump_mm: f32) -> Option<f32> {
    if tap.index == OUTSIDE {
        return None;
    }
    let t = taps(p, cw, tap);
    let (lo, hi) = t.iter().fold((f32::MAX, 0.0f32), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    let d = if lo > 0.0 && hi - lo <= jump_mm {
        blend(t, tap.fx, tap.fy)
    } else {
        t[usize::from(tap.fx >= 0.5) + 2 * usize::from(tap.fy >= 0.5)]
    };
    (d > 0.0).then_some(d)
}

#[cfg(test)]
mod tests {
    use super::super::{Background, Homography};
    use super::*;

    /// A camera looking straight at a 1.0 × 0.75 m table that fills its
    /// 8 × 6 image (pixel centres at the table's cell centres), and a sensor
    /// of 16 × 12 over the same table: each camera pixel covers 2 × 2
    /// contact pixels.
    fn straight(conversion: Conversion) -> Calibration {
        let image = [[-0.5, -0.5], [7.5, -0.5], [7.5, 5.5], [-0.5, 5.5]];
        let table = [[-0.5, 0.375], [0.5, 0.375], [0.5, -0.375], [-0.5, -0.375]];
        Calibration::new(conversion, [8, 6], image, table, "test").expect("valid")
    }

    /// The 16 × 12 contact sensor over the table [`straight`] films.
    fn sensor() -> Sensor {
        Sensor::new(16, 12, 1.0, 0.75)
    }

    /// An 8 × 6 camera frame of `pixels` rectified through `cal` onto
    /// [`sensor`]; the rectifier must take it.
    fn rectified(cal: &Calibration, pixels: Pixels) -> ContactImage {
        let frame = CameraImage { width: 8, height: 6, pixels };
        let mut out = ContactImage::default();
        assert!(Rectifier::new(cal, &sensor()).rectify(&frame, &mut out));
        out
    }

    #[test]
    fn ir_levels_are_thresholded_and_stretched() {
        let cal = straight(Conversion::Ir { threshold: 55, background: None });
        let mut levels = vec![0u8; 48];
        levels[2 * 8 + 3] = 255; // camera pixel (3, 2)
        levels[4 * 8 + 6] = 155; // (6, 4): 100 above the threshold
        let out = rectified(&cal, Pixels::Grey8(levels));
        // Contact pixel (7, 5) has its centre a quarter camera pixel right
        // of and below camera pixel (3, 2)'s centre: weight 0.75 × 0.75 of 255,
        // the rest 0, so level 143.4: (143.4 − 55) · 255/200 = 112.7.
        assert_eq!(out.pixels[5 * 16 + 7], 113);
        // Contact (12, 8) is 1/4 left and up of camera (6, 4): 0.5625 · 155 = 87.2 → 41.
        assert_eq!(out.pixels[8 * 16 + 12], 41);
        // A contact pixel whose samples are all dark stays 0, not negative.
        assert_eq!(out.pixels[0], 0);
        let lit = out.pixels.iter().filter(|&&g| g > 0).count();
        assert_eq!(lit, 8, "4 contact pixels round each lit camera pixel");
    }

    #[test]
    fn a_background_is_subtracted_where_it_lies() {
        let mut bg = vec![10u8; 48];
        bg[2 * 8 + 3] = 200;
        let background =
            Background { name: "bg.png".into(), image: CameraImage { width: 8, height: 6, pixels: Pixels::Grey8(bg) } };
        let cal = straight(Conversion::Ir { threshold: 20, background: Some(background) });
        let mut levels = vec![40u8; 48];
        levels[2 * 8 + 3] = 230; // bright everywhere, but as bright as the empty table here
        let out = rectified(&cal, Pixels::Grey8(levels));
        // Everywhere 30 above the background: (30 − 20) · 255/235 = 10.85.
        assert!(out.pixels.iter().all(|&g| g == 11), "{:?}", out.pixels);
    }

    #[test]
    fn depth_in_the_touch_band_is_bright_and_edges_are_not_blended() {
        let cal = straight(Conversion::Depth { table_depth_mm: 1000.0, touch_band_mm: [4.0, 30.0] });
        let mut mm = vec![1000u16; 48];
        mm[2 * 8 + 3] = 996; // 4 mm up: full touch
        mm[2 * 8 + 4] = 983; // 17 mm up: half
        mm[4 * 8 + 2] = 940; // 60 mm up: a hovering hand
        mm[4 * 8 + 3] = 0; // no reading
        let mut out = rectified(&cal, Pixels::Grey16(mm));
        // Contact (7, 5) blends (3,2)=996 and (4,2)=983 ... with table 1000 neighbours:
        // they differ by 17 mm > 13, so it takes the nearest reading, 996 → 255.
        assert_eq!(out.pixels[5 * 16 + 7], 255);
        // Contact (8, 4) is nearest camera (4, 2) at 17 mm: 255 · 13/26.
        assert_eq!(out.pixels[4 * 16 + 8], 128);
        // Round the hovering hand (60 mm) nothing lights: no invented heights.
        for (c, r) in [(4, 8), (5, 8), (4, 9), (5, 9), (3, 9), (6, 10), (7, 8)] {
            assert_eq!(out.pixels[r * 16 + c], 0, "({c}, {r})");
        }
        let eight = CameraImage { width: 8, height: 6, pixels: Pixels::Grey8(vec![0; 48]) };
        assert!(!Rectifier::new(&cal, &sensor()).rectify(&eight, &mut out), "8-bit is not millimetres");
    }

    /// Through a keystoned view the contact pixel over a table point samples
    /// the camera pixel where that point appears.
    #[test]
    fn a_perspective_view_is_undone() {
        let image = [[70.0, 40.0], [590.0, 60.0], [620.0, 450.0], [30.0, 430.0]];
        let table = [[-0.5, 0.375], [0.5, 0.375], [0.5, -0.375], [-0.5, -0.375]];
        let cal = Calibration::new(Conversion::Ir { threshold: 0, background: None }, [640, 480], image, table, "t")
            .expect("valid");
        let to_image = Homography::from_points(&table, &image).expect("map");
        let sensor = Sensor::default();
        // A bright 5×5 square in the camera where table point (0.2, -0.1) appears.
        let [x, y] = to_image.apply([0.2, -0.1]).expect("finite");
        let mut levels = vec![0u8; 640 * 480];
        for dy in -2..=2 {
            for dx in -2..=2 {
                levels[(y.round() as i64 + dy) as usize * 640 + (x.round() as i64 + dx) as usize] = 255;
            }
        }
        let frame = CameraImage { width: 640, height: 480, pixels: Pixels::Grey8(levels) };
        let mut out = ContactImage::default();
        assert!(Rectifier::new(&cal, &sensor).rectify(&frame, &mut out));
        let p = sensor.to_pixel(crate::pipeline::surface::TablePoint::new(0.2, -0.1)).to_array();
        assert_eq!(out.get(p[0].round() as i32, p[1].round() as i32), 255);
        // The lit region's centroid lies on the point, within a contact pixel.
        let (mut sx, mut sy, mut n) = (0.0, 0.0, 0.0);
        for (i, &g) in out.pixels.iter().enumerate() {
            let g = f64::from(g);
            sx += g * (i % 640) as f64;
            sy += g * (i / 640) as f64;
            n += g;
        }
        let (cx, cy) = (sx / n, sy / n);
        assert!((cx - f64::from(p[0])).abs() < 1.0 && (cy - f64::from(p[1])).abs() < 1.0, "({cx}, {cy}) vs {p:?}");
        // Outside the camera's view (beyond the far-left corner) nothing is seen.
        assert!(frame.width == 640 && out.get(0, 0) == 0);
    }
}
