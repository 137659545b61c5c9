//! The one place where "close enough" is defined.
//!
//! Every threshold in the module is `RELATIVE * size + ROUNDING * ε * magnitude`:
//!
//! * `size` is a length of the geometry itself (a polygon's extent, or the
//!   smaller of two extents). The relative part (`1e-9`) is what a person
//!   means by "these two vertices are the same" or "these polygons touch":
//!   it is far above the error of the handful of floating-point operations
//!   behind a distance, and far below anything a table-top footprint cares
//!   about.
//! * `magnitude` is the largest absolute coordinate involved. Inputs far from
//!   the origin (coordinates ~1e6) carry a rounding error of about
//!   `ε · magnitude` in every coordinate *before* we see them, so a touching
//!   pair built by an ordinary float computation (an offset, a rotation) can
//!   be off by a few units in the last place of 1e6. `ROUNDING = 8` (8 to 16 ulps)
//!   covers that. Our own arithmetic needs no such allowance: every
//!   coordinate we compare is a difference `b − a` of two nearby input
//!   points, which floating point computes almost exactly.
//!
//! At unit scale the tolerance is about 1e-9; at 1e6 with unit sizes about
//! 2.8e-9; for a 1e-6 polygon near the origin about 1e-15.
//!
//! Rejected alternative: a fixed absolute slop as in `Box2D` (0.005 m). Our
//! inputs range from 1e-6 to 1e6, so no single length can serve.
//!
//! Design: docs/design/contact-theory.md.

/// Relative part of every tolerance.
pub const RELATIVE: f64 = 1e-9;

/// Multiple of machine epsilon applied to the largest coordinate.
pub const ROUNDING: f64 = 8.0;

/// `RELATIVE * size + ROUNDING * ε * magnitude`.
pub fn scale_tolerance(size: f64, magnitude: f64) -> f64 {
    RELATIVE * size + ROUNDING * f64::EPSILON * magnitude
}

/// Relative part of the tight tolerance.
pub const TIGHT_RELATIVE: f64 = 1e-12;

/// Multiple of machine epsilon in the tight tolerance (1 to 2 ulps).
pub const TIGHT_ROUNDING: f64 = 2.0;

/// `TIGHT_RELATIVE * size + TIGHT_ROUNDING * ε * magnitude`: how far
/// cleaning may move a polygon's boundary *outward-in* (welding vertices,
/// dropping a vertex that bulges out of its chord). Kept a thousand times
/// below [`scale_tolerance`] so that cleaning alone never moves a touching
/// pair out of the touching band.
pub fn tight_tolerance(size: f64, magnitude: f64) -> f64 {
    TIGHT_RELATIVE * size + TIGHT_ROUNDING * f64::EPSILON * magnitude
}

#[cfg(test)]
mod tests {
    use super::scale_tolerance;

    #[test]
    fn unit_geometry_gets_a_nano_tolerance() {
        let tol = scale_tolerance(1.0, 1.0);
        assert!(tol > 1e-9 && tol < 1.1e-9, "{tol}");
    }

    #[test]
    fn far_coordinates_widen_the_tolerance() {
        // Size 1 at 1e6: 1e-9 + 8 ε 1e6 ≈ 2.8e-9.
        let tol = scale_tolerance(1.0, 1e6);
        assert!(tol > 2.7e-9 && tol < 2.9e-9, "{tol}");
    }
}
