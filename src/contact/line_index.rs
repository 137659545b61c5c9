//! An index over a convex block's edge lines, for the queries a
//! [`CachedBlock`](super::cached::CachedBlock) answers at many points: an
//! edge near a query point's direction in O(1), and the edge with the
//! largest plane distance `g_k(q) = n_k · (q − s_k)` in O(√n) instead of
//! O(n).
//!
//! **The guess.** A table of the edges by the direction of their outward
//! normals, in equal steps of a pseudo-angle (`y / (|x| + |y|)`, folded to
//! a full turn: monotone in the angle and free of trigonometry), gives the
//! edge whose normal points where `q` lies as seen from an interior point.
//! That edge faces `q` when `q` is well outside; it is only ever a starting
//! point. Nearer the interior point than the nearest edge line, no edge
//! faces `q`, and no guess is made.
//!
//! **The deepest edge.** Inside the block the edge with the largest plane
//! distance gives the penetration depth, and no binary search finds it: the
//! depth is not unimodal around the boundary (a rectangle has two minima,
//! one per long side). It is found by branch and bound over buckets of
//! about `√n` consecutive edges. A bucket keeps a centre `p` (the point at
//! equal plane distance from its first, middle and last lines), the largest
//! plane distance `top` of its edges at `p`, and the arc its normals sweep
//! (a middle direction `c`, half-angle `α`). For each of its edges,
//!
//! ```text
//! g_k(q) = g_k(p) + n_k · (q − p)  ≤  top + max over the arc of u · (q − p)
//!                                  ≤  top + (a, or a cos α if a < 0) + |b| sin α
//! ```
//!
//! with `a`, `b` the components of `q − p` along `c` and across it. Where
//! the bucket's lines touch a circle about `p` (a boundary that is round at
//! that scale) the bound is within a few `α²` of the bucket's true largest
//! plane distance, and it takes no square root. The bounds are kept in
//! single precision, sixteen buckets to a group, so that a group is a few
//! vector instructions. A query bounds a group, measures the bucket with
//! the highest bound, then measures only the buckets whose bound still
//! reaches the best found: usually none. Where many edges tie (the centre
//! of a regular polygon) every bucket is measured, as it must be.
//!
//! The edge found is exactly the one a linear pass finds, the first of the
//! largest: every plane distance is computed by the same expression as
//! [`ContactEdge::plane_distance`], ties go to the lower index, and a bucket
//! is skipped only when its bound is below the best by a margin (1e-5 of
//! the scale) far larger than any rounding of the bound, single precision
//! included.
//!
//! Building is O(n): a pseudo-angle and a dot product per edge, a small
//! linear solve per bucket. Why buckets and not a deeper tree or the
//! block's medial axis: docs/design/contact-theory.md.

use super::entrance_block::ContactEdge;
use super::vec2::{Vec2, mean};

/// A bucket is skipped only when its bound is below the best plane
/// distance by this much of the scale (`|q − o|` plus the block's radius
/// about `o`): far above the rounding of bounds kept in single precision.
const MARGIN: f64 = 1e-5;

/// The index over one block's edges (see the module docs).
#[derive(Clone, Debug)]
pub(crate) struct LineIndex {
    /// The edges' outward unit normals and start points, contiguous for
    /// the bucket scans, padded to whole groups (see [`LineIndex::new`]).
    normals: Vec<Vec2>,
    starts: Vec<Vec2>,
    /// The number of edges.
    edges: usize,
    /// The interior point directions are measured from.
    origin: Vec2,
    /// The farthest corner from `origin`: the scale of the margin.
    radius: f64,
    /// The square of the nearest edge line's distance from `origin`: a
    /// point nearer `origin` than that faces no edge.
    inner2: f64,
    /// Edges to a bucket, a power of two.
    size: usize,
    /// Bounds of the buckets, [`LANES`] to a group.
    buckets: Vec<Group>,
    /// For each of its equal pseudo-angle steps, the edge whose normal
    /// enters it first, or else the edge whose normal came before it.
    by_direction: Vec<usize>,
}

/// Buckets bounded together, in straight-line code the compiler runs
/// several lanes at a time.
const LANES: usize = 16;

