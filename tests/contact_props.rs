//! Property tests of the contact module on random convex pairs: the O(m + n)
//! entrance block against the O(m·n) brute force and against parry2d's
//! GJK/EPA, plus the cached block and the concave union.
//!
//! parry is compared only on pairs whose signed distance is clear of zero
//! (|d| > 1e-6 of the scale): at exact coincidence (touching, shared edges)
//! GJK/EPA report an arbitrary normal or miss the contact, which is a known
//! limitation of that method, not a disagreement about geometry. The exact
//! and degenerate cases are covered against the brute force here (integer
//! grid polygons touch, share edges and vertices all the time) and by name
//! in `contact_hard_cases.rs`.
//!
//! Case counts are kept so the file runs in a few seconds in release.

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query;
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use proptest::prelude::*;
use surfacelab::contact::{
    CachedBlock, ContactReport, ConvexPolygon, EntranceBlock, Relation, SimplePolygon, UnionBlock, Vec2,
    brute_force_report, brute_force_report_at, contact_report,
};

/// Strict convex hull (monotone chain), dropping collinear points.
fn hull(mut pts: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    pts.sort_by(|p, q| p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1])));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    let mut lower: Vec<[f64; 2]> = Vec::new();
    for &p in &pts {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0.0 {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<[f64; 2]> = Vec::new();
    for &p in pts.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0.0 {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

fn area(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    (0..n).map(|i| p[i][0] * p[(i + 1) % n][1] - p[(i + 1) % n][0] * p[i][1]).sum::<f64>() * 0.5
}

/// Random convex polygon around the origin, size about 1: either the hull
/// of random points or a polygon on an ellipse (many vertices).
fn convex() -> impl Strategy<Value = Vec<[f64; 2]>> {
    let from_points = prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64), 3..24)
        .prop_map(|v| hull(v.into_iter().map(|(x, y)| [x, y]).collect()));
    let on_ellipse = (prop::collection::vec(0.0..std::f64::consts::TAU, 3..80), 0.2..1.0f64, 0.2..1.0f64, 0.0..3.2f64)
        .prop_map(|(mut t, rx, ry, rot)| {
            t.sort_by(f64::total_cmp);
            let (s, c) = rot.sin_cos();
            hull(
                t.into_iter()
                    .map(|t| [rx * t.cos() * c - ry * t.sin() * s, rx * t.cos() * s + ry * t.sin() * c])
                    .collect(),
            )
        });
    prop_oneof![from_points, on_ellipse].prop_filter("a proper polygon", |p| p.len() >= 3 && area(p) > 1e-3)
}

/// Random convex polygon with small integer coordinates: parallel edges,
/// exact touching and shared vertices are common.
fn grid_convex() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec((-3i32..=3, -3i32..=3), 3..10)
        .prop_map(|v| hull(v.into_iter().map(|(x, y)| [f64::from(x), f64::from(y)]).collect()))
        .prop_filter("a proper polygon", |p| p.len() >= 3 && area(p) > 0.4)
}

/// Regular polygons whose edges are parallel to each other's up to
/// rounding (the paper's discretised circles): n and 2n sides, phases in
/// steps of π/n.
fn regular() -> impl Strategy<Value = Vec<[f64; 2]>> {
    (3usize..13, 0usize..2, 0u32..24, 0.3..1.0f64).prop_map(|(n, double, k, r)| {
        let sides = n << double;
        let phase = f64::from(k) * std::f64::consts::PI / n as f64;
        (0..sides)
            .map(|i| {
                let t = phase + std::f64::consts::TAU * i as f64 / sides as f64;
                [r * t.cos(), r * t.sin()]
            })
            .collect()
    })
}

fn shifted(p: &[[f64; 2]], scale: f64, dx: f64, dy: f64) -> ConvexPolygon {
    let pts: Vec<[f64; 2]> = p.iter().map(|q| [q[0] * scale + dx, q[1] * scale + dy]).collect();
    ConvexPolygon::from_xy(&pts).expect("hull is convex")
}

