//! An entrance block kept for repeated queries while only A's translation
//! changes: a finger blob sliding over one footprint, a proxy swept along a
//! path. The block is built once (O(m + n)); each query is then a point
//! query against it.
//!
//! Costs per query, `n` = number of contact edges:
//! * **relation** — O(log n): a wedge search from an interior point finds
//!   the edge whose wedge holds the query point; one side test says inside
//!   or outside. Outside, the distance decides separated/touching (below).
//!   Inside, a second wedge search in the block shrunk by the tolerance (its
//!   edges moved inward, made on the first call) says intersecting or
//!   touching.
//! * **signed distance outside** — O(log n): a table of the edges by
//!   normal direction gives, in O(1), the edge whose normal points at the
//!   query point, which faces it unless the point is barely outside (then
//!   the depth search below finds one that does). The nearest point lies on
//!   the chain of edges that face the query point, and along that chain the
//!   distance falls then rises (a convex set seen from outside), so a
//!   galloping binary search from that edge, forward or backward (whichever
//!   way the distance falls there), finds where it turns; the edges either
//!   side of the turn are compared.
//! * **penetration depth inside** — O(√n). The depth is the distance to the
//!   nearest edge *line*, and that is not unimodal around the boundary (a
//!   rectangle has two minima, one per long side), so no binary search
//!   finds it. A branch and bound over buckets of about √(n/2) edges
//!   ([`LineIndex`]) finds the same edge line a linear scan does, and the
//!   report is then built exactly as the linear scan builds it: the same
//!   numbers, bit for bit.
//!
//! If the shrunk block is degenerate (an edge shorter than the tolerance at
//! a sharp corner, or a block thinner than twice the tolerance) the inside
//! relation falls back to the depth.

use super::entrance_block::{ContactEdge, EntranceBlock, Nearest, nearest_from_farthest, wrap};
use super::line_index::LineIndex;
use super::polygon::ConvexPolygon;
use super::report::{ContactReport, Relation};
use super::vec2::{Vec2, mean};
use std::sync::OnceLock;

/// An entrance block with what its point queries need.
#[derive(Clone, Debug)]
pub struct CachedBlock {
    block: EntranceBlock,
    /// The edges' normals and start points indexed by direction, with a
    /// point strictly inside the block (the mean of its corners).
    lines: LineIndex,
    /// The block shrunk by the tolerance, if it is a proper polygon: made
    /// on the first [`CachedBlock::relation`], which alone needs it.
    inner: OnceLock<Option<Shrunk>>,
}

#[derive(Clone, Debug)]
struct Shrunk {
    /// Corner `k` starts the edge parallel to the block's edge `k`.
    corners: Vec<Vec2>,
    interior: Vec2,
}

impl CachedBlock {
    /// Builds the block for A and B where they are now. Queries take A's
    /// translation from here.
    pub fn new(a: &ConvexPolygon, b: &ConvexPolygon) -> Self {
        Self::from_block(EntranceBlock::new(a, b))
    }

    pub fn from_block(block: EntranceBlock) -> Self {
        let lines = LineIndex::new(block.edges());
        Self { block, lines, inner: OnceLock::new() }
    }

    pub fn block(&self) -> &EntranceBlock {
        &self.block
    }

    /// Separated, touching or intersecting with A moved by `translation`.
    /// O(log n).
    pub fn relation(&self, translation: Vec2) -> Relation {
        let q = translation;
        let edges = self.block.edges();
        let tol = self.block.tolerance();
        let k = wedge(self.lines.starts(), self.lines.origin(), q);
        if edges[k].plane_distance(q) > 0.0 {
            let d = self.nearest_outside(q, k).signed_distance;
            return Relation::from_signed_distance(d, tol);
        }
        match self.inner.get_or_init(|| shrink(edges, tol)) {
            Some(inner) => {
                let k = wedge(&inner.corners, inner.interior, q);
                if edges[k].normal.dot(q - inner.corners[k]) < 0.0 {
                    Relation::Intersecting
                } else {
                    Relation::Touching
                }
            }
            None => Relation::from_signed_distance(self.nearest_inside(q, k).signed_distance, tol),
        }
    }

