//! The entrance block of two convex polygons, built by the paper's O(m + n)
//! walk, and the queries answered from its boundary.
//!
//! **Setting.** A moves by translation, B is fixed. The entrance block is the
//! set of positions of A's reference point `p` at which A touches or overlaps
//! B: `E(A, B) = B − A + p`, the Minkowski sum `B ⊕ (−A)` shifted by `p`.
//! Here `p` is A's first vertex as the caller gave it (the first input vertex
//! that survived cleaning); it only matters for [`EntranceBlock::boundary`],
//! which returns the block in the paper's coordinates.
//!
//! **Translation space.** Internally every boundary point is stored as
//! `t = b − a` (a point of B minus a point of A): the translation of A, from
//! where it was at build time, that brings those two points together. The
//! block in these coordinates is `B ⊕ (−A)` itself, the current position of
//! A is the origin, and the paper's reference point is never subtracted back
//! out. Every stored coordinate is the difference of two input points, so
//! polygons far from the origin (1e6) that are close to each other keep all
//! their significant digits.
//!
//! **The walk.** Start with A's top-right vertex against B's bottom-left one
//! (the pair whose contact point is the lowest point of the block), then step
//! in counter-clockwise order: whichever of the next edge of B (an
//! angle–edge cover: a vertex of A slides along an edge of B) or the next
//! edge of −A (an edge–angle cover: a vertex of B slides along an edge of A)
//! turns least comes first (compared by the polygons' precomputed unit
//! normals, so a step takes no square root). Parallel edges (same direction
//! within `1e-12` rad) are taken together as one edge–edge contact edge,
//! including a pair that rounding splits across the start. Every emitted
//! cover is valid in the paper's sense (formulas 5–6) by construction,
//! because it is taken exactly when its angle is reached, and the walk ends
//! after `m + n` edge steps, so it cannot loop on bad input.
//!
//! **Stored or not.** [`EntranceBlock`] stores the boundary (with the
//! features and points behind every edge) for repeated queries, e.g. by
//! [`CachedBlock`](super::cached::CachedBlock). A single query does not need
//! it: [`contact_report`] runs the same walk and keeps only the few covers
//! the answer can come from, about twice as fast at 64 vertices (writing
//! 128-byte edges is most of the stored build's cost), and walks only a
//! few covers where a separating axis or an expanding polytope has found
//! the part of the boundary the answer lies on.
//!
//! **Queries.** The current position of A is the origin `q = 0` (or any
//! translation `q` passed to [`EntranceBlock::report_at`]). `q` outside the
//! block → separated, and the distance to the boundary is the gap; on the
//! boundary → touching; inside → intersecting, and the nearest boundary point
//! is the shortest exit. The signed distance of `q` to a contact edge `e` is
//! the paper's `v · (q − e₁)` with `v` the unit outward normal (formula 8).

use super::polygon::ConvexPolygon;
use super::report::{ContactReport, Feature, Features, Relation};
use super::tolerance::scale_tolerance;
use super::vec2::Vec2;

/// Two edges whose directions differ by less than this (sine of the angle)
/// are treated as parallel. Merging them moves the boundary by at most
/// `1e-12 ×` the shorter edge, far inside every tolerance.
pub(crate) const PARALLEL: f64 = 1e-12;

/// Which pair of features a contact edge stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CoverKind {
    /// Vertex `a[0]` of A slides along edge `b[0] → b[1]` of B (formula 2).
    AngleEdge,
    /// Vertex `b[0]` of B slides along edge `a[0] → a[1]` of A (formula 3).
    EdgeAngle,
    /// Edge `a[0] → a[1]` of A slides along the parallel edge `b[0] → b[1]`
    /// of B: the angle–edge cover of `a[0]` followed by the edge–angle cover
    /// of `b[1]`, which are collinear.
    EdgeEdge,
}

