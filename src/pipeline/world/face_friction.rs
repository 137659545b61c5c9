//! Torsional friction of a face resting flat on the table.
//!
//! **Why.** rapier holds a box flat on the table by one contact point at
//! each corner of its face, and Coulomb friction acts at each point. A box
//! turning in place then meets friction at the corners' radius: for a
//! square face `0.71 s` from its centre, where pressure spread over the face
//! (the usual model of a flat rigid face on a flat table) rubs at a mean
//! radius of `0.38 s`. The table then resists a box's turning 1.85 times
//! too hard, and two fingertips twisting a 6 cm box (the paper's Figure 2,
//! middle) turn it only a small part of their 90°.
//!
//! **How.** While the manifold's points lie within [`FLAT`] of one plane
//! (a face at rest, not one that has started to tip), each point is moved
//! towards the points' centroid so that the points' radius becomes the mean
//! radius of the face they span; as the spread of the points' separations
//! grows towards [`FLAT`] they move back out to where rapier put them, with
//! no jump from one step to the next. The normal and the friction
//! coefficient are untouched, so sliding friction, the press and the weight
//! are rapier's, and a face that has tipped by [`FLAT`] pivots about its
//! real edge. rapier applies a point's normal and friction at the same
//! place, so while the face lies flat the press acts at the mean radius
//! too: a face starts to tip at about half the pull at its top that its
//! edge would hold, and rights itself unless that pull still tips it once
//! the points are back at the edge (0.5 mm of tilt, 1° across a 3 cm face).
//!
//! The hook is on the table only: rapier recomputes every step the
//! contacts of a pair with a hook (it cannot recycle them), and pairs
//! between objects keep rapier's recycling (see the behaviour suite's
//! `PILE_CONTACTS` gap for what recycling does there).
//!
//! **Measured** (`surfacelab behaviours`, `two_finger_twist` and the
//! `pin_and_spin_*` cases, with the hook and without): two fingertips
//! twisting a 6 cm box 90° turn it further with Proxy, and about twice as
//! far with Particle; pin and spin turns it about as far either way with
//! Proxy and Joint. The same hook changing nothing (so only recycling off
//! on the table) barely moves the twist: the points' radius is the cause.
//!
//! Design: docs/design/world-and-effects.md.

use glam::{Vec2, Vec3};
use rapier3d::prelude::*;

/// How far (m) a manifold's points may lie from one plane and still be
/// (partly) a face at rest: half a millimetre is a 1° tilt across a 3 cm
/// face. Switching all the way at a smaller distance without the blend, or
/// blending over a smaller one, gives particles landing on a box over half
/// their weight's impulse in their first step, more than without the hook;
/// blended over half a millimetre they get under half, as
/// `tests/particle_press.rs` asks.
const FLAT: f32 = 0.0005;

/// The hook, passed to each physics step.
#[derive(Debug, Default, Clone, Copy)]
pub(super) struct FaceFriction;

impl PhysicsHooks for FaceFriction {
    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        // A rigid object on the table. A cloth's contacts (no rigid body)
        // are left unmodified, though, like every pair with the table, not
        // recycled (the torn-paper snapshot, `tests/snapshots/soft_tear.png`,
        // is rendered so).
        let bodies = context.bodies;
        let dynamic = |h: Option<RigidBodyHandle>| h.and_then(|h| bodies.get(h)).is_some_and(RigidBody::is_dynamic);
        if !(dynamic(context.rigid_body1) || dynamic(context.rigid_body2)) {
            return;
        }
        let Some(rigid) = context.rigid_mut() else { return };
        let contacts = &mut *rigid.solver_contacts;
        if contacts.len() < 3 {
            return;
        }
        let (lo, hi) =
            contacts.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), c| (lo.min(c.dist), hi.max(c.dist)));
        if hi - lo >= FLAT {
            return;
        }
        let points: Vec<Vec3> = contacts.iter().map(|c| c.anchor1).collect();
        let Some(k) = mean_radius_ratio(&points, *rigid.normal) else { return };
        // All the way in for a face at rest, back out to the corners as it
        // tilts towards FLAT: no jump from one step to the next.
        let k = k + (1.0 - k) * (hi - lo) / FLAT;
        let centre = points.iter().copied().sum::<Vec3>() / points.len() as f32;
        for c in contacts.iter_mut() {
            let shift = (centre - c.anchor1) * (1.0 - k);
            c.anchor1 += shift;
            c.anchor2 += shift;
        }
    }
}

