//! Convex polygons, cleaned once at construction so the algorithms downstream
//! can assume clean input (`Box2D`'s `b2ComputeHull` does the same).
//!
//! Cleaning, in order:
//! 1. every coordinate must be finite;
//! 2. consecutive vertices within the *tight* tolerance are welded (the
//!    first one of a cluster, in input order, is kept);
//! 3. the winding is read from the signed area and normalised to
//!    counter-clockwise (the paper's right-hand order); zero area is an error;
//! 4. straight angles are dropped, as the paper does (they do not change the
//!    entrance block but cost time in every walk): a run of vertices goes
//!    when every one of them lies within the tight tolerance *outside* the
//!    chord that replaces them, or within the ordinary tolerance *inside* it;
//! 5. what is left must not turn right by more than the ordinary tolerance
//!    anywhere and must go around exactly once.
//!
//! Two tolerances, on purpose (see [`tight_tolerance`] and
//! [`scale_tolerance`], each of the polygon's own extent and largest
//! coordinate): a vertex bulging *out* is real convex geometry, so it is
//! kept unless it is within rounding (1e-12 of the size); a vertex dented
//! *in* by less than the ordinary tolerance (1e-9) is taken as a rounding
//! accident of a straight edge, not as a reflex angle, and dropping it only
//! moves the boundary outward to the chord. Every dropped vertex is checked
//! against the final chord, so drops do not accumulate. Each kept vertex
//! remembers its index in the caller's input, so contact features can be
//! reported in the caller's numbering.
//!
//! Rejected alternative: computing the convex hull of the input (as `Box2D`
//! does). A footprint that is *not* convex must be reported, not silently
//! replaced by its hull: the caller may want the concave path instead.

use super::error::{ContactError, PolygonError};
use super::tolerance::{scale_tolerance, tight_tolerance};
use super::vec2::{Vec2, at_or_after_in_half};

/// A strictly convex polygon with counter-clockwise vertices.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexPolygon {
    vertices: Vec<Vec2>,
    /// `source[i]` is the caller's index of `vertices[i]`.
    source: Vec<usize>,
    extent: f64,
    magnitude: f64,
    tolerance: f64,
    tight: f64,
    /// Position (in `vertices`) of the smallest source index.
    first: usize,
    /// `normals[i]`: unit outward normal of edge `i → i + 1`, computed once
    /// here so that building an entrance block takes no square root.
    normals: Vec<Vec2>,
    /// Centre of the bounding box: the separated-pair early exit's first
    /// guess of the direction between two polygons (free here, O(n) later).
    centre: Vec2,
}

impl ConvexPolygon {
    /// Cleans `points` (either winding) into a convex polygon.
    pub fn new(points: &[Vec2]) -> Result<Self, PolygonError> {
        if let Some(clean) = Self::already_clean(points, None) {
            return Ok(clean);
        }
        let source: Vec<usize> = (0..points.len()).collect();
        Self::slow_clean(points, &source)
    }

    /// [`ConvexPolygon::new`] from `[x, y]` pairs.
    pub fn from_xy(points: &[[f64; 2]]) -> Result<Self, PolygonError> {
        let points: Vec<Vec2> = points.iter().copied().map(Vec2::from).collect();
        Self::new(&points)
    }

    /// [`ConvexPolygon::new`] with the polygon's name in the error, e.g.
    /// "polygon `a`: vertex 3 makes a reflex angle (the polygon is not convex)".
    pub fn named(name: &str, points: &[Vec2]) -> Result<Self, ContactError> {
        Self::new(points).map_err(|problem| ContactError::polygon(name, problem))
    }

    /// Like `new`, but `points[i]` is reported as the caller's vertex
    /// `sources[i]` (used by the convex pieces of a concave polygon).
    pub(crate) fn with_sources(points: &[Vec2], sources: &[usize]) -> Result<Self, PolygonError> {
        if let Some(clean) = Self::already_clean(points, Some(sources)) {
            return Ok(clean);
        }
        Self::slow_clean(points, sources)
    }