/// One straight piece of the entrance block's boundary, in translation
/// space, keeping the pair of features that made it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactEdge {
    /// Translation of A that brings vertex `a[0]` onto vertex `b[0]`.
    pub start: Vec2,
    /// From `start` to the end of the edge. Taken from the polygons' own
    /// edge vectors (not `end − start`) so its direction is as exact as the
    /// input.
    pub direction: Vec2,
    /// Unit outward normal (the block is counter-clockwise).
    pub normal: Vec2,
    pub kind: CoverKind,
    /// Caller indices of A's vertex at `start` and of the next vertex of A.
    pub a: [usize; 2],
    /// Caller indices of B's vertex at `start` and of the next vertex of B.
    pub b: [usize; 2],
    /// A's vertex `a[0]` where A was at build time.
    pub a_point: Vec2,
    /// B's vertex `b[0]`.
    pub b_point: Vec2,
    /// For [`CoverKind::EdgeEdge`], the fraction of the edge's length that
    /// B's edge contributes (that part comes first); 1 for angle–edge and 0
    /// for edge–angle covers.
    pub split: f64,
}

impl ContactEdge {
    #[inline]
    pub fn end(&self) -> Vec2 {
        self.start + self.direction
    }

    /// The paper's signed distance `v · (q − e₁)`: positive outside.
    #[inline]
    pub fn plane_distance(&self, q: Vec2) -> f64 {
        self.normal.dot(q - self.start)
    }

    /// The point of this edge closest to `q`.
    #[inline]
    pub fn closest_point(&self, q: Vec2) -> Vec2 {
        let len2 = self.direction.length_squared();
        let t = if len2 > 0.0 { ((q - self.start).dot(self.direction) / len2).clamp(0.0, 1.0) } else { 0.0 };
        self.start + self.direction * t
    }
}

/// The nearest boundary point to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Nearest {
    pub(crate) edge: usize,
    pub(crate) point: Vec2,
    pub(crate) signed_distance: f64,
}

/// The entrance block `B ⊕ (−A)` of two convex polygons.
#[derive(Clone, Debug, PartialEq)]
pub struct EntranceBlock {
    reference: Vec2,
    edges: Vec<ContactEdge>,
    tolerance: f64,
}

impl EntranceBlock {
    /// Builds the boundary in O(m + n).
    pub fn new(a: &ConvexPolygon, b: &ConvexPolygon) -> Self {
        let (n, m) = (a.len(), b.len());
        let mut edges = Vec::with_capacity(n + m);
        let (mut i, mut j) = start_state(a, b);
        let (mut done_a, mut done_b) = (0, 0);
        let start = Cover { i, j, step: next_step(a, b, (i, j), 0, 0) };
        let mut last = start;
        while done_a < n || done_b < m {
            let step = next_step(a, b, (i, j), done_a, done_b);
            let cover = Cover { i, j, step };
            edges.push(contact_edge(a, b, cover));
            last = cover;
            if step != Step::A {
                j = if j + 1 == m { 0 } else { j + 1 };
                done_b += 1;
            }
            if step != Step::B {
                i = if i + 1 == n { 0 } else { i + 1 };
                done_a += 1;
            }
        }
        if let Some(joined) = join_straddle(a, b, last, start, edges.len()) {
            let end = edges.len() - 1;
            edges[end] = contact_edge(a, b, joined);
            edges.remove(0);
        }
        Self { reference: a.first_input_vertex(), edges, tolerance: pair_tolerance(a, b) }
    }

    /// The same block judged with another touching tolerance (the union of
    /// a concave pair's blocks uses the whole polygons' tolerance).
    pub fn with_tolerance(mut self, tolerance: f64) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// The reference point `p`: A's first input vertex (that survived
    /// cleaning) at build time.
    pub fn reference(&self) -> Vec2 {
        self.reference
    }

    /// The contact edges, counter-clockwise, in translation space.
    pub fn edges(&self) -> &[ContactEdge] {
        &self.edges
    }