/// The mean distance from the centroid of the polygon the points span
/// (pressure spread evenly over it) over the points' own mean distance
/// from it: the factor that moves each point to the face's mean radius.
/// `None` for fewer than three points or no area.
fn mean_radius_ratio(points: &[Vec3], normal: Vec3) -> Option<f32> {
    let n = normal.normalize_or_zero();
    if points.len() < 3 || n == Vec3::ZERO {
        return None;
    }
    let centre = points.iter().copied().sum::<Vec3>() / points.len() as f32;
    // In the face's plane, ordered by angle round the centre.
    let u = (points[0] - centre).reject_from_normalized(n).normalize_or_zero();
    if u == Vec3::ZERO {
        return None;
    }
    let v = n.cross(u);
    let mut flat: Vec<Vec2> = points.iter().map(|p| Vec2::new((*p - centre).dot(u), (*p - centre).dot(v))).collect();
    flat.sort_by(|a, b| a.y.atan2(a.x).total_cmp(&b.y.atan2(b.x)));
    let corner = flat.iter().map(|p| p.length()).sum::<f32>() / flat.len() as f32;
    // The face as triangles fanned from the centre; each triangle's mean
    // distance from the centre by a 4 × 4 midpoint rule in its own
    // coordinates (within 1% of the exact 0.3826 s for a square).
    let (mut area, mut moment) = (0.0f32, 0.0f32);
    for i in 0..flat.len() {
        let (a, b) = (flat[i], flat[(i + 1) % flat.len()]);
        let t_area = 0.5 * a.perp_dot(b).abs();
        let mut sum = 0.0;
        let steps = 4;
        let mut count = 0;
        for s in 0..steps {
            for t in 0..steps {
                let (x, y) = ((s as f32 + 0.5) / steps as f32, (t as f32 + 0.5) / steps as f32);
                // The unit square folded onto the triangle (0, a, b).
                let (x, y) = if x + y > 1.0 { (1.0 - x, 1.0 - y) } else { (x, y) };
                sum += (a * x + b * y).length();
                count += 1;
            }
        }
        area += t_area;
        moment += t_area * sum / count as f32;
    }
    (area > 0.0 && corner > 0.0).then(|| (moment / area) / corner)
}

#[cfg(test)]
mod tests {
    use super::mean_radius_ratio;
    use glam::Vec3;

    #[test]
    fn a_square_face_rubs_at_0_54_of_its_corner_radius() {
        // Uniform pressure on a square of side s: mean radius 0.3826 s;
        // corners at 0.7071 s.
        let s = 0.06;
        let square = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(s, 0.0, 0.0), Vec3::new(s, s, 0.0), Vec3::new(0.0, s, 0.0)];
        let k = mean_radius_ratio(&square, Vec3::Z).expect("a face");
        assert!((k - 0.3826 * std::f32::consts::SQRT_2).abs() < 0.01, "{k}");
    }

    #[test]
    fn a_long_face_and_a_tilted_one_keep_their_own_ratio() {
        // A 4:1 rectangle: its mean radius by a 200 x 200 grid, over its
        // half-diagonal.
        let (a, b) = (0.08f32, 0.02f32);
        let rect = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(a, 0.0, 0.0), Vec3::new(a, b, 0.0), Vec3::new(0.0, b, 0.0)];
        let mut mean = 0.0f64;
        let n = 200;
        for i in 0..n {
            for j in 0..n {
                let x = (f64::from(i) + 0.5) / f64::from(n) * f64::from(a) - f64::from(a) / 2.0;
                let y = (f64::from(j) + 0.5) / f64::from(n) * f64::from(b) - f64::from(b) / 2.0;
                mean += x.hypot(y);
            }
        }
        mean /= f64::from(n * n);
        let expected = mean / (0.5 * f64::from(a).hypot(f64::from(b)));
        let k = mean_radius_ratio(&rect, Vec3::Z).expect("a face");
        assert!((f64::from(k) - expected).abs() < 0.01, "{k} vs {expected}");
        // The same face stood on its side: the plane comes from the normal.
        let side: Vec<Vec3> = rect.iter().map(|p| Vec3::new(p.z, p.x, p.y)).collect();
        let k_side = mean_radius_ratio(&side, Vec3::X).expect("a face");
        assert!((k_side - k).abs() < 1e-4, "{k_side} vs {k}");
    }

    #[test]
    fn fewer_than_three_points_are_left_alone() {
        assert!(mean_radius_ratio(&[Vec3::ZERO, Vec3::X], Vec3::Z).is_none());
    }
}
