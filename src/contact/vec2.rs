//! A plain 2D vector in `f64`, the one numeric type of the contact module.
//!
//! The module keeps its own small vector rather than borrowing `glam`'s so
//! that it stays free of the rest of the crate (it is reused by the CLI's
//! `contact` command and the trade-off study) and so that every operation the
//! geometry relies on (`cross`, `perp`) is spelled out next to its meaning.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

/// A point or a displacement in the table plane.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec2 {
    pub x: f64,
    pub y: f64,
}

impl Vec2 {
    pub const ZERO: Self = Self { x: 0.0, y: 0.0 };

    pub const fn new(x: f64, y: f64) -> Self {
        Self { x, y }
    }

    pub fn dot(self, other: Self) -> f64 {
        self.x * other.x + self.y * other.y
    }

    /// The z component of the 3D cross product: positive when `other` turns
    /// counter-clockwise from `self` (the paper's right-hand rule).
    pub fn cross(self, other: Self) -> f64 {
        self.x * other.y - self.y * other.x
    }

    pub fn length_squared(self) -> f64 {
        self.dot(self)
    }

    /// `sqrt(x² + y²)`, not `hypot`: `hypot` guards against overflow beyond
    /// 1e154, which no table coordinate reaches, at several times the cost
    /// (it dominated the entrance block's build time).
    pub fn length(self) -> f64 {
        self.length_squared().sqrt()
    }

    /// Rotated a quarter turn clockwise: for an edge of a counter-clockwise
    /// polygon this points out of the polygon.
    pub fn perp_cw(self) -> Self {
        Self::new(self.y, -self.x)
    }

    /// This vector scaled to length one, or zero if it has no length.
    pub fn normalized(self) -> Self {
        let len = self.length();
        if len > 0.0 { self * len.recip() } else { Self::ZERO }
    }

    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }

    /// The point a fraction `t` of the way from `self` to `to`.
    pub fn lerp(self, to: Self, t: f64) -> Self {
        self + (to - self) * t
    }

    /// The larger of the two absolute coordinates (an L∞ norm), used to size
    /// rounding tolerances.
    pub fn max_abs(self) -> f64 {
        self.x.abs().max(self.y.abs())
    }
}

impl From<[f64; 2]> for Vec2 {
    fn from([x, y]: [f64; 2]) -> Self {
        Self::new(x, y)
    }
}

impl From<Vec2> for [f64; 2] {
    fn from(v: Vec2) -> Self {
        [v.x, v.y]
    }
}

impl Add for Vec2 {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Self::new(self.x + rhs.x, self.y + rhs.y)
    }
}

impl AddAssign for Vec2 {
    fn add_assign(&mut self, rhs: Self) {
        *self = *self + rhs;
    }
}

impl Sub for Vec2 {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        Self::new(self.x - rhs.x, self.y - rhs.y)
    }
}

impl SubAssign for Vec2 {
    fn sub_assign(&mut self, rhs: Self) {
        *self = *self - rhs;
    }
}

impl Neg for Vec2 {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y)
    }
}

impl Mul<f64> for Vec2 {
    type Output = Self;
    fn mul(self, rhs: f64) -> Self {
        Self::new(self.x * rhs, self.y * rhs)
    }
}

impl Div<f64> for Vec2 {
    type Output = Self;
    fn div(self, rhs: f64) -> Self {
        Self::new(self.x / rhs, self.y / rhs)
    }
}

/// Whether `v` is at or counter-clockwise after `d`, for two vectors that
/// lie in the same half-turn `half` counter-clockwise from `base` (0:
/// `[0, π)`, 1: `[π, 2π)`, as the contact walks sort normals).
///
/// Less than three eighths of a turn apart, the sign of `d × v` says it.
/// Further apart, only near the half's two ends, that sign is not to be
/// trusted: rounding can put a vector half a turn from `base` in either
/// half, and two vectors "in one half" are then half a turn apart, where
/// `d × v` is noise. There the one nearer the half's start (by the sign of
/// its dot product with `base`, reliable that far from the middle) comes
/// first. A proptest found the noisy sign sending the separating-axis
/// search to the opposite vertex: touching pairs called separated by 0.6.
pub(crate) fn at_or_after_in_half(d: Vec2, v: Vec2, base: Vec2, half: u8) -> bool {
    let (x, y) = (d.cross(v), d.dot(v));
    if y < 0.0 && x.abs() < -y { if half == 0 { base.dot(v) < 0.0 } else { base.dot(v) > 0.0 } } else { x >= 0.0 }
}

/// The mean of some points, summed relative to the first so that points
/// far from the origin keep their digits.
pub(crate) fn mean(points: &[Vec2]) -> Vec2 {
    let origin = points[0];
    let sum = points.iter().fold(Vec2::ZERO, |s, &p| s + (p - origin));
    origin + sum / points.len() as f64
}

#[cfg(test)]
mod tests {
    use super::Vec2;

    #[test]
    fn cross_is_positive_for_a_left_turn() {
        assert_eq!(Vec2::new(1.0, 0.0).cross(Vec2::new(0.0, 1.0)), 1.0);
        assert_eq!(Vec2::new(0.0, 1.0).cross(Vec2::new(1.0, 0.0)), -1.0);
    }

    #[test]
    fn perp_cw_points_out_of_a_ccw_edge() {
        // The bottom edge of a CCW unit square runs +x; outside is -y.
        assert_eq!(Vec2::new(1.0, 0.0).perp_cw(), Vec2::new(0.0, -1.0));
    }
}
