//! Rasterization of hands into the contact image.
//!
//! Each patch is evaluated only inside its own bounding box (grown by half
//! the edge falloff), as a signed distance per pixel centre; overlapping
//! patches combine by maximum, so the result does not depend on their order
//! and a hand is the union of its parts.

use rand::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;

use std::ops::Range;

use super::footprint::Patch;
use super::hand::Hand;
use super::image::ContactImage;
use super::sensor::{Sensor, TablePoint};

/// Additive sensor noise: every pixel gets a uniform integer in
/// `-amplitude..=amplitude` (clamped to 0..=255), drawn from a `ChaCha8Rng`
/// seeded with `seed`. The same seed gives the same image.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Noise {
    pub seed: u64,
    pub amplitude: u8,
}

/// How the contact image is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RasterParams {
    /// Width of the soft edge in pixels, centred on the outline: the grey
    /// is half the touch level exactly on the outline and reaches full and
    /// zero `falloff_px / 2` inside and outside. Diffuse illumination blurs
    /// the outline over a few pixels; a non-zero width is also what gives
    /// the Sobel stage a gradient and block matching sub-pixel accuracy.
    pub falloff_px: f32,
    /// Optional sensor noise over the whole frame.
    pub noise: Option<Noise>,
}

impl Default for RasterParams {
    fn default() -> Self {
        Self { falloff_px: 4.0, noise: None }
    }
}

/// Draws `hands` into a new image of the sensor's size.
pub fn rasterize(hands: &[Hand], sensor: &Sensor, params: &RasterParams) -> ContactImage {
    let mut image = ContactImage::new(sensor.width_px as usize, sensor.height_px as usize);
    draw(hands, sensor, params, &mut image);
    image
}

/// Draws `hands` into `image`, resizing it to the sensor and clearing it
/// first; reuses the allocation from frame to frame.
pub fn rasterize_into(hands: &[Hand], sensor: &Sensor, params: &RasterParams, image: &mut ContactImage) {
    let all = 0..sensor.height_px as usize;
    rasterize_rows(hands, sensor, params, image, all);
}

/// As [`rasterize_into`], for an image that is black outside the rows
/// `lit` (what the previous call returned): only those rows are cleared.
/// Returns the rows this frame lit (possibly empty), for the next call and
/// for the vision pipeline (its `process_rows`).
///
/// Why: whole hands are drawn every frame of a study, and clearing,
/// thresholding, labelling and copying the whole 640×480 image each frame
/// would take a large share of a study's CPU (`perf record` on a
/// 2-participant run: memset, memmove, `find_blobs`, `process_with`).
pub fn rasterize_rows(
    hands: &[Hand],
    sensor: &Sensor,
    params: &RasterParams,
    image: &mut ContactImage,
    lit: Range<usize>,
) -> Range<usize> {
    let (w, h) = (sensor.width_px as usize, sensor.height_px as usize);
    if image.width != w || image.height != h || image.pixels.len() != w * h {
        *image = ContactImage::new(w, h);
    } else {
        let (r0, r1) = (lit.start.min(h), lit.end.min(h));
        if r0 < r1 {
            image.pixels[r0 * w..r1 * w].fill(0);
        }
    }
    draw(hands, sensor, params, image)
}

/// Draws bare patches at full pressure (their `level` sets the grey): for
/// known-answer tests with exact shapes, and for tangibles defined outside
/// [`Hand`].
pub fn rasterize_patches(patches: &[Patch], sensor: &Sensor, params: &RasterParams) -> ContactImage {
    let mut image = ContactImage::new(sensor.width_px as usize, sensor.height_px as usize);
    for patch in patches {
        let _ = draw_patch(patch, 1.0, sensor, params.falloff_px, &mut image);
    }
    if let Some(noise) = params.noise {
        add_noise(&mut image, noise);
    }
    image
}

