//! Shapes the contact module's own tests share.

use super::vec2::Vec2;

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

/// `n` points at distinct random angles on an ellipse with random axes
/// (0.5 to 1.5), turn and centre near `at`, counter-clockwise: the random
/// convex polygons of the contact benchmark.
pub(crate) fn random_ellipse(rng: &mut impl rand::Rng, n: usize, at: Vec2) -> Vec<Vec2> {
    let (ax, ay) = (rng.random_range(0.5..1.5), rng.random_range(0.5..1.5));
    let turn: f64 = rng.random_range(0.0..std::f64::consts::TAU);
    let mut angles: Vec<f64> = (0..n).map(|_| rng.random_range(0.0..std::f64::consts::TAU)).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    angles
        .iter()
        .map(|t| {
            let (x, y) = (ax * t.cos(), ay * t.sin());
            at + Vec2::new(x * turn.cos() - y * turn.sin(), x * turn.sin() + y * turn.cos())
        })
        .collect()
}