    /// The touching tolerance (see [`pair_tolerance`]).
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The boundary's vertices in the paper's coordinates (positions of the
    /// reference point), counter-clockwise.
    pub fn boundary(&self) -> Vec<Vec2> {
        self.edges.iter().map(|e| e.start + self.reference).collect()
    }

    /// Everything about A where it was at build time.
    pub fn report(&self) -> ContactReport {
        self.report_at(Vec2::ZERO)
    }

    /// Everything about A moved by `translation` from where it was at build
    /// time. O(m + n).
    pub fn report_at(&self, translation: Vec2) -> ContactReport {
        let nearest = nearest_on_chain(&self.edges, translation);
        self.report_from(translation, nearest)
    }

    pub fn relation(&self) -> Relation {
        self.report().relation
    }

    pub fn signed_distance(&self) -> f64 {
        nearest_on_chain(&self.edges, Vec2::ZERO).signed_distance
    }

    pub fn exit(&self) -> Vec2 {
        nearest_on_chain(&self.edges, Vec2::ZERO).point
    }

    #[inline]
    pub(crate) fn report_from(&self, q: Vec2, nearest: Nearest) -> ContactReport {
        let edge = &self.edges[nearest.edge];
        let (witness, features) = contact_at(edge, nearest.point, q, self.tolerance);
        ContactReport {
            relation: Relation::from_signed_distance(nearest.signed_distance, self.tolerance),
            distance: nearest.signed_distance,
            exit: nearest.point - q,
            witness,
            features,
            tolerance: self.tolerance,
        }
    }
}

/// One step of the walk: the state `(i, j)` (vertex `aᵢ` of A on vertex
/// `bⱼ` of B at the cover's start) and which edge moves on. Small on
/// purpose: the one-shot query never builds the full [`ContactEdge`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Cover {
    pub(crate) i: usize,
    pub(crate) j: usize,
    pub(crate) step: Step,
}

/// Where the walk starts. The lowest point of `B ⊕ (−A)` is B's lowest
/// vertex minus A's highest; ties go to B's leftmost and A's rightmost, so
/// that both chains of edges start at an angle in [0, π) and increase to
/// below 2π.
fn start_state(a: &ConvexPolygon, b: &ConvexPolygon) -> (usize, usize) {
    let i = extreme(a.vertices(), |p, q| p.y > q.y || (p.y == q.y && p.x > q.x));
    let j = extreme(b.vertices(), |p, q| p.y < q.y || (p.y == q.y && p.x < q.x));
    (i, j)
}

/// One step of the merge from state `(i, j)` with `done_a` edges of −A and
/// `done_b` of B already used. Ordered by the unit normals, which turn
/// exactly as the edges do (a quarter turn preserves cross products and
/// half-planes) and need no lengths for the parallel test; −A's edge is A's
/// edge turned round, so its normal is minus A's.
#[inline]
fn next_step(a: &ConvexPolygon, b: &ConvexPolygon, (i, j): (usize, usize), done_a: usize, done_b: usize) -> Step {
    if done_a == a.len() {
        Step::B
    } else if done_b == b.len() {
        Step::A
    } else {
        order(b.normals()[j], -a.normals()[i])
    }
}

/// The last and first covers joined, when they are a parallel pair
/// straddling the start: B's first edge at angle 0 and −A's last at 2π
/// minus a rounding, or the other way round. They are one edge–edge cover,
/// and that cover is exactly the parallel step the walk would have taken
/// from `last`'s state (its start is `b[0] − a[0]`, its end `b[1] − a[1]`,
/// whichever part came first). `count` covers were emitted; a block keeps
/// at least three.
fn join_straddle(a: &ConvexPolygon, b: &ConvexPolygon, last: Cover, first: Cover, count: usize) -> Option<Cover> {
    let straddle = matches!((last.step, first.step), (Step::A, Step::B) | (Step::B, Step::A))
        && count >= 4
        && parallel(cover_normal(a, b, last), cover_normal(a, b, first));
    straddle.then_some(Cover { step: Step::Both, ..last })
}