/// Draws the hands; returns the rows it may have lit.
fn draw(hands: &[Hand], sensor: &Sensor, params: &RasterParams, image: &mut ContactImage) -> Range<usize> {
    let mut lit: Option<Range<usize>> = None;
    let mut patches = Vec::with_capacity(8);
    for hand in hands {
        let pressure = hand.pressure.clamp(0.0, 1.0);
        if pressure.is_nan() || pressure == 0.0 {
            continue;
        }
        patches.clear();
        hand.push_patches(&mut patches);
        let grow = |lit: Option<Range<usize>>, rows: Range<usize>| {
            Some(lit.map_or(rows.clone(), |l| l.start.min(rows.start)..l.end.max(rows.end)))
        };
        for patch in &patches {
            if let Some(rows) = draw_patch(patch, pressure, sensor, params.falloff_px, image) {
                lit = grow(lit, rows);
            }
        }
        if let Some(rows) =
            hand.outline_rings().and_then(|r| draw_outline(&r, pressure, sensor, params.falloff_px, image))
        {
            lit = grow(lit, rows);
        }
    }
    if let Some(noise) = params.noise {
        add_noise(image, noise);
        // Noise lights any pixel.
        return 0..image.height;
    }
    lit.unwrap_or(0..0)
}

/// The columns `[c0, c1]` and rows `[r0, r1]` (inclusive) of the pixels
/// whose centres may lie within `reach` of the table box `lo..hi`; `None`
/// when the box is not finite or misses the image.
fn pixel_window(
    lo: [f32; 2],
    hi: [f32; 2],
    reach: f32,
    sensor: &Sensor,
    image: &ContactImage,
) -> Option<([usize; 2], [usize; 2])> {
    if !(lo[0].is_finite() && lo[1].is_finite() && hi[0].is_finite() && hi[1].is_finite()) {
        return None;
    }
    // Pixel rows grow as y falls: the top of the box is the first row.
    let a = sensor.to_pixel(TablePoint::new(lo[0] - reach, hi[1] + reach)).to_array();
    let b = sensor.to_pixel(TablePoint::new(hi[0] + reach, lo[1] - reach)).to_array();
    let max_c = image.width as f32 - 1.0;
    let max_r = image.height as f32 - 1.0;
    if b[0] < 0.0 || b[1] < 0.0 || a[0] > max_c || a[1] > max_r {
        return None;
    }
    let (c0, c1) = (a[0].ceil().max(0.0) as usize, b[0].floor().min(max_c) as usize);
    let (r0, r1) = (a[1].ceil().max(0.0) as usize, b[1].floor().min(max_r) as usize);
    (c0 <= c1 && r0 <= r1).then_some(([c0, c1], [r0, r1]))
}

/// What drawing one shape shares: its peak grey and soft edge, and the
/// pixels its box may touch, with where their centres lie on the table.
struct Brush {
    peak: f32,
    /// Width of the soft edge (m), centred on the shape's edge.
    falloff: f32,
    /// Inclusive columns and rows of the pixels within reach of the box
    /// (see [`pixel_window`]).
    window: ([usize; 2], [usize; 2]),
    /// The centre of pixel (0, 0) on the table (m); rows go down y.
    origin: [f32; 2],
    /// The pixel size (m).
    size: [f32; 2],
}

impl Brush {
    /// A brush for a shape within the table box `lo..hi` drawn at `peak`;
    /// `None` when the image is empty or the box misses it.
    fn new(
        peak: f32,
        [lo, hi]: [[f32; 2]; 2],
        sensor: &Sensor,
        falloff_px: f32,
        image: &ContactImage,
    ) -> Option<Brush> {
        if image.width == 0 || image.height == 0 {
            return None;
        }
        let falloff = falloff_px.max(1e-3) * sensor.metres_per_pixel();
        let reach = 0.5 * falloff;
        let window = pixel_window(lo, hi, reach, sensor, image)?;
        let size = sensor.pixel_size();
        let origin = [-0.5 * sensor.table_width_m + 0.5 * size[0], 0.5 * sensor.table_depth_m - 0.5 * size[1]];
        Some(Brush { peak, falloff, window, origin, size })
    }

    /// Half the falloff: pixels further outside the shape stay dark.
    fn reach(&self) -> f32 {
        0.5 * self.falloff
    }

    /// Table x of column `c`'s pixel centres.
    fn x(&self, c: usize) -> f32 {
        self.origin[0] + c as f32 * self.size[0]
    }

    /// Table y of row `r`'s pixel centres.
    fn y(&self, r: usize) -> f32 {
        self.origin[1] - r as f32 * self.size[1]
    }

