//! The one-shot query's early exit for overlapping pairs: the expanding
//! polytope (EPA) on the entrance block, with support points in O(log n),
//! then a short walk over the covers of the one face it ends on, instead of
//! the whole O(m + n) boundary.
//!
//! **Why.** On random overlapping pairs the full walk visits all `m + n`
//! covers to find the one farthest out, and at n = 256…1024 parry2d's
//! GJK/EPA is barely slower than that, short of the 1.5× margin that
//! `cargo bench --bench contact` targets on random pairs.
//! The answer is the cover whose line passes nearest A's position (the
//! origin of translation space), and for a point inside a convex set that
//! is the face an EPA converges on.
//!
//! **How.**
//! 1. Block support points in three directions a third of a turn apart
//!    (each a vertex of B minus a vertex of A, found by binary search on the
//!    polygons' normals) make a polygon inscribed in the block.
//! 2. Repeatedly take the polygon's face nearest the origin and the block's
//!    support point along that face's outward normal. A support point beyond
//!    the face is inserted between the face's ends (it lies on the block's
//!    boundary between them, so the polygon stays convex and inscribed).
//!    A face whose own support point is one of its ends, or lies on its
//!    line, is part of the block's boundary.
//! 3. That face is the answer: the inscribed polygon holds the origin, so
//!    every boundary point of the block is at least as far as the polygon's
//!    nearest face; and that face lies on the block's boundary, so no point
//!    of it is farther. With the origin on the far side of a face (the pair
//!    is not overlapping after all) or within the touching tolerance, the
//!    full walk answers instead.
//! 4. The covers from the face's first end to its last (with one more on
//!    each side) are stepped through exactly as the separated exit's walk
//!    steps ([`super::local_walk`]); the report is built from the one
//!    farthest out and its neighbours just as the full walk builds it, so
//!    the distance agrees with the full walk to rounding.
//!
//! Every check that fails (a degenerate face, a support point that would
//! dent the polygon, more faces or covers than valid input needs) hands the
//! pair to the full walk, which is always right.
//!
//! Design: docs/design/contact-theory.md.

use super::entrance_block::{Cover, Step, contact_edge, cover_report};
use super::local_walk::{order_back, order_from, support, unsplit};
use super::polygon::ConvexPolygon;
use super::report::ContactReport;
use super::vec2::Vec2;

/// Below this many vertices in all, the full walk is faster than the
/// search. Measured on the benchmark's random overlapping pairs
/// (`cargo bench --bench contact -- contact/random_overlap`, the constant
/// set to 0 and to `usize::MAX` in turn): the walk is faster at n = 32 a
/// side, the search at n = 64.
pub(crate) const MIN_VERTICES: usize = 96;

/// The most support points the inscribed polygon may gather. On the
/// benchmark's random ellipses it ends with about 2 log₂ n; a pair that
/// needs more is left to the full walk.
const MAX_SUPPORTS: usize = 64;

/// The most covers between a final face's two ends. Its ends are block
/// vertices on one supporting line, so one cover (two where rounding split a
/// parallel pair) lies between them on clean input.
const MAX_FACE_COVERS: usize = 8;

/// A support point of the block: state `(i, j)` (vertex `bⱼ − aᵢ`) and the
/// direction it was found in, from which the local walk measures angles.
#[derive(Clone, Copy, Debug)]
struct Support {
    i: usize,
    j: usize,
    point: Vec2,
    direction: Vec2,
}

impl Support {
    fn find(a: &ConvexPolygon, b: &ConvexPolygon, direction: Vec2) -> Self {
        let (i, j) = support(a, b, direction);
        Self { i, j, point: b.vertices()[j] - a.vertices()[i], direction }
    }

    fn same_vertex(&self, other: &Self) -> bool {
        (self.i, self.j) == (other.i, other.j)
    }
}

/// The report for a pair whose block holds the origin farther than
/// `tolerance` inside, or `None` when the search cannot say so (the caller
/// then runs the full walk).
pub(crate) fn overlapping_report(a: &ConvexPolygon, b: &ConvexPolygon, tolerance: f64) -> Option<ContactReport> {
    if a.len() + b.len() < MIN_VERTICES {
        return None;
    }
    search(a, b, tolerance)
}

