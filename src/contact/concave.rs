//! Concave (simple) polygons: convex decomposition and the union of the
//! pieces' entrance blocks. The paper leaves concave polygons open; this is
//! the standard reduction.
//!
//! **Decomposition.** The cleaned ring (same cleaning as
//! [`ConvexPolygon`]) must be simple: no two non-adjacent edges within the
//! tolerance of each other (O(n²) check, skipped when the ring is already
//! convex). It is ear-clipped into triangles, then Hertel–Mehlhorn merges
//! neighbours across every diagonal whose removal leaves both end angles
//! convex (at most 4× the optimal number of pieces, O(n) merges after an
//! O(n²)–O(n³) ear clipping — meant for footprints of tens to hundreds of
//! vertices, not thousands). A non-convex ring of more than
//! [`MAX_CONCAVE_VERTICES`] vertices after cleaning is refused with
//! [`PolygonError::TooManyVertices`] instead of running for seconds; convex
//! rings of any size are not decomposed and have no limit.
//!
//! **Union.** A + t meets B exactly when some piece of A + t meets some
//! piece of B, so the set of overlapping translations is the union `U` of the
//! pieces' entrance blocks `Bⱼ ⊕ (−Aᵢ)`. What [`UnionBlock`] computes:
//! * relation — intersecting if the origin is inside some block by more
//!   than the tolerance; else touching if it is within the tolerance of
//!   one; else separated;
//! * separated: distance, exit, witness and features of the nearest block
//!   (min over the pieces — exact);
//! * intersecting: the shortest translation after which *no* pair of pieces
//!   overlaps, i.e. the nearest point of `U`'s boundary. Every edge of every
//!   block is clipped against the interior of every other block (shrunk by
//!   a rounding-level slack `s = 8 ε · magnitude`, so edges shared between
//!   blocks survive), and the nearest surviving point wins. This handles
//!   holes in `U` (a small A that fits a pocket of B) and is exact up to
//!   rounding: where an edge enters another block at a grazing angle θ the
//!   surviving end can sit `s / sin θ` inside it, so the exit may be that
//!   much too short. Cost O(E²) for E contact edges in all blocks.
//!
//! Features index the caller's input vertices; an edge of a piece may be a
//! diagonal of the decomposition, but a point of `U`'s boundary never lies
//! on a diagonal-only cover when A has area, so reported edges are real.

use std::collections::HashMap;

use super::entrance_block::{ContactEdge, EntranceBlock, Nearest, nearest_on_boundary};
use super::error::{ContactError, PolygonError};
use super::polygon::{ConvexPolygon, Ring, Turn, turn};
use super::report::{ContactReport, Relation};
use super::tolerance::scale_tolerance;
use super::vec2::Vec2;

/// The most vertices (after cleaning) a non-convex ring may have. The
/// simplicity check and the ear clipping grow at least quadratically:
/// through `surfacelab contact --concave`, an alternating-radius star of
/// 2,000 vertices against a small square answers within a fraction of a
/// second, and one four times as large takes seconds.
pub const MAX_CONCAVE_VERTICES: usize = 2_000;

/// A simple polygon (convex or not), cleaned, with its convex pieces.
#[derive(Clone, Debug)]
pub struct SimplePolygon {
    vertices: Vec<Vec2>,
    source: Vec<usize>,
    pieces: Vec<ConvexPolygon>,
    convex: bool,
    extent: f64,
    magnitude: f64,
}

