//! Block-matching flow: how far the image content at a point moved since
//! the previous frame (the paper's Figure 6 input for particles).
//!
//! For a point `p` of the current frame, the flow is the displacement `d`
//! that minimises the sum of absolute differences (SAD) between the block
//! around `p` now and the block around `p - d` in the previous frame: the
//! content at `p` was at `p - d` one frame ago. The search covers a square
//! of `search_radius` around a *guess* (the pipeline predicts it from the
//! contact's tracked motion, so fast flicks need no large radius): a
//! descent from the guess, with a full scan of the square when the descent
//! ends on a poor match. The integer minimum is then refined to sub-pixel
//! by fitting a quadratic surface (a 2-D parabola) to the 3 x 3 sums of
//! squared differences around it.
//!
//! Accuracy (`tests/surface_vision.rs`, flat hand, default parameters):
//! median error 0.03 px for a 3.9 px translation and 0.04 px for a 3 degree
//! turn; without the guess, the component across the outline stays within
//! 0.05 px while the component along it is lost (median 1.2 px and 0.6 px).
//!
//! Block matching on an outline suffers the aperture problem: along a
//! straight edge every displacement parallel to it fits equally well. Each
//! candidate therefore pays a small cost for its distance from the guess
//! (see [`STRAY_COST`]), and the sub-pixel fit moves along the valley only
//! towards the guess, so the ambiguous component comes from the contact's
//! rigid motion rather than from noise. A nearly round contact turning
//! about its centroid is the extreme case: its image barely changes, so its
//! tracked turn is added along its outline
//! ([`BlockMatcher::flow_at_turning`]).

use crate::pipeline::surface::ContactImage;

/// A block matcher with fixed block size and search radius; holds the
/// candidate displacements sorted by distance from the guess.
#[derive(Debug, Clone, PartialEq)]
pub struct BlockMatcher {
    half: i32,
    radius: i32,
    /// Pixels in a block.
    pixels: u32,
    /// Candidate offsets from the guess, nearest first, with the cost added
    /// for straying that far from the guess.
    offsets: Vec<([i32; 2], u32)>,
    /// The same costs as a `(2r + 1)^2` grid, row-major from `(-r, -r)`.
    stray: Vec<u32>,
    /// One lane mask (0xff = in the block) per [`LANES`]-pixel chunk of a
    /// block row.
    masks: Vec<[u8; LANES]>,
}

/// Block rows are compared this many pixels at a time, as fixed-size
/// arrays the compiler turns into SIMD instructions (a 7-pixel row as one
/// masked 8-lane chunk). The exact shape matters: masking both pixels
/// *before* `(a - b).unsigned_abs()` on `i32` compiles to one `psadbw`;
/// `u8::abs_diff`, a mask applied after, or runtime-length slices of 7
/// stay scalar, at about six times the instructions.
const LANES: usize = 8;

/// Most chunks a block holds: blocks are at most 15 x 15 pixels (two
/// chunks per row), so a block lives on the stack.
const MAX_CHUNKS: usize = 32;

/// Largest block side [`BlockMatcher::new`] accepts.
pub const MAX_BLOCK: usize = 15;

/// One block of the current frame: masked chunks, row after row.
type Block = [[u8; LANES]; MAX_CHUNKS];

/// Sum of absolute differences of one chunk; `a` is already masked. Out of
/// line for the same reason as [`ssd8`]: whether the compiler vectorises it
/// once inlined depends on the caller (it did not inside the pipeline).
///
/// The chunks are passed by reference on purpose: by value (as clippy
/// suggests for 8-byte arrays) the same body compiles to 80 scalar
/// instructions instead of one `psadbw`.
#[inline(never)]
#[allow(clippy::trivially_copy_pass_by_ref)]
fn sad8(a: &[u8; LANES], b: &[u8; LANES], mask: &[u8; LANES]) -> u32 {
    a.iter().zip(b.iter()).zip(mask.iter()).map(|((&x, &y), &m)| (i32::from(x) - i32::from(y & m)).unsigned_abs()).sum()
}

