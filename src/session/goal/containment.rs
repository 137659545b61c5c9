//! How deep an object's footprint lies inside a goal area.
//!
//! A goal area (a sorting zone, the gather circle, a region) holds an
//! object when the whole of the object is inside it, as a person judging
//! "in the bin" sees it, not when its centre is: an 8 cm box whose centre
//! is 1 mm inside a zone hangs 3.9 cm out of it. The *depth* is the
//! distance the footprint could move in the worst direction and stay
//! inside: positive inside, zero touching the border from within, and
//! negative by how far the footprint sticks out.
//!
//! Both areas are convex and so is a footprint's hull, and the distance
//! from a point to a convex area's border (inside) is a concave function:
//! its least value over the footprint is at a corner of the hull, so the
//! depth is the least over the footprint's points, and no polygon
//! clipping is needed.

use crate::pipeline::world::ObjectPose;
use crate::scene::{self, Ring, Shape};
use glam::Vec2;

/// Points per round outline. They sit `1 / cos(π / RING)` out so that
/// their polygon contains the circle (0.5% of its radius).
const RING: usize = 32;

/// A convex goal area on the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Area {
    Rect { min: Vec2, max: Vec2 },
    Circle { center: Vec2, radius: f32 },
}

impl Area {
    /// How far inside the area `p` lies (negative outside: for a
    /// rectangle, how far past the nearest side it has to come in).
    pub fn depth_of_point(&self, p: Vec2) -> f32 {
        match *self {
            Area::Rect { min, max } => (p - min).min(max - p).min_element(),
            Area::Circle { center, radius } => radius - (p - center).length(),
        }
    }

    /// The least depth over the footprint: ≥ 0 when it lies wholly inside.
    /// `None` for an empty footprint.
    pub fn depth(&self, footprint: &[Vec2]) -> Option<f32> {
        footprint.iter().map(|&p| self.depth_of_point(p)).reduce(f32::min)
    }
}

/// Points on the table whose convex hull contains what the object covers
/// seen from straight above (see [`scene::footprint`]).
pub fn footprint(shape: Shape, pose: &ObjectPose) -> Vec<Vec2> {
    scene::footprint(shape, pose.position, pose.rotation, Ring::around(RING))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Quat, Vec3};

    fn pose(x: f32, y: f32, turn_deg: f32) -> ObjectPose {
        ObjectPose {
            position: Vec3::new(x, y, 0.025),
            rotation: Quat::from_rotation_z(turn_deg.to_radians()),
            linvel: Vec3::ZERO,
            angvel: Vec3::ZERO,
            active: true,
        }
    }

    #[test]
    fn a_box_is_inside_only_when_all_of_it_is() {
        let zone = Area::Rect { min: Vec2::new(0.28, -0.375), max: Vec2::new(0.5, 0.375) };
        let cube = Shape::Box { half_extents: Vec3::splat(0.04) };
        // Centre 1 mm inside the zone's edge: 3.9 cm of it hangs out.
        let d = zone.depth(&footprint(cube, &pose(0.281, 0.0, 0.0))).expect("points");
        assert!((d + 0.039).abs() < 1e-5, "{d}");
        // 5 cm in: 1 cm to spare.
        let d = zone.depth(&footprint(cube, &pose(0.33, 0.0, 0.0))).expect("points");
        assert!((d - 0.01).abs() < 1e-5, "{d}");
        // Turned 45°, its corner reaches 4·√2 = 5.66 cm from its centre.
        let d = zone.depth(&footprint(cube, &pose(0.33, 0.0, 45.0))).expect("points");
        assert!((d - (0.05 - 0.04 * 2f32.sqrt())).abs() < 1e-5, "{d}");
    }

    #[test]
    fn a_ball_in_the_gather_circle() {
        let circle = Area::Circle { center: Vec2::ZERO, radius: 0.13 };
        let ball = Shape::Sphere { radius: 0.011 };
        // However it has rolled, a ball 11.5 cm out has 4 mm to spare
        // (within the 0.5% its outline is drawn outside the circle).
        for turn in [0.0f32, 30.0, 77.0] {
            let mut p = pose(0.115, 0.0, 0.0);
            p.rotation = Quat::from_rotation_x(turn.to_radians());
            let d = circle.depth(&footprint(ball, &p)).expect("points");
            assert!((0.0039..=0.004).contains(&d), "{turn}: {d}");
        }
        assert!(circle.depth(&footprint(ball, &pose(0.125, 0.0, 0.0))).expect("points") < 0.0);
        assert_eq!(circle.depth(&[]), None);
    }

    #[test]
    fn a_lying_cylinder_covers_its_length() {
        let zone = Area::Rect { min: Vec2::new(-0.1, -0.1), max: Vec2::new(0.1, 0.1) };
        // A 2 cm-radius, 10 cm-long cylinder lying along x at the centre:
        // its shadow is 10 x 4 cm, so 5 cm to spare in a 20 cm square.
        let mut p = pose(0.0, 0.0, 0.0);
        p.rotation = Quat::from_rotation_y(std::f32::consts::FRAC_PI_2);
        let cyl = Shape::Cylinder { radius: 0.02, half_height: 0.05 };
        let d = zone.depth(&footprint(cyl, &p)).expect("points");
        assert!((d - 0.05).abs() < 1e-5, "{d}");
    }
}