#[inline]
fn cover_normal(a: &ConvexPolygon, b: &ConvexPolygon, c: Cover) -> Vec2 {
    match c.step {
        Step::A => -a.normals()[c.i],
        Step::B | Step::Both => b.normals()[c.j],
    }
}

/// The full contact edge of a cover.
#[inline]
pub(crate) fn contact_edge(a: &ConvexPolygon, b: &ConvexPolygon, c: Cover) -> ContactEdge {
    let (av, bv) = (a.vertices(), b.vertices());
    let i1 = if c.i + 1 == av.len() { 0 } else { c.i + 1 };
    let j1 = if c.j + 1 == bv.len() { 0 } else { c.j + 1 };
    let (edge_b, edge_a) = (bv[j1] - bv[c.j], av[c.i] - av[i1]);
    let (kind, direction, split) = match c.step {
        Step::B => (CoverKind::AngleEdge, edge_b, 1.0),
        Step::A => (CoverKind::EdgeAngle, edge_a, 0.0),
        Step::Both => {
            let (lb, la) = (edge_b.length(), edge_a.length());
            (CoverKind::EdgeEdge, edge_b + edge_a, lb / (lb + la))
        }
    };
    ContactEdge {
        start: bv[c.j] - av[c.i],
        direction,
        normal: cover_normal(a, b, c),
        kind,
        a: [a.source_index(c.i), a.source_index(i1)],
        b: [b.source_index(c.j), b.source_index(j1)],
        a_point: av[c.i],
        b_point: bv[c.j],
        split,
    }
}

/// A contact query answered during the walk (for pairs the separated-pair
/// exit did not settle, see [`crate::contact::contact_report`]), without storing the block:
/// the same answers as `EntranceBlock::new(a, b).report()` for a single
/// query (the block is worth building only to ask again). It keeps the
/// cover farthest out (with its two neighbours) for the inside case and the
/// nearest cover facing A's position for the outside case: the paper's
/// "only the part of the boundary near p". Written as its own plain loop
/// rather than by sharing an iterator or callback with
/// [`EntranceBlock::new`]: at 64 vertices that bookkeeping would cost as
/// much as the geometry.
pub(crate) fn walk_report(a: &ConvexPolygon, b: &ConvexPolygon, tolerance: f64) -> ContactReport {
    let (av, bv, na, nb) = (a.vertices(), b.vertices(), a.normals(), b.normals());
    let (n, m) = (av.len(), bv.len());
    let (mut i, mut j) = start_state(a, b);
    let (mut done_a, mut done_b) = (0, 0);
    // Inside: the cover farthest out and its neighbours.
    let mut max_g = f64::NEG_INFINITY;
    let mut best = Cover { i, j, step: Step::B };
    let (mut before, mut after): (Option<Cover>, Option<Cover>) = (None, None);
    let mut want_after = false;
    let (mut first, mut previous): (Option<Cover>, Option<Cover>) = (None, None);
    // Outside: the nearest of the covers that face A's position (origin).
    let (mut out_d2, mut out_cover, mut out_point) = (f64::INFINITY, best, Vec2::ZERO);
    let mut count = 0;
    while done_a < n || done_b < m {
        let i1 = if i + 1 == n { 0 } else { i + 1 };
        let j1 = if j + 1 == m { 0 } else { j + 1 };
        let step = next_step(a, b, (i, j), done_a, done_b);
        let cover = Cover { i, j, step };
        let start = bv[j] - av[i];
        let g = -(if step == Step::A { -na[i] } else { nb[j] }).dot(start);
        if want_after {
            after = Some(cover);
            want_after = false;
        }
        if g > max_g {
            (max_g, best, before, want_after) = (g, cover, previous, true);
        }
        if g > -tolerance {
            let direction = match step {
                Step::B => bv[j1] - bv[j],
                Step::A => av[i] - av[i1],
                Step::Both => (bv[j1] - bv[j]) + (av[i] - av[i1]),
            };
            let t = (-start.dot(direction) / direction.length_squared()).clamp(0.0, 1.0);
            let p = start + direction * t;
            let d2 = p.length_squared();
            if d2 < out_d2 {
                (out_d2, out_cover, out_point) = (d2, cover, p);
            }
        }
        if first.is_none() {
            first = Some(cover);
        }
        previous = Some(cover);
        count += 1;
        if step != Step::A {
            j = j1;
            done_b += 1;
        }
        if step != Step::B {
            i = i1;
            done_a += 1;
        }
    }
    if want_after {
        after = first;
    }
    before = before.or(previous);
    // The walk's join of a parallel pair straddling the start.
    let joined = match (previous, first) {
        (Some(last), Some(first)) => join_straddle(a, b, last, first, count),
        _ => None,
    };
    let join = |c: Cover| match joined {
        Some(merged) if Some(c) == first || Some(c) == previous => merged,
        _ => c,
    };
    let (cover, point, signed) = if max_g > 0.0 {
        (join(out_cover), out_point, out_d2.sqrt())
    } else {
        let mut pick = (f64::INFINITY, best, Vec2::ZERO);
        for c in [before, Some(best), after].into_iter().flatten() {
            let p = contact_edge(a, b, join(c)).closest_point(Vec2::ZERO);
            let d2 = p.length_squared();
            if d2 < pick.0 {
                pick = (d2, join(c), p);
            }
        }
        (pick.1, pick.2, -pick.0.sqrt())
    };
    cover_report(a, b, cover, point, signed, tolerance)
}