    /// Signed distance with A moved by `translation`: O(log n) when
    /// separated, O(√n) when inside the block.
    pub fn signed_distance(&self, translation: Vec2) -> f64 {
        self.nearest(translation).signed_distance
    }

    /// The full report with A moved by `translation` (costs as
    /// [`CachedBlock::signed_distance`]).
    pub fn report(&self, translation: Vec2) -> ContactReport {
        self.block.report_from(translation, self.nearest(translation))
    }

    /// The nearest boundary point. An edge guessed from `q`'s direction
    /// that faces `q` proves it outside; otherwise the index finds the edge
    /// line farthest out, which either faces `q` (outside after all) or
    /// gives the depth.
    fn nearest(&self, q: Vec2) -> Nearest {
        let edges = self.block.edges();
        let guess = self.lines.guess(q);
        if let Some(k) = guess.filter(|&k| edges[k].plane_distance(q) > 0.0) {
            return self.nearest_outside(q, k);
        }
        let (far, g) = self.lines.farthest(q, guess.unwrap_or(0));
        if g > 0.0 { self.nearest_outside(q, far) } else { nearest_from_farthest(edges, q, far, g) }
    }

    /// Inside edge `k` (any edge): the farthest-out edge line from the line
    /// index, then what the linear scan does with it.
    fn nearest_inside(&self, q: Vec2, k: usize) -> Nearest {
        let (far, g) = self.lines.farthest(q, k);
        nearest_from_farthest(self.block.edges(), q, far, g)
    }

    /// `q` is outside edge `k`, so `k` faces `q` (any such edge will do:
    /// the facing edges form one chain, and the searches below run along
    /// it from wherever they start).
    fn nearest_outside(&self, q: Vec2, k: usize) -> Nearest {
        let edges = self.block.edges();
        let n = edges.len();
        let nk = edges[k].normal;
        // Forward from k: false while the edge faces q, is less than half a
        // turn ahead of k and the distance still falls at its end.
        let stops_forward = |o: usize| {
            let e = &edges[wrap(k + o, n)];
            let c = nk.cross(e.normal);
            let half_turn_on = c < 0.0 || (c == 0.0 && nk.dot(e.normal) < 0.0);
            half_turn_on || e.plane_distance(q) <= 0.0 || (e.end() - q).dot(e.direction) >= 0.0
        };
        // Backward from k: the mirror image, judged at the edge's start.
        let stops_backward = |o: usize| {
            let e = &edges[wrap(k + n - o, n)];
            let c = e.normal.cross(nk);
            let half_turn_on = c < 0.0 || (c == 0.0 && nk.dot(e.normal) < 0.0);
            half_turn_on || e.plane_distance(q) <= 0.0 || (e.start - q).dot(e.direction) <= 0.0
        };
        // Only one way needs searching: when q's foot on edge k's line lies
        // past k's end the nearest point is ahead, and the backward search
        // would stop at k at once; otherwise it is at or behind k's end, and
        // the forward search would.
        let turn = wrap(
            if stops_forward(0) { k + n - first_true(n, stops_backward) } else { k + first_true(n, stops_forward) },
            n,
        );
        let mut best = Nearest { edge: k, point: q, signed_distance: f64::INFINITY };
        let mut best_d2 = f64::INFINITY;
        for j in [wrap(turn + n - 1, n), turn, wrap(turn + 1, n)] {
            let p = edges[j].closest_point(q);
            let d2 = (q - p).length_squared();
            if d2 < best_d2 {
                best_d2 = d2;
                best = Nearest { edge: j, point: p, signed_distance: 0.0 };
            }
        }
        best.signed_distance = best_d2.sqrt();
        best
    }
}

/// The first `o` in `0..n` for which `pred` holds, `pred` being false then
/// true over that range; `n − 1` if it never holds. Galloping (0, 2, 5,
/// 10, …) before the binary search: the searches start at an edge facing
/// the query point, usually a few edges from the nearest one.
fn first_true(n: usize, pred: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, n);
    let (mut probe, mut width) = (0, 1);
    while probe < n {
        if pred(probe) {
            hi = probe;
            break;
        }
        lo = probe + 1;
        width *= 2;
        probe = lo + width / 2;
    }
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if pred(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo.min(n - 1)
}