/// Distance from `p` to the boundary of `poly`.
fn boundary_distance(poly: &ConvexPolygon, p: Vec2) -> f64 {
    let v = poly.vertices();
    let n = v.len();
    (0..n)
        .map(|i| {
            let (s, e) = (v[i], v[(i + 1) % n]);
            let d = e - s;
            let t = ((p - s).dot(d) / d.length_squared()).clamp(0.0, 1.0);
            (p - (s + d * t)).length()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The checks every report must pass on its own, `scale` being the size of
/// the problem.
fn check_self_consistent(
    a: &ConvexPolygon,
    b: &ConvexPolygon,
    r: &ContactReport,
    scale: f64,
) -> Result<(), TestCaseError> {
    let eps = 1e-9 * scale;
    prop_assert!((r.exit.length() - r.distance.abs()).abs() <= eps, "|exit| != |distance|: {r:?}");
    prop_assert_eq!(r.relation, Relation::from_signed_distance(r.distance, r.tolerance));
    let [wa, wb] = r.witness;
    prop_assert!((wb - wa - r.exit).length() <= eps, "witness does not span the exit: {r:?}");
    prop_assert!(boundary_distance(a, wa) <= eps, "witness a off A: {r:?}");
    prop_assert!(boundary_distance(b, wb) <= eps, "witness b off B: {r:?}");
    // Moving A by the exit leaves it touching B.
    let after = brute_force_report_at(a, b, r.exit);
    prop_assert!(after.distance.abs() <= eps, "after the exit: {after:?} (from {r:?})");
    prop_assert!(!r.features.is_empty());
    Ok(())
}

fn check_against_brute_force(a: &ConvexPolygon, b: &ConvexPolygon, scale: f64) -> Result<(), TestCaseError> {
    let walk = EntranceBlock::new(a, b).report();
    // The one-shot query walks the same boundary without storing it.
    let one_shot = contact_report(a, b);
    prop_assert_eq!(one_shot.relation, walk.relation);
    prop_assert!((one_shot.distance - walk.distance).abs() <= 1e-12 * scale, "one-shot {one_shot:?} block {walk:?}");
    let brute = brute_force_report(a, b);
    prop_assert_eq!(walk.relation, brute.relation, "walk {:?} brute {:?}", walk, brute);
    prop_assert!((walk.distance - brute.distance).abs() <= 1e-9 * scale, "walk {walk:?} brute {brute:?}");
    check_self_consistent(a, b, &walk, scale)?;
    check_self_consistent(a, b, &brute, scale)?;
    if (walk.exit - brute.exit).length() <= walk.tolerance {
        let mut w: Vec<_> = walk.features.to_vec();
        let mut f: Vec<_> = brute.features.to_vec();
        w.sort_by_key(|x| format!("{x:?}"));
        f.sort_by_key(|x| format!("{x:?}"));
        prop_assert_eq!(w, f, "features differ: walk {:?} brute {:?}", walk, brute);
    }
    Ok(())
}

/// parry's `from_convex_polyline` drops vertices whose neighbouring edges
/// turn by less than ~1.7e-4 rad, which moves the boundary by up to 6e-5 on
/// these polygons; `_unmodified` keeps our (already clean) vertices.
fn parry_polygon(p: &ConvexPolygon) -> ParryPolygon {
    let pts = p.vertices().iter().map(|v| Vector::new(v.x, v.y)).collect();
    ParryPolygon::from_convex_polyline_unmodified(pts).expect("parry accepts a clean convex polygon")
}

/// A pair the proptest `walk_matches_brute_force_on_regular_polygons`
/// found (shrunk input, as printed): B shifted by `(dx, dy)`, then A moved
/// exactly onto a vertex (`snap` 1) or into an edge (`snap` 2) of their
/// block, so the two touch.
fn snapped(a: &[[f64; 2]], b: &[[f64; 2]], dx: f64, dy: f64, snap: u32) -> (ConvexPolygon, ConvexPolygon) {
    let (a, b) = (shifted(a, 1.0, 0.0, 0.0), shifted(b, 1.0, dx, dy));
    let block = EntranceBlock::new(&a, &b);
    let t = if snap == 1 {
        block.edges()[(dx.to_bits() % block.edges().len() as u64) as usize].start
    } else {
        let e = block.edges()[(dy.to_bits() % block.edges().len() as u64) as usize];
        e.start + e.direction * 0.37
    };
    (a.translated(t).expect("moved"), b)
}

/// Two touching pairs of regular polygons that a one-shot query can call
/// separated: a normal half a turn from the search's reference direction
/// falls in either half by rounding, and the separating axis search would
/// take the opposite vertex (`at_or_after_in_half` decides it). The
/// proptest meets such pairs rarely; these two are kept.
#[test]
#[allow(clippy::unreadable_literal)] // the proptest's numbers, as printed
fn touching_regular_polygons_are_not_called_separated() {
    let twelve_gon = [
        [-0.5963911214470748, -0.15980251936483533],
        [-0.4365886020822396, -0.4365886020822395],
        [-0.15980251936483525, -0.5963911214470748],
        [0.15980251936483503, -0.596391121447075],
        [0.4365886020822394, -0.4365886020822396],
        [0.5963911214470748, -0.15980251936483528],
        [0.596391121447075, 0.159802519364835],
        [0.4365886020822396, 0.4365886020822394],
        [0.1598025193648353, 0.5963911214470748],
        [-0.15980251936483497, 0.596391121447075],
        [-0.43658860208223976, 0.43658860208223926],
        [-0.5963911214470748, 0.15980251936483533],
    ];
    let pentagon = [
        [0.11684149789852764, 0.3596011545411927],
        [-0.3058950127947921, 0.22224573590016156],
        [-0.30589501279479275, -0.2222457359001606],
        [0.11684149789852656, -0.359601154541193],
        [0.3781070297925316, -2.7782853826232203e-16],
    ];
    let sixteen_gon = [
        [0.4178476540563943, 0.0],
        [0.3860408952905594, 0.1599033744600016],
        [0.295462909686167, 0.29546290968616695],
        [0.1599033744600016, 0.3860408952905594],
        [2.5585789603569693e-17, 0.4178476540563943],
        [-0.15990337446000158, 0.3860408952905594],
        [-0.29546290968616695, 0.295462909686167],
        [-0.3860408952905594, 0.15990337446000163],
        [-0.4178476540563943, 5.1171579207139385e-17],
        [-0.38604089529055946, -0.15990337446000155],
        [-0.29546290968616706, -0.29546290968616695],
        [-0.15990337446000183, -0.38604089529055935],
        [-7.675736881070907e-17, -0.4178476540563943],
        [0.1599033744600017, -0.38604089529055935],
        [0.29546290968616695, -0.29546290968616706],
        [0.38604089529055935, -0.15990337446000186],
    ];
    let octagon = [
        [-1.3426633334725545e-16, -0.7309118756566487],
        [0.5168327437265948, -0.516832743726595],
        [0.7309118756566487, -1.7902177779634063e-16],
        [0.516832743726595, 0.5168327437265948],
        [2.237772222454258e-16, 0.7309118756566487],
        [-0.5168327437265944, 0.5168327437265955],
        [-0.7309118756566487, 2.685326666945109e-16],
        [-0.5168327437265946, -0.5168327437265953],
    ];
    for (a, b) in [
        snapped(&twelve_gon, &pentagon, 0.46956896127740283, -1.0067426580287355, 1),
        snapped(&sixteen_gon, &octagon, -1.4266335369060743, 0.768266070324618, 2),
    ] {
        let one_shot = contact_report(&a, &b);
        assert_eq!(one_shot.relation, Relation::Touching, "{one_shot:?}");
        assert!(one_shot.distance.abs() <= one_shot.tolerance, "{one_shot:?}");
        check_against_brute_force(&a, &b, 1.0).expect("agrees with the brute force");
    }
}

proptest! {
    // A rejected case (`walk_matches_parry` on a pair within 1e-6 of
    // touching, `touching_by_construction_is_touching` on a B that rounding
    // welds far from the origin) is not a tested case: proptest still runs
    // 600 real ones, and fails the test past `max_global_rejects`. Both are
    // rounding coincidences on continuous random inputs: none in 600 cases
    // measured, so six (1% of the cases) fail the test.
    #![proptest_config(ProptestConfig {
        cases: 600,
        max_global_rejects: 6,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn walk_matches_brute_force_on_random_pairs(
        a in convex(),
        b in convex(),
        dx in -2.5..2.5f64,
        dy in -2.5..2.5f64,
        scale in prop_oneof![Just(1.0), 1e-3..1e3f64],
    ) {
        let (a, b) = (shifted(&a, scale, 0.0, 0.0), shifted(&b, scale, dx * scale, dy * scale));
        check_against_brute_force(&a, &b, scale)?;
    }

    #[test]
    fn walk_matches_brute_force_on_integer_grids(
        a in grid_convex(), b in grid_convex(), dx in -6i32..=6, dy in -6i32..=6,
    ) {
        let (a, b) = (shifted(&a, 1.0, 0.0, 0.0), shifted(&b, 1.0, f64::from(dx), f64::from(dy)));
        check_against_brute_force(&a, &b, 1.0)?;
    }

    #[test]
    fn walk_matches_brute_force_on_regular_polygons(
        a in regular(), b in regular(), dx in -2.0..2.0f64, dy in -2.0..2.0f64, snap in 0u32..3,
    ) {
        let (a, b) = (shifted(&a, 1.0, 0.0, 0.0), shifted(&b, 1.0, dx, dy));
        // Also exactly onto a vertex or an edge of the entrance block.
        let block = EntranceBlock::new(&a, &b);
        let t = match snap {
            0 => Vec2::ZERO,
            1 => block.edges()[(dx.to_bits() % block.edges().len() as u64) as usize].start,
            _ => {
                let e = block.edges()[(dy.to_bits() % block.edges().len() as u64) as usize];
                e.start + e.direction * 0.37
            }
        };
        let (a, b) = (a.translated(t).expect("moved"), b);
        check_against_brute_force(&a, &b, 1.0)?;
    }

    #[test]
    fn walk_matches_brute_force_far_from_the_origin(
        a in convex(), b in convex(), dx in -2.5..2.5f64, dy in -2.5..2.5f64,
    ) {
        let (a, b) = (shifted(&a, 1.0, 1e6, -1e6), shifted(&b, 1.0, 1e6 + dx, -1e6 + dy));
        check_against_brute_force(&a, &b, 1e6 * 1e-3)?;
    }

    #[test]
    fn walk_matches_parry(a in convex(), b in convex(), dx in -2.5..2.5f64, dy in -2.5..2.5f64) {
        let (a, b) = (shifted(&a, 1.0, 0.0, 0.0), shifted(&b, 1.0, dx, dy));
        let ours = EntranceBlock::new(&a, &b).report();
        prop_assume!(ours.distance.abs() > 1e-6);
        let (pa, pb) = (parry_polygon(&a), parry_polygon(&b));
        let id = Pose::identity();
        let theirs = query::contact(&id, &pa, &id, &pb, ours.distance.max(0.0) + 1.0)
            .expect("supported")
            .expect("within prediction");
        // parry's GJK and EPA stop at about 1e-8 of the size here (exact
        // rational arithmetic on such a case agrees with ours), so the
        // comparison is at 1e-7.
        let eps = 1e-7;
        prop_assert!(
            (theirs.dist - ours.distance).abs() <= eps,
            "parry {} ours {:?}", theirs.dist, ours
        );
        let relation = if theirs.dist > 0.0 { Relation::Separated } else { Relation::Intersecting };
        prop_assert_eq!(ours.relation, relation);
        // parry's exit: from its point on A to its point on B when apart,
        // along −normal1 by the depth when overlapping.
        let exit = if theirs.dist > 0.0 {
            Vec2::new(theirs.point2.x - theirs.point1.x, theirs.point2.y - theirs.point1.y)
        } else {
            Vec2::new(theirs.normal1.x, theirs.normal1.y) * theirs.dist
        };
        prop_assert!((exit.length() - ours.exit.length()).abs() <= eps);
        // Ties (several shortest exits) are allowed; parry's must then be
        // one of ours: A moved by it just touches B.
        if (exit - ours.exit).length() > 1e-6 {
            let after = brute_force_report_at(&a, &b, exit);
            prop_assert!(
                after.distance.abs() <= eps,
                "parry exit {exit:?} vs ours {:?}: {after:?}", ours.exit
            );
        }
    }

    /// B placed so that its extreme vertex in direction −u sits on A's
    /// extreme vertex in direction u: touching by construction, up to the
    /// rounding of the placement, at any scale and distance from the origin.
    #[test]
    fn touching_by_construction_is_touching(
        a in convex(), b in convex(), angle in 0.0..std::f64::consts::TAU,
        scale in prop_oneof![Just(1.0), Just(1e-6), Just(1e3)],
        far in prop_oneof![Just(0.0), Just(1e6)],
    ) {
        let u = Vec2::new(angle.cos(), angle.sin());
        let a = shifted(&a, scale, far, far);
        let b0 = shifted(&b, scale, 0.0, 0.0);
        let support = |p: &ConvexPolygon, d: Vec2| {
            p.vertices().iter().copied().fold(p.vertices()[0], |m, v| if v.dot(d) > m.dot(d) { v } else { m })
        };
        let offset = support(&a, u) - support(&b0, -u);
        // Far from the origin rounding may weld B's shortest edges; a B
        // that does not survive the move is not this property's business.
        let Ok(b) = b0.translated(offset) else {
            return Err(TestCaseError::reject("B degenerates at 1e6"));
        };
        let walk = EntranceBlock::new(&a, &b).report();
        prop_assert_eq!(walk.relation, Relation::Touching, "{:?}", walk);
        prop_assert_eq!(brute_force_report(&a, &b).relation, Relation::Touching);
        prop_assert!(!walk.features.is_empty());
    }

    #[test]
    fn cached_block_matches_the_linear_scan(
        a in convex(),
        b in convex(),
        moves in prop::collection::vec((-3.0..3.0f64, -3.0..3.0f64), 1..20),
    ) {
        let (a, b) = (shifted(&a, 1.0, 0.0, 0.0), shifted(&b, 1.0, 0.0, 0.0));
        let cached = CachedBlock::new(&a, &b);
        for (x, y) in moves {
            let t = Vec2::new(x, y);
            let slow = cached.block().report_at(t);
            let fast = cached.report(t);
            prop_assert!((fast.distance - slow.distance).abs() <= 1e-12, "at {t:?}: {fast:?} vs {slow:?}");
            prop_assert_eq!(cached.relation(t), slow.relation);
            // The block built with A already moved answers the same.
            let moved = EntranceBlock::new(&a.translated(t).expect("unit polygons survive a move"), &b).report();
            prop_assert!((moved.distance - slow.distance).abs() <= 1e-9);
        }
    }

    #[test]
    fn cached_relation_is_exact_at_the_touching_band(a in grid_convex(), b in grid_convex(), dx in -6i32..=6, dy in -6i32..=6) {
        let (a, b) = (shifted(&a, 1.0, 0.0, 0.0), shifted(&b, 1.0, 0.0, 0.0));
        let cached = CachedBlock::new(&a, &b);
        let t = Vec2::new(f64::from(dx), f64::from(dy));
        prop_assert_eq!(cached.relation(t), brute_force_report_at(&a, &b, t).relation);
    }

    /// The cached block at random translations round an overlapping pair
    /// (a disc of radius 2: mostly inside, some outside) answers what the
    /// linear scan of the same block answers (inside, the same report bit
    /// for bit; outside, the same relation and the distance to 1e-12) and
    /// what the one-shot query with A moved answers (the same relation, the
    /// distance to 1e-9, as above).
    #[test]
    fn cached_reports_are_the_one_shot_reports(
        a in convex(),
        b in convex(),
        (dx, dy) in (-0.5..0.5f64, -0.5..0.5f64),
        moves in prop::collection::vec((0.0..std::f64::consts::TAU, 0.0..1.0f64), 1..24),
    ) {
        let (a, b) = (shifted(&a, 1.0, 0.0, 0.0), shifted(&b, 1.0, dx, dy));
        let cached = CachedBlock::new(&a, &b);
        for (angle, r) in moves {
            let t = Vec2::new(angle.cos(), angle.sin()) * (2.0 * r.sqrt());
            let fast = cached.report(t);
            let slow = cached.block().report_at(t);
            if slow.distance < 0.0 {
                prop_assert_eq!(fast, slow, "at {:?}", t);
            } else {
                prop_assert_eq!(fast.relation, slow.relation, "at {:?}", t);
                prop_assert!((fast.distance - slow.distance).abs() <= 1e-12, "at {t:?}: {fast:?} vs {slow:?}");
            }
            prop_assert_eq!(cached.signed_distance(t), fast.distance);
            prop_assert_eq!(cached.relation(t), slow.relation, "at {:?}", t);
            let one = contact_report(&a.translated(t).expect("unit polygons survive a move"), &b);
            prop_assert!((one.distance - fast.distance).abs() <= 1e-9, "at {t:?}: {one:?} vs {fast:?}");
            // A distance within rounding of the touching band may fall
            // either side of it after the move.
            if (fast.distance.abs() - fast.tolerance).abs() > 1e-9 {
                prop_assert_eq!(one.relation, fast.relation, "at {:?}", t);
            }
        }
    }
}

/// Star-shaped simple polygon: radii at sorted angles.
fn star() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec((0.0..std::f64::consts::TAU, 0.3..1.0f64), 3..12).prop_map(|mut v| {
        v.sort_by(|p, q| p.0.total_cmp(&q.0));
        v.dedup_by(|p, q| (p.0 - q.0).abs() < 0.05);
        v.into_iter().map(|(t, r)| [r * t.cos(), r * t.sin()]).collect()
    })
}

proptest! {
    // Random stars that are not simple polygons (too few points left after
    // merging close angles) are rejected, not tested: 2 measured beside the
    // 60 real cases; more than ten (a sixth of the cases) fail the test.
    #![proptest_config(ProptestConfig {
        cases: 60,
        max_global_rejects: 10,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// The union's answers: separated distance is the minimum over the
    /// pieces, and an intersecting exit leaves every pair of pieces at most
    /// touching and is no longer than the shortest exit found by sweeping
    /// 72 directions.
    #[test]
    fn concave_union_exit_is_valid_and_shortest(a in star(), b in star(), dx in -1.5..1.5f64, dy in -1.5..1.5f64) {
        let (Ok(a), Ok(b)) = (SimplePolygon::from_xy(&a), SimplePolygon::from_xy(&b)) else {
            return Err(TestCaseError::reject("not a simple polygon"));
        };
        let union = UnionBlock::new(&a, &b);
        let t = Vec2::new(dx, dy);
        let r = union.report_at(t);
        let pairs = |at: Vec2| -> f64 {
            a.pieces().iter().flat_map(|pa| b.pieces().iter().map(move |pb| brute_force_report_at(pa, pb, at).distance))
                .fold(f64::INFINITY, f64::min)
        };
        prop_assert!((r.exit.length() - r.distance.abs()).abs() <= 1e-9);
        if r.relation == Relation::Intersecting {
            let after = pairs(t + r.exit);
            prop_assert!(after >= -1e-9, "still overlapping by {after} after {r:?}");
            // Direction sweep: bisect the first separating distance.
            let mut sweep = f64::INFINITY;
            for k in 0..72 {
                let dir = Vec2::new(f64::from(k * 5).to_radians().cos(), f64::from(k * 5).to_radians().sin());
                let (mut lo, mut hi) = (0.0, 8.0);
                if pairs(t + dir * hi) < 0.0 { continue; }
                for _ in 0..40 {
                    let mid = 0.5 * (lo + hi);
                    if pairs(t + dir * mid) >= 0.0 { hi = mid } else { lo = mid }
                }
                sweep = sweep.min(hi);
            }
            prop_assert!(r.exit.length() <= sweep + 1e-9, "exit {} longer than sweep {sweep}", r.exit.length());
        } else {
            prop_assert!((r.distance - pairs(t)).abs() <= 1e-9, "{r:?} vs {}", pairs(t));
        }
    }
}
