//! Which particles can touch something movable this step, decided on the
//! glass where the camera sees each body.
//!
//! A particle is a line-of-sight capsule (or a ball) on the camera ray of
//! its outline point, so it can meet a body only where that point's ray
//! passes near the body. Each movable body's bound (an oriented box or
//! cylinder, [`Reach`]), grown by what the particle reaches off its ray,
//! the body's travel in the step and a slack, is projected through the eye
//! onto the glass: its hull there is a convex region. A particle whose
//! start lies farther from every region than it can move (magnified by
//! perspective) touches nothing movable this step.
//!
//! Footprints rather than axis-aligned boxes around each body: a box
//! turned 30°, a cylinder or a ball fills its footprint more tightly than
//! its box does, and the projection is exact where a pixel box of eight
//! projected corners would be a box around a box.

use crate::pipeline::surface::{Sensor, TablePoint};
use crate::pipeline::vision::{ConvexRegion, FlowInterest};
use crate::pipeline::world::{Reach, World, highest_top};
use glam::{Vec2, Vec3};

/// Below this share of the eye's height left above a grown body, the
/// projection's magnification is too large to bound usefully: nothing is
/// culled.
const MIN_CLEARANCE: f32 = 0.1;

/// Every movable body's reach on the glass this step.
#[derive(Debug, Clone, PartialEq)]
pub struct SightReach {
    /// Each body's grown bound projected onto the glass (table metres).
    outlines: Vec<Vec<Vec2>>,
    regions: Vec<ConvexRegion>,
    /// The bodies' bounds and speeds, for particles that are balls.
    bodies: Vec<Reach>,
    /// The step (s), a particle's radius and the slack (m).
    dt: f32,
    radius: f32,
    slack: f32,
    /// How much longer a displacement near the bodies looks on the glass
    /// than it is, at most; `None` when it cannot be bounded (a body
    /// near the eye) and every particle must be kept.
    magnification: Option<f32>,
}

impl SightReach {
    /// The reach of every movable body in `world` within a step of `dt`
    /// for particles of `radius`: each bound grown by twice the radius (a
    /// particle lies within that of its point's camera ray: its centre
    /// sits a radius off the touched point, and a capsule runs from there
    /// towards the eye), the `slack` and the body's own travel. `travel`
    /// bounds how far a particle moves in the step.
    pub fn new(world: &World, dt: f32, radius: f32, slack: f32, travel: f32) -> Self {
        let eye = world.eye();
        let (mut top, mut lateral) = (0.0f32, 0.0f32);
        let mut outlines = Vec::new();
        let bodies = world.movable_reach();
        for b in &bodies {
            let corners = b.bound.corners(2.0 * radius + slack + b.speed * dt);
            for c in &corners {
                top = top.max(c.z);
                lateral = lateral.max((c.truncate() - eye.truncate()).length());
            }
            outlines.push(corners.into_iter().map(|c| world.screen_point(c)).collect::<Vec<_>>());
        }
        // The projection p(q) = e + (q - e) h / (h - z) (on the plane
        // z = 0) stretches a displacement at height z, a distance L from
        // the eye's foot, by at most h / (h - z) · sqrt(1 + (L / (h - z))²).
        // A particle that can touch a grown body passes within `travel`
        // of one of its points, so z and L there exceed the corners' by at
        // most `travel`.
        let h = eye.z;
        let clearance = h - (top + travel);
        let magnification = (clearance > MIN_CLEARANCE * h).then(|| {
            let l = lateral + travel;
            h / clearance * (1.0 + (l / clearance).powi(2)).sqrt()
        });
        let regions = outlines.iter().filter_map(|o| ConvexRegion::hull_of(o)).collect();
        Self { outlines, regions, bodies, dt, radius, slack, magnification }
    }

    /// The highest point of any movable body now (not grown by a step's
    /// travel), so that its caller need not collect the bodies again.
    pub fn highest_top(&self) -> f32 {
        highest_top(&self.bodies)
    }

    /// Whether a particle starting on the camera ray of glass point
    /// `start` and moving at most `travel` (m) in the step may touch a
    /// movable body.
    pub fn may_touch(&self, start: Vec2, travel: f32) -> bool {
        match self.magnification {
            None => true,
            Some(k) => self.regions.iter().any(|r| r.within(start, k * travel)),
        }
    }

    /// Whether a ball particle centred at `center`, moving at most
    /// `travel` (m) in the step, may touch a movable body: tested in
    /// space, which is tighter than [`Self::may_touch`] for a ball low
    /// beside a tall body whose top the camera sees over it.
    pub fn ball_may_touch(&self, center: Vec3, travel: f32) -> bool {
        self.magnification.is_none()
            || self
                .bodies
                .iter()
                .any(|b| b.bound.distance(center) <= self.radius + travel + b.speed * self.dt + self.slack)
    }

