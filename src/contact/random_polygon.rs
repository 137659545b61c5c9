//! Random convex polygons: the pairs the contact benchmark times and the
//! contact tests compare exits on.

use super::vec2::Vec2;

/// `n` points at distinct random angles on an ellipse with random axes
/// (0.5 to 1.5), turn and centre near `at`, counter-clockwise: a random
/// convex polygon with no three points collinear.
pub fn random_ellipse(rng: &mut impl rand::Rng, n: usize, at: Vec2) -> Vec<Vec2> {
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
