//! Where something can still move this step: a bound around every body a
//! technique body could push, and how fast it moves.
//!
//! The Particle technique asks this to skip particles that land on bare
//! table far from anything that moves: such a particle touches nothing but
//! the table during its one step, so simulating it changes no object's
//! motion, only the cost (two flat hands on the sorting scene sense about
//! 1400 particles, most of them on empty table).

use super::world::World;
use crate::scene::{Ring, Shape, solid_outline};
use glam::{Quat, Vec3};

/// Points on a ring that circumscribes a circle: their polygon contains
/// the circle when they sit `1 / cos(π / RING)` times its radius out.
const RING: usize = 16;

/// A solid that contains a body: an oriented box or an oriented upright
/// cylinder (a ball and a capsule stand in their cylinders, which from a
/// camera a metre above look at most a few per cent larger).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    Box { center: Vec3, rotation: Quat, half: Vec3 },
    Cylinder { center: Vec3, rotation: Quat, radius: f32, half_height: f32 },
}

/// The highest point (m, at least the table's 0) of any of these bounds.
pub fn highest_top(bodies: &[Reach]) -> f32 {
    bodies.iter().flat_map(|b| b.bound.corners(0.0)).fold(0.0f32, |top, c| top.max(c.z))
}

/// A movable body's bound, and its speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reach {
    pub bound: Bound,
    /// Fastest point of the body (m/s): its linear speed, plus its spin
    /// times the bound's half-diagonal.
    pub speed: f32,
}

impl Bound {
    /// The farthest a point of the bound lies from its centre.
    pub fn half_diagonal(&self) -> f32 {
        match *self {
            Bound::Box { half, .. } => half.length(),
            Bound::Cylinder { radius, half_height, .. } => radius.hypot(half_height),
        }
    }

    /// How far `p` lies outside the bound (0 inside).
    pub fn distance(&self, p: Vec3) -> f32 {
        match *self {
            Bound::Box { center, rotation, half } => {
                let q = (rotation.inverse() * (p - center)).abs() - half;
                q.max(Vec3::ZERO).length()
            }
            Bound::Cylinder { center, rotation, radius, half_height } => {
                let q = rotation.inverse() * (p - center);
                let radial = (q.truncate().length() - radius).max(0.0);
                let axial = (q.z.abs() - half_height).max(0.0);
                radial.hypot(axial)
            }
        }
    }

    /// Points whose convex hull contains every point within `grow` of the
    /// bound: the corners of the box grown by `grow` on every side, or two
    /// circumscribing rings of the cylinder grown so.
    pub fn corners(&self, grow: f32) -> Vec<Vec3> {
        match *self {
            Bound::Box { center, rotation, half } => {
                let box_ = Shape::Box { half_extents: half + Vec3::splat(grow) };
                solid_outline(box_, center, rotation, Ring::on(RING))
            }
            Bound::Cylinder { center, rotation, radius, half_height } => {
                let cylinder = Shape::Cylinder { radius: radius + grow, half_height: half_height + grow };
                solid_outline(cylinder, center, rotation, Ring::around(RING))
            }
        }
    }
}

