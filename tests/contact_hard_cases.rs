//! One named test per hard case of the contact geometry. Every convex case
//! is answered by the O(m + n) entrance block and checked against the
//! O(m·n) brute force as well as against numbers worked out by hand.

use std::f64::consts::{PI, SQRT_2};

use surfacelab::contact::{
    CircleFit, ContactReport, ConvexPolygon, CoverKind, EntranceBlock, Feature, MAX_CONCAVE_VERTICES, PolygonError,
    Relation, SimplePolygon, UnionBlock, Vec2, brute_force_report_at, discretize_circle,
};

fn poly(points: &[[f64; 2]]) -> ConvexPolygon {
    ConvexPolygon::from_xy(points).expect("a valid convex polygon")
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> ConvexPolygon {
    poly(&[[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
}

/// The walk's report with A moved by `t`, after checking that the brute
/// force agrees on relation and distance (to `1e-12` of `scale`).
fn answer_at(a: &ConvexPolygon, b: &ConvexPolygon, t: Vec2, scale: f64) -> ContactReport {
    let walk = EntranceBlock::new(a, b).report_at(t);
    let brute = brute_force_report_at(a, b, t);
    assert_eq!(walk.relation, brute.relation, "walk {walk:?}\nbrute {brute:?}");
    assert!((walk.distance - brute.distance).abs() <= 1e-12 * scale, "walk {walk:?}\nbrute {brute:?}");
    assert!((walk.exit.length() - walk.distance.abs()).abs() <= 1e-12 * scale, "{walk:?}");
    walk
}

fn answer(a: &ConvexPolygon, b: &ConvexPolygon) -> ContactReport {
    answer_at(a, b, Vec2::ZERO, 1.0)
}

/// [`answer`], asserted to be of `relation`.
fn answer_is(a: &ConvexPolygon, b: &ConvexPolygon, relation: Relation) -> ContactReport {
    let r = answer(a, b);
    assert_eq!(r.relation, relation, "{r:?}");
    r
}

fn sorted(features: &[Feature]) -> Vec<Feature> {
    let mut f = features.to_vec();
    f.sort_by_key(|x| format!("{x:?}"));
    f
}

fn close(v: Vec2, x: f64, y: f64, eps: f64) -> bool {
    (v - Vec2::new(x, y)).length() <= eps
}

#[test]
fn exactly_touching_edge_on_edge() {
    let a = rect(0.0, 0.0, 1.0, 1.0);
    let b = rect(1.0, 0.25, 3.0, 0.75);
    let r = answer_is(&a, &b, Relation::Touching);
    assert_eq!(r.distance, 0.0);
    assert_eq!(r.exit, Vec2::ZERO);
    // B's left edge lies on A's right edge (A's vertices 1 → 2): its two
    // ends, B's vertices 0 and 3, are the features.
    assert_eq!(
        sorted(&r.features),
        sorted(&[
            Feature::EdgeAngle { a_edge: [1, 2], b_vertex: 0 },
            Feature::EdgeAngle { a_edge: [1, 2], b_vertex: 3 },
        ])
    );
    assert!(close(r.witness[0], 1.0, 0.5, 1e-15) && close(r.witness[1], 1.0, 0.5, 1e-15), "{r:?}");
}

#[test]
fn exactly_touching_vertex_on_edge() {
    let a = poly(&[[-1.0, -1.0], [1.0, -1.0], [0.0, 0.0]]);
    let b = rect(-2.0, 0.0, 2.0, 1.0);
    let r = answer_is(&a, &b, Relation::Touching);
    assert_eq!(r.distance, 0.0);
    assert_eq!(r.features.as_slice(), &[Feature::AngleEdge { a_vertex: 2, b_edge: [0, 1] }]);
    assert_eq!(r.witness, [Vec2::ZERO, Vec2::ZERO]);
    // A hair below: separated by exactly that hair, same feature.
    let r = answer_at(&a, &b, Vec2::new(0.0, -1e-3), 1.0);
    assert_eq!(r.relation, Relation::Separated);
    assert!((r.distance - 1e-3).abs() < 1e-15);
    assert_eq!(r.features.as_slice(), &[Feature::AngleEdge { a_vertex: 2, b_edge: [0, 1] }]);
}

#[test]
fn overlapping_parallel_edges_report_both_ends_of_the_overlap() {
    let a = rect(0.0, 0.0, 1.0, 1.0);
    let b = rect(1.0, 0.5, 2.0, 1.5);
    let ends = sorted(&[
        // B's corner (1, 0.5) on A's right edge, A's corner (1, 1) on B's left edge.
        Feature::EdgeAngle { a_edge: [1, 2], b_vertex: 0 },
        Feature::AngleEdge { a_vertex: 2, b_edge: [3, 0] },
    ]);
    let r = answer_is(&a, &b, Relation::Touching);
    assert_eq!(sorted(&r.features), ends);
    assert!(close(r.witness[1], 1.0, 0.75, 1e-15), "{r:?}");

    // Pushed 0.1 into each other: the shortest exit is straight back.
    let b = rect(0.9, 0.5, 2.0, 1.5);
    let r = answer_is(&a, &b, Relation::Intersecting);
    assert!((r.distance + 0.1).abs() < 1e-15, "{r:?}");
    assert!(close(r.exit, -0.1, 0.0, 1e-15), "{r:?}");
    assert_eq!(sorted(&r.features), ends);
}

#[test]
fn vertex_on_vertex() {
    let r = answer_is(&rect(0.0, 0.0, 1.0, 1.0), &rect(1.0, 1.0, 2.0, 2.0), Relation::Touching);
    assert_eq!(r.features.as_slice(), &[Feature::AngleAngle { a_vertex: 2, b_vertex: 0 }]);

    let diamond = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];
    let a = poly(&diamond);
    let b = poly(&diamond.map(|[x, y]| [x + 2.0, y]));
    let r = answer_is(&a, &b, Relation::Touching);
    assert_eq!(r.features.as_slice(), &[Feature::AngleAngle { a_vertex: 0, b_vertex: 2 }]);
    assert_eq!(r.witness, [Vec2::new(1.0, 0.0), Vec2::new(1.0, 0.0)]);
}

#[test]
fn deep_penetration() {
    let a = rect(0.1, 0.4, 0.3, 0.6);
    let b = rect(0.0, 0.0, 10.0, 10.0);
    let r = answer_is(&a, &b, Relation::Intersecting);
    assert!((r.distance + 0.3).abs() < 1e-15, "{r:?}");
    assert!(close(r.exit, -0.3, 0.0, 1e-15), "{r:?}");
    let after = answer_at(&a, &b, r.exit, 1.0);
    assert_eq!(after.relation, Relation::Touching);
}

#[test]
fn identical_polygons() {
    // A regular hexagon of circumradius 1 is √3 wide between opposite edges:
    // that is the shortest way out of itself.
    let hexagon = discretize_circle(Vec2::new(0.3, -0.2), 1.0, 6, CircleFit::Inscribed, 0.0).expect("hexagon");
    let r = answer_is(&hexagon, &hexagon, Relation::Intersecting);
    assert!((r.distance + 3f64.sqrt()).abs() < 1e-12, "{r:?}");
    let after = answer_at(&hexagon, &hexagon, r.exit, 1.0);
    assert_eq!(after.relation, Relation::Touching, "{after:?}");
    // Edge on edge once out: two ends.
    assert_eq!(after.features.len(), 2, "{after:?}");
}

#[test]
fn nested_polygons() {
    let small = rect(4.0, 4.0, 5.0, 6.0);
    let big = rect(0.0, 0.0, 10.0, 10.0);
    // Small inside big: out through the left side, 5 away.
    let r = answer_is(&small, &big, Relation::Intersecting);
    assert_eq!(r.distance, -5.0);
    assert_eq!(r.exit, Vec2::new(-5.0, 0.0));
    // Big around small: big moves right by 5 to clear it.
    let r = answer(&big, &small);
    assert_eq!(r.distance, -5.0);
    assert_eq!(r.exit, Vec2::new(5.0, 0.0));
}

#[test]
fn coordinates_around_a_million() {
    let o = 1e6;
    let a = rect(o + 0.1, o + 0.3, o + 1.1, o + 1.3);
    let touching = rect(o + 1.1, o + 0.8, o + 2.1, o + 1.8);
    let r = answer_at(&a, &touching, Vec2::ZERO, o);
    assert_eq!(r.relation, Relation::Touching, "{r:?}");
    assert_eq!(r.features.len(), 2);

    let apart = rect(o + 1.1 + 1e-6, o + 0.8, o + 2.1, o + 1.8);
    let r = answer_at(&a, &apart, Vec2::ZERO, o);
    assert_eq!(r.relation, Relation::Separated, "{r:?}");
    assert!((r.distance - 1e-6).abs() < 1e-9, "{r:?}");

    let into = rect(o + 1.1 - 1e-6, o + 0.8, o + 2.1, o + 1.8);
    let r = answer_at(&a, &into, Vec2::ZERO, o);
    assert_eq!(r.relation, Relation::Intersecting, "{r:?}");
    assert!((r.distance + 1e-6).abs() < 1e-9, "{r:?}");
}

#[test]
fn polygons_a_micron_across() {
    let s = 1e-6;
    let a = rect(0.0, 0.0, s, s);
    let r = answer_at(&a, &rect(s, 0.5 * s, 2.0 * s, 1.5 * s), Vec2::ZERO, s);
    assert_eq!(r.relation, Relation::Touching);
    // A gap of a thousandth of the size is a gap, not a touch.
    let r = answer_at(&a, &rect(1.001 * s, 0.5 * s, 2.0 * s, 1.5 * s), Vec2::ZERO, s);
    assert_eq!(r.relation, Relation::Separated, "{r:?}");
    assert!((r.distance - 1e-3 * s).abs() < 1e-12 * s, "{r:?}");
    let r = answer_at(&a, &rect(0.999 * s, 0.5 * s, 2.0 * s, 1.5 * s), Vec2::ZERO, s);
    assert_eq!(r.relation, Relation::Intersecting, "{r:?}");
}

#[test]
fn polygons_a_micron_across_at_a_million() {
    let (o, s) = (1e6, 1e-6);
    let a = rect(o, o, o + s, o + s);
    let r = answer_at(&a, &rect(o + s, o + 0.5 * s, o + 2.0 * s, o + 1.5 * s), Vec2::ZERO, s);
    assert_eq!(r.relation, Relation::Touching, "{r:?}");
    // 1e-7 is ~860 units in the last place at 1e6: clearly apart.
    let r = answer_at(&a, &rect(o + 1.1 * s, o + 0.5 * s, o + 2.0 * s, o + 1.5 * s), Vec2::ZERO, s);
    assert_eq!(r.relation, Relation::Separated, "{r:?}");
    assert!((r.distance - 0.1 * s).abs() < 1e-9, "{r:?}");
}

#[test]
fn triangle_against_a_4096_gon() {
    let circle = discretize_circle(Vec2::ZERO, 1.0, 4096, CircleFit::Inscribed, 0.0).expect("4096-gon");
    assert_eq!(circle.len(), 4096);
    let triangle = poly(&[[1.5, 0.0], [2.5, -0.5], [2.5, 0.5]]);
    // The apex faces the circle's vertex 0 at (1, 0).
    let r = answer_is(&triangle, &circle, Relation::Separated);
    assert!((r.distance - 0.5).abs() < 1e-12, "{r:?}");
    assert_eq!(r.features.as_slice(), &[Feature::AngleAngle { a_vertex: 0, b_vertex: 0 }]);
    // Pushed 0.6 left, the apex is 0.1 inside, between the two edges that
    // meet at vertex 0: out along either edge's normal, by 0.1 cos(π/4096).
    let r = answer_at(&triangle, &circle, Vec2::new(-0.6, 0.0), 1.0);
    assert_eq!(r.relation, Relation::Intersecting);
    assert!((r.distance + 0.1 * (PI / 4096.0).cos()).abs() < 1e-12, "{r:?}");
    // The same with the roles swapped (the 4096-gon moves).
    let r = answer(&circle, &triangle);
    assert!((r.distance - 0.5).abs() < 1e-12, "{r:?}");
    assert_eq!(EntranceBlock::new(&circle, &triangle).edges().len(), 4096 + 3);
}

#[test]
fn nearly_collinear_vertices() {
    // Points within rounding of the square's edges, bulging out or in,
    // are straight angles: the square comes out.
    let noisy =
        poly(&[[0.0, 0.0], [0.5, -1e-14], [1.0, 0.0], [1.0 + 1e-14, 0.5], [1.0, 1.0], [0.5, 1.0 - 1e-13], [0.0, 1.0]]);
    assert_eq!(noisy.source_indices(), &[0, 2, 4, 6]);
    let b = rect(1.5, 0.2, 2.5, 0.4);
    assert!((answer(&noisy, &b).distance - 0.5).abs() < 1e-15);

    // A bulge of 1e-10 is real geometry and is kept: B 5e-9 below the edge
    // is 4.9e-9 from the bulge.
    let bulge = poly(&[[0.0, 0.0], [0.5, -1e-10], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    assert_eq!(bulge.len(), 5);
    let r = answer_is(&bulge, &rect(0.0, -2.0, 1.0, -5e-9), Relation::Separated);
    assert!((r.distance - 4.9e-9).abs() < 1e-17, "{r:?}");
    assert_eq!(r.features.as_slice(), &[Feature::AngleEdge { a_vertex: 1, b_edge: [2, 3] }]);

    // A dent of 1e-6 is a reflex angle.
    let err = ConvexPolygon::from_xy(&[[0.0, 0.0], [0.5, 1e-6], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
        .expect_err("must be rejected");
    assert_eq!(err, PolygonError::Reflex { vertex: 1 });
}

#[test]
fn paper_example_two_triangles_without_parallel_edges() {
    // Figure 12: two triangles, no edge of one parallel to an edge of the
    // other, so the entrance block has 3 angle–edge and 3 edge–angle covers.
    let a = poly(&[[0.0, 0.0], [2.0, 0.3], [0.6, 1.8]]);
    let b = poly(&[[4.0, 0.2], [6.0, 1.0], [4.5, 2.5]]);
    let block = EntranceBlock::new(&a, &b);
    let kinds: Vec<CoverKind> = block.edges().iter().map(|e| e.kind).collect();
    assert_eq!(kinds.iter().filter(|&&k| k == CoverKind::AngleEdge).count(), 3);
    assert_eq!(kinds.iter().filter(|&&k| k == CoverKind::EdgeAngle).count(), 3);
    assert_eq!(answer(&a, &b).relation, Relation::Separated);
    // Figure 12(d): A placed on an edge–angle cover touches B with that
    // edge of A on that vertex of B.
    let edge = block.edges().iter().find(|e| e.kind == CoverKind::EdgeAngle).expect("an edge–angle cover");
    let on_cover = edge.start + edge.direction * 0.5;
    let r = answer_at(&a, &b, on_cover, 1.0);
    assert_eq!(r.relation, Relation::Touching);
    assert_eq!(r.features.as_slice(), &[Feature::EdgeAngle { a_edge: edge.a, b_vertex: edge.b[0] }]);
    // Backed off along the cover's normal by 0.01: separated by 0.01.
    let r = answer_at(&a, &b, on_cover + edge.normal * 0.01, 1.0);
    assert!((r.distance - 0.01).abs() < 1e-14, "{r:?}");
    // The block in the paper's coordinates is the walk's, moved by p.
    assert_eq!(block.reference(), Vec2::new(0.0, 0.0));
    assert_eq!(block.boundary()[0], block.edges()[0].start);
}

#[test]
fn paper_example_circle_of_10_segments_with_parallel_edges() {
    // Figure 13: a circle discretised into 10 segments. Its bottom edge
    // (vertices 7 and 8, at 252° and 288°) is parallel to the top of B.
    let a = discretize_circle(Vec2::ZERO, 1.0, 10, CircleFit::Inscribed, 0.0).expect("10-gon");
    let b = rect(-3.0, -3.0, 3.0, -1.0);
    let block = EntranceBlock::new(&a, &b);
    assert_eq!(block.edges().iter().filter(|e| e.kind == CoverKind::EdgeEdge).count(), 2);
    let v = a.vertices();
    let bottom = v[7].y;
    // Lowered onto B: the whole bottom edge lies on B's top edge.
    let r = answer_at(&a, &b, Vec2::new(0.0, -1.0 - bottom), 1.0);
    assert_eq!(r.relation, Relation::Touching, "{r:?}");
    assert_eq!(
        sorted(&r.features),
        sorted(&[
            Feature::AngleEdge { a_vertex: 7, b_edge: [2, 3] },
            Feature::AngleEdge { a_vertex: 8, b_edge: [2, 3] },
        ])
    );
    // Slid right until vertex 7 sits on B's corner (3, -1): the two angle–
    // edge covers and the edge–angle cover meet in an angle–angle contact.
    let t = Vec2::new(3.0, -1.0) - v[7];
    let r = answer_at(&a, &b, t, 1.0);
    assert_eq!(r.relation, Relation::Touching, "{r:?}");
    assert_eq!(r.features.as_slice(), &[Feature::AngleAngle { a_vertex: 7, b_vertex: 2 }]);
    // Slid back left by 0.2, the bottom edge overlaps B's top from A's
    // vertex 7 to B's corner: those are the two ends.
    let r = answer_at(&a, &b, t - Vec2::new(0.2, 0.0), 1.0);
    assert_eq!(r.relation, Relation::Touching, "{r:?}");
    assert_eq!(
        sorted(&r.features),
        sorted(&[
            Feature::AngleEdge { a_vertex: 7, b_edge: [2, 3] },
            Feature::EdgeAngle { a_edge: [7, 8], b_vertex: 2 },
        ])
    );
    // Slid right by 0.2 it leaves the corner: separated, edge 6→7 nearest
    // to the corner.
    let r = answer_at(&a, &b, t + Vec2::new(0.2, 0.0), 1.0);
    assert_eq!(r.relation, Relation::Separated, "{r:?}");
    assert_eq!(r.features.as_slice(), &[Feature::EdgeAngle { a_edge: [6, 7], b_vertex: 2 }]);
}

#[test]
fn a_small_square_in_a_pocket_exits_into_the_pocket() {
    // A C-shaped B with a 1 × 1 pocket at (1..2, 1..2), open to the right
    // through a 1-wide mouth; A is a 0.8 square in the pocket, then pushed
    // 0.3 into the pocket's floor. The shortest exit is back up into the
    // pocket, 0.1 out of the floor (a notch of the union of entrance
    // blocks), not out of B altogether.
    let b = SimplePolygon::from_xy(&[
        [0.0, 0.0],
        [3.0, 0.0],
        [3.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [3.0, 2.0],
        [3.0, 3.0],
        [0.0, 3.0],
    ])
    .expect("C shape");
    let a = SimplePolygon::from_xy(&[[1.1, 1.1], [1.9, 1.1], [1.9, 1.9], [1.1, 1.9]]).expect("square");
    let union = UnionBlock::new(&a, &b);
    let r = union.report();
    assert_eq!(r.relation, Relation::Separated);
    assert!((r.distance - 0.1).abs() < 1e-12, "{r:?}");
    let r = union.report_at(Vec2::new(0.0, -0.2));
    assert_eq!(r.relation, Relation::Intersecting);
    assert!((r.distance + 0.1).abs() < 1e-12, "{r:?}");
    assert!(close(r.exit, 0.0, 0.1, 1e-12), "{r:?}");
    // Diagonal push into the corner: out along the diagonal, √2 · 0.05.
    let r = union.report_at(Vec2::new(-0.15, -0.15));
    assert!((r.distance + 0.05 * SQRT_2).abs() < 1e-12, "{r:?}");
}

/// A star whose radius alternates between 1 and 0.6: every vertex is real
/// (none is welded or straight), every second one is reflex.
fn star(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let t = 2.0 * PI * i as f64 / n as f64;
            let r = if i % 2 == 0 { 1.0 } else { 0.6 };
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

#[test]
fn concave_decomposition_is_bounded_and_says_so() {
    // One vertex pair over the documented limit: refused by name, not run for seconds.
    let over = MAX_CONCAVE_VERTICES + 2;
    let err = SimplePolygon::from_xy(&star(over)).expect_err("over the limit");
    assert_eq!(err, PolygonError::TooManyVertices { vertices: over, limit: MAX_CONCAVE_VERTICES });
    assert!(err.to_string().contains("at most 2000"), "{err}");

    // At the limit it decomposes, and the pieces cover the star's area:
    // n/2 kites of area 2 · ½ · 1 · 0.6 · sin(2π/n).
    let at = SimplePolygon::from_xy(&star(MAX_CONCAVE_VERTICES)).expect("at the limit");
    assert!(!at.is_convex());
    let n = MAX_CONCAVE_VERTICES as f64;
    let expected = n * 0.5 * 0.6 * (2.0 * PI / n).sin();
    let area: f64 = at.pieces().iter().map(|p| shoelace(p.vertices())).sum();
    assert!((area - expected).abs() < 1e-9, "pieces {area} vs star {expected}");

    // A convex ring is never decomposed, so it has no limit.
    let circle: Vec<[f64; 2]> = (0..3 * MAX_CONCAVE_VERTICES)
        .map(|i| {
            let t = 2.0 * PI * i as f64 / (3 * MAX_CONCAVE_VERTICES) as f64;
            [t.cos(), t.sin()]
        })
        .collect();
    let big = SimplePolygon::from_xy(&circle).expect("convex: no limit");
    assert!(big.is_convex());
    assert_eq!(big.pieces().len(), 1);
}

fn shoelace(p: &[Vec2]) -> f64 {
    (0..p.len()).map(|i| p[i].x * p[(i + 1) % p.len()].y - p[(i + 1) % p.len()].x * p[i].y).sum::<f64>() / 2.0
}
