//! The result of a scene ray cast.

use crate::scene::ObjectId;
use glam::Vec3;
use rapier3d::prelude::SoftBodyHandle;

/// Where a ray met the scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RayHit {
    /// The scene object hit, or `None` for the table, its walls or a fixed
    /// environment part with no object index.
    pub object: Option<ObjectId>,
    pub point: Vec3,
    /// Outward surface normal at `point`.
    pub normal: Vec3,
    /// Distance along the (unit) ray.
    pub toi: f32,
    /// The soft body hit (a cloth, a block or a torn piece of one) and its
    /// particle nearest to `point`; `object` is `None` then.
    pub soft: Option<(SoftBodyHandle, u32)>,
}

/// Where a ray first meets a solid cylinder standing on its local y axis
/// (radius `radius`, from `-half_height` to `half_height`), in the
/// cylinder's frame: the time of impact along `dir` and the outward
/// normal there, or `None` if it misses within `max_toi`. A ray starting
/// inside hits at once, with a zero normal (parry's convention for solid
/// shapes).
///
/// Exact, unlike parry's, which casts rays at cylinders by GJK with
/// absolute tolerances: from the eye 1.2 m above the table its hits on
/// the 5 cm steering cylinder's top can be a millimetre off the surface,
/// and a hit under the top near the rim is taken for the wall (see
/// [`super::World::cast_ray`]). Solved in f64 from the point of the ray
/// nearest the axis, so that a ray from a metre away loses no precision.
pub fn cylinder_hit(origin: Vec3, dir: Vec3, half_height: f32, radius: f32, max_toi: f32) -> Option<(f32, Vec3)> {
    let o = origin.as_dvec3();
    let d = dir.as_dvec3();
    let (r, hh) = (f64::from(radius), f64::from(half_height));
    // Where the ray is between the caps' planes.
    let (mut enter, mut exit) = (f64::NEG_INFINITY, f64::INFINITY);
    let mut enter_normal = glam::DVec3::ZERO;
    if d.y.abs() < 1e-12 {
        if o.y.abs() > hh {
            return None;
        }
    } else {
        let (t1, t2) = ((-hh - o.y) / d.y, (hh - o.y) / d.y);
        let (near, far) = if t1 < t2 { (t1, t2) } else { (t2, t1) };
        enter = near;
        exit = far;
        enter_normal = glam::DVec3::new(0.0, -d.y.signum(), 0.0);
    }
    // Where it is within the radius: a quadratic in the xz plane, solved
    // about the ray's point nearest the axis.
    let a = d.x * d.x + d.z * d.z;
    if a < 1e-18 {
        if o.x * o.x + o.z * o.z > r * r {
            return None;
        }
    } else {
        let t0 = -(o.x * d.x + o.z * d.z) / a;
        let (px, pz) = (o.x + t0 * d.x, o.z + t0 * d.z);
        let left = r * r - (px * px + pz * pz);
        if left < 0.0 {
            return None;
        }
        let half = (left / a).sqrt();
        let (near, far) = (t0 - half, t0 + half);
        if near > enter {
            enter = near;
            let (x, z) = (o.x + near * d.x, o.z + near * d.z);
            enter_normal = glam::DVec3::new(x, 0.0, z) / r;
        }
        exit = exit.min(far);
    }
    if enter > exit || exit < 0.0 {
        return None;
    }
    if enter < 0.0 {
        return Some((0.0, Vec3::ZERO));
    }
    (enter <= f64::from(max_toi)).then(|| (enter as f32, enter_normal.normalize_or_zero().as_vec3()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rays_meet_a_cylinder_on_its_surface() {
        let (hh, r) = (0.025f32, 0.025f32);
        // Straight down onto the top, 2 cm out: the top at y = hh.
        let (t, n) = cylinder_hit(Vec3::new(0.02, 1.0, 0.0), Vec3::NEG_Y, hh, r, 10.0).expect("top");
        assert!((t - (1.0 - hh)).abs() < 1e-6, "{t}");
        assert_eq!(n, Vec3::Y);
        // Level at the wall: hits it at x = -r with the normal -x.
        let (t, n) = cylinder_hit(Vec3::new(-1.0, 0.01, 0.0), Vec3::X, hh, r, 10.0).expect("wall");
        assert!((t - (1.0 - r)).abs() < 1e-6, "{t}");
        assert!((n - Vec3::NEG_X).length() < 1e-6, "{n}");
        // Grazing past the rim, or stopped short of it, misses.
        assert!(cylinder_hit(Vec3::new(-1.0, hh + 1e-4, 0.0), Vec3::X, hh, r, 10.0).is_none());
        assert!(cylinder_hit(Vec3::new(0.0, 1.0, 0.0), Vec3::NEG_Y, hh, r, 0.5).is_none());
        // Slanted rays from a metre away (the eye above the table) land on
        // the surface their normal says, to a micrometre.
        for k in 0..400 {
            let target = Vec3::new((k % 20) as f32 * 0.003 - 0.03, hh - (k / 20) as f32 * 0.002, 0.004);
            let origin = Vec3::new(-0.34, 1.1, -0.22);
            let dir = (target - origin).normalize();
            let Some((t, n)) = cylinder_hit(origin, dir, hh, r, 10.0) else { continue };
            let p = origin + dir * t;
            let radial = p.x.hypot(p.z);
            if n == Vec3::Y {
                assert!((p.y - hh).abs() < 1e-6 && radial <= r + 1e-6, "top hit at {p}");
            } else {
                assert!(
                    n.y == 0.0 && (radial - r).abs() < 1e-6 && p.y.abs() <= hh + 1e-6,
                    "wall hit at {p}, normal {n}"
                );
            }
        }
    }
}
