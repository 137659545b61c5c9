//! Circles as convex polygons of N segments, as the paper's second example
//! does, with the error that costs.
//!
//! An **inscribed** N-gon has its vertices on the circle; it lies inside the
//! circle and its edges' midpoints fall short of it by the sagitta
//! `r (1 − cos(π/N))`. A **circumscribed** N-gon has its edges tangent to the
//! circle (vertices at `r / cos(π/N)`); it contains the circle and its
//! vertices overshoot by `r (1/cos(π/N) − 1) = r (1 − cos(π/N)) / cos(π/N)`.
//! Either way the Hausdorff distance between disc and polygon is that
//! figure, so every distance, exit length or contact point computed with the
//! polygon is within it of the disc's: inscribed polygons can only
//! under-report overlap, circumscribed ones over-report it. Halving the
//! error takes about √2 times the segments (`1 − cos x ≈ x²/2`).

use super::error::PolygonError;
use super::polygon::ConvexPolygon;
use super::vec2::Vec2;

/// Where the polygon sits relative to the circle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CircleFit {
    /// Vertices on the circle; the polygon is inside it.
    Inscribed,
    /// Edges tangent to the circle; the polygon contains it.
    Circumscribed,
}

/// A circle of `radius` about `center` as a counter-clockwise polygon of
/// `segments` edges, vertex 0 at angle `phase` (radians from +x; for a
/// circumscribed polygon this is the direction of vertex 0, not of an edge's
/// tangent point).
pub fn discretize_circle(
    center: Vec2,
    radius: f64,
    segments: usize,
    fit: CircleFit,
    phase: f64,
) -> Result<ConvexPolygon, PolygonError> {
    if !(radius.is_finite() && radius > 0.0) {
        return Err(PolygonError::BadRadius { radius });
    }
    if segments < 3 {
        return Err(PolygonError::TooFewPoints { distinct: segments });
    }
    let half_step = std::f64::consts::PI / segments as f64;
    let r = match fit {
        CircleFit::Inscribed => radius,
        CircleFit::Circumscribed => radius / half_step.cos(),
    };
    let points: Vec<Vec2> = (0..segments)
        .map(|k| {
            let t = phase + 2.0 * half_step * k as f64;
            center + Vec2::new(t.cos(), t.sin()) * r
        })
        .collect();
    ConvexPolygon::new(&points)
}

/// The Hausdorff distance between the disc and its N-gon (see the module
/// documentation): `r (1 − cos(π/N))` inscribed, that over `cos(π/N)`
/// circumscribed.
pub fn discretization_error(radius: f64, segments: usize, fit: CircleFit) -> f64 {
    let half_step = std::f64::consts::PI / segments.max(1) as f64;
    // 1 − cos x = 2 sin²(x/2), which keeps its digits for large N.
    let sagitta = 2.0 * radius * (0.5 * half_step).sin().powi(2);
    match fit {
        CircleFit::Inscribed => sagitta,
        CircleFit::Circumscribed => sagitta / half_step.cos(),
    }
}

/// The fewest segments (at least 3) whose discretization error is at most
/// `max_error`, for the accuracy-versus-time study. `None` when the error
/// asked for is not positive or not reachable below `usize::MAX` segments.
pub fn segments_for_error(radius: f64, max_error: f64, fit: CircleFit) -> Option<usize> {
    if !(max_error > 0.0 && radius > 0.0) {
        return None;
    }
    if discretization_error(radius, 3, fit) <= max_error {
        return Some(3);
    }
    // Inscribed: r(1 − cos(π/N)) ≤ e  ⇔  N ≥ π / acos(1 − e/r).
    let guess = std::f64::consts::PI / (1.0 - max_error / radius).clamp(-1.0, 1.0).acos();
    if !guess.is_finite() || guess >= usize::MAX as f64 / 2.0 {
        return None;
    }
    let mut n = (guess.floor() as usize).max(3);
    while discretization_error(radius, n, fit) > max_error {
        n += 1;
    }
    Some(n)
}

#[cfg(test)]
mod tests {
    use super::{CircleFit, discretization_error, discretize_circle, segments_for_error};
    use crate::contact::vec2::Vec2;

    #[test]
    fn the_inscribed_error_is_the_sagitta() {
        let p = discretize_circle(Vec2::ZERO, 2.0, 10, CircleFit::Inscribed, 0.0).expect("10-gon");
        assert_eq!(p.len(), 10);
        let v = p.vertices();
        let mid = (v[0] + v[1]) * 0.5;
        let err = 2.0 - mid.length();
        assert!((err - discretization_error(2.0, 10, CircleFit::Inscribed)).abs() < 1e-12);
        assert!((err - 2.0 * (1.0 - (std::f64::consts::PI / 10.0).cos())).abs() < 1e-12);
    }

    #[test]
    fn the_circumscribed_polygon_touches_the_circle_at_edge_midpoints() {
        let p = discretize_circle(Vec2::new(1.0, 1.0), 1.0, 16, CircleFit::Circumscribed, 0.3).expect("16-gon");
        let v = p.vertices();
        let mid = (v[3] + v[4]) * 0.5 - Vec2::new(1.0, 1.0);
        assert!((mid.length() - 1.0).abs() < 1e-12);
        let overshoot = (v[3] - Vec2::new(1.0, 1.0)).length() - 1.0;
        assert!((overshoot - discretization_error(1.0, 16, CircleFit::Circumscribed)).abs() < 1e-12);
    }

    #[test]
    fn segments_for_error_is_the_smallest_that_meets_it() {
        for fit in [CircleFit::Inscribed, CircleFit::Circumscribed] {
            for &e in &[1e-1, 1e-3, 1e-6] {
                let n = segments_for_error(1.0, e, fit).expect("reachable");
                assert!(discretization_error(1.0, n, fit) <= e);
                assert!(n == 3 || discretization_error(1.0, n - 1, fit) > e);
            }
        }
        assert_eq!(segments_for_error(1.0, 0.0, CircleFit::Inscribed), None);
    }

    #[test]
    fn bad_circles_are_errors() {
        assert!(discretize_circle(Vec2::ZERO, 0.0, 8, CircleFit::Inscribed, 0.0).is_err());
        assert!(discretize_circle(Vec2::ZERO, f64::NAN, 8, CircleFit::Inscribed, 0.0).is_err());
        assert!(discretize_circle(Vec2::ZERO, 1.0, 2, CircleFit::Inscribed, 0.0).is_err());
    }
}