    /// Steps 1–5 of the module docs, each its own pass.
    pub(crate) fn slow_clean(points: &[Vec2], sources: &[usize]) -> Result<Self, PolygonError> {
        let ring = Ring::clean(points, sources)?;
        ring.check_convex()?;
        let first = (0..ring.source.len()).min_by_key(|&i| ring.source[i]).unwrap_or(0);
        let normals = edge_normals(&ring.points);
        let centre = bounding_box(&ring.points).map_or(Vec2::ZERO, |(lo, hi)| (lo + hi) * 0.5);
        Ok(Self {
            first,
            normals,
            centre,
            vertices: ring.points,
            source: ring.source,
            extent: ring.extent,
            magnitude: ring.magnitude,
            tolerance: ring.tolerance,
            tight: ring.tight,
        })
    }

    /// The fast path for input that cleaning would leave as it is: finite,
    /// counter-clockwise, no two neighbours within welding distance, every
    /// vertex turning left by clearly more than the tight tolerance, and
    /// winding once. One pass for the box, one for the turns (no square
    /// root, no `atan2`: the winding is counted from the edges' half-planes,
    /// exact when every turn is a left turn below π), then the copy and the
    /// normals. `None` sends the input to [`ConvexPolygon::slow_clean`],
    /// which then also reports what is wrong.
    ///
    /// Every test carries a margin (twice the tolerance, plus a bound on the
    /// rounding of the cross product), so that whatever this accepts the
    /// slow path would have returned unchanged: the same polygon, bit for
    /// bit (a proptest checks it). On the random ellipses of
    /// `benches/contact.rs`, this makes `new` at n = 1024 several times
    /// faster than the slow path, whose per-vertex `atan2` and divisions
    /// are most of its cost.
    fn already_clean(points: &[Vec2], sources: Option<&[usize]>) -> Option<Self> {
        let n = points.len();
        if n < 3 {
            return None;
        }
        let (lo, hi) = bounding_box(points)?;
        let extent = (hi.x - lo.x).max(hi.y - lo.y).max(0.0);
        let magnitude = lo.max_abs().max(hi.max_abs());
        if !(extent.is_finite() && magnitude.is_finite()) {
            return None;
        }
        let tolerance = scale_tolerance(extent, magnitude);
        let tight = tight_tolerance(extent, magnitude);
        let tight2x4 = 4.0 * tight * tight;
        let l1 = |v: Vec2| v.x.abs() + v.y.abs();
        let mut wraps = 0usize;
        let mut prev = points[n - 2];
        let mut v = points[n - 1];
        let mut d1 = v - prev;
        for &next in points {
            let d2 = next - v;
            let chord = next - prev;
            let c = d1.cross(d2);
            let len2 = chord.length_squared();
            let rounding = 32.0 * f64::EPSILON * l1(d1) * (l1(d2) + l1(chord));
            let clear = d1.length_squared() > tight2x4 && len2 > tight2x4 && c > rounding && c * c > tight2x4 * len2;
            if !clear {
                return None;
            }
            wraps += usize::from(upper_half(d2) && !upper_half(d1));
            (prev, v, d1) = (v, next, d2);
        }
        // Going round once counter-clockwise, the edge direction enters the
        // upper half-plane exactly once.
        if wraps != 1 {
            return None;
        }
        if signed_area(points) * 2.0 <= 2.0 * tight * extent {
            return None;
        }
        let source: Vec<usize> = match sources {
            Some(s) => s.to_vec(),
            None => (0..n).collect(),
        };
        let first = (0..n).min_by_key(|&i| source[i]).unwrap_or(0);
        Some(Self {
            vertices: points.to_vec(),
            source,
            extent,
            magnitude,
            tolerance,
            tight,
            first,
            normals: edge_normals(points),
            centre: (lo + hi) * 0.5,
        })
    }

    /// The bounding box's centre.
    pub(crate) fn centre(&self) -> Vec2 {
        self.centre
    }

    /// The first edge `k` (cyclically from edge 0) whose outward normal is at
    /// or counter-clockwise after direction `d`, so that vertex `k` is a
    /// support vertex in direction `d` (its normal cone runs from edge
    /// `k − 1`'s normal to edge `k`'s). O(log n) by binary search on the
    /// normals' angles from `normals[0]`, which increase round the polygon.
    pub(crate) fn first_edge_at_or_after(&self, d: Vec2) -> usize {
        let normals = &self.normals;
        let base = normals[0];
        let half = |v: Vec2| {
            let c = base.cross(v);
            u8::from(!(c > 0.0 || (c == 0.0 && base.dot(v) > 0.0)))
        };
        let hd = half(d);
        let at_or_after = |v: Vec2| {
            let hv = half(v);
            if hv == hd { at_or_after_in_half(d, v, base, hv) } else { hv > hd }
        };
        let (mut lo, mut hi) = (0, normals.len());
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if at_or_after(normals[mid]) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        if lo == normals.len() { 0 } else { lo }
    }