impl SimplePolygon {
    /// Cleans `points` (either winding) and decomposes it.
    pub fn new(points: &[Vec2]) -> Result<Self, PolygonError> {
        let sources: Vec<usize> = (0..points.len()).collect();
        let ring = match Ring::clean(points, &sources) {
            Ok(ring) => ring,
            // A bow tie has zero area; say what is really wrong with it.
            Err(PolygonError::ZeroArea) => {
                check_simple(&Ring::weld(points, &sources)?)?;
                return Err(PolygonError::ZeroArea);
            }
            Err(e) => return Err(e),
        };
        let n = ring.points.len();
        let mut convex = true;
        for i in 0..n {
            match ring.turn_at(i) {
                Turn::Convex | Turn::Straight => {}
                Turn::Reflex => convex = false,
                Turn::Fold => {
                    return Err(PolygonError::FoldsBack { vertex: ring.source[i] });
                }
            }
        }
        // A convex ring that winds once is simple; anything else is checked.
        let whole = if convex { ConvexPolygon::with_sources(&ring.points, &ring.source).ok() } else { None };
        let pieces = if let Some(piece) = whole {
            vec![piece]
        } else {
            convex = false;
            if n > MAX_CONCAVE_VERTICES {
                return Err(PolygonError::TooManyVertices { vertices: n, limit: MAX_CONCAVE_VERTICES });
            }
            check_simple(&ring)?;
            decompose(&ring)?
        };
        Ok(Self {
            vertices: ring.points,
            source: ring.source,
            pieces,
            convex,
            extent: ring.extent,
            magnitude: ring.magnitude,
        })
    }

    /// [`SimplePolygon::new`] from `[x, y]` pairs.
    pub fn from_xy(points: &[[f64; 2]]) -> Result<Self, PolygonError> {
        let points: Vec<Vec2> = points.iter().copied().map(Vec2::from).collect();
        Self::new(&points)
    }

    /// [`SimplePolygon::new`] with the polygon's name in the error.
    pub fn named(name: &str, points: &[Vec2]) -> Result<Self, ContactError> {
        Self::new(points).map_err(|problem| ContactError::polygon(name, problem))
    }

    /// The cleaned ring, counter-clockwise.
    pub fn vertices(&self) -> &[Vec2] {
        &self.vertices
    }

    pub fn source_indices(&self) -> &[usize] {
        &self.source
    }

    /// Convex pieces whose union is the polygon (one piece if it is convex).
    pub fn pieces(&self) -> &[ConvexPolygon] {
        &self.pieces
    }

    pub fn is_convex(&self) -> bool {
        self.convex
    }

    pub fn extent(&self) -> f64 {
        self.extent
    }

    pub fn magnitude(&self) -> f64 {
        self.magnitude
    }
}

/// No two non-adjacent edges may come within the tolerance of each other.
fn check_simple(ring: &Ring) -> Result<(), PolygonError> {
    let p = &ring.points;
    let n = p.len();
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue; // adjacent across the wrap
            }
            if segment_distance(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]) <= ring.tolerance {
                return Err(PolygonError::SelfIntersecting { first: ring.source[i], second: ring.source[j] });
            }
        }
    }
    Ok(())
}

fn segment_distance(a0: Vec2, a1: Vec2, b0: Vec2, b1: Vec2) -> f64 {
    let side = |p: Vec2, q: Vec2, r: Vec2| (q - p).cross(r - p);
    let (d1, d2) = (side(a0, a1, b0), side(a0, a1, b1));
    let (d3, d4) = (side(b0, b1, a0), side(b0, b1, a1));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        return 0.0;
    }
    let point_segment = |p: Vec2, s: Vec2, e: Vec2| {
        let d = e - s;
        let t = ((p - s).dot(d) / d.length_squared()).clamp(0.0, 1.0);
        (p - (s + d * t)).length()
    };
    point_segment(a0, b0, b1)
        .min(point_segment(a1, b0, b1))
        .min(point_segment(b0, a0, a1))
        .min(point_segment(b1, a0, a1))
}

/// Ear clipping, then Hertel–Mehlhorn merging.
fn decompose(ring: &Ring) -> Result<Vec<ConvexPolygon>, PolygonError> {
    let p = &ring.points;
    let triangles = ear_clip(ring);
    let pieces = merge_triangles(ring, &triangles);
    let mut out = Vec::new();
    for piece in pieces.into_iter().flatten() {
        let points: Vec<Vec2> = piece.iter().map(|&i| p[i]).collect();
        let sources: Vec<usize> = piece.iter().map(|&i| ring.source[i]).collect();
        match ConvexPolygon::with_sources(&points, &sources) {
            Ok(convex) => out.push(convex),
            // A sliver thinner than the tolerance covers nothing worth a piece.
            Err(PolygonError::ZeroArea | PolygonError::TooFewPoints { .. }) => {}
            Err(e) => return Err(e),
        }
    }
    if out.is_empty() {
        return Err(PolygonError::ZeroArea);
    }
    Ok(out)
}