    /// Where the vision stage must measure flow for [`Self::may_touch`] to
    /// see every particle it keeps, when a particle moves at most
    /// `speedup` times its point's flow: one that climbed a wall starts one
    /// flow back, so a kept point lies within `1 + speedup · k` flows of a
    /// region on the glass. In pixels that is scaled by the pixels' aspect.
    pub fn flow_interest(&self, sensor: &Sensor, speedup: f32) -> FlowInterest {
        let Some(k) = self.magnification else { return FlowInterest::All };
        let [sx, sy] = sensor.pixel_size();
        let aspect = sx.max(sy) / sx.min(sy);
        let regions = self
            .outlines
            .iter()
            .filter_map(|o| {
                let px: Vec<Vec2> = o.iter().map(|p| sensor.to_pixel(TablePoint(*p)).0).collect();
                ConvexRegion::hull_of(&px)
            })
            .collect();
        FlowInterest::Near { regions, flow_scale: (1.0 + speedup * k) * aspect }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::world::parry::query;
    use crate::pipeline::world::prelude::{Pose, Segment};
    use crate::scene::test_scenes::fixture;

    /// A 6 cm box turned 45° at (-0.25, 0.1) and a 6 cm ball at (0.2, -0.1),
    /// at rest on a table under the default camera.
    fn world() -> World {
        World::new(&fixture("turned_box_and_ball"))
    }

    /// The distance from the camera ray of glass point `g` (its segment
    /// from the table up to the eye) to the nearest movable object.
    fn ray_distance(w: &World, g: Vec2) -> f32 {
        let ray = Segment::new(g.extend(0.0), w.eye());
        w.object_ids()
            .map(|id| {
                let c = &w.physics().colliders[w.object_collider(id)];
                query::distance(&Pose::IDENTITY, &ray, c.position(), c.shape()).expect("supported").distance
            })
            .fold(f32::MAX, f32::min)
    }

    #[test]
    fn every_particle_that_can_touch_a_body_is_kept_and_bare_table_is_not() {
        let w = world();
        let (r, slack, travel) = (0.003, 0.01, 0.02);
        let grow = 2.0 * r + slack;
        let reach = SightReach::new(&w, 1.0 / 60.0, r, slack, travel);
        let (mut near, mut kept_far, mut far) = (0, 0, 0);
        for i in 0..120 {
            for j in 0..90 {
                let g = Vec2::new(-0.5 + i as f32 / 120.0, -0.375 + j as f32 * 0.75 / 90.0);
                let d = ray_distance(&w, g);
                // The guarantee: within reach of a body means kept.
                if d <= grow + travel {
                    near += 1;
                    assert!(reach.may_touch(g, travel), "{g}: {d} m from a body, culled");
                } else if d > 2.0 * (grow + travel) {
                    far += 1;
                    kept_far += usize::from(reach.may_touch(g, travel));
                }
            }
        }
        assert!(near > 100, "{near} points near a body");
        // What is kept far away is what perspective and the bounds add.
        assert!(kept_far * 50 < far, "kept {kept_far} of {far} far points");
    }

    #[test]
    fn a_turned_box_culls_what_its_axis_aligned_box_kept() {
        let w = world();
        let reach = SightReach::new(&w, 1.0 / 60.0, 0.003, 0.01, 0.0);
        // The box turned 45° spans ±4.2 cm about its centre along x and y:
        // its axis-aligned box grown by 1.6 cm reached (-0.19, 0.16); the
        // turned box, grown so, ends 3.7 cm short of that corner on the table.
        let corner = Vec2::new(-0.25 + 0.042 + 0.014, 0.1 + 0.042 + 0.014);
        assert!(ray_distance(&w, corner) > 0.025, "{}", ray_distance(&w, corner));
        assert!(!reach.may_touch(corner, 0.0));
        // Its own side, 1 cm out, is kept.
        let side = Vec2::new(-0.25 + 0.042 + 0.01, 0.1);
        assert!(reach.may_touch(side, 0.0));
    }

    #[test]
    fn a_ball_particle_is_tested_where_it_is() {
        let w = world();
        let reach = SightReach::new(&w, 1.0 / 60.0, 0.003, 0.01, 0.0);
        // On the table beside the ball at (0.2, -0.1), 3 cm from its side:
        // beyond radius + slack (1.3 cm) of its cylinder, and a ball there
        // is culled...
        let low = Vec3::new(0.2 + 0.03 + 0.03, -0.1, 0.003);
        assert!(!reach.ball_may_touch(low, 0.0));
        // ...unless it moves 2 cm within the step.
        assert!(reach.ball_may_touch(low, 0.02));
        // Every ball kept is also kept by the camera-ray test, which the
        // flow interest is built from.
        for i in 0..60 {
            for j in 0..40 {
                let c = Vec3::new(0.1 + i as f32 * 0.004, -0.2 + j as f32 * 0.005, 0.003);
                if reach.ball_may_touch(c, 0.01) {
                    assert!(reach.may_touch(w.screen_point(c), 0.01), "{c}");
                }
            }
        }
    }

    /// The Particle technique's cap on a particle's speed over its point's.
    const SPEEDUP: f32 = 1.2;

    #[test]
    fn the_flow_interest_covers_every_kept_particle() {
        let w = world();
        let sensor = Sensor::default();
        let reach = SightReach::new(&w, 1.0 / 60.0, 0.003, 0.01, 0.05);
        let interest = reach.flow_interest(&sensor, SPEEDUP);
        let [sx, _] = sensor.pixel_size();
        for i in 0..200 {
            for j in 0..150 {
                let g = Vec2::new(-0.5 + i as f32 / 200.0, -0.375 + j as f32 * 0.75 / 150.0);
                // A point moving 4 px a frame: its particle moves at most 1.2
                // times that, and is kept only where it may touch a body.
                let flow_px = 4.0;
                if reach.may_touch(g, SPEEDUP * flow_px * sx) {
                    let px = sensor.to_pixel(TablePoint(g)).to_array();
                    assert!(interest.wants(px, [flow_px, 0.0], 0.0), "{g} kept but its flow was not asked for");
                }
            }
        }
    }
}