/// The one-shot report for A's position (the origin) whose nearest block
/// boundary point `point` lies on `cover`, `signed` from it: what the full
/// walk and both early exits return.
pub(crate) fn cover_report(
    a: &ConvexPolygon,
    b: &ConvexPolygon,
    cover: Cover,
    point: Vec2,
    signed: f64,
    tolerance: f64,
) -> ContactReport {
    let (witness, features) = contact_at(&contact_edge(a, b, cover), point, Vec2::ZERO, tolerance);
    ContactReport {
        relation: Relation::from_signed_distance(signed, tolerance),
        distance: signed,
        exit: point,
        witness,
        features,
        tolerance,
    }
}

/// The touching tolerance of a pair: [`scale_tolerance`] of the *smaller*
/// extent (a gap that is a billionth of the smaller polygon is a touch) and
/// of the largest coordinate or extent (our arithmetic and the caller's
/// rounding grow with those).
pub fn pair_tolerance(a: &ConvexPolygon, b: &ConvexPolygon) -> f64 {
    let size = a.extent().min(b.extent());
    let magnitude = a.magnitude().max(b.magnitude()).max(a.extent()).max(b.extent());
    scale_tolerance(size, magnitude)
}

/// The index of the vertex that beats every other under `better`.
fn extreme(points: &[Vec2], better: impl Fn(Vec2, Vec2) -> bool) -> usize {
    let mut best = 0;
    for (i, &p) in points.iter().enumerate().skip(1) {
        if better(p, points[best]) {
            best = i;
        }
    }
    best
}