/// [`LANES`] pieces' bounds, one array per quantity, in single precision
/// (twice the lanes per instruction; the search's margin covers the
/// rounding): for each piece of the chain, a centre `p` behind its edges
/// (relative to the index's interior point), the largest plane distance of
/// its edges at `p` (−∞ for a lane past the last edge, which is then never
/// measured), and the arc its outward normals sweep, as a middle direction
/// `c` with the cosine and sine of the half-angle `α`.
#[derive(Clone, Debug)]
struct Group {
    centre_x: [f32; LANES],
    centre_y: [f32; LANES],
    top: [f32; LANES],
    mid_x: [f32; LANES],
    mid_y: [f32; LANES],
    cos: [f32; LANES],
    sin: [f32; LANES],
}

impl Group {
    const EMPTY: Self = Self {
        centre_x: [0.0; LANES],
        centre_y: [0.0; LANES],
        top: [f32::NEG_INFINITY; LANES],
        mid_x: [1.0; LANES],
        mid_y: [0.0; LANES],
        cos: [-1.0; LANES],
        sin: [1.0; LANES],
    };

    /// Lane `i` bounds the edges with these normals and start points (a
    /// piece of a convex chain inside a block of this `radius` about
    /// `origin`).
    fn set(&mut self, i: usize, normals: &[Vec2], starts: &[Vec2], origin: Vec2, radius: f64) {
        let offset = centre(normals, starts).map(|p| p - origin).filter(|p| p.length() <= radius).unwrap_or(Vec2::ZERO);
        (self.centre_x[i], self.centre_y[i]) = (offset.x as f32, offset.y as f32);
        // The largest plane distance at the centre as stored.
        let centre = origin + Vec2::new(f64::from(self.centre_x[i]), f64::from(self.centre_y[i]));
        let top = normals.iter().zip(starts).map(|(n, &s)| n.dot(centre - s)).fold(f64::NEG_INFINITY, f64::max);
        self.top[i] = top as f32;
        let (first, last) = (normals[0], normals[normals.len() - 1]);
        let mid = (first + last).normalized();
        // Less than a half-turn (the sine of the sweep positive by more
        // than any rounding; one edge sweeps nothing): the arc about `mid`.
        // Otherwise `cos = −1, sin = 1` about any axis bounds `u · y` by
        // `|y|`, as every direction must be.
        let (c, cos, sin) = if normals.len() == 1 || (first.cross(last) > 1e-12 && mid != Vec2::ZERO) {
            (mid, mid.dot(first), mid.cross(first).abs())
        } else {
            (Vec2::new(1.0, 0.0), -1.0, 1.0)
        };
        (self.mid_x[i], self.mid_y[i], self.cos[i], self.sin[i]) = (c.x as f32, c.y as f32, cos as f32, sin as f32);
    }

    /// Every lane's bound at the point `x` from the interior point. With
    /// `y = x − p`, `a = c · y` and `b = c⊥ · y`, a unit `u` at most `α`
    /// from `c` has `u · y ≤ (a if a ≥ 0, else a cos α) + |b| sin α`:
    /// within a few `α²` of the exact maximum over the arc, and no square
    /// root.
    #[inline]
    fn bounds(&self, x: [f32; 2]) -> [f32; LANES] {
        std::array::from_fn(|i| {
            let (yx, yy) = (x[0] - self.centre_x[i], x[1] - self.centre_y[i]);
            let a = self.mid_x[i] * yx + self.mid_y[i] * yy;
            let b = self.mid_x[i] * yy - self.mid_y[i] * yx;
            let along = if a >= 0.0 { a } else { a * self.cos[i] };
            self.top[i] + along + b.abs() * self.sin[i]
        })
    }
}