/// Sum of squared differences of one chunk; `a` is already masked. Kept
/// out of line: inlined into [`BlockMatcher::ssd_around`]'s loops it stops
/// being vectorised and costs several times as many instructions.
/// By reference for the reason given at [`sad8`].
#[inline(never)]
#[allow(clippy::trivially_copy_pass_by_ref)]
fn ssd8(a: &[u8; LANES], b: &[u8; LANES], mask: &[u8; LANES]) -> u32 {
    a.iter()
        .zip(b.iter())
        .zip(mask.iter())
        .map(|((&x, &y), &m)| {
            let e = i32::from(x) - i32::from(y & m);
            (e * e).unsigned_abs()
        })
        .sum()
}

/// `LANES` pixels from `at`; the caller guarantees they exist.
#[inline]
fn lanes(pixels: &[u8], at: usize) -> [u8; LANES] {
    pixels[at..at + LANES].try_into().unwrap_or([0; LANES])
}

/// The eight neighbours of a candidate.
const NEIGHBOURS: [[i32; 2]; 8] = [[-1, 0], [1, 0], [0, -1], [0, 1], [-1, -1], [1, -1], [-1, 1], [1, 1]];

/// Mean absolute difference per block pixel (grey levels) above which the
/// descent's result is distrusted and the whole window is scanned. A good
/// match of a moving soft outline stays under ~10.
const EXHAUSTIVE_ABOVE: u32 = 24;

/// Cost of straying from the guess, in grey levels of absolute difference
/// per block pixel per pixel of distance. Along an outline the SAD valley
/// is nearly flat, and a rotating or deforming contact makes its floor
/// bumpy: without a price on distance the search lands on whichever bump is
/// lowest, pixels away along the outline. Crossing the outline costs about
/// the edge slope (~64 grey levels per pixel at full pressure) per block
/// pixel, far above this, so real motion across the outline still wins.
const STRAY_COST: f32 = 2.0;

impl BlockMatcher {
    /// `block_size` is rounded up to odd (a block centred on its pixel) and
    /// limited to [`MAX_BLOCK`]; `search_radius` is in pixels around the
    /// guess.
    pub fn new(block_size: usize, search_radius: usize) -> Self {
        let half = (block_size.clamp(1, MAX_BLOCK) / 2) as i32;
        let radius = search_radius as i32;
        let pixels = ((2 * half + 1) * (2 * half + 1)) as u32;
        let mut offsets: Vec<([i32; 2], u32)> = (-radius..=radius)
            .flat_map(|dy| (-radius..=radius).map(move |dx| [dx, dy]))
            .map(|[dx, dy]| {
                ([dx, dy], (STRAY_COST * pixels as f32 * ((dx * dx + dy * dy) as f32).sqrt()).round() as u32)
            })
            .collect();
        let stray = offsets.iter().map(|&(_, s)| s).collect();
        offsets.sort_by_key(|&([dx, dy], _)| (dx * dx + dy * dy, dy, dx));
        let n = (2 * half + 1) as usize;
        let masks =
            (0..n.div_ceil(LANES)).map(|c| std::array::from_fn(|i| if c * LANES + i < n { 0xff } else { 0 })).collect();
        Self { half, radius, pixels, offsets, stray, masks }
    }

    pub fn block_size(&self) -> usize {
        2 * self.half as usize + 1
    }

    pub fn search_radius(&self) -> usize {
        self.radius as usize
    }

    /// Flow at pixel `at` of `cur` since `prev` (pixels per frame), searched
    /// around `guess`. `None` when the frames differ in size or are empty.
    pub fn flow_at(&self, prev: &ContactImage, cur: &ContactImage, at: [u32; 2], guess: [f32; 2]) -> Option<[f32; 2]> {
        self.flow_at_turning(prev, cur, at, guess, [0.0, 0.0])
    }