    /// The cleaned vertices, counter-clockwise.
    pub fn vertices(&self) -> &[Vec2] {
        &self.vertices
    }

    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Always false: a polygon has at least three vertices.
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    /// The caller's index of cleaned vertex `i`.
    pub fn source_index(&self, i: usize) -> usize {
        self.source[i]
    }

    /// Unit outward normal of each edge `i → i + 1`.
    pub fn normals(&self) -> &[Vec2] {
        &self.normals
    }

    /// The caller's first vertex that survived cleaning (the entrance
    /// block's reference point).
    pub fn first_input_vertex(&self) -> Vec2 {
        self.vertices[self.first]
    }

    /// The caller's index of every cleaned vertex, in cleaned order.
    pub fn source_indices(&self) -> &[usize] {
        &self.source
    }

    /// The larger side of the axis-aligned bounding box.
    pub fn extent(&self) -> f64 {
        self.extent
    }

    /// The largest absolute coordinate.
    pub fn magnitude(&self) -> f64 {
        self.magnitude
    }

    /// The ordinary tolerance of this polygon ([`scale_tolerance`]): how far
    /// a vertex may dent inward and still count as straight.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The tight tolerance ([`tight_tolerance`]) it was welded with.
    pub fn tight_tolerance(&self) -> f64 {
        self.tight
    }

    /// The same polygon moved by `offset`, cleaned again: far from the
    /// origin, rounding can merge vertices that were distinct (a 1e-14 edge
    /// of a polygon at the origin vanishes at 1e6). Vertex numbering is
    /// kept. For a polygon that only slides against one other, prefer
    /// [`EntranceBlock::report_at`](super::entrance_block::EntranceBlock::report_at)
    /// or [`CachedBlock`](super::cached::CachedBlock), which need no copy.
    pub fn translated(&self, offset: Vec2) -> Result<Self, PolygonError> {
        let vertices: Vec<Vec2> = self.vertices.iter().map(|&v| v + offset).collect();
        Self::with_sources(&vertices, &self.source)
    }

    /// Area (positive: the vertices are counter-clockwise).
    pub fn area(&self) -> f64 {
        signed_area(&self.vertices)
    }

    /// Whether `point` is inside or on the boundary (within the tolerance).
    /// O(n); for repeated hit tests against one footprint see
    /// [`CachedBlock`](super::cached::CachedBlock).
    pub fn contains(&self, point: Vec2) -> bool {
        let n = self.vertices.len();
        (0..n).all(|i| {
            let s = self.vertices[i];
            let e = self.vertices[(i + 1) % n] - s;
            e.cross(point - s) >= -self.tolerance * e.length()
        })
    }
}

/// How a boundary turns at a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Turn {
    /// Left by more than the tight tolerance: convex in a counter-clockwise
    /// ring.
    Convex,
    /// Neither convex nor reflex: within the tolerances of the chord.
    Straight,
    /// Right by more than the ordinary tolerance: a reflex angle.
    Reflex,
    /// The boundary goes back the way it came (a zero-width spike).
    Fold,
}

/// The two thresholds of cleaning (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Slack {
    /// How far out of its chord a vertex may bulge and still be straight.
    pub(crate) outward: f64,
    /// How far into its chord a vertex may dent and still be straight.
    pub(crate) inward: f64,
}

/// Classifies vertex `v` between `prev` and `next` by its height above the
/// chord `prev → next` (positive outward for a counter-clockwise ring),
/// which is a length and so compares with the tolerances at any scale (an
/// angle test would drop long, almost straight chains that bulge by far
/// more than the tolerance).
pub(crate) fn turn(prev: Vec2, v: Vec2, next: Vec2, slack: Slack) -> Turn {
    let chord = next - prev;
    let len = chord.length();
    if len <= slack.outward {
        return Turn::Fold;
    }
    let (d1, d2) = (v - prev, next - v);
    let height = d1.cross(d2) / len;
    if height > slack.outward {
        Turn::Convex
    } else if height < -slack.inward {
        Turn::Reflex
    } else if d1.dot(d2) < 0.0 {
        Turn::Fold
    } else {
        Turn::Straight
    }
}