/// [`overlapping_report`] at any size.
fn search(a: &ConvexPolygon, b: &ConvexPolygon, tolerance: f64) -> Option<ContactReport> {
    let towards = a.centre() - b.centre();
    let first = if towards.length_squared() > 0.0 { towards.normalized() } else { Vec2::new(1.0, 0.0) };
    if !first.is_finite() {
        return None;
    }
    // A support-line gap below this is rounding: the face is on the boundary.
    let flat = 16.0 * f64::EPSILON * (a.extent() + b.extent() + towards.length());
    let (c, s) = (-0.5, 0.75f64.sqrt());
    let third = |v: Vec2| Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y);
    // The inscribed polygon, counter-clockwise.
    let mut polygon: Vec<Support> = Vec::with_capacity(MAX_SUPPORTS);
    for direction in [first, third(first), third(third(first))] {
        let v = Support::find(a, b, direction);
        if polygon.last().is_none_or(|last| !last.same_vertex(&v)) {
            polygon.push(v);
        }
    }
    if polygon.len() > 2 && polygon[0].same_vertex(&polygon[polygon.len() - 1]) {
        polygon.pop();
    }
    if polygon.len() < 2 {
        return None;
    }
    while polygon.len() < MAX_SUPPORTS {
        let count = polygon.len();
        // The face nearest the origin: for a counter-clockwise polygon the
        // origin's distance inside face p → q is (p × q) / |q − p|.
        let (mut depth, mut k, mut normal) = (f64::INFINITY, 0, Vec2::ZERO);
        for f in 0..count {
            let (p, q) = (polygon[f].point, polygon[if f + 1 == count { 0 } else { f + 1 }].point);
            let e = q - p;
            let length = e.length();
            if length.is_nan() || length <= 0.0 {
                return None;
            }
            let d = p.cross(q) / length;
            if d < depth {
                (depth, k, normal) = (d, f, Vec2::new(e.y, -e.x) / length);
            }
        }
        let (p, q) = (polygon[k], polygon[(k + 1) % count]);
        let v = Support::find(a, b, normal);
        if v.same_vertex(&p) || v.same_vertex(&q) || normal.dot(v.point) - depth <= flat {
            return if depth > tolerance { report_on_face(a, b, &p, &q, depth, tolerance) } else { None };
        }
        // The new vertex lies between p and q on the block's boundary; a
        // rounding that put it behind either neighbouring face would dent
        // the polygon.
        let (before, after) = (polygon[(k + count - 1) % count].point, polygon[(k + 2) % count].point);
        if count > 2
            && ((p.point - before).cross(v.point - p.point) < 0.0 || (q.point - v.point).cross(after - q.point) < 0.0)
        {
            return None;
        }
        polygon.insert(k + 1, v);
    }
    None
}

/// The report from the covers of the block between `p` and `q`, the ends
/// of a face on the block's boundary `depth` from the origin.
fn report_on_face(
    a: &ConvexPolygon,
    b: &ConvexPolygon,
    p: &Support,
    q: &Support,
    depth: f64,
    tolerance: f64,
) -> Option<ContactReport> {
    let (av, bv, na, nb) = (a.vertices(), b.vertices(), a.normals(), b.normals());
    let (len_a, len_b) = (av.len(), bv.len());
    let (mut i, mut j) = unsplit(a, b, p.i, p.j);
    let end = unsplit(a, b, q.i, q.j);
    let mut covers = [Cover { i, j, step: Step::B }; MAX_FACE_COVERS + 2];
    // The cover that ends at p.
    let (ip, jp) = (if i == 0 { len_a - 1 } else { i - 1 }, if j == 0 { len_b - 1 } else { j - 1 });
    let step = order_back(p.direction, nb[jp], -na[ip]);
    covers[0] = match step {
        Step::B => Cover { i, j: jp, step },
        Step::A => Cover { i: ip, j, step },
        Step::Both => Cover { i: ip, j: jp, step },
    };
    // Then p's own cover and on to q's, which follows the face.
    let mut count = 1;
    let mut current = p.direction;
    loop {
        let step = order_from(current, nb[j], -na[i]);
        covers[count] = Cover { i, j, step };
        count += 1;
        if count > 2 && (i, j) == end {
            break;
        }
        if count == covers.len() {
            return None;
        }
        current = if step == Step::A { -na[i] } else { nb[j] };
        if step != Step::A {
            j = if j + 1 == len_b { 0 } else { j + 1 };
        }
        if step != Step::B {
            i = if i + 1 == len_a { 0 } else { i + 1 };
        }
    }
    let covers = &covers[..count];
    // The cover farthest out, as the full walk measures it (first wins).
    let g = |c: &Cover| -(if c.step == Step::A { -na[c.i] } else { nb[c.j] }).dot(bv[c.j] - av[c.i]);
    let mut best = 0;
    for (k, c) in covers.iter().enumerate().skip(1) {
        if g(c) > g(&covers[best]) {
            best = k;
        }
    }
    // Its neighbours must be among the covers stepped through.
    if best == 0 || best + 1 == count {
        return None;
    }
    let mut pick = (f64::INFINITY, covers[best], Vec2::ZERO);
    for &c in &covers[best - 1..=best + 1] {
        let point = contact_edge(a, b, c).closest_point(Vec2::ZERO);
        let d2 = point.length_squared();
        if d2 < pick.0 {
            pick = (d2, c, point);
        }
    }
    let (d2, cover, point) = pick;
    let signed = -d2.sqrt();
    // The walked covers and the face must tell the same depth.
    if (signed + depth).abs() > tolerance {
        return None;
    }
    Some(cover_report(a, b, cover, point, signed, tolerance))
}