    /// [`Self::flow_at`] for a point of a contact too round for its turn to
    /// show in the image: `hidden_turn` is the part of `guess` that its
    /// tracked turn contributes (its rigid guess minus the same without the
    /// turn). Where the outline bends within the block, the fit measures
    /// the motion along it but not that turn, so the turn is added along
    /// the outline. A fingertip patch (12 x 14 px) turning with two fingers
    /// that twist a box a quarter turn in 1.5 s: the flow alone sees no turn
    /// about each fingertip's centroid against the true 0.017 rad a frame,
    /// so its particles would rub the turning box like a pad that does not
    /// turn and brake it (`two_finger_twist`).
    pub fn flow_at_turning(
        &self,
        prev: &ContactImage,
        cur: &ContactImage,
        at: [u32; 2],
        guess: [f32; 2],
        hidden_turn: [f32; 2],
    ) -> Option<[f32; 2]> {
        let (w, h) = (cur.width, cur.height);
        if w == 0 || h == 0 || prev.width != w || prev.height != h || !guess[0].is_finite() || !guess[1].is_finite() {
            return None;
        }
        let p = [at[0] as i32, at[1] as i32];
        let centre = [guess[0].round() as i32, guess[1].round() as i32];
        // Everything the search and the refinement read, inside the frame?
        // (Rows are read in whole chunks of lanes: up to LANES - 1 extra
        // pixels on the right.)
        let reach = self.half + self.radius + 1;
        let spare = (self.masks.len() * LANES) as i32 - (2 * self.half + 1);
        let inside = |v: i32, n: usize| v - reach >= 0 && v + reach < n as i32;
        let inside_x = |v: i32| v - reach >= 0 && v + reach + spare < w as i32;
        let fast = inside_x(p[0])
            && inside(p[1], h)
            && inside_x(p[0] - centre[0])
            && inside(p[1] - centre[1], h)
            && p[0] - self.half >= 0
            && p[1] - self.half >= 0
            && p[0] + self.half < w as i32
            && p[1] + self.half < h as i32;
        let block = if fast { self.block(cur, p) } else { [[0; LANES]; MAX_CHUNKS] };
        let cost = |d: [i32; 2], bound: u32| {
            if fast { self.sad_fast(&block, prev, p, d, bound) } else { self.sad_clamped(prev, cur, p, d, bound) }
        };
        let stray = |d: [i32; 2]| {
            self.stray
                [((d[1] - centre[1] + self.radius) * (2 * self.radius + 1) + d[0] - centre[0] + self.radius) as usize]
        };
        // Descent from the guess: move to the cheapest of the eight
        // neighbours while that lowers the cost. The soft outline makes the
        // cost unimodal over a few pixels, so this finds the minimum with
        // ~10-20 block comparisons where a full scan of the window needs
        // (2r + 1)^2 (49 at r = 3).
        let mut best = centre;
        let mut best_cost = cost(centre, u32::MAX);
        loop {
            let from = best;
            for o in NEIGHBOURS {
                let d = [from[0] + o[0], from[1] + o[1]];
                if (d[0] - centre[0]).abs() > self.radius || (d[1] - centre[1]).abs() > self.radius {
                    continue;
                }
                let s = stray(d);
                if s >= best_cost {
                    continue;
                }
                let c = cost(d, best_cost - s).saturating_add(s);
                if c < best_cost {
                    best_cost = c;
                    best = d;
                }
            }
            if best == from {
                break;
            }
        }
        // A poor match means the descent may sit in a local minimum (the
        // guess was far off, or two outlines meet): scan the whole window.
        if best_cost > EXHAUSTIVE_ABOVE * self.pixels {
            for &(o, s) in &self.offsets {
                if s >= best_cost {
                    // Offsets come nearest first: none further can win.
                    break;
                }
                let d = [centre[0] + o[0], centre[1] + o[1]];
                let c = cost(d, best_cost - s).saturating_add(s);
                if c < best_cost {
                    best_cost = c;
                    best = d;
                }
            }
        }
        // Sub-pixel: squared differences, not absolute ones. Near its
        // minimum SAD is V-shaped (a sum of |slope * error|), and a
        // parabola through a V is biased towards whole pixels, badly so in
        // the diagonal valleys of oblique outlines; SSD over the soft
        // outline is a true quadratic there, so the parabola fits.
        let costs = if fast {
            self.ssd_around(&block, prev, p, best)
        } else {
            let at = |dx: i32, dy: i32| self.ssd_clamped(prev, cur, p, [best[0] + dx, best[1] + dy]);
            [[at(-1, -1), at(0, -1), at(1, -1)], [at(-1, 0), at(0, 0), at(1, 0)], [at(-1, 1), at(0, 1), at(1, 1)]]
        };
        let towards_guess = [guess[0] - best[0] as f32, guess[1] - best[1] as f32];
        let delta = refine(costs, towards_guess, self.radius as f32 + 1.0, hidden_turn);
        let flow = [best[0] as f32 + delta[0], best[1] as f32 + delta[1]];
        Some(flow)
    }

