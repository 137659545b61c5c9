//! Primitive footprints on the table plane, evaluated as signed distances.
//!
//! Every hand and tangible is a union of these. A signed distance (negative
//! inside, metres) gives the rasterizer both the inside test and a soft,
//! resolution-independent edge from one evaluation per pixel.

/// One primitive footprint, in table metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Footprint {
    /// An ellipse with semi-axes `radii` along its own x and y, rotated by
    /// `angle` (radians, counter-clockwise).
    Ellipse { centre: [f32; 2], radii: [f32; 2], angle: f32 },
    /// All points within `radius` of the segment `a`-`b`.
    Capsule { a: [f32; 2], b: [f32; 2], radius: f32 },
    /// A rectangle with half extents `half` along its own axes, rotated by
    /// `angle`, its corners rounded with `corner` (`corner <= min(half)`).
    RoundedRect { centre: [f32; 2], half: [f32; 2], angle: f32, corner: f32 },
    /// An annulus: the rim of a cup standing on the glass.
    Ring { centre: [f32; 2], radius: f32, half_width: f32 },
}

/// A shape that touches the glass with a relative grey `level` (0..=1): the
/// palm presses harder than the fingers, a cup rim shows uniformly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Patch {
    pub shape: Footprint,
    pub level: f32,
}

/// A [`Footprint`] ready for many distance queries: no trigonometry or
/// division per point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Prepared {
    Ellipse { centre: [f32; 2], sin: f32, cos: f32, inv: [f32; 2], inv2: [f32; 2], inner: f32 },
    Capsule { a: [f32; 2], ab: [f32; 2], inv_len2: f32, radius: f32 },
    RoundedRect { centre: [f32; 2], sin: f32, cos: f32, inner: [f32; 2], corner: f32 },
    Ring { centre: [f32; 2], radius: f32, half_width: f32 },
}

impl Prepared {
    /// See [`Footprint::distance`].
    #[inline]
    pub fn distance(&self, p: [f32; 2]) -> f32 {
        match *self {
            Self::Ellipse { centre, sin, cos, inv, inv2, inner } => {
                let q = rotate([p[0] - centre[0], p[1] - centre[1]], cos, -sin);
                let k0 = length([q[0] * inv[0], q[1] * inv[1]]);
                let k1 = length([q[0] * inv2[0], q[1] * inv2[1]]);
                if k1 <= f32::EPSILON { inner } else { k0 * (k0 - 1.0) / k1 }
            }
            Self::Capsule { a, ab, inv_len2, radius } => {
                let ap = [p[0] - a[0], p[1] - a[1]];
                let t = ((ap[0] * ab[0] + ap[1] * ab[1]) * inv_len2).clamp(0.0, 1.0);
                length([ap[0] - t * ab[0], ap[1] - t * ab[1]]) - radius
            }
            Self::RoundedRect { centre, sin, cos, inner, corner } => {
                let q = rotate([p[0] - centre[0], p[1] - centre[1]], cos, -sin);
                let d = [q[0].abs() - inner[0], q[1].abs() - inner[1]];
                let outside = length([d[0].max(0.0), d[1].max(0.0)]);
                outside + d[0].max(d[1]).min(0.0) - corner
            }
            Self::Ring { centre, radius, half_width } => {
                (length([p[0] - centre[0], p[1] - centre[1]]) - radius).abs() - half_width
            }
        }
    }
}

fn rotate(v: [f32; 2], cos: f32, sin: f32) -> [f32; 2] {
    [v[0] * cos - v[1] * sin, v[0] * sin + v[1] * cos]
}

/// Euclidean length. Not `hypot`: its overflow care costs several times a
/// square root, and table coordinates are nowhere near overflow.
#[inline]
fn length(v: [f32; 2]) -> f32 {
    (v[0] * v[0] + v[1] * v[1]).sqrt()
}

impl Footprint {
    /// Signed distance from `p` to the outline, metres: negative inside.
    ///
    /// Exact for capsules, rounded rectangles and rings. For ellipses it is
    /// the first-order approximation `k0 (k0 - 1) / k1` (Quilez), exact on
    /// the outline and within a few per cent near it, which is all the soft
    /// edge needs; the exact ellipse distance is a quartic.
    pub fn distance(&self, p: [f32; 2]) -> f32 {
        self.prepare().distance(p)
    }

    /// The shape with its rotation and divisions worked out once, for
    /// evaluating many points (the rasterizer calls it per pixel).
    pub fn prepare(&self) -> Prepared {
        match *self {
            Self::Ellipse { centre, radii, angle } => {
                let (sin, cos) = angle.sin_cos();
                Prepared::Ellipse {
                    centre,
                    sin,
                    cos,
                    inv: [1.0 / radii[0], 1.0 / radii[1]],
                    inv2: [1.0 / (radii[0] * radii[0]), 1.0 / (radii[1] * radii[1])],
                    inner: -radii[0].min(radii[1]),
                }
            }
            Self::Capsule { a, b, radius } => {
                let ab = [b[0] - a[0], b[1] - a[1]];
                let len2 = ab[0] * ab[0] + ab[1] * ab[1];
                Prepared::Capsule { a, ab, inv_len2: if len2 > 0.0 { 1.0 / len2 } else { 0.0 }, radius }
            }
            Self::RoundedRect { centre, half, angle, corner } => {
                let (sin, cos) = angle.sin_cos();
                Prepared::RoundedRect { centre, sin, cos, inner: [half[0] - corner, half[1] - corner], corner }
            }
            Self::Ring { centre, radius, half_width } => Prepared::Ring { centre, radius, half_width },
        }
    }