#[cfg(test)]
mod tests {
    use super::search;
    use crate::contact::circle::{CircleFit, discretize_circle};
    use crate::contact::entrance_block::pair_tolerance;
    use crate::contact::polygon::ConvexPolygon;
    use crate::contact::random_ellipse;
    use crate::contact::report::Relation;
    use crate::contact::test_support::{agrees_on, agrees_with_the_walk, grid_pair, random_pair};
    use crate::contact::vec2::Vec2;
    use proptest::prelude::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    /// The search, where it answers, against the full walk (an answer is
    /// always an overlap); whether it answered.
    fn agrees(a: &ConvexPolygon, b: &ConvexPolygon) -> Result<bool, TestCaseError> {
        let fast = search(a, b, pair_tolerance(a, b));
        if let Some(fast) = &fast {
            prop_assert_eq!(fast.relation, Relation::Intersecting, "{:?}", fast);
        }
        agrees_with_the_walk(a, b, fast)
    }

    #[test]
    fn the_search_agrees_with_the_full_walk_on_grids() {
        agrees_on(grid_pair(3), agrees);
    }

    #[test]
    fn the_search_agrees_with_the_full_walk_on_random_polygons() {
        agrees_on(prop_oneof![random_pair(80, 1.5, 0.0), random_pair(80, 1.5, 1e6)], agrees);
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

        /// Regular polygons have parallel edges, which the block takes
        /// together, and ties between covers farthest out.
        #[test]
        fn the_search_agrees_with_the_full_walk_on_regular_polygons(
            n in 3usize..200, m in 3usize..200,
            ra in 0.1..2.0f64, rb in 0.1..2.0f64,
            turn_a in prop_oneof![Just(0.0), 0.0..1.0f64], turn_b in prop_oneof![Just(0.0), 0.0..1.0f64],
            dx in -1.0..1.0f64, dy in prop_oneof![Just(0.0), -1.0..1.0f64],
        ) {
            let a = discretize_circle(Vec2::ZERO, ra, n, CircleFit::Inscribed, turn_a).expect("n-gon");
            let b = discretize_circle(Vec2::new(dx, dy), rb, m, CircleFit::Inscribed, turn_b).expect("n-gon");
            agrees(&a, &b)?;
        }
    }

    /// On the benchmark's random overlapping ellipses the search answers
    /// every pair, at every size it is used for, and agrees with the walk.
    #[test]
    fn the_search_answers_random_overlapping_ellipses() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for n in [24, 64, 256, 1024, 4096] {
            for _ in 0..40 {
                let a = ConvexPolygon::new(&random_ellipse(&mut rng, n, Vec2::ZERO)).expect("convex");
                let b = ConvexPolygon::new(&random_ellipse(&mut rng, n, Vec2::new(0.3, -0.4))).expect("convex");
                assert!(agrees(&a, &b).expect("agrees with the walk"), "no answer at n = {n}");
            }
        }
    }

    #[test]
    fn separated_and_touching_pairs_are_left_to_the_full_walk() {
        let square = |x: f64, s: f64| ConvexPolygon::from_xy(&[[x, 0.0], [x + s, 0.0], [x + s, s], [x, s]]);
        let (a, b) = (square(0.0, 1.0).expect("a"), square(3.0, 2.0).expect("b"));
        assert!(search(&a, &b, pair_tolerance(&a, &b)).is_none());
        let (a, b) = (square(0.0, 1.0).expect("a"), square(1.0, 2.0).expect("b"));
        assert!(search(&a, &b, pair_tolerance(&a, &b)).is_none());
        let (a, b) = (square(0.0, 1.0).expect("a"), square(0.5, 2.0).expect("b"));
        let report = search(&a, &b, pair_tolerance(&a, &b)).expect("overlapping by half a unit");
        assert!((report.distance + 0.5).abs() < 1e-15, "{report:?}");
    }
}