/// Whether two unit normals point the same way within [`PARALLEL`].
pub(crate) fn parallel(u: Vec2, v: Vec2) -> bool {
    u.cross(v).abs() <= PARALLEL && u.dot(v) > 0.0
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Step {
    /// Take B's edge: an angle–edge cover.
    B,
    /// Take −A's edge: an edge–angle cover.
    A,
    /// Parallel: an edge–edge contact edge.
    Both,
}

/// Which of two edges comes first counter-clockwise, given their unit
/// outward normals (an edge's direction is its normal turned a quarter
/// counter-clockwise, so the order of normals is the order of edges).
/// Parallel is tested first: two directions a rounding apart may straddle
/// the ±x axis that separates the half-planes (the 10-gon's bottom edge
/// against a horizontal edge is the paper's own example). Otherwise,
/// comparing half-planes first makes this a total order on [0, 2π) rather
/// than the cross product's "within π of each other".
fn order(normal_b: Vec2, normal_a: Vec2) -> Step {
    if parallel(normal_b, normal_a) {
        return Step::Both;
    }
    let (hb, ha) = (half_plane(normal_b), half_plane(normal_a));
    if hb != ha {
        return if hb < ha { Step::B } else { Step::A };
    }
    if normal_b.cross(normal_a) > 0.0 { Step::B } else { Step::A }
}

/// 0 when the edge whose outward normal is `n` points into [0, π), 1 for
/// [π, 2π). The edge's direction is `(−n.y, n.x)`; normalising kept every
/// sign, so this agrees exactly with the half-plane of the edge vector.
fn half_plane(n: Vec2) -> u8 {
    u8::from(!(n.x > 0.0 || (n.x == 0.0 && n.y < 0.0)))
}

/// The nearest point of a convex boundary to `q`, by linear scan. The edges
/// need not be ordered or disjoint (the brute force passes every valid
/// cover, and parallel covers overlap), only cover the boundary.
///
/// The sign comes from the largest plane distance `g` (positive only
/// outside a convex region). Outside, the nearest point lies on an edge
/// that faces `q` (at a vertex, at least one of its two edges does);
/// inside, it is the foot on the nearest supporting line. Either way only
/// the edges with `g` within `slack` of the test are measured as segments:
/// the slack keeps a collinear edge that rounding put a hair on the wrong
/// side (near-straight corners, the brute force's overlapping covers),
/// and costs nothing else.
pub(crate) fn nearest_on_boundary(edges: &[ContactEdge], q: Vec2, slack: f64) -> Nearest {
    let mut max_g = f64::NEG_INFINITY;
    for e in edges {
        max_g = max_g.max(e.plane_distance(q));
    }
    let outside = max_g > 0.0;
    let threshold = if outside { -slack } else { max_g - slack };
    let mut nearest = Nearest { edge: 0, point: q, signed_distance: 0.0 };
    let mut best_d2 = f64::INFINITY;
    for (k, e) in edges.iter().enumerate() {
        if e.plane_distance(q) < threshold {
            continue;
        }
        let p = e.closest_point(q);
        let d2 = (q - p).length_squared();
        if d2 < best_d2 {
            best_d2 = d2;
            nearest = Nearest { edge: k, point: p, signed_distance: 0.0 };
        }
    }
    let d = best_d2.sqrt();
    nearest.signed_distance = if outside { d } else { -d };
    nearest
}

/// [`nearest_on_boundary`] for a block's own boundary, whose edges form one
/// convex chain in order: after one pass for the largest plane distance,
/// the nearest edge is found near the largest one instead of by a second
/// full pass. Inside, the foot on the farthest-out line lies on that edge
/// (its neighbours are checked for rounding at near-straight corners).
/// Outside, the distance along the chain of edges facing `q` falls then
/// rises (a convex set seen from outside), so walking downhill from the
/// facing edge with the largest plane distance reaches the minimum.
pub(crate) fn nearest_on_chain(edges: &[ContactEdge], q: Vec2) -> Nearest {
    let (mut max_g, mut k) = (f64::NEG_INFINITY, 0);
    for (i, e) in edges.iter().enumerate() {
        let g = e.plane_distance(q);
        if g > max_g {
            (max_g, k) = (g, i);
        }
    }
    nearest_from_farthest(edges, q, k, max_g)
}

/// The rest of [`nearest_on_chain`] once its first pass is done: `k` is
/// the first edge with the largest plane distance, `max_g` that distance.
/// [`CachedBlock`](super::cached::CachedBlock) finds them by a search
/// instead of a pass and finishes here, so that its answer is this one.
#[inline]
pub(crate) fn nearest_from_farthest(edges: &[ContactEdge], q: Vec2, k: usize, max_g: f64) -> Nearest {
    let n = edges.len();
    let measure = |i: usize| {
        let p = edges[i].closest_point(q);
        ((q - p).length_squared(), p)
    };
    let (mut best_d2, mut point) = measure(k);
    let mut best = k;
    if max_g > 0.0 {
        for step in [1, n - 1] {
            loop {
                let next = wrap(best + step, n);
                let (d2, p) = measure(next);
                if d2 < best_d2 {
                    (best, best_d2, point) = (next, d2, p);
                } else {
                    break;
                }
            }
        }
    } else {
        for i in [wrap(k + n - 1, n), wrap(k + 1, n)] {
            // A neighbour whose line lies farther than the nearest point so
            // far, by more than any rounding of either, has no point nearer:
            // it is not measured (a division saved), and would not be taken.
            let e = &edges[i];
            let beyond = -e.plane_distance(q) - 1e-9 * (q.max_abs() + e.start.max_abs() + e.direction.max_abs());
            if beyond > 0.0 && beyond * beyond > best_d2 {
                continue;
            }
            let (d2, p) = measure(i);
            if d2 < best_d2 {
                (best, best_d2, point) = (i, d2, p);
            }
        }
    }
    let d = best_d2.sqrt();
    Nearest { edge: best, point, signed_distance: if max_g > 0.0 { d } else { -d } }
}

/// `i mod n` for `i < 2n`, by one comparison rather than a division (the
/// division dominated the O(log n) searches that step round the chain).
#[inline]
pub(crate) fn wrap(i: usize, n: usize) -> usize {
    if i >= n { i - n } else { i }
}

/// Witness points and features for the boundary point `point` of `edge`,
/// A being at translation `q`.
#[inline]
pub(crate) fn contact_at(edge: &ContactEdge, point: Vec2, q: Vec2, tol: f64) -> ([Vec2; 2], Features) {
    let len2 = edge.direction.length_squared();
    let len = len2.sqrt();
    let t = if len2 > 0.0 { ((point - edge.start).dot(edge.direction) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let along = t * len;
    let exit = point - q;
    let mut features = Features::new();
    let witness = match edge.kind {
        CoverKind::AngleEdge => {
            features.push(if along <= tol {
                Feature::AngleAngle { a_vertex: edge.a[0], b_vertex: edge.b[0] }
            } else if len - along <= tol {
                Feature::AngleAngle { a_vertex: edge.a[0], b_vertex: edge.b[1] }
            } else {
                Feature::AngleEdge { a_vertex: edge.a[0], b_edge: edge.b }
            });
            [edge.a_point + q, edge.b_point + edge.direction * t]
        }
        CoverKind::EdgeAngle => {
            features.push(if along <= tol {
                Feature::AngleAngle { a_vertex: edge.a[0], b_vertex: edge.b[0] }
            } else if len - along <= tol {
                Feature::AngleAngle { a_vertex: edge.a[1], b_vertex: edge.b[0] }
            } else {
                Feature::EdgeAngle { a_edge: edge.a, b_vertex: edge.b[0] }
            });
            [edge.a_point - edge.direction * t + q, edge.b_point]
        }
        CoverKind::EdgeEdge => {
            // Along B's edge (0 at b[0], lb at b[1]) A's edge runs from a[1]
            // at u − la up to a[0] at u; they share [lower, upper].
            let lb = edge.split * len;
            let la = len - lb;
            let u = along;
            let lower = (u - la).max(0.0);
            let upper = u.min(lb);
            let classify = |x: f64| {
                let a_vertex = if (x - u).abs() <= tol {
                    Some(edge.a[0])
                } else if (x - (u - la)).abs() <= tol {
                    Some(edge.a[1])
                } else {
                    None
                };
                let b_vertex = if x.abs() <= tol {
                    Some(edge.b[0])
                } else if (x - lb).abs() <= tol {
                    Some(edge.b[1])
                } else {
                    None
                };
                match (a_vertex, b_vertex) {
                    (Some(a_vertex), Some(b_vertex)) => Feature::AngleAngle { a_vertex, b_vertex },
                    (Some(a_vertex), None) => Feature::AngleEdge { a_vertex, b_edge: edge.b },
                    (None, Some(b_vertex)) => Feature::EdgeAngle { a_edge: edge.a, b_vertex },
                    // Unreachable: `lower` is 0 or u − la and `upper` is u
                    // or lb, each exactly a vertex position.
                    (None, None) => Feature::EdgeAngle { a_edge: edge.a, b_vertex: edge.b[0] },
                }
            };
            features.push(classify(lower));
            if upper - lower > tol {
                features.push(classify(upper));
            }
            let mid = 0.5 * (lower + upper);
            let b_on_edge = if len > 0.0 { edge.b_point + edge.direction * (mid / len) } else { edge.b_point };
            [b_on_edge - exit, b_on_edge]
        }
    };
    (witness, features)
}

#[cfg(test)]
mod tests {
    use super::{CoverKind, EntranceBlock};
    use crate::contact::polygon::ConvexPolygon;
    use crate::contact::report::Relation;
    use crate::contact::vec2::Vec2;

    fn square(x: f64, y: f64, s: f64) -> ConvexPolygon {
        ConvexPolygon::from_xy(&[[x, y], [x + s, y], [x + s, y + s], [x, y + s]]).expect("square")
    }

    #[test]
    fn two_axis_aligned_squares_give_a_square_block_of_edge_edge_covers() {
        let block = EntranceBlock::new(&square(0.0, 0.0, 1.0), &square(3.0, 0.0, 2.0));
        assert_eq!(block.edges().len(), 4);
        assert!(block.edges().iter().all(|e| e.kind == CoverKind::EdgeEdge));
        // Translations that make them touch: x ∈ [2, 5], y ∈ [-1, 2].
        let mut corners: Vec<Vec2> = block.edges().iter().map(|e| e.start).collect();
        // Counter-clockwise from wherever the walk put its first edge.
        let lowest_left = corners.iter().position(|&c| c == Vec2::new(2.0, -1.0)).expect("corner");
        corners.rotate_left(lowest_left);
        assert_eq!(corners, vec![Vec2::new(2.0, -1.0), Vec2::new(5.0, -1.0), Vec2::new(5.0, 2.0), Vec2::new(2.0, 2.0)]);
        let r = block.report();
        assert_eq!(r.relation, Relation::Separated);
        assert_eq!(r.distance, 2.0);
        assert_eq!(r.exit, Vec2::new(2.0, 0.0));
    }

    #[test]
    fn the_walk_emits_m_plus_n_covers_without_parallel_edges() {
        let a = ConvexPolygon::from_xy(&[[0.0, 0.0], [1.0, 0.1], [0.3, 0.9]]).expect("triangle");
        let b = ConvexPolygon::from_xy(&[[2.0, 0.0], [3.0, 0.5], [2.2, 1.3], [1.9, 0.7]]).expect("quad");
        let block = EntranceBlock::new(&a, &b);
        assert_eq!(block.edges().len(), 7);
        let angle_edge = block.edges().iter().filter(|e| e.kind == CoverKind::AngleEdge).count();
        assert_eq!(angle_edge, 4);
        // Consecutive edges join up.
        let edges = block.edges();
        for k in 0..edges.len() {
            let gap = (edges[k].end() - edges[(k + 1) % edges.len()].start).length();
            assert!(gap < 1e-12, "edge {k} leaves a gap of {gap}");
        }
    }
}