    /// The grey at signed distance `d` (m) from the edge, negative inside:
    /// half the peak on the edge, smoothstepped across the falloff; `None`
    /// beyond reach outside.
    fn grey(&self, d: f32) -> Option<u8> {
        if d >= self.reach() {
            return None;
        }
        let t = (0.5 - d / self.falloff).clamp(0.0, 1.0);
        Some(grey_level(self.peak * t * t * (3.0 - 2.0 * t)))
    }
}

/// `v.round() as u8` (half away from zero, saturating), without the libm
/// call `round` compiles to on baseline x86-64: it runs once per drawn
/// pixel, where a libm call costs a few per cent of a frame (`perf` on the
/// frame benchmark). For
/// `0 <= v < 2^23` the fraction `v - trunc(v)` is exact, so the comparison
/// with one half decides as `round` does; `v + 0.5` truncated would not
/// (`0.49999997 + 0.5` rounds to 1.0 in f32). It equals `round` on all 2^32
/// f32 bit patterns, NaN and infinities included.
#[inline]
fn grey_level(v: f32) -> u8 {
    // `as` saturates: NaN and negatives give 0, 2^23 and above are whole
    // numbers already, and above u32::MAX the sum must not wrap.
    let whole = v as u32;
    let up = u32::from(v - whole as f32 >= 0.5);
    whole.saturating_add(up).min(255) as u8
}

/// Draws one patch; returns the rows it covered (`None`: off the image).
fn draw_patch(
    patch: &Patch,
    pressure: f32,
    sensor: &Sensor,
    falloff_px: f32,
    image: &mut ContactImage,
) -> Option<Range<usize>> {
    let peak = 255.0 * pressure * patch.level.clamp(0.0, 1.0);
    let brush = Brush::new(peak, patch.shape.bounds(), sensor, falloff_px, image)?;
    let ([c0, c1], [r0, r1]) = brush.window;
    let shape = patch.shape.prepare();
    for r in r0..=r1 {
        let y = brush.y(r);
        let row = &mut image.pixels[r * image.width..(r + 1) * image.width];
        for (c, px) in row.iter_mut().enumerate().take(c1 + 1).skip(c0) {
            if let Some(grey) = brush.grey(shape.distance([brush.x(c), y])) {
                *px = (*px).max(grey);
            }
        }
    }
    (r0 <= r1).then_some(r0..r1 + 1)
}