    /// The block of `cur` around `p` as masked chunks of lanes, row after
    /// row: read once per point, compared with many blocks of `prev`.
    fn block(&self, cur: &ContactImage, p: [i32; 2]) -> Block {
        let w = cur.width;
        let chunks = self.masks.len();
        let (cx, cy) = ((p[0] - self.half) as usize, (p[1] - self.half) as usize);
        let mut block = [[0u8; LANES]; MAX_CHUNKS];
        for k in 0..self.rows() {
            for c in 0..chunks {
                let a = lanes(&cur.pixels, (cy + k) * w + cx + c * LANES);
                let mask = self.masks[c];
                block[k * chunks + c] = std::array::from_fn(|i| a[i] & mask[i]);
            }
        }
        block
    }

    fn rows(&self) -> usize {
        2 * self.half as usize + 1
    }

    /// SAD between `block` (from [`Self::block`] at `p`) and the block at
    /// `p - d` in `prev`, all inside the frame (with [`LANES`] - 1 pixels to
    /// spare on the right); stops once it reaches `bound`.
    fn sad_fast(&self, block: &Block, prev: &ContactImage, p: [i32; 2], d: [i32; 2], bound: u32) -> u32 {
        let w = prev.width;
        let chunks = self.masks.len();
        let (qx, qy) = ((p[0] - d[0] - self.half) as usize, (p[1] - d[1] - self.half) as usize);
        let mut sum = 0u32;
        for k in 0..self.rows() {
            let rb = (qy + k) * w + qx;
            for c in 0..chunks {
                sum += sad8(&block[k * chunks + c], &lanes(&prev.pixels, rb + c * LANES), &self.masks[c]);
            }
            if sum >= bound {
                break;
            }
        }
        sum
    }

    /// Sums of squared differences between `block` and the blocks of `prev`
    /// at `p - (d + (dx, dy))` for the 3 x 3 `(dx, dy)` around `d`, as
    /// `[row dy][column dx]`; one pass over the block rows.
    fn ssd_around(&self, block: &Block, prev: &ContactImage, p: [i32; 2], d: [i32; 2]) -> [[f32; 3]; 3] {
        let w = prev.width;
        let chunks = self.masks.len();
        // Origin of the prev block for the centre displacement; a
        // displacement one more to the right reads one pixel further left.
        let (qx, qy) = ((p[0] - d[0] - self.half) as usize, (p[1] - d[1] - self.half) as usize);
        let mut sums = [[0u32; 3]; 3];
        for k in 0..self.rows() {
            for c in 0..chunks {
                let a = &block[k * chunks + c];
                let mask = &self.masks[c];
                for (j, row) in sums.iter_mut().enumerate() {
                    // One read covers the three horizontal displacements;
                    // the one for dx = +1 starts leftmost.
                    let start = (qy + k + 1 - j) * w + qx - 1 + c * LANES;
                    let Some(window) = prev.pixels.get(start..start + LANES + 2) else {
                        continue;
                    };
                    for (i, sum) in row.iter_mut().enumerate() {
                        let b: &[u8; LANES] = window[2 - i..2 - i + LANES].try_into().unwrap_or(&[0; LANES]);
                        *sum += ssd8(a, b, mask);
                    }
                }
            }
        }
        sums.map(|row| row.map(|v| v as f32))
    }

    /// The same near the image border, replicating border pixels.
    fn ssd_clamped(&self, prev: &ContactImage, cur: &ContactImage, p: [i32; 2], d: [i32; 2]) -> f32 {
        let (w, h) = (cur.width as i32, cur.height as i32);
        let at = |img: &ContactImage, x: i32, y: i32| {
            i32::from(img.pixels[(y.clamp(0, h - 1) * w + x.clamp(0, w - 1)) as usize])
        };
        let mut sum = 0i64;
        for dy in -self.half..=self.half {
            for dx in -self.half..=self.half {
                let e = at(cur, p[0] + dx, p[1] + dy) - at(prev, p[0] - d[0] + dx, p[1] - d[1] + dy);
                sum += i64::from(e * e);
            }
        }
        sum as f32
    }