/// The ring cut into triangles by ear clipping, as vertex indices.
fn ear_clip(ring: &Ring) -> Vec<[usize; 3]> {
    let p = &ring.points;
    let tol = ring.slack();
    let mut chain: Vec<usize> = (0..p.len()).collect();
    let mut triangles: Vec<[usize; 3]> = Vec::new();
    while chain.len() > 3 {
        let m = chain.len();
        let mut clipped = false;
        for k in 0..m {
            let (u, v, w) = (chain[(k + m - 1) % m], chain[k], chain[(k + 1) % m]);
            match turn(p[u], p[v], p[w], tol) {
                // A straight vertex of the remaining chain is dropped without
                // a triangle (the pieces then meet at a T, which the union
                // does not mind).
                Turn::Straight => {
                    chain.remove(k);
                    clipped = true;
                    break;
                }
                Turn::Convex => {}
                Turn::Reflex | Turn::Fold => continue,
            }
            let blocked = chain
                .iter()
                .any(|&x| x != u && x != v && x != w && in_triangle(p[x], p[u], p[v], p[w], ring.tolerance));
            if !blocked {
                triangles.push([u, v, w]);
                chain.remove(k);
                clipped = true;
                break;
            }
        }
        if !clipped {
            // Only rounding can leave a simple polygon without an ear: clip
            // the most convex vertex so the decomposition still terminates.
            let k = (0..m).max_by(|&x, &y| height(p, &chain, x).total_cmp(&height(p, &chain, y))).unwrap_or(0);
            triangles.push([chain[(k + m - 1) % m], chain[k], chain[(k + 1) % m]]);
            chain.remove(k);
        }
    }
    if chain.len() == 3 && turn(p[chain[0]], p[chain[1]], p[chain[2]], tol) == Turn::Convex {
        triangles.push([chain[0], chain[1], chain[2]]);
    }
    triangles
}

/// Hertel–Mehlhorn: neighbouring triangles merged across every diagonal
/// whose removal keeps the piece convex, each diagonal tried once.
fn merge_triangles(ring: &Ring, triangles: &[[usize; 3]]) -> Vec<Option<Vec<usize>>> {
    let p = &ring.points;
    let tol = ring.slack();
    let mut pieces: Vec<Option<Vec<usize>>> = triangles.iter().map(|t| Some(t.to_vec())).collect();
    let mut owner: HashMap<(usize, usize), usize> = HashMap::new();
    for (id, t) in triangles.iter().enumerate() {
        for k in 0..3 {
            owner.insert((t[k], t[(k + 1) % 3]), id);
        }
    }
    let mut diagonals: Vec<(usize, usize)> =
        owner.keys().copied().filter(|&(u, v)| u < v && owner.contains_key(&(v, u))).collect();
    diagonals.sort_unstable();
    for (u, v) in diagonals {
        let (Some(&pi), Some(&qi)) = (owner.get(&(u, v)), owner.get(&(v, u))) else {
            continue;
        };
        if pi == qi {
            continue;
        }
        let (Some(pp), Some(qq)) = (pieces[pi].as_ref(), pieces[qi].as_ref()) else {
            continue;
        };
        // pp holds u → v, qq holds v → u. Merged: pp from v round to u, then
        // qq strictly between u and v.
        let merged = merge_across(pp, qq, u, v);
        let len = merged.len();
        let pos_u = merged.iter().position(|&x| x == u).unwrap_or(0);
        let ok = [pos_u, 0].iter().all(|&at| {
            let t = turn(p[merged[(at + len - 1) % len]], p[merged[at]], p[merged[(at + 1) % len]], tol);
            matches!(t, Turn::Convex | Turn::Straight)
        });
        if ok {
            for k in 0..len {
                owner.insert((merged[k], merged[(k + 1) % len]), pi);
            }
            owner.remove(&(u, v));
            owner.remove(&(v, u));
            pieces[pi] = Some(merged);
            pieces[qi] = None;
        }
    }
    pieces
}

