//! The one-shot query's early exit for separated pairs: a separating axis
//! found by support points in O(log n), then a walk along only the part of
//! the entrance block that faces A's position, instead of the whole
//! O(m + n) boundary.
//!
//! **Why.** On random separated pairs parry's GJK, which only ever visits
//! a few support points, is faster than the full walk, short of the
//! target (at least as fast as parry, 1×) that `cargo bench --bench
//! contact` reports on random pairs. The nearest point of the block
//! `B ⊕ (−A)` to A's position (the origin of translation space) lies on
//! the chain of block edges facing the origin, and along that chain the
//! distance falls then rises (a convex set seen from outside), so a walk
//! downhill from any visible vertex of the block reaches it.
//!
//! **How.**
//! 1. A direction `n` from B's bounding-box centre towards A's is refined a
//!    few times, each time to the direction from the closest point of the
//!    segment between the last two block support points towards the origin
//!    (the GJK step, on two points). Each support point of the block is a
//!    vertex of B minus a vertex of A, found by binary search on each
//!    polygon's normals ([`ConvexPolygon::first_edge_at_or_after`]).
//! 2. The gap along `n`, `min n·a − max n·b`, is a lower bound on the
//!    distance. If it never exceeds the touching tolerance the pair is not
//!    certainly separated and the full walk answers instead.
//! 3. Otherwise the block vertex extreme in `n` is visible from the origin
//!    (the gap is positive), and the walk steps from it, forward or
//!    backward along the block, while the distance falls and the next edge
//!    faces the origin (an edge facing away can bring the distance down
//!    again, on the far side: a proptest on integer grids found one). Each step merges
//!    the next edge of B and of −A exactly as the full walk does (parallel
//!    edges first, as one edge–edge cover), but ordered by angle from the
//!    current edge rather than from the x axis, so it may start anywhere.
//!
//! The report is built from the nearest cover just as the full walk builds
//! it, so the distance agrees with [`contact_report`]'s full walk to
//! rounding (a proptest checks 1e-12 of the size, and the features).
//!
//! Design: docs/design/contact-theory.md.
//!
//! [`contact_report`]: super::query::contact_report

use super::entrance_block::{Cover, Step, cover_report};
use super::local_walk::{cover_direction, order_back, order_from, support, unsplit};
use super::polygon::ConvexPolygon;
use super::report::ContactReport;
use super::vec2::Vec2;

/// GJK refinements of the search direction before the walk. Each costs two
/// binary searches; on the benchmark's random ellipses three left the walk
/// a handful of steps at every n, and more did not pay.
const REFINEMENTS: usize = 3;

/// The report for a pair that a separating axis with a gap beyond
/// `tolerance` proves separated, or `None` when no such axis was found (the
/// caller then runs the full walk).
pub(crate) fn separated_report(a: &ConvexPolygon, b: &ConvexPolygon, tolerance: f64) -> Option<ContactReport> {
    let (av, bv) = (a.vertices(), b.vertices());
    let mut n = a.centre() - b.centre();
    // Coincident centres (or NaN): no direction to start from.
    if n.length_squared().is_nan() || n.length_squared() <= 0.0 {
        return None;
    }
    let (mut i, mut j) = support(a, b, n);
    let mut v = bv[j] - av[i];
    let mut separated = -n.dot(v) > tolerance * n.length();
    for _ in 0..REFINEMENTS {
        if separated {
            break;
        }
        // The direction from the block's support point towards the origin.
        let next = -v;
        if next.length_squared().is_nan() || next.length_squared() <= 0.0 {
            return None;
        }
        let (i2, j2) = support(a, b, next);
        let w = bv[j2] - av[i2];
        // GJK on the segment [v, w]: the closest point to the origin.
        let s = w - v;
        let len2 = s.length_squared();
        let t = if len2 > 0.0 { (-v.dot(s) / len2).clamp(0.0, 1.0) } else { 0.0 };
        let closest = v + s * t;
        let last = v;
        (i, j, v, n) = (i2, j2, w, next);
        separated = -n.dot(v) > tolerance * n.length();
        if separated {
            break;
        }
        // The origin on a segment between two block points is in the block.
        if closest.length_squared() <= 0.0 {
            return None;
        }
        let towards = -closest;
        let (i3, j3) = support(a, b, towards);
        let u = bv[j3] - av[i3];
        if -towards.dot(u) > tolerance * towards.length() {
            (i, j, v, n) = (i3, j3, u, towards);
            separated = true;
        } else if encloses_origin(last, w, u) {
            // Three block points round the origin: the pair overlaps, and
            // the refinements left would only fail to separate it (a large
            // share of an overlapping query's time at every n; `cargo bench
            // --bench contact`).
            return None;
        }
    }
    if !separated {
        return None;
    }
    let (i, j) = unsplit(a, b, i, j);
    let (cover, point) = walk_downhill(a, b, i, j, n)?;
    let signed = point.length();
    Some(cover_report(a, b, cover, point, signed, tolerance))
}

/// Whether the origin lies strictly inside the triangle `p q r` (either
/// winding).
fn encloses_origin(p: Vec2, q: Vec2, r: Vec2) -> bool {
    let (x, y, z) = (p.cross(q), q.cross(r), r.cross(p));
    (x > 0.0 && y > 0.0 && z > 0.0) || (x < 0.0 && y < 0.0 && z < 0.0)
}

