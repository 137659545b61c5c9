//! Shapes and checks the contact module's own tests share.

use super::entrance_block::EntranceBlock;
use super::polygon::ConvexPolygon;
use super::report::ContactReport;
use super::vec2::Vec2;
use proptest::prelude::*;
use proptest::test_runner::TestRunner;

/// A pair of convex polygons, or `None` where a hull is degenerate.
pub(crate) type MaybePair = Option<(ConvexPolygon, ConvexPolygon)>;

/// Runs `agrees` on 2000 pairs drawn from `pairs` (a degenerate one passes
/// as it is), panicking with the smallest pair it fails on.
pub(crate) fn agrees_on(
    pairs: impl Strategy<Value = MaybePair>,
    agrees: impl Fn(&ConvexPolygon, &ConvexPolygon) -> Result<bool, TestCaseError>,
) {
    let mut runner =
        TestRunner::new(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() });
    let result = runner.run(&pairs, |pair| {
        if let Some((a, b)) = pair {
            agrees(&a, &b)?;
        }
        Ok(())
    });
    result.unwrap_or_else(|e| panic!("{e}"));
}

/// Two hulls of 3 to 9 integer points in [−3, 3]², B shifted by up to
/// `shift` each way: parallel edges, collinear points and exact touches
/// everywhere. `None` where a hull is degenerate.
pub(crate) fn grid_pair(shift: i32) -> impl Strategy<Value = MaybePair> {
    let points = || prop::collection::vec((-3i32..=3, -3i32..=3), 3..10);
    (points(), points(), -shift..=shift, -shift..=shift).prop_map(|(a, b, dx, dy)| {
        let at = |p: Vec<(i32, i32)>, dx: i32, dy: i32| {
            hull(p.into_iter().map(|(x, y)| Vec2::new(f64::from(x + dx), f64::from(y + dy))).collect())
        };
        ConvexPolygon::new(&at(a, 0, 0)).ok().zip(ConvexPolygon::new(&at(b, dx, dy)).ok())
    })
}

/// Two hulls of 3 to `max_points − 1` random points in [−1, 1]², A
/// stretched along x and B along y by 0.02 to 3, B shifted by up to `shift`
/// each way, both moved `far` out along x and in along y.
pub(crate) fn random_pair(max_points: usize, shift: f64, far: f64) -> impl Strategy<Value = MaybePair> {
    let points = move || prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64), 3..max_points);
    let stretch = || 0.02..3.0f64;
    (points(), points(), stretch(), stretch(), -shift..=shift, -shift..=shift).prop_map(
        move |(a, b, sx, sy, dx, dy)| {
            let a = hull(a.into_iter().map(|(x, y)| Vec2::new(x * sx + far, y - far)).collect());
            let b = hull(b.into_iter().map(|(x, y)| Vec2::new(x + dx + far, y * sy + dy - far)).collect());
            ConvexPolygon::new(&a).ok().zip(ConvexPolygon::new(&b).ok())
        },
    )
}

/// Strict convex hull (monotone chain), counter-clockwise.
pub(crate) fn hull(mut pts: Vec<Vec2>) -> Vec<Vec2> {
    pts.sort_by(|p, q| p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y)));
    pts.dedup();
    let cross = |o: Vec2, a: Vec2, b: Vec2| (a - o).cross(b - o);
    let mut chain: Vec<Vec2> = Vec::new();
    for pass in [pts.clone(), pts.into_iter().rev().collect()] {
        let base = chain.len();
        for p in pass {
            while chain.len() >= base + 2 && cross(chain[chain.len() - 2], chain[chain.len() - 1], p) <= 0.0 {
                chain.pop();
            }
            chain.push(p);
        }
        chain.pop();
    }
    chain
}

/// An early exit's report, where it answered, against the full walk's:
/// the same relation, the distance to 1e-12 of the pair's size, and the
/// same features where the exits agree. Whether it answered.
pub(crate) fn agrees_with_the_walk(
    a: &ConvexPolygon,
    b: &ConvexPolygon,
    fast: Option<ContactReport>,
) -> Result<bool, TestCaseError> {
    let Some(fast) = fast else { return Ok(false) };
    let full = EntranceBlock::new(a, b).report();
    let scale = a.extent().max(b.extent()).max(a.magnitude()).max(b.magnitude());
    prop_assert_eq!(fast.relation, full.relation, "fast {:?} full {:?}", fast, full);
    prop_assert!((fast.distance - full.distance).abs() <= 1e-12 * scale, "fast {:?} full {:?}", fast, full);
    prop_assert!((fast.exit.length() - fast.distance.abs()).abs() <= 1e-12 * scale, "fast {:?}", fast);
    if (fast.exit - full.exit).length() <= full.tolerance {
        let (mut f, mut w) = (fast.features.to_vec(), full.features.to_vec());
        f.sort_by_key(|x| format!("{x:?}"));
        w.sort_by_key(|x| format!("{x:?}"));
        prop_assert_eq!(f, w, "fast {:?} full {:?}", fast, full);
    }
    Ok(true)
}