fn merge_across(pp: &[usize], qq: &[usize], u: usize, v: usize) -> Vec<usize> {
    let start_v = pp.iter().position(|&x| x == v).unwrap_or(0);
    let start_u = qq.iter().position(|&x| x == u).unwrap_or(0);
    let mut merged: Vec<usize> = (0..pp.len()).map(|k| pp[(start_v + k) % pp.len()]).collect();
    merged.extend((1..qq.len() - 1).map(|k| qq[(start_u + k) % qq.len()]));
    merged
}

fn height(p: &[Vec2], chain: &[usize], k: usize) -> f64 {
    let m = chain.len();
    let (u, v, w) = (p[chain[(k + m - 1) % m]], p[chain[k]], p[chain[(k + 1) % m]]);
    (v - u).cross(w - v) / (w - u).length().max(f64::MIN_POSITIVE)
}

/// Inside or within `tol` of the counter-clockwise triangle `a b c`.
fn in_triangle(x: Vec2, a: Vec2, b: Vec2, c: Vec2, tol: f64) -> bool {
    [(a, b), (b, c), (c, a)].iter().all(|&(s, e)| (e - s).cross(x - s) >= -tol * (e - s).length())
}

/// The union of the entrance blocks of every pair of pieces.
#[derive(Clone, Debug)]
pub struct UnionBlock {
    blocks: Vec<EntranceBlock>,
    tolerance: f64,
    /// How deep inside another block a boundary point must be to count as
    /// covered: rounding level only (the rounding part of the tolerance),
    /// so that blocks sharing a boundary line keep it, while a crossing is
    /// placed within `slack / sin θ` of where it really is.
    slack: f64,
}

impl UnionBlock {
    pub fn new(a: &SimplePolygon, b: &SimplePolygon) -> Self {
        let size = a.extent().min(b.extent());
        let magnitude = a.magnitude().max(b.magnitude()).max(a.extent()).max(b.extent());
        let tolerance = scale_tolerance(size, magnitude);
        let slack = scale_tolerance(0.0, magnitude);
        let blocks = a
            .pieces()
            .iter()
            .flat_map(|pa| b.pieces().iter().map(move |pb| EntranceBlock::new(pa, pb).with_tolerance(tolerance)))
            .collect();
        Self { blocks, tolerance, slack }
    }

    pub fn blocks(&self) -> &[EntranceBlock] {
        &self.blocks
    }

    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    pub fn report(&self) -> ContactReport {
        self.report_at(Vec2::ZERO)
    }

    /// The report with A moved by `translation` (see the module docs for
    /// what the exit means here).
    pub fn report_at(&self, translation: Vec2) -> ContactReport {
        let q = translation;
        let nearest: Vec<Nearest> =
            self.blocks.iter().map(|b| nearest_on_boundary(b.edges(), q, self.tolerance)).collect();
        let (closest, deepest) = nearest
            .iter()
            .enumerate()
            .min_by(|x, y| x.1.signed_distance.total_cmp(&y.1.signed_distance))
            .map_or((0, f64::INFINITY), |(i, n)| (i, n.signed_distance));
        if deepest >= -self.tolerance {
            return self.blocks[closest].report_from(q, nearest[closest]);
        }
        let mut best: Option<(usize, Nearest)> = None;
        let mut best_d2 = f64::INFINITY;
        for (bi, block) in self.blocks.iter().enumerate() {
            for (ei, edge) in block.edges().iter().enumerate() {
                let covered: Vec<(f64, f64)> = self
                    .blocks
                    .iter()
                    .enumerate()
                    .filter(|&(bj, _)| bj != bi)
                    .filter_map(|(_, other)| inside_interval(edge, other.edges(), self.slack))
                    .collect();
                if let Some(t) = nearest_uncovered(edge, &covered, q) {
                    let point = edge.start + edge.direction * t;
                    let d2 = (point - q).length_squared();
                    if d2 < best_d2 {
                        best_d2 = d2;
                        best = Some((bi, Nearest { edge: ei, point, signed_distance: -d2.sqrt() }));
                    }
                }
            }
        }
        match best {
            Some((bi, n)) => {
                let mut report = self.blocks[bi].report_from(q, n);
                report.relation = Relation::from_signed_distance(n.signed_distance, self.tolerance);
                report
            }
            // Unreachable for a bounded union; fall back to the deepest block.
            None => self.blocks[closest].report_from(q, nearest[closest]),
        }
    }
}