/// The index `k` of the wedge (rays from `center` through corners `k` and
/// `k + 1`) that holds `q`, by binary search on the angle measured
/// counter-clockwise from corner 0. `center` must be strictly inside the
/// convex, counter-clockwise polygon `corners`.
fn wedge(corners: &[Vec2], center: Vec2, q: Vec2) -> usize {
    let r0 = corners[0] - center;
    let half = |v: Vec2| {
        let c = r0.cross(v);
        u8::from(!(c > 0.0 || (c == 0.0 && r0.dot(v) > 0.0)))
    };
    let d = q - center;
    let hd = half(d);
    let at_or_before = |v: Vec2| {
        let hv = half(v);
        if hv == hd { v.cross(d) >= 0.0 } else { hv < hd }
    };
    let (mut lo, mut hi) = (0, corners.len());
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if at_or_before(corners[mid] - center) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The block with every edge moved inward by `tol`, if no edge vanishes.
fn shrink(edges: &[ContactEdge], tol: f64) -> Option<Shrunk> {
    let n = edges.len();
    let mut corners = Vec::with_capacity(n);
    for k in 0..n {
        let (n0, n1) = (edges[(k + n - 1) % n].normal, edges[k].normal);
        // The corner where the two moved lines meet: n0·(x − w) = n1·(x − w) = −tol.
        let denom = 1.0 + n0.dot(n1);
        if denom <= 1e-9 {
            return None;
        }
        corners.push(edges[k].start - (n0 + n1) * (tol / denom));
    }
    for k in 0..n {
        if (corners[(k + 1) % n] - corners[k]).dot(edges[k].direction) <= 0.0 {
            return None;
        }
    }
    let interior = mean(&corners);
    let inside = (0..n).all(|k| edges[k].normal.dot(interior - corners[k]) < 0.0);
    inside.then_some(Shrunk { corners, interior })
}

#[cfg(test)]
mod tests {
    use super::CachedBlock;
    use crate::contact::circle::{CircleFit, discretize_circle};
    use crate::contact::report::Relation;
    use crate::contact::vec2::Vec2;

    #[test]
    fn cached_queries_match_the_linear_scan() {
        let a = discretize_circle(Vec2::ZERO, 1.0, 37, CircleFit::Inscribed, 0.1).expect("circle");
        let b = discretize_circle(Vec2::new(0.5, 0.2), 2.0, 64, CircleFit::Circumscribed, 0.0).expect("circle");
        let cached = CachedBlock::new(&a, &b);
        for i in 0..400 {
            let t = f64::from(i) * 0.1;
            let q = Vec2::new(7.0 * (t * 0.7).cos(), 5.0 * (t * 1.3).sin());
            let fast = cached.report(q);
            let slow = cached.block().report_at(q);
            assert!((fast.distance - slow.distance).abs() < 1e-12, "at {q:?}: {fast:?} vs {slow:?}");
            assert_eq!(cached.relation(q), slow.relation, "at {q:?}");
        }
    }

    #[test]
    fn the_shrunk_block_separates_touching_from_intersecting() {
        let a = discretize_circle(Vec2::ZERO, 1.0, 8, CircleFit::Inscribed, 0.0).expect("circle");
        let b = discretize_circle(Vec2::ZERO, 1.0, 8, CircleFit::Inscribed, 0.0).expect("circle");
        let cached = CachedBlock::new(&a, &b);
        // Block = the 8-gon of radius 2; vertex 0 at (2, 0).
        assert_eq!(cached.relation(Vec2::new(2.0, 0.0)), Relation::Touching);
        assert_eq!(cached.relation(Vec2::new(2.0 - 1e-6, 0.0)), Relation::Intersecting);
        assert_eq!(cached.relation(Vec2::new(2.0 + 1e-6, 0.0)), Relation::Separated);
        assert_eq!(cached.relation(Vec2::ZERO), Relation::Intersecting);
    }
}