/// A closed ring after steps 1–4 of the cleaning (shared with the concave
/// polygons, which stop before the convexity check).
#[derive(Clone, Debug)]
pub(crate) struct Ring {
    pub(crate) points: Vec<Vec2>,
    pub(crate) source: Vec<usize>,
    pub(crate) extent: f64,
    pub(crate) magnitude: f64,
    /// Ordinary tolerance: inward slack, simplicity checks.
    pub(crate) tolerance: f64,
    /// Tight tolerance: welding, outward slack, zero area.
    pub(crate) tight: f64,
}

impl Ring {
    /// Steps 1–4.
    pub(crate) fn clean(points: &[Vec2], sources: &[usize]) -> Result<Self, PolygonError> {
        let mut ring = Self::weld(points, sources)?;
        ring.orient()?;
        ring.drop_straight();
        if ring.points.len() < 3 {
            return Err(PolygonError::ZeroArea);
        }
        Ok(ring)
    }

    /// Steps 1–2.
    pub(crate) fn weld(points: &[Vec2], sources: &[usize]) -> Result<Self, PolygonError> {
        debug_assert_eq!(points.len(), sources.len());
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(PolygonError::NotFinite { vertex: sources[i] });
        }
        if points.len() < 3 {
            return Err(PolygonError::TooFewPoints { distinct: distinct_count(points) });
        }
        let extent = extent(points);
        let magnitude = max_abs(points);
        let tolerance = scale_tolerance(extent, magnitude);
        let tight = tight_tolerance(extent, magnitude);

        let mut kept: Vec<Vec2> = Vec::with_capacity(points.len());
        let mut source: Vec<usize> = Vec::with_capacity(points.len());
        for (&p, &s) in points.iter().zip(sources) {
            if kept.last().is_none_or(|&last| (p - last).length() > tight) {
                kept.push(p);
                source.push(s);
            }
        }
        while kept.len() > 1 && (kept[kept.len() - 1] - kept[0]).length() <= tight {
            kept.pop();
            source.pop();
        }
        if kept.len() < 3 {
            return Err(PolygonError::TooFewPoints { distinct: kept.len() });
        }
        Ok(Self { points: kept, source, extent, magnitude, tolerance, tight })
    }

    pub(crate) fn slack(&self) -> Slack {
        Slack { outward: self.tight, inward: self.tolerance }
    }

    /// Step 3. Twice the area is compared with tight tolerance × extent:
    /// only a polygon thinner than rounding has no area.
    fn orient(&mut self) -> Result<(), PolygonError> {
        let area = signed_area(&self.points);
        if area.abs() * 2.0 <= self.tight * self.extent {
            return Err(PolygonError::ZeroArea);
        }
        if area < 0.0 {
            self.points.reverse();
            self.source.reverse();
        }
        Ok(())
    }

    /// Step 4. A stack pass (as in a monotone-chain hull) drops runs of
    /// straight vertices in one sweep; the wrap-around is settled after it.
    fn drop_straight(&mut self) {
        let n = self.points.len();
        let mut kept: Vec<usize> = Vec::with_capacity(n);
        for i in 0..n {
            kept.push(i);
            while kept.len() >= 3 {
                let k = kept.len();
                if self.run_is_straight(kept[k - 3], kept[k - 1]) {
                    kept.remove(k - 2);
                } else {
                    break;
                }
            }
        }
        loop {
            let k = kept.len();
            if k < 3 {
                break;
            }
            if self.run_is_straight(kept[k - 2], kept[0]) {
                kept.pop();
            } else if self.run_is_straight(kept[k - 1], kept[1]) {
                kept.remove(0);
            } else {
                break;
            }
        }
        self.points = kept.iter().map(|&i| self.points[i]).collect();
        self.source = kept.iter().map(|&i| self.source[i]).collect();
    }

    /// Whether every input vertex strictly between `u` and `w` (going
    /// forward round the ring) may be replaced by the chord `u → w`.
    fn run_is_straight(&self, u: usize, w: usize) -> bool {
        let p = &self.points;
        let n = p.len();
        let slack = self.slack();
        let chord = p[w] - p[u];
        let len = chord.length();
        if len <= slack.outward {
            return false;
        }
        let mut x = (u + 1) % n;
        while x != w {
            let d = p[x] - p[u];
            let height = d.cross(chord) / len;
            let along = d.dot(chord) / len;
            if height > slack.outward || height < -slack.inward || along < 0.0 || along > len {
                return false;
            }
            x = (x + 1) % n;
        }
        true
    }

    /// The turn at cleaned vertex `i`.
    pub(crate) fn turn_at(&self, i: usize) -> Turn {
        let n = self.points.len();
        turn(self.points[(i + n - 1) % n], self.points[i], self.points[(i + 1) % n], self.slack())
    }

    /// Step 5: no vertex turns right beyond the tolerance, none folds back,
    /// and the boundary goes around once. (A vertex left `Straight` here is
    /// one whose removal would have moved a dropped neighbour too far; it is
    /// kept as a vertex of angle ~π.)
    fn check_convex(&self) -> Result<(), PolygonError> {
        let n = self.points.len();
        for i in 0..n {
            match self.turn_at(i) {
                Turn::Convex | Turn::Straight => {}
                Turn::Reflex => {
                    return Err(PolygonError::Reflex { vertex: self.source[i] });
                }
                Turn::Fold => {
                    return Err(PolygonError::FoldsBack { vertex: self.source[i] });
                }
            }
        }
        // All left turns can still wind twice (a pentagram): the exterior
        // angles of a simple convex polygon add up to exactly one turn.
        let total: f64 = (0..n)
            .map(|i| {
                let d1 = self.points[i] - self.points[(i + n - 1) % n];
                let d2 = self.points[(i + 1) % n] - self.points[i];
                d1.cross(d2).atan2(d1.dot(d2))
            })
            .sum();
        let turns = (total / std::f64::consts::TAU).round() as i64;
        if turns != 1 {
            return Err(PolygonError::Winding { turns });
        }
        Ok(())
    }
}