impl LineIndex {
    /// The index over `edges`, a convex, counter-clockwise chain.
    pub(crate) fn new(edges: &[ContactEdge]) -> Self {
        let n = edges.len();
        let size = bucket_size(n);
        // Whole buckets: the last edge repeats to fill the last one (a
        // repeat never beats it, nor comes before it in a tie).
        let padded = n.div_ceil(size) * size;
        let normals: Vec<Vec2> = (0..padded).map(|k| edges[k.min(n - 1)].normal).collect();
        let starts: Vec<Vec2> = (0..padded).map(|k| edges[k.min(n - 1)].start).collect();
        let origin = mean(&starts[..n]);
        let radius = starts[..n].iter().fold(0.0f64, |r, &s| r.max((s - origin).length_squared())).sqrt();
        let mut buckets = vec![Group::EMPTY; n.div_ceil(size * LANES)];
        for b in 0..n.div_ceil(size) {
            let (lo, hi) = (b * size, ((b + 1) * size).min(n));
            buckets[b / LANES].set(b % LANES, &normals[lo..hi], &starts[lo..hi], origin, radius);
        }
        let by_direction = direction_table(&normals[..n]);
        let inner = (0..n).map(|k| -normals[k].dot(origin - starts[k])).fold(f64::INFINITY, f64::min);
        let inner2 = if inner > 0.0 { inner * inner } else { 0.0 };
        Self { normals, starts, edges: n, origin, radius, inner2, size, buckets, by_direction }
    }

    /// The edges' start points.
    pub(crate) fn starts(&self) -> &[Vec2] {
        &self.starts[..self.edges]
    }

    /// A point strictly inside the block: the mean of its corners.
    pub(crate) fn origin(&self) -> Vec2 {
        self.origin
    }

    /// An edge whose outward normal points about where `q` lies from the
    /// interior point (O(1)), to try as an edge facing `q`; `None` where
    /// `q` lies so near the interior point that no edge faces it and one
    /// group of buckets holds them all (so the search needs no start).
    #[inline]
    pub(crate) fn guess(&self, q: Vec2) -> Option<usize> {
        let x = q - self.origin;
        if self.buckets.len() == 1 && x.length_squared() < self.inner2 {
            return None;
        }
        Some(self.by_direction[step(x, self.by_direction.len())])
    }

    /// The first edge with the largest plane distance at `q`, and that
    /// distance, starting from edge `guess` (any edge: a good one only
    /// skips more buckets).
    pub(crate) fn farthest(&self, q: Vec2, guess: usize) -> (usize, f64) {
        let x = q - self.origin;
        // Far above the single-precision rounding of the bounds (about
        // 1e-7 of the scale per operation); |x| ≤ |x.x| + |x.y|.
        let margin = MARGIN * (x.x.abs() + x.y.abs() + 4.0 * self.radius);
        let x = [x.x as f32, x.y as f32];
        let mut best = (usize::MAX, f64::NEG_INFINITY);
        // Measures bucket `b`: the first of its largest plane distances
        // (each by the same expression as `ContactEdge::plane_distance`),
        // kept if it beats the best or ties it at a lower index.
        let mut measure = |b: usize| {
            let lo = b * self.size;
            let (normals, starts) = (&self.normals[lo..lo + self.size], &self.starts[lo..lo + self.size]);
            let mut top = (f64::NEG_INFINITY, 0);
            for (k, (n, &s)) in normals.iter().zip(starts).enumerate() {
                let g = n.dot(q - s);
                if g > top.0 {
                    top = (g, k);
                }
            }
            let at = lo + top.1;
            if top.0 > best.1 || (top.0 == best.1 && at < best.0) {
                best = (at, top.0);
            }
            best.1
        };
        // In the guess's group of buckets, the one with the highest bound
        // first; then every bucket whose bound reaches the best found.
        let home = guess / (self.size * LANES);
        let home_bounds = self.buckets[home].bounds(x);
        let start = home * LANES + argmax(&home_bounds);
        let mut best_g = measure(start);
        // The bounds are compared in single precision against the best less
        // the margin, rounded: the margin dwarfs that rounding too.
        let mut need = (best_g - margin) as f32;
        for (j, group) in self.buckets.iter().enumerate() {
            let bounds = if j == home { home_bounds } else { group.bounds(x) };
            for (i, &bound) in bounds.iter().enumerate() {
                if bound >= need && j * LANES + i != start {
                    best_g = measure(j * LANES + i);
                    need = (best_g - margin) as f32;
                }
            }
        }
        best
    }
}

/// The first lane with the largest value.
#[inline]
fn argmax(values: &[f32; LANES]) -> usize {
    let top = values.iter().fold(f32::NEG_INFINITY, |m, &v| if v > m { v } else { m });
    values.iter().position(|&v| v == top).unwrap_or(0)
}