    /// The same near the image border, replicating border pixels.
    fn sad_clamped(&self, prev: &ContactImage, cur: &ContactImage, p: [i32; 2], d: [i32; 2], bound: u32) -> u32 {
        let (w, h) = (cur.width as i32, cur.height as i32);
        let at = |img: &ContactImage, x: i32, y: i32| img.pixels[(y.clamp(0, h - 1) * w + x.clamp(0, w - 1)) as usize];
        let mut sum = 0u32;
        for dy in -self.half..=self.half {
            for dx in -self.half..=self.half {
                let a = at(cur, p[0] + dx, p[1] + dy);
                let b = at(prev, p[0] - d[0] + dx, p[1] - d[1] + dy);
                sum += u32::from(a.abs_diff(b));
            }
            if sum >= bound {
                break;
            }
        }
        sum
    }
}

/// Sub-pixel offset of the cost minimum from the 3 x 3 costs around the
/// integer minimum (`costs[row][column]`, centre = minimum).
///
/// Fits `c(d) = c0 + g.d + d.H.d / 2` by finite differences and moves to
/// its minimum, `-H^-1 g`, but only along the eigenvectors of `H` with a
/// clear curvature (at most a pixel), plus `hidden_turn` along the second
/// (see [`BlockMatcher::flow_at_turning`]). Along an outline the cost is a
/// valley (the aperture problem): there the fit knows nothing, and the
/// offset along the valley is `towards_guess` (the guess minus the integer
/// minimum) projected on it. The projection is not clamped to a pixel: on a
/// slanted outline the integer grid meets the valley floor at points that
/// can lie several pixels along it from the guess, and this is how the
/// estimate slides back.
fn refine(costs: [[f32; 3]; 3], towards_guess: [f32; 2], max_slide: f32, hidden_turn: [f32; 2]) -> [f32; 2] {
    let c0 = costs[1][1];
    let g = [0.5 * (costs[1][2] - costs[1][0]), 0.5 * (costs[2][1] - costs[0][1])];
    let hxx = costs[1][2] + costs[1][0] - 2.0 * c0;
    let hyy = costs[2][1] + costs[0][1] - 2.0 * c0;
    let hxy = 0.25 * (costs[2][2] - costs[2][0] - costs[0][2] + costs[0][0]);
    // Eigen-decomposition of the symmetric 2 x 2 curvature.
    let mean = 0.5 * (hxx + hyy);
    let spread = (0.25 * (hxx - hyy).powi(2) + hxy * hxy).sqrt();
    let (big, small) = (mean + spread, mean - spread);
    if big <= 0.0 {
        return [0.0, 0.0];
    }
    let v_big = if spread > 0.0 {
        let (x, y) = if hxx >= hyy { (big - hyy, hxy) } else { (hxy, big - hxx) };
        let n = x.hypot(y);
        [x / n, y / n]
    } else {
        [1.0, 0.0]
    };
    let v_small = [-v_big[1], v_big[0]];
    let newton = |v: [f32; 2], lambda: f32| (-(v[0] * g[0] + v[1] * g[1]) / lambda).clamp(-1.0, 1.0);
    let across = newton(v_big, big);
    let along = if small > 0.05 * big {
        newton(v_small, small) + v_small[0] * hidden_turn[0] + v_small[1] * hidden_turn[1]
    } else {
        (v_small[0] * towards_guess[0] + v_small[1] * towards_guess[1]).clamp(-max_slide, max_slide)
    };
    [across * v_big[0] + along * v_small[0], across * v_big[1] + along * v_small[1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A smooth blob: a bright disc with a linear ramp at its edge.
    fn disc(w: usize, h: usize, c: [f32; 2], r: f32) -> ContactImage {
        let mut img = ContactImage::new(w, h);
        for y in 0..h {
            for x in 0..w {
                let d = (x as f32 - c[0]).hypot(y as f32 - c[1]) - r;
                img.pixels[y * w + x] = (255.0 * (0.5 - d / 4.0).clamp(0.0, 1.0)).round() as u8;
            }
        }
        img
    }

    /// Two frames of a `size` × `size` image: a disc of radius `r` at
    /// `from`, then at `to`.
    fn moved_disc(size: usize, from: [f32; 2], to: [f32; 2], r: f32) -> (ContactImage, ContactImage) {
        (disc(size, size, from, r), disc(size, size, to, r))
    }

    /// The 3 x 3 costs of `c(d) = big/2 (d.n)^2 + small/2 (d.t - along)^2`
    /// for the unit vectors `n` (across) and `t` (along).
    fn valley(big: f32, small: f32, n: [f32; 2], along: f32) -> [[f32; 3]; 3] {
        let t = [-n[1], n[0]];
        std::array::from_fn(|row| {
            std::array::from_fn(|col| {
                let d = [col as f32 - 1.0, row as f32 - 1.0];
                let (a, b) = (d[0] * n[0] + d[1] * n[1], d[0] * t[0] + d[1] * t[1] - along);
                1000.0 + 0.5 * big * a * a + 0.5 * small * b * b
            })
        })
    }

    #[test]
    fn a_hidden_turn_is_added_along_a_bending_outline_only() {
        let n = [0.6f32, 0.8];
        let t = [-n[1], n[0]];
        let along = |v: [f32; 2]| v[0] * t[0] + v[1] * t[1];
        let across = |v: [f32; 2]| v[0] * n[0] + v[1] * n[1];
        let turn = [t[0] * 0.1, t[1] * 0.1];
        let guess = [t[0] * 0.6, t[1] * 0.6];
        // A bending outline: the fit's own minimum along it (0.2), plus the
        // turn it cannot see (0.1); the guess plays no part.
        let d = refine(valley(100.0, 40.0, n, 0.2), guess, 4.0, turn);
        assert!((along(d) - 0.3).abs() < 1e-3 && across(d).abs() < 1e-3, "{d:?}");
        let d = refine(valley(100.0, 40.0, n, 0.2), guess, 4.0, [0.0, 0.0]);
        assert!((along(d) - 0.2).abs() < 1e-3, "{d:?}");
        // A straight outline: the guess alone, which already holds the turn.
        let d = refine(valley(100.0, 1.0, n, 0.2), guess, 4.0, turn);
        assert!((along(d) - 0.6).abs() < 1e-3 && across(d).abs() < 1e-3, "{d:?}");
    }

    #[test]
    fn recovers_a_sub_pixel_shift_at_the_outline() {
        let (prev, cur) = moved_disc(64, [30.0, 30.0], [31.4, 28.7], 10.0);
        let m = BlockMatcher::new(7, 3);
        // A point of the outline the motion crosses head-on: the whole
        // vector is observable.
        let f = m.flow_at(&prev, &cur, [38, 23], [0.0, 0.0]).expect("same size");
        assert!((f[0] - 1.4).abs() < 0.25 && (f[1] + 1.3).abs() < 0.25, "{f:?}");
        // Where the outline runs along the motion only the normal component
        // is observable (aperture problem): check that one.
        let f = m.flow_at(&prev, &cur, [24, 21], [0.0, 0.0]).expect("same size");
        let n = [-7.4f32 / 10.7, -7.7 / 10.7];
        let normal = |v: [f32; 2]| v[0] * n[0] + v[1] * n[1];
        assert!((normal(f) - normal([1.4, -1.3])).abs() < 0.2, "{f:?}");
        // A large motion is found from a good guess with a small radius.
        let far = disc(64, 64, [40.0, 30.0], 10.0);
        // There the outline is vertical: the vertical component is not
        // observable and follows the guess.
        let f = m.flow_at(&prev, &far, [31, 30], [9.0, 0.3]).expect("same size");
        assert!((f[0] - 10.0).abs() < 0.2 && (f[1] - 0.3).abs() < 0.1, "{f:?}");
    }

    #[test]
    fn borders_and_mismatched_frames() {
        let (prev, cur) = moved_disc(16, [2.0, 2.0], [3.0, 2.0], 4.0);
        let m = BlockMatcher::new(7, 4);
        let f = m.flow_at(&prev, &cur, [7, 2], [0.0, 0.0]).expect("same size");
        assert!((f[0] - 1.0).abs() < 0.3, "{f:?}");
        assert!(m.flow_at(&prev, &ContactImage::new(8, 8), [0, 0], [0.0, 0.0]).is_none());
        let one = ContactImage::new(1, 1);
        assert_eq!(m.flow_at(&one, &one, [0, 0], [0.0, 0.0]), Some([0.0, 0.0]));
    }
}