/// The nearest point to the origin of the block's boundary, walking from
/// the visible block vertex of state `(i, j)` (whose next edges are at or
/// after direction `n`) while the distance falls. Returns the cover it lies
/// on and the point, computed as the full walk computes it. `None` if the
/// walk runs past `m + n` steps (it cannot on valid input).
fn walk_downhill(a: &ConvexPolygon, b: &ConvexPolygon, i: usize, j: usize, n: Vec2) -> Option<(Cover, Vec2)> {
    let (av, bv, na, nb) = (a.vertices(), b.vertices(), a.normals(), b.normals());
    let (len_a, len_b) = (av.len(), bv.len());
    let foot = |c: Cover| {
        let start = bv[c.j] - av[c.i];
        let direction = cover_direction(av, bv, c);
        let t = (-start.dot(direction) / direction.length_squared()).clamp(0.0, 1.0);
        start + direction * t
    };
    let (mut i, mut j, mut current) = (i, j, n);
    // Forward: while the origin projects past the start of the next edge.
    let mut moved = false;
    for _ in 0..len_a + len_b {
        let step = order_from(current, nb[j], -na[i]);
        let cover = Cover { i, j, step };
        let start = bv[j] - av[i];
        let direction = cover_direction(av, bv, cover);
        let normal = if step == Step::A { -na[i] } else { nb[j] };
        // Only edges facing the origin: behind them the distance may fall
        // again, on the far side of the block.
        let ahead = if normal.dot(start) < 0.0 { -start.dot(direction) } else { 0.0 };
        if ahead <= 0.0 {
            if moved {
                return Some((cover, foot(cover)));
            }
            break;
        }
        moved = true;
        if ahead < direction.length_squared() {
            return Some((cover, foot(cover)));
        }
        current = normal;
        if step != Step::A {
            j = if j + 1 == len_b { 0 } else { j + 1 };
        }
        if step != Step::B {
            i = if i + 1 == len_a { 0 } else { i + 1 };
        }
    }
    if moved {
        return None;
    }
    // Backward: while the origin projects before the end of the previous
    // edge. `current` is the direction the state was found at.
    let here = Cover { i, j, step: order_from(current, nb[j], -na[i]) };
    for _ in 0..len_a + len_b {
        let (ip, jp) = (if i == 0 { len_a - 1 } else { i - 1 }, if j == 0 { len_b - 1 } else { j - 1 });
        let step = order_back(current, nb[jp], -na[ip]);
        let cover = match step {
            Step::B => Cover { i, j: jp, step },
            Step::A => Cover { i: ip, j, step },
            Step::Both => Cover { i: ip, j: jp, step },
        };
        let end = bv[j] - av[i];
        let direction = cover_direction(av, bv, cover);
        let normal = if step == Step::A { -na[cover.i] } else { nb[cover.j] };
        if end.dot(direction) <= 0.0 || normal.dot(end) >= 0.0 {
            // The vertex (i, j) is nearest: report it as the start of the
            // edge after it, or the end of this one once the walk has moved.
            return Some(if i == here.i && j == here.j { (here, foot(here)) } else { (cover, foot(cover)) });
        }
        let start = bv[cover.j] - av[cover.i];
        if -start.dot(direction) > 0.0 {
            return Some((cover, foot(cover)));
        }
        current = normal;
        (i, j) = (cover.i, cover.j);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::{encloses_origin, separated_report};
    use crate::contact::entrance_block::{EntranceBlock, pair_tolerance};
    use crate::contact::polygon::ConvexPolygon;
    use crate::contact::test_support::{agrees_on, agrees_with_the_walk, grid_pair, random_pair};
    use crate::contact::vec2::Vec2;
    use proptest::prelude::*;

    fn agrees(a: &ConvexPolygon, b: &ConvexPolygon) -> Result<bool, TestCaseError> {
        agrees_with_the_walk(a, b, separated_report(a, b, pair_tolerance(a, b)))
    }

    #[test]
    fn the_early_exit_agrees_with_the_full_walk_on_grids() {
        agrees_on(grid_pair(8), agrees);
    }

    #[test]
    fn the_early_exit_agrees_with_the_full_walk_on_random_polygons() {
        agrees_on(random_pair(60, 6.0, 0.0), agrees);
    }

    fn square(x: f64, y: f64, s: f64) -> ConvexPolygon {
        ConvexPolygon::from_xy(&[[x, y], [x + s, y], [x + s, y + s], [x, y + s]]).expect("square")
    }

    #[test]
    fn parallel_faces_give_the_edge_edge_contact_of_the_full_walk() {
        let (a, b) = (square(0.0, 0.0, 1.0), square(3.0, 0.0, 2.0));
        let fast = separated_report(&a, &b, pair_tolerance(&a, &b)).expect("separated");
        let full = EntranceBlock::new(&a, &b).report();
        assert_eq!(fast.distance, 2.0);
        assert_eq!(fast.exit, Vec2::new(2.0, 0.0));
        let (mut f, mut w) = (fast.features.to_vec(), full.features.to_vec());
        f.sort_by_key(|x| format!("{x:?}"));
        w.sort_by_key(|x| format!("{x:?}"));
        assert_eq!(f, w);
    }

    #[test]
    fn a_triangle_encloses_the_origin_in_either_winding_and_not_on_its_edge() {
        let (p, q, r) = (Vec2::new(-1.0, -1.0), Vec2::new(2.0, -1.0), Vec2::new(-1.0, 2.0));
        assert!(encloses_origin(p, q, r));
        assert!(encloses_origin(r, q, p));
        assert!(!encloses_origin(p + Vec2::new(2.0, 0.0), q + Vec2::new(2.0, 0.0), r + Vec2::new(2.0, 0.0)));
        // The origin on the edge p → q.
        assert!(!encloses_origin(Vec2::new(-1.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)));
    }

    #[test]
    fn overlapping_pairs_are_left_to_the_full_walk() {
        let (a, b) = (square(0.0, 0.0, 1.0), square(0.5, 0.5, 1.0));
        assert!(separated_report(&a, &b, pair_tolerance(&a, &b)).is_none());
    }
}