/// Edges to a bucket: the power of two at or above `√(n/2)`, at least 4.
/// A query bounds every bucket and measures about one; at 128 edges (two
/// 64-gons) this makes one group of 16 buckets of 8, which measured faster
/// than 8 buckets of 16 or 32 of 4 (`cargo bench --bench contact --
/// translations`).
fn bucket_size(n: usize) -> usize {
    (n / 2).isqrt().next_power_of_two().max(4)
}

/// The point at equal plane distance from the first, middle and last of
/// the lines (the centre of the circle they touch, for a bucket cut from a
/// round boundary), if those three lines are far from parallel.
fn centre(normals: &[Vec2], starts: &[Vec2]) -> Option<Vec2> {
    let (f, m, l) = (0, normals.len() / 2, normals.len() - 1);
    let (u, v) = (normals[f] - normals[m], normals[l] - normals[m]);
    let (a, b) =
        (normals[f].dot(starts[f]) - normals[m].dot(starts[m]), normals[l].dot(starts[l]) - normals[m].dot(starts[m]));
    // u · p = a and v · p = b.
    let det = u.cross(v);
    if det.abs() <= 1e-9 {
        return None;
    }
    let p = Vec2::new(a * v.y - b * u.y, u.x * b - v.x * a) / det;
    p.is_finite().then_some(p)
}

/// The pseudo-angle of `v` in [0, 4), counter-clockwise from straight
/// down, scaled to `steps` equal steps. The zero vector falls in step 0.
#[inline]
fn step(v: Vec2, steps: usize) -> usize {
    let p = v.y / (v.x.abs() + v.y.abs());
    let turn = if v.x >= 0.0 { 1.0 + p } else { 3.0 - p };
    // `as` saturates (and takes NaN to 0).
    ((turn * 0.25 * steps as f64) as usize).min(steps - 1)
}

/// The guess table: as many steps as normals. Written without branches
/// on the data (a step holds one normal, none or several about as often),
/// since it is rebuilt with every block.
fn direction_table(normals: &[Vec2]) -> Vec<usize> {
    let steps = normals.len();
    let mut table = vec![usize::MAX; steps];
    // Backwards, so that the first normal in a step is the one left there.
    for (k, &u) in normals.iter().enumerate().rev() {
        table[step(u, steps)] = k;
    }
    // An empty step takes the edge before it, counter-clockwise, wrapping
    // round from the last filled step.
    let mut carry = table.iter().rev().copied().find(|&k| k != usize::MAX).unwrap_or(0);
    for slot in &mut table {
        carry = if *slot == usize::MAX { carry } else { *slot };
        *slot = carry;
    }
    table
}

#[cfg(test)]
mod tests {
    use super::{LineIndex, step};
    use crate::contact::circle::{CircleFit, discretize_circle};
    use crate::contact::entrance_block::EntranceBlock;
    use crate::contact::polygon::ConvexPolygon;
    use crate::contact::random_ellipse;
    use crate::contact::test_support::random_pair;
    use crate::contact::vec2::Vec2;
    use proptest::prelude::*;
    use rand::SeedableRng;

    /// The linear pass the index replaces: the first edge with the largest
    /// plane distance.
    fn scan(block: &EntranceBlock, q: Vec2) -> (usize, f64) {
        let mut best = (0, f64::NEG_INFINITY);
        for (k, e) in block.edges().iter().enumerate() {
            let g = e.plane_distance(q);
            if g > best.1 {
                best = (k, g);
            }
        }
        best
    }

    fn rect(w: f64, h: f64) -> ConvexPolygon {
        ConvexPolygon::from_xy(&[[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]]).expect("rectangle")
    }

    #[test]
    fn the_pseudo_angle_turns_counter_clockwise_from_straight_down() {
        let dirs =
            [(0.0, -1.0), (1.0, -1.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0), (-1.0, -1.0)];
        let steps: Vec<usize> = dirs.iter().map(|&(x, y)| step(Vec2::new(x, y), 8)).collect();
        assert_eq!(steps, vec![0, 1, 2, 3, 4, 5, 6, 7]);
        assert_eq!(step(Vec2::new(-1e-300, -1.0), 8), 7);
        assert_eq!(step(Vec2::ZERO, 8), 0);
    }