impl World {
    /// The reach of every active dynamic scene object and every soft body,
    /// as of now.
    pub fn movable_reach(&self) -> Vec<Reach> {
        let physics = self.physics();
        let mut out = Vec::new();
        for id in self.object_ids() {
            if !self.is_movable(id) {
                continue;
            }
            let pose = self.object_pose(id);
            let (center, rotation) = (pose.position, pose.rotation);
            let bound = match self.scene().object(id).shape {
                Shape::Box { half_extents } => Bound::Box { center, rotation, half: half_extents },
                Shape::Sphere { radius } => Bound::Cylinder { center, rotation, radius, half_height: radius },
                Shape::Cylinder { radius, half_height } => Bound::Cylinder { center, rotation, radius, half_height },
                Shape::Capsule { radius, half_height } => {
                    Bound::Cylinder { center, rotation, radius, half_height: half_height + radius }
                }
            };
            let speed = pose.linvel.length() + pose.angvel.length() * bound.half_diagonal();
            out.push(Reach { bound, speed });
        }
        for (_, b) in physics.soft_bodies.iter().filter(|(_, b)| b.is_enabled()) {
            let (mut min, mut max, mut speed) = (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN), 0.0f32);
            for p in b.particle_positions() {
                min = min.min(p);
                max = max.max(p);
            }
            for v in b.particle_velocities() {
                speed = speed.max(v.length());
            }
            if min.cmple(max).all() {
                let half = 0.5 * (max - min) + Vec3::splat(b.particle_radius());
                let bound = Bound::Box { center: 0.5 * (min + max), rotation: Quat::IDENTITY, half };
                out.push(Reach { bound, speed });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `p` lies in the convex hull of `pts` in the xy-plane
    /// (a brute-force check: on the inner side of every hull edge).
    fn in_hull_xy(pts: &[Vec3], p: Vec3) -> bool {
        // p is outside iff some line through two hull points has every
        // point on one side and p strictly on the other.
        for a in pts {
            for b in pts {
                let d = (*b - *a).truncate();
                if d.length() < 1e-9 {
                    continue;
                }
                let side = |q: Vec3| d.perp_dot((q - *a).truncate());
                let (lo, hi) =
                    pts.iter().fold((f32::MAX, f32::MIN), |(lo, hi), q| (lo.min(side(*q)), hi.max(side(*q))));
                if lo >= -1e-6 && side(p) < -1e-6 || hi <= 1e-6 && side(p) > 1e-6 {
                    return false;
                }
            }
        }
        true
    }

    #[test]
    fn corners_contain_the_grown_bound() {
        let turn = Quat::from_rotation_z(0.7);
        let cyl =
            Bound::Cylinder { center: Vec3::new(0.1, 0.2, 0.05), rotation: turn, radius: 0.03, half_height: 0.05 };
        let pts = cyl.corners(0.01);
        // Every point 4 cm from the axis (radius + grow) at any angle is inside the rings' hull...
        for k in 0..360 {
            let a = (k as f32).to_radians();
            let p = Vec3::new(0.1 + 0.04 * a.cos(), 0.2 + 0.04 * a.sin(), 0.05);
            assert!(in_hull_xy(&pts, p), "angle {k}");
        }
        // ...and the rings reach no further than 1 / cos(π/16) of that.
        let far = pts.iter().map(|p| (p.truncate() - Vec3::new(0.1, 0.2, 0.0).truncate()).length()).fold(0.0, f32::max);
        assert!(far <= 0.04 / (std::f32::consts::PI / 16.0).cos() + 1e-6 && far > 0.0405, "{far}");
        let boxed = Bound::Box {
            center: Vec3::ZERO,
            rotation: Quat::from_rotation_z(std::f32::consts::FRAC_PI_4),
            half: Vec3::new(0.02, 0.02, 0.01),
        };
        let c = boxed.corners(0.005);
        // A box turned 45°: its corners lie on the axes, 0.025·√2 out.
        assert!(c.iter().any(|p| (p.x - 0.025 * 2f32.sqrt()).abs() < 1e-6 && p.y.abs() < 1e-6));
        assert!(c.iter().all(|p| (p.z.abs() - 0.015).abs() < 1e-6));
        assert!((boxed.half_diagonal() - 0.03).abs() < 1e-6);
        // Distances: 1 cm beyond a turned box's corner (on the x axis), 2 cm
        // above the cylinder's top, 3 cm beside its side and 4 cm above (5 cm).
        let past_corner = Vec3::new(0.02 * 2f32.sqrt() + 0.01, 0.0, 0.0);
        assert!((boxed.distance(past_corner) - 0.01).abs() < 1e-6, "{}", boxed.distance(past_corner));
        assert_eq!(boxed.distance(Vec3::new(0.01, 0.0, 0.0)), 0.0);
        assert!((cyl.distance(Vec3::new(0.1, 0.2, 0.12)) - 0.02).abs() < 1e-6);
        let beside = Vec3::new(0.1 + 0.06 * 0.7f32.cos(), 0.2 + 0.06 * 0.7f32.sin(), 0.14);
        assert!((cyl.distance(beside) - 0.05).abs() < 1e-5, "{}", cyl.distance(beside));
    }
}
