//! Where something can still move this step: the boxes around every body a
//! technique body could push, grown by how far it can travel.
//!
//! The Particle technique asks this to skip particles that land on bare
//! table far from anything that moves: such a particle touches nothing but
//! the table during its one step, so simulating it changes no object's
//! motion, only the cost (two flat hands on the sorting scene sense about
//! 1400 particles, most of them on empty table).

use super::world::World;
use glam::Vec3;

/// An axis-aligned box around a movable body, and its speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reach {
    pub min: Vec3,
    pub max: Vec3,
    /// Fastest point of the body (m/s): its linear speed, plus its spin
    /// times its half-diagonal.
    pub speed: f32,
}

impl Reach {
    /// Whether a sphere of `radius` at `p`, moving at up to `speed`, can
    /// touch the body within `dt` (plus a `slack`).
    pub fn can_touch(&self, p: Vec3, radius: f32, speed: f32, dt: f32, slack: f32) -> bool {
        let grow = Vec3::splat(radius + (speed + self.speed) * dt + slack);
        let (lo, hi) = (self.min - grow, self.max + grow);
        p.cmpge(lo).all() && p.cmple(hi).all()
    }

    /// Whether a capsule (segment `a`–`b`, `radius`), moving at up to
    /// `speed`, can touch the body within `dt` (plus a `slack`): the
    /// segment clipped against the grown box (slab test) is not empty.
    pub fn can_touch_segment(&self, a: Vec3, b: Vec3, radius: f32, speed: f32, dt: f32, slack: f32) -> bool {
        let grow = Vec3::splat(radius + (speed + self.speed) * dt + slack);
        let (lo, hi) = (self.min - grow, self.max + grow);
        let d = b - a;
        let (mut t0, mut t1) = (0.0f32, 1.0f32);
        for k in 0..3 {
            if d[k].abs() < 1e-9 {
                if a[k] < lo[k] || a[k] > hi[k] {
                    return false;
                }
                continue;
            }
            let (u, v) = ((lo[k] - a[k]) / d[k], (hi[k] - a[k]) / d[k]);
            t0 = t0.max(u.min(v));
            t1 = t1.min(u.max(v));
            if t0 > t1 {
                return false;
            }
        }
        true
    }
}

impl World {
    /// The reach of every active dynamic scene object and every soft body
    /// piece, as of now.
    pub fn movable_reach(&self) -> Vec<Reach> {
        let physics = self.physics();
        let mut out = Vec::new();
        for id in self.object_ids() {
            if !self.is_active(id) {
                continue;
            }
            let Some(body) = physics.bodies.get(self.object_body(id)) else { continue };
            if !body.is_dynamic() {
                continue;
            }
            let Some(collider) = physics.colliders.get(self.object_collider(id)) else { continue };
            let aabb = collider.compute_aabb();
            let (min, max) = (aabb.mins, aabb.maxs);
            let speed = body.linvel().length() + body.angvel().length() * (max - min).length() * 0.5;
            out.push(Reach { min, max, speed });
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
                let skin = Vec3::splat(b.particle_radius());
                out.push(Reach { min: min - skin, max: max + skin, speed });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reach_grows_with_both_speeds() {
        let r = Reach { min: Vec3::ZERO, max: Vec3::splat(0.1), speed: 1.0 };
        let p = Vec3::new(0.2, 0.05, 0.05);
        // 0.1 m away: a still particle of radius 3 mm cannot touch it in a 1/60 s step...
        assert!(!r.can_touch(p, 0.003, 0.0, 1.0 / 60.0, 0.0));
        // ...nor one at 4 m/s (6.7 cm + 1.7 cm + 3 mm < 10 cm)...
        assert!(!r.can_touch(p, 0.003, 4.0, 1.0 / 60.0, 0.0));
        // ...but with 2 cm of slack it can.
        assert!(r.can_touch(p, 0.003, 4.0, 1.0 / 60.0, 0.02));
        assert!(r.can_touch(Vec3::splat(0.05), 0.0, 0.0, 0.0, 0.0), "inside");
    }

    #[test]
    fn a_segment_reaches_a_box_it_passes_beside_or_through() {
        let r = Reach { min: Vec3::ZERO, max: Vec3::splat(0.1), speed: 0.0 };
        // A line of sight from the table beside the box up past its top edge.
        let (a, b) = (Vec3::new(0.13, 0.05, 0.0), Vec3::new(-0.2, 0.05, 1.0));
        assert!(r.can_touch_segment(a, b, 0.0, 0.0, 0.0, 0.0), "it crosses above the box's edge x = 0.1 at z = 0.09");
        assert!(!r.can_touch(a, 0.003, 0.0, 1.0 / 60.0, 0.0), "its foot alone is 3 cm away");
        // Leaning the other way it never comes nearer than 3 cm.
        let b2 = Vec3::new(0.45, 0.05, 1.0);
        assert!(!r.can_touch_segment(a, b2, 0.003, 0.0, 1.0 / 60.0, 0.0));
        // ...until the box moves fast enough to close the gap within the step.
        let fast = Reach { speed: 2.0, ..r };
        assert!(fast.can_touch_segment(a, b2, 0.003, 0.0, 1.0 / 60.0, 0.0));
        // A vertical segment (zero extent in x and y) is tested slab by slab.
        assert!(!r.can_touch_segment(Vec3::new(0.05, 0.05, 0.5), Vec3::new(0.05, 0.05, 2.0), 0.0, 0.0, 0.0, 0.0));
        assert!(r.can_touch_segment(Vec3::new(0.05, 0.05, 0.05), Vec3::new(0.05, 0.05, 2.0), 0.0, 0.0, 0.0, 0.0));
    }
}