    #[test]
    fn the_guess_is_the_edge_whose_normal_points_at_the_query() {
        // Block: x in [-1, 5], y in [-1, 0.5], corners averaging (2, -0.25).
        let block = EntranceBlock::new(&rect(1.0, 1.0), &rect(5.0, 0.5));
        let lines = LineIndex::new(block.edges());
        assert_eq!(lines.origin(), Vec2::new(2.0, -0.25));
        for u in [Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0), Vec2::new(-1.0, 0.0), Vec2::new(0.0, -1.0)] {
            for d in [0.8, 3.0, 100.0] {
                let k = lines.guess(Vec2::new(2.0, -0.25) + u * d).expect("outside the inscribed circle");
                assert_eq!(block.edges()[k].normal, u, "{u:?} at {d}");
            }
            // Nearer the centre than the nearest side (0.75 away), no edge
            // faces the point.
            assert_eq!(lines.guess(Vec2::new(2.0, -0.25) + u * 0.7), None);
        }
    }

    #[test]
    fn a_rectangle_block_finds_the_nearer_long_side_and_the_first_of_a_tie() {
        // Block: x in [-1, 5], y in [-1, 0.5]; the row y = -0.25 ties the
        // long sides, the point (2, -0.25) ties them with nothing else.
        let block = EntranceBlock::new(&rect(1.0, 1.0), &rect(5.0, 0.5));
        let lines = LineIndex::new(block.edges());
        let cases =
            [(2.0, -0.25, -0.75), (4.0, -0.25, -0.75), (2.0, 0.25, -0.25), (-0.5, 0.0, -0.5), (2.0, -0.75, -0.25)];
        for (x, y, depth) in cases {
            let q = Vec2::new(x, y);
            for guess in 0..block.edges().len() {
                let found = lines.farthest(q, guess);
                assert_eq!(found, scan(&block, q), "at {q:?} from {guess}");
                assert_eq!(found.1, depth, "at {q:?}");
            }
        }
    }

    #[test]
    fn a_regular_polygon_ties_every_edge_at_its_centre_and_the_first_wins() {
        let a = discretize_circle(Vec2::ZERO, 1.0, 200, CircleFit::Inscribed, 0.0).expect("circle");
        let block = EntranceBlock::new(&a, &a);
        let lines = LineIndex::new(block.edges());
        for q in [Vec2::ZERO, Vec2::new(1e-9, 0.0), Vec2::new(0.3, -1.2), Vec2::new(5.0, 5.0)] {
            assert_eq!(lines.farthest(q, lines.guess(q).unwrap_or(0)), scan(&block, q), "at {q:?}");
        }
    }

    #[test]
    fn large_random_blocks_match_the_linear_pass() {
        // The contact benchmark's shapes, up to 1024 vertices a side (so
        // several groups of buckets), at random points around them.
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        for n in [64, 256, 1024] {
            let a = ConvexPolygon::new(&random_ellipse(&mut rng, n, Vec2::ZERO)).expect("convex");
            let b = ConvexPolygon::new(&random_ellipse(&mut rng, n, Vec2::new(0.3, -0.4))).expect("convex");
            let block = EntranceBlock::new(&a, &b);
            let lines = LineIndex::new(block.edges());
            for i in 0..300 {
                let t = f64::from(i);
                let q = Vec2::new(2.5 * (t * 0.37).sin() * (t * 0.11).cos(), 2.5 * (t * 0.23).cos());
                assert_eq!(lines.farthest(q, lines.guess(q).unwrap_or(0)), scan(&block, q), "n = {n} at {q:?}");
            }
        }
    }

    proptest! {
        #[test]
        fn the_index_finds_the_linear_passs_edge(
            pair in prop_oneof![Just(0.0), Just(1e6)].prop_flat_map(|far| random_pair(40, 1.0, far)),
            moves in prop::collection::vec((-3.0..3.0f64, -3.0..3.0f64), 1..16),
            guess in 0usize..1000,
        ) {
            let Some((a, b)) = pair else { return Ok(()) };
            let block = EntranceBlock::new(&a, &b);
            let lines = LineIndex::new(block.edges());
            for (x, y) in moves {
                let q = Vec2::new(x, y);
                prop_assert_eq!(lines.farthest(q, guess % block.edges().len()), scan(&block, q), "at {:?}", q);
                prop_assert_eq!(lines.farthest(q, lines.guess(q).unwrap_or(0)), scan(&block, q), "at {:?}", q);
            }
        }
    }
}
