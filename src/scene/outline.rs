//! A shape's outline at a pose: the points whose convex hull is the solid,
//! and its footprint on the table seen from straight above.
//!
//! Goals (is it in the zone?), hit-testing (which silhouette does a hand
//! overlap?) and the world's reach (can a particle touch it this step?)
//! all outline the same shapes; one sampling of their round parts, with a
//! ring size each caller picks for its accuracy and cost, keeps the three
//! in agreement.

use super::Shape;
use glam::{Quat, Vec2, Vec3};
use std::f32::consts::{PI, TAU};

/// How a circle of the outline is sampled: `points` at equal angles from
/// the shape's local x axis, either on the circle (their polygon lies
/// inside it, short by `1 - cos(π / points)` of its radius) or
/// circumscribing it (`1 / cos(π / points)` out: their polygon contains it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Ring {
    pub points: usize,
    pub circumscribed: bool,
}

impl Ring {
    /// `points` on the circle.
    pub const fn on(points: usize) -> Ring {
        Ring { points, circumscribed: false }
    }

    /// `points` whose polygon contains the circle.
    pub const fn around(points: usize) -> Ring {
        Ring { points, circumscribed: true }
    }

    /// The radius the points sit at for a circle of radius `r`.
    fn radius(self, r: f32) -> f32 {
        if self.circumscribed { r / (PI / self.points as f32).cos() } else { r }
    }

    /// The ring's points for a circle of radius `r`, in the plane at
    /// height `z` of the shape's frame.
    fn circle(self, r: f32, z: f32) -> impl Iterator<Item = Vec3> {
        let (n, r) = (self.points, self.radius(r));
        (0..n).map(move |k| {
            let a = k as f32 * TAU / n as f32;
            Vec3::new(r * a.cos(), r * a.sin(), z)
        })
    }
}

/// Points whose convex hull is the solid at position `at`, turned by
/// `rotation` (its round parts as `ring`s): a box's eight corners; two end
/// rings of a cylinder; a capsule's end rings and its two tips; a
/// sphere's three great circles, which bound its silhouette from any eye.
pub fn solid_outline(shape: Shape, at: Vec3, rotation: Quat, ring: Ring) -> Vec<Vec3> {
    let local: Vec<Vec3> = match shape {
        Shape::Box { half_extents: h } => {
            (0..8).map(|k| Vec3::new(sign(k & 1) * h.x, sign(k & 2) * h.y, sign(k & 4) * h.z)).collect()
        }
        Shape::Sphere { radius } => ring
            .circle(radius, 0.0)
            .chain((0..ring.points).flat_map(|k| {
                let a = k as f32 * TAU / ring.points as f32;
                let r = ring.radius(radius);
                [Vec3::new(r * a.cos(), 0.0, r * a.sin()), Vec3::new(0.0, r * a.cos(), r * a.sin())]
            }))
            .collect(),
        Shape::Cylinder { radius, half_height } => {
            ring.circle(radius, -half_height).chain(ring.circle(radius, half_height)).collect()
        }
        Shape::Capsule { radius, half_height } => ring
            .circle(radius, -half_height)
            .chain(ring.circle(radius, half_height))
            .chain([Vec3::new(0.0, 0.0, half_height + radius), Vec3::new(0.0, 0.0, -half_height - radius)])
            .collect(),
    };
    local.into_iter().map(|p| at + rotation * p).collect()
}

/// Points on the table whose convex hull contains what the shape at `at`,
/// turned by `rotation`, covers seen from straight above: a box's corners
/// and a cylinder's end rings, turned with it; a ball's disc, however it
/// has turned; the discs of a capsule's two round ends, however it leans.
pub fn footprint(shape: Shape, at: Vec3, rotation: Quat, ring: Ring) -> Vec<Vec2> {
    let disc = |centre: Vec3, radius: f32| ring.circle(radius, 0.0).map(move |p| centre.truncate() + p.truncate());
    match shape {
        Shape::Box { .. } | Shape::Cylinder { .. } => {
            solid_outline(shape, at, rotation, ring).into_iter().map(Vec3::truncate).collect()
        }
        Shape::Sphere { radius } => disc(at, radius).collect(),
        Shape::Capsule { radius, half_height } => {
            let axis = rotation * Vec3::Z * half_height;
            disc(at - axis, radius).chain(disc(at + axis, radius)).collect()
        }
    }
}