    /// Axis-aligned bounds `[min, max]` in metres.
    pub fn bounds(&self) -> [[f32; 2]; 2] {
        let (c, e) = match *self {
            Self::Ellipse { centre, radii, angle } => {
                let (sin, cos) = angle.sin_cos();
                (centre, [(radii[0] * cos).hypot(radii[1] * sin), (radii[0] * sin).hypot(radii[1] * cos)])
            }
            Self::Capsule { a, b, radius } => (
                [(a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5],
                [(a[0] - b[0]).abs() * 0.5 + radius, (a[1] - b[1]).abs() * 0.5 + radius],
            ),
            Self::RoundedRect { centre, half, angle, .. } => {
                let (sin, cos) = angle.sin_cos();
                (centre, [half[0] * cos.abs() + half[1] * sin.abs(), half[0] * sin.abs() + half[1] * cos.abs()])
            }
            Self::Ring { centre, radius, half_width } => (centre, [radius + half_width; 2]),
        };
        [[c[0] - e[0], c[1] - e[1]], [c[0] + e[0], c[1] + e[1]]]
    }

    /// Area in square metres (for tests and sanity checks).
    pub fn area(&self) -> f32 {
        use std::f32::consts::PI;
        match *self {
            Self::Ellipse { radii, .. } => PI * radii[0] * radii[1],
            Self::Capsule { a, b, radius } => PI * radius * radius + 2.0 * radius * length([b[0] - a[0], b[1] - a[1]]),
            Self::RoundedRect { half, corner, .. } => 4.0 * half[0] * half[1] - (4.0 - PI) * corner * corner,
            Self::Ring { radius, half_width, .. } => 4.0 * PI * radius * half_width,
        }
    }

    /// The same shape moved by the rigid motion (rotate by `angle` about the
    /// origin, then translate by `offset`): how hand models place their
    /// local parts on the table.
    pub fn placed(&self, offset: [f32; 2], angle: f32) -> Self {
        let (sin, cos) = angle.sin_cos();
        let m = |p: [f32; 2]| {
            let r = rotate(p, cos, sin);
            [r[0] + offset[0], r[1] + offset[1]]
        };
        match *self {
            Self::Ellipse { centre, radii, angle: a } => Self::Ellipse { centre: m(centre), radii, angle: a + angle },
            Self::Capsule { a, b, radius } => Self::Capsule { a: m(a), b: m(b), radius },
            Self::RoundedRect { centre, half, angle: a, corner } => {
                Self::RoundedRect { centre: m(centre), half, angle: a + angle, corner }
            }
            Self::Ring { centre, radius, half_width } => Self::Ring { centre: m(centre), radius, half_width },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_have_the_right_sign_and_size() {
        let e = Footprint::Ellipse { centre: [1.0, 1.0], radii: [0.2, 0.1], angle: std::f32::consts::FRAC_PI_2 };
        assert!(e.distance([1.0, 1.0]) < 0.0);
        // Rotated a quarter turn: the long axis is now along y.
        assert!(e.distance([1.0, 1.19]) < 0.0);
        assert!(e.distance([1.19, 1.0]) > 0.0);
        assert!((e.distance([1.0, 1.3]) - 0.1).abs() < 0.01);

        let c = Footprint::Capsule { a: [0.0, 0.0], b: [1.0, 0.0], radius: 0.1 };
        assert!((c.distance([0.5, 0.3]) - 0.2).abs() < 1e-6);
        assert!((c.distance([-0.3, 0.0]) - 0.2).abs() < 1e-6);

        let r = Footprint::RoundedRect { centre: [0.0, 0.0], half: [0.5, 0.2], angle: 0.0, corner: 0.05 };
        assert!((r.distance([0.7, 0.0]) - 0.2).abs() < 1e-6);
        assert!((r.distance([0.0, -0.1]) + 0.1).abs() < 1e-6);

        let ring = Footprint::Ring { centre: [0.0, 0.0], radius: 0.04, half_width: 0.003 };
        assert!(ring.distance([0.0, 0.0]) > 0.0);
        assert!(ring.distance([0.04, 0.0]) < 0.0);
    }

    #[test]
    fn bounds_contain_the_shape() {
        let r = Footprint::RoundedRect { centre: [0.0, 0.0], half: [0.5, 0.2], angle: 0.3, corner: 0.0 }
            .placed([1.0, 2.0], 0.4);
        let [lo, hi] = r.bounds();
        for i in 0..100 {
            for j in 0..100 {
                let p = [
                    lo[0] - 0.1 + (hi[0] - lo[0] + 0.2) * i as f32 / 99.0,
                    lo[1] - 0.1 + (hi[1] - lo[1] + 0.2) * j as f32 / 99.0,
                ];
                if r.distance(p) < 0.0 {
                    assert!(p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1]);
                }
            }
        }
    }
}