/// Twice-halved shoelace sum, taken relative to the first vertex so that
/// coordinates far from the origin do not cancel catastrophically.
pub(crate) fn signed_area(points: &[Vec2]) -> f64 {
    let Some(&origin) = points.first() else {
        return 0.0;
    };
    let n = points.len();
    let mut twice = 0.0;
    for i in 1..n.saturating_sub(1) {
        twice += (points[i] - origin).cross(points[i + 1] - origin);
    }
    twice * 0.5
}

/// Unit outward normal of every edge `i → i + 1` of a counter-clockwise ring.
fn edge_normals(points: &[Vec2]) -> Vec<Vec2> {
    let n = points.len();
    (0..n).map(|i| (points[if i + 1 == n { 0 } else { i + 1 }] - points[i]).perp_cw().normalized()).collect()
}

/// Whether direction `d` points into the upper half-plane `[0, π)`.
fn upper_half(d: Vec2) -> bool {
    d.y > 0.0 || (d.y == 0.0 && d.x > 0.0)
}

/// The lowest and highest corner of the bounding box, `None` if a
/// coordinate is not finite or there are no points.
fn bounding_box(points: &[Vec2]) -> Option<(Vec2, Vec2)> {
    let first = *points.first()?;
    let (mut lo, mut hi) = (first, first);
    let mut finite = true;
    for p in points {
        finite &= p.is_finite();
        lo = Vec2::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Vec2::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    finite.then_some((lo, hi))
}

pub(crate) fn extent(points: &[Vec2]) -> f64 {
    let (mut lo, mut hi) = (Vec2::new(f64::INFINITY, f64::INFINITY), Vec2::new(f64::NEG_INFINITY, f64::NEG_INFINITY));
    for p in points {
        lo = Vec2::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Vec2::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    (hi.x - lo.x).max(hi.y - lo.y).max(0.0)
}

pub(crate) fn max_abs(points: &[Vec2]) -> f64 {
    points.iter().fold(0.0, |m, p| m.max(p.max_abs()))
}

fn distinct_count(points: &[Vec2]) -> usize {
    let mut distinct: Vec<Vec2> = Vec::new();
    for &p in points {
        if !distinct.contains(&p) {
            distinct.push(p);
        }
    }
    distinct.len()
}

#[cfg(test)]
mod tests {
    use super::{ConvexPolygon, PolygonError, Vec2};

    fn poly(points: &[[f64; 2]]) -> Result<ConvexPolygon, PolygonError> {
        ConvexPolygon::from_xy(points)
    }

    #[test]
    fn clockwise_input_is_reversed_and_keeps_source_indices() {
        let p = poly(&[[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]).expect("square");
        assert!(p.area() > 0.0);
        assert_eq!(p.len(), 4);
        for (i, &v) in p.vertices().iter().enumerate() {
            let input = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]][p.source_index(i)];
            assert_eq!(v, Vec2::from(input));
        }
    }

    #[test]
    fn near_duplicates_are_welded_and_the_first_is_kept() {
        let p = poly(&[[0.0, 0.0], [1.0, 0.0], [1.0 + 1e-16, 1e-16], [1.0, 1.0], [0.0, 1.0], [1e-16, 0.0]])
            .expect("square");
        assert_eq!(p.len(), 4);
        assert_eq!(p.source_indices(), &[0, 1, 3, 4]);
    }

    #[test]
    fn a_bulge_above_rounding_is_kept_and_a_dent_below_the_tolerance_is_dropped() {
        let bulge = poly(&[[0.0, 0.0], [0.5, -1e-11], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).expect("bulge");
        assert_eq!(bulge.len(), 5);
        let dent = poly(&[[0.0, 0.0], [0.5, 1e-11], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).expect("dent");
        assert_eq!(dent.source_indices(), &[0, 2, 3, 4]);
        let reflex =
            poly(&[[0.0, 0.0], [0.5, 1e-6], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).expect_err("must be rejected");
        assert_eq!(reflex, PolygonError::Reflex { vertex: 1 });
    }

    #[test]
    fn drops_do_not_accumulate_along_a_gentle_arc() {
        // 2001 vertices on an arc whose sagitta between neighbours (2.5e-17)
        // is far below the tight tolerance (1e-12) but whose total sagitta
        // is 1e-10: dropping them one chord at a time would flatten it, so
        // each run is checked against its final chord and the arc survives
        // to within the tight tolerance.
        let mut pts: Vec<[f64; 2]> = (0..=2000)
            .map(|k| {
                let x = f64::from(k) / 2000.0;
                [x, -4e-10 * x * (1.0 - x)]
            })
            .collect();
        pts.extend([[1.0, 1.0], [0.0, 1.0]]);
        let p = poly(&pts).expect("arc");
        let lowest = p.vertices().iter().map(|v| v.y).fold(f64::INFINITY, f64::min);
        assert!(lowest < -0.98e-10, "the arc was flattened to {lowest}");
        assert!(p.len() < 100, "{} vertices kept", p.len());
    }

    #[test]
    fn straight_angles_are_dropped() {
        let p = poly(&[[0.0, 0.0], [0.5, 0.0], [1.0, 0.0], [1.0, 0.5], [1.0, 1.0], [0.0, 1.0]])
            .expect("square with midpoints");
        assert_eq!(p.source_indices(), &[0, 2, 4, 5]);
    }

    #[test]
    fn a_reflex_vertex_is_named_by_its_input_index() {
        let err = poly(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 1.0], [0.0, 2.0]]).expect_err("must be rejected");
        assert_eq!(err, PolygonError::Reflex { vertex: 3 });
        // The same shape clockwise: still input vertex 3.
        let err = poly(&[[0.0, 2.0], [1.0, 1.0], [2.0, 2.0], [2.0, 0.0], [0.0, 0.0]]).expect_err("must be rejected");
        assert_eq!(err, PolygonError::Reflex { vertex: 1 });
    }

    #[test]
    fn degenerate_inputs_are_errors() {
        assert_eq!(
            poly(&[[0.0, 0.0], [1.0, 1.0]]).expect_err("must be rejected"),
            PolygonError::TooFewPoints { distinct: 2 }
        );
        assert_eq!(
            poly(&[[0.0, 0.0], [1.0, 1.0], [0.0, 0.0]]).expect_err("must be rejected"),
            PolygonError::TooFewPoints { distinct: 2 }
        );
        assert_eq!(poly(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]).expect_err("must be rejected"), PolygonError::ZeroArea);
        assert_eq!(
            poly(&[[0.0, 0.0], [f64::NAN, 1.0], [2.0, 0.0]]).expect_err("must be rejected"),
            PolygonError::NotFinite { vertex: 1 }
        );
        assert_eq!(
            poly(&[[0.0, 0.0], [f64::INFINITY, 1.0], [2.0, 0.0]]).expect_err("must be rejected"),
            PolygonError::NotFinite { vertex: 1 }
        );
    }

    #[test]
    fn a_pentagram_winds_twice() {
        let star: Vec<[f64; 2]> = (0..5)
            .map(|k| {
                let t = f64::from(k * 2) * std::f64::consts::TAU / 5.0;
                [t.cos(), t.sin()]
            })
            .collect();
        assert_eq!(poly(&star).expect_err("must be rejected"), PolygonError::Winding { turns: 2 });
    }

    #[test]
    fn a_spike_folds_back() {
        let err = poly(&[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]]).expect_err("must be rejected");
        assert!(matches!(err, PolygonError::FoldsBack { .. } | PolygonError::Reflex { .. }), "{err:?}");
    }

    /// Points on an ellipse at sorted angles: convex and counter-clockwise,
    /// clean unless two angles fall within welding distance.
    fn on_ellipse(angles: &[f64], rx: f64, ry: f64, at: Vec2) -> Vec<Vec2> {
        let mut t = angles.to_vec();
        t.sort_by(f64::total_cmp);
        t.iter().map(|t| at + Vec2::new(rx * t.cos(), ry * t.sin())).collect()
    }

    #[test]
    fn clean_input_takes_the_fast_path() {
        let pts = on_ellipse(&[0.0, 1.0, 2.0, 3.0, 4.0, 5.0], 2.0, 1.0, Vec2::new(1e6, -3.0));
        let fast = ConvexPolygon::already_clean(&pts, None).expect("clean");
        let slow = ConvexPolygon::slow_clean(&pts, &[0, 1, 2, 3, 4, 5]).expect("clean");
        assert_eq!(fast, slow);
        // Clockwise, a duplicate or a straight angle each go the slow way.
        let cw: Vec<Vec2> = pts.iter().rev().copied().collect();
        assert!(ConvexPolygon::already_clean(&cw, None).is_none());
        let mut dup = pts.clone();
        dup.insert(2, pts[1]);
        assert!(ConvexPolygon::already_clean(&dup, None).is_none());
        let mut straight = pts.clone();
        straight.insert(1, pts[0].lerp(pts[1], 0.5));
        assert!(ConvexPolygon::already_clean(&straight, None).is_none());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig {
            cases: 2000,
            failure_persistence: None,
            ..proptest::prelude::ProptestConfig::default()
        })]

        /// Whatever the fast path accepts, the slow path returns unchanged.
        #[test]
        fn the_fast_path_gives_the_slow_paths_polygon(
            angles in proptest::collection::vec(0.0..std::f64::consts::TAU, 3..70),
            rx in 1e-7..10.0f64, ry in 1e-7..10.0f64,
            x in -1e6..1e6f64, y in -1e6..1e6f64, far in proptest::bool::ANY,
            edit in 0usize..5, at in 0usize..70, grid in proptest::bool::ANY,
        ) {
            let centre = if far { Vec2::new(x, y) } else { Vec2::ZERO };
            let mut pts = on_ellipse(&angles, rx, ry, centre);
            if grid {
                // Snapped to a coarse grid: collinear runs, duplicates, reflex angles.
                pts = pts.iter().map(|p| Vec2::new((p.x * 4.0).round() / 4.0, (p.y * 4.0).round() / 4.0)).collect();
            }
            let k = at % pts.len();
            match edit {
                0 => pts.reverse(),
                1 => pts.insert(k, pts[k]),
                2 => { let mid = pts[k].lerp(pts[(k + 1) % pts.len()], 0.5); pts.insert(k + 1, mid); }
                3 => pts[k] = pts[k].lerp(centre, 1e-10),
                _ => {}
            }
            let sources: Vec<usize> = (0..pts.len()).collect();
            let slow = ConvexPolygon::slow_clean(&pts, &sources);
            if let Some(fast) = ConvexPolygon::already_clean(&pts, None) {
                proptest::prop_assert_eq!(Ok(fast), slow.clone());
            }
            proptest::prop_assert_eq!(ConvexPolygon::new(&pts), slow);
        }
    }

    #[test]
    fn contains_accepts_the_boundary() {
        let p = poly(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).expect("square");
        assert!(p.contains(Vec2::new(0.5, 0.5)));
        assert!(p.contains(Vec2::new(1.0, 0.3)));
        assert!(!p.contains(Vec2::new(1.0 + 1e-6, 0.3)));
    }
}