fn sign(bit: usize) -> f32 {
    if bit == 0 { -1.0 } else { 1.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The area of the convex hull of `points` (parry's hull, then the
    /// shoelace formula).
    fn hull_area(points: &[Vec2]) -> f32 {
        use parry2d_f64::math::Vector;
        let pts: Vec<Vector> = points.iter().map(|p| Vector::new(f64::from(p.x), f64::from(p.y))).collect();
        let hull = parry2d_f64::transformation::convex_hull(&pts);
        let n = hull.len();
        let twice: f64 = (0..n).map(|i| hull[i].x * hull[(i + 1) % n].y - hull[i].y * hull[(i + 1) % n].x).sum();
        (0.5 * twice.abs()) as f32
    }

    /// The area of a regular polygon of `n` points at radius `r`.
    fn polygon_area(n: usize, r: f32) -> f32 {
        0.5 * n as f32 * r * r * (TAU / n as f32).sin()
    }

    #[test]
    fn footprint_areas_match_the_shapes() {
        let at = Vec3::new(0.1, -0.2, 0.03);
        let turn = Quat::from_rotation_z(0.7);
        // A box covers width × depth, however it turns about the vertical.
        let cube = Shape::Box { half_extents: Vec3::new(0.04, 0.025, 0.03) };
        let a = hull_area(&footprint(cube, at, turn, Ring::around(32)));
        assert!((a - 0.08 * 0.05).abs() < 1e-6, "{a}");
        for n in [16, 24, 32] {
            let r = 0.03;
            let disc = PI * r * r;
            // Circumscribing points: at least the disc, at most n·tan(π/n)·r².
            for shape in [Shape::Sphere { radius: r }, Shape::Cylinder { radius: r, half_height: 0.02 }] {
                let a = hull_area(&footprint(shape, at, Quat::IDENTITY, Ring::around(n)));
                let most = n as f32 * (PI / n as f32).tan() * r * r;
                assert!(a >= disc * (1.0 - 1e-5) && a <= most * (1.0 + 1e-5), "{n}: {a} not in {disc}..{most}");
            }
            // Points on the circle: the inscribed polygon, short of the disc.
            let a = hull_area(&footprint(Shape::Sphere { radius: r }, at, turn, Ring::on(n)));
            let want = polygon_area(n, r);
            assert!((a - want).abs() < 1e-6 * want.max(1e-3) + 1e-9 && a < disc, "{n}: {a} against {want}");
        }
        // A capsule lying along x: a stadium, its straight part plus a disc.
        let lying = Quat::from_rotation_y(std::f32::consts::FRAC_PI_2);
        let (r, h) = (0.02, 0.05);
        let a = hull_area(&footprint(Shape::Capsule { radius: r, half_height: h }, at, lying, Ring::on(64)));
        let want = 2.0 * h * 2.0 * r + polygon_area(64, r);
        assert!((a - want).abs() < 1e-6, "{a} against {want}");
        // A cylinder lying along x: a rectangle, its length by its diameter.
        let a = hull_area(&footprint(Shape::Cylinder { radius: r, half_height: h }, at, lying, Ring::on(32)));
        assert!((a - 2.0 * h * 2.0 * r).abs() < 1e-6, "{a}");
    }

    #[test]
    fn a_solid_outline_turns_with_the_shape_and_bounds_it() {
        let ball = Shape::Sphere { radius: 0.01 };
        let pts = solid_outline(ball, Vec3::new(0.2, 0.0, 0.01), Quat::from_rotation_x(0.4), Ring::on(24));
        assert_eq!(pts.len(), 3 * 24);
        for p in &pts {
            assert!(((*p - Vec3::new(0.2, 0.0, 0.01)).length() - 0.01).abs() < 1e-6, "{p}");
        }
        let can = Shape::Capsule { radius: 0.01, half_height: 0.02 };
        let pts = solid_outline(can, Vec3::ZERO, Quat::IDENTITY, Ring::around(16));
        assert_eq!(pts.len(), 2 * 16 + 2);
        assert!(pts.iter().any(|p| p.z == 0.03) && pts.iter().any(|p| p.z == -0.03));
    }
}