/// The open parameter interval of `edge` that lies more than `tol` inside
/// the convex block `other` (Cyrus–Beck), unclamped.
fn inside_interval(edge: &ContactEdge, other: &[ContactEdge], tol: f64) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    for e in other {
        // Inside by more than tol: f0 + t·fd < 0.
        let f0 = e.plane_distance(edge.start) + tol;
        let fd = e.normal.dot(edge.direction);
        if fd == 0.0 {
            if f0 >= 0.0 {
                return None;
            }
            continue;
        }
        let t = -f0 / fd;
        if fd > 0.0 {
            t1 = t1.min(t);
        } else {
            t0 = t0.max(t);
        }
        if t0 >= t1 {
            return None;
        }
    }
    (t1 > 0.0 && t0 < 1.0).then_some((t0, t1))
}

/// The parameter in [0, 1] of the point of `edge` nearest to `q` that is in
/// none of the open intervals `covered`.
fn nearest_uncovered(edge: &ContactEdge, covered: &[(f64, f64)], q: Vec2) -> Option<f64> {
    let len2 = edge.direction.length_squared();
    let ideal = if len2 > 0.0 { ((q - edge.start).dot(edge.direction) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let free = |t: f64| covered.iter().all(|&(t0, t1)| !(t0 < t && t < t1));
    let mut candidates = vec![ideal, 0.0, 1.0];
    for &(t0, t1) in covered {
        candidates.push(t0);
        candidates.push(t1);
    }
    candidates
        .into_iter()
        .filter(|&t| (0.0..=1.0).contains(&t) && free(t))
        .min_by(|&x, &y| (x - ideal).abs().total_cmp(&(y - ideal).abs()))
}

#[cfg(test)]
mod tests {
    use super::{SimplePolygon, UnionBlock};
    use crate::contact::error::PolygonError;
    use crate::contact::polygon::ConvexPolygon;
    use crate::contact::report::Relation;
    use crate::contact::vec2::Vec2;

    fn l_shape() -> SimplePolygon {
        SimplePolygon::from_xy(&[[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]]).expect("L")
    }

    #[test]
    fn an_l_shape_merges_into_two_pieces_of_the_right_area() {
        let l = l_shape();
        assert!(!l.is_convex());
        assert_eq!(l.pieces().len(), 2);
        let area: f64 = l.pieces().iter().map(ConvexPolygon::area).sum();
        assert!((area - 5.0).abs() < 1e-12);
    }

    #[test]
    fn a_bow_tie_is_not_simple() {
        let err =
            SimplePolygon::from_xy(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]).expect_err("must be rejected");
        assert!(matches!(err, PolygonError::SelfIntersecting { .. }), "{err:?}");
    }

    #[test]
    fn a_square_in_the_crook_of_the_l_is_pushed_out_of_both_arms() {
        // A unit square at (1.2, 1.2)-(2.2, 2.2) sits in the L's notch
        // without touching; moved to (0.5, 0.5) it overlaps both arms.
        let b = l_shape();
        let a = SimplePolygon::from_xy(&[[1.2, 1.2], [2.2, 1.2], [2.2, 2.2], [1.2, 2.2]]).expect("square");
        let union = UnionBlock::new(&a, &b);
        let r = union.report();
        assert_eq!(r.relation, Relation::Separated);
        assert!((r.distance - 0.2).abs() < 1e-12, "{r:?}");
        let r = union.report_at(Vec2::new(-0.7, -0.7));
        assert_eq!(r.relation, Relation::Intersecting);
        // Up or right by 0.5 clears one arm but not the other; left or down
        // by 1.5 clears both; back along the diagonal to the notch corner by
        // 0.5·√2 ≈ 0.707 is the shortest.
        let moved = Vec2::new(-0.7, -0.7) + r.exit;
        let after = union.report_at(moved);
        assert_eq!(after.relation, Relation::Touching, "{after:?}");
        assert!((r.distance + 0.5 * std::f64::consts::SQRT_2).abs() < 1e-9, "{r:?}");
    }
}