/// Draws an outline's rings (table metres, even-odd, see
/// [`super::Outline`]) with the soft edge every patch gets: the grey is a
/// function of the signed distance to the nearest edge, half the level on
/// the outline. Returns the rows it covered (`None`: off the image).
///
/// Inside/outside comes from one even-odd scan per row; the distance only
/// matters within half the falloff of an edge, so it is computed per edge
/// over that edge's own band of pixels and not per pixel over every edge
/// (a hand's few hundred contour points would make that the frame's
/// largest cost).
fn draw_outline(
    rings: &[Vec<[f32; 2]>],
    pressure: f32,
    sensor: &Sensor,
    falloff_px: f32,
    image: &mut ContactImage,
) -> Option<Range<usize>> {
    let mut lo = [f32::MAX; 2];
    let mut hi = [f32::MIN; 2];
    for p in rings.iter().flatten() {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let brush = Brush::new(255.0 * pressure, [lo, hi], sensor, falloff_px, image)?;
    let (reach, ([c0, c1], [r0, r1])) = (brush.reach(), brush.window);
    let (w, h) = (c1 - c0 + 1, r1 - r0 + 1);
    // Unsigned distance to the nearest edge, capped at `reach`.
    let mut near = vec![reach; w * h];
    for ring in rings {
        let mut j = ring.len() - 1;
        for i in 0..ring.len() {
            let (p, q) = (ring[j], ring[i]);
            j = i;
            let ea = sensor.to_pixel(TablePoint::new(p[0].min(q[0]) - reach, p[1].max(q[1]) + reach)).to_array();
            let eb = sensor.to_pixel(TablePoint::new(p[0].max(q[0]) + reach, p[1].min(q[1]) - reach)).to_array();
            let ec0 = (ea[0].ceil().max(c0 as f32) as usize).min(c1 + 1);
            let ec1 = eb[0].floor().min(c1 as f32);
            let er0 = (ea[1].ceil().max(r0 as f32) as usize).min(r1 + 1);
            let er1 = eb[1].floor().min(r1 as f32);
            if ec1 < ec0 as f32 || er1 < er0 as f32 {
                continue;
            }
            let pq = [q[0] - p[0], q[1] - p[1]];
            let len2 = pq[0] * pq[0] + pq[1] * pq[1];
            let inv = if len2 > 0.0 { 1.0 / len2 } else { 0.0 };
            for r in er0..=er1 as usize {
                let y = brush.y(r);
                let row = &mut near[(r - r0) * w..(r - r0 + 1) * w];
                for c in ec0..=ec1 as usize {
                    let ap = [brush.x(c) - p[0], y - p[1]];
                    let t = ((ap[0] * pq[0] + ap[1] * pq[1]) * inv).clamp(0.0, 1.0);
                    let d = ((ap[0] - t * pq[0]).powi(2) + (ap[1] - t * pq[1]).powi(2)).sqrt();
                    let slot = &mut row[c - c0];
                    *slot = slot.min(d);
                }
            }
        }
    }
    let mut crossings: Vec<f32> = Vec::new();
    for r in r0..=r1 {
        let y = brush.y(r);
        crossings.clear();
        for ring in rings {
            let mut j = ring.len() - 1;
            for i in 0..ring.len() {
                let (p, q) = (ring[j], ring[i]);
                j = i;
                if (p[1] <= y) != (q[1] <= y) {
                    crossings.push(p[0] + (y - p[1]) * (q[0] - p[0]) / (q[1] - p[1]));
                }
            }
        }
        crossings.sort_unstable_by(f32::total_cmp);
        let row = &mut image.pixels[r * image.width..(r + 1) * image.width];
        let distances = &near[(r - r0) * w..(r - r0 + 1) * w];
        // Crossings left of the pixel centre so far: odd = inside.
        let mut passed = 0;
        for c in c0..=c1 {
            let x = brush.x(c);
            while passed < crossings.len() && crossings[passed] <= x {
                passed += 1;
            }
            let unsigned = distances[c - c0];
            let d = if passed % 2 == 1 { -unsigned } else { unsigned };
            if let Some(grey) = brush.grey(d) {
                row[c] = row[c].max(grey);
            }
        }
    }
    Some(r0..r1 + 1)
}

fn add_noise(image: &mut ContactImage, noise: Noise) {
    if noise.amplitude == 0 {
        return;
    }
    let mut rng = ChaCha8Rng::seed_from_u64(noise.seed);
    let a = u32::from(noise.amplitude);
    // One 64-bit draw gives four pixels 16 random bits each, scaled to
    // 0..=2a by multiply-and-shift (bias below 1/256 of a grey level):
    // a per-pixel `random_range` made noise cost more than drawing hands.
    for chunk in image.pixels.chunks_mut(4) {
        let bits = rng.next_u64();
        for (k, px) in chunk.iter_mut().enumerate() {
            let r = ((bits >> (16 * k)) & 0xffff) as u32;
            let n = ((r * (2 * a + 1)) >> 16) as i32 - a as i32;
            *px = (i32::from(*px) + n).clamp(0, 255) as u8;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::surface::HandKind;

    #[test]
    fn pressure_sets_the_grey_level() {
        let sensor = Sensor::default();
        let full = rasterize(&[Hand::new(1, HandKind::Fist, 0.0, 0.0)], &sensor, &RasterParams::default());
        let half =
            rasterize(&[Hand::new(1, HandKind::Fist, 0.0, 0.0).with_pressure(0.5)], &sensor, &RasterParams::default());
        assert_eq!(full.pixels.iter().max(), Some(&255));
        assert_eq!(half.pixels.iter().max(), Some(&128));
    }

    #[test]
    fn off_table_hands_draw_nothing_and_do_not_panic() {
        let sensor = Sensor::default();
        let far = Hand::new(1, HandKind::Forearm, 5.0, -3.0);
        let nan = Hand::new(2, HandKind::FlatHand, f32::NAN, 0.0);
        let image = rasterize(&[far, nan], &sensor, &RasterParams::default());
        assert!(image.is_blank());
    }

    /// A square outline is drawn as the square footprint with sharp
    /// corners is: the same inside, the same soft edge (both are exact
    /// distances), so vision sees a contour hand as it sees a template.
    #[test]
    fn an_outline_draws_like_the_same_footprint() {
        use crate::pipeline::surface::{Footprint, Outline, Patch};
        let sensor = Sensor::default();
        let params = RasterParams::default();
        let ring = vec![[0.05, -0.02], [0.13, -0.02], [0.13, 0.04], [0.05, 0.04]];
        let hand = Hand::contour(1, &Outline::new(vec![ring]).expect("valid"));
        let drawn = rasterize(&[hand], &sensor, &params);
        let rect = Footprint::RoundedRect { centre: [0.09, 0.01], half: [0.04, 0.03], angle: 0.0, corner: 0.0 };
        let reference = rasterize_patches(&[Patch { shape: rect, level: 1.0 }], &sensor, &params);
        let worst = drawn.pixels.iter().zip(&reference.pixels).map(|(a, b)| a.abs_diff(*b)).max();
        assert!(worst <= Some(1), "largest difference {worst:?} grey levels");
        // 8 × 6 cm at 1.5625 mm pixels: about 51 × 38 = 1966 pixels at half grey or more.
        let lit = drawn.pixels.iter().filter(|&&p| p >= 128).count();
        assert!((1900..=2050).contains(&lit), "{lit} pixels");
    }

    #[test]
    fn grey_levels_round_as_f32_round_does() {
        let mut values = vec![0.0, 0.5, 1.5, 2.5, 0.499_999_97, 254.5, 254.499_98, 255.0, 255.5, 256.0];
        values.extend([1e9, 5e9, f32::MAX, -0.4, -3.0]);
        values.extend([f32::NAN, f32::INFINITY, f32::NEG_INFINITY, f32::MIN_POSITIVE, 8_388_607.5, 8_388_608.0]);
        // Every f32 between 0 and 300 whose bits end in 12 zeros, and the
        // neighbours of every half.
        let (lo, hi) = (0.0f32.to_bits(), 300.0f32.to_bits());
        values.extend((lo..=hi).step_by(4096).map(f32::from_bits));
        for k in 0..600 {
            let half = k as f32 + 0.5;
            values.extend([half.next_down(), half, half.next_up()]);
        }
        for v in values {
            assert_eq!(grey_level(v), v.round() as u8, "{v:e}");
        }
    }

    #[test]
    fn an_outline_with_a_hole_leaves_it_dark_and_pressure_sets_its_grey() {
        use crate::pipeline::surface::Outline;
        let sensor = Sensor::default();
        let square = |h: f32| vec![[-h, -h], [h, -h], [h, h], [-h, h]];
        let mut hand = Hand::contour(1, &Outline::new(vec![square(0.1), square(0.04)]).expect("valid"));
        hand.pressure = 0.6;
        let image = rasterize(&[hand], &sensor, &RasterParams::default());
        let at = |p: [f32; 2]| {
            let [c, r] = sensor.to_pixel(TablePoint::from(p)).to_array();
            image.pixels[r.round() as usize * image.width + c.round() as usize]
        };
        assert_eq!(at([0.0, 0.0]), 0, "the hole");
        assert_eq!(at([0.07, 0.0]), 153, "between the contours: 0.6 of 255");
        assert_eq!(at([0.15, 0.0]), 0, "outside");
        // A soft edge, as every patch has: the pixel the outline runs through is grey.
        let edge = at([0.1, 0.0]);
        assert!(edge > 0 && edge < 153, "{edge}");
    }

    #[test]
    fn noise_is_deterministic() {
        let sensor = Sensor::new(64, 48, 1.0, 0.75);
        let params = RasterParams { noise: Some(Noise { seed: 7, amplitude: 5 }), ..RasterParams::default() };
        let a = rasterize(&[], &sensor, &params);
        let b = rasterize(&[], &sensor, &params);
        assert_eq!(a, b);
        assert!(!a.is_blank());
        assert!(a.pixels.iter().all(|&p| p <= 5));
    }
}
