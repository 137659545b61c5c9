//! What each hand rests on: the movable objects under a contact when it
//! landed, how high they hold it, and where the flat of the hand presses
//! on them.
//!
//! **Why.** The paper's particles lie on the outline only, and a
//! line-of-sight particle (see `particle_capsules`) stands for the side of
//! the hand from the surface its outline point's ray meets up towards the
//! eye. A flat hand laid on a ball rests on the ball's top, 6 cm up: its
//! outline beyond the ball's silhouette is that high too and cannot reach
//! the ball's flank, and its palm presses the ball's top. Drawn from the
//! table up, the trailing edge's capsules would meet the ball at its
//! equator as soon as the hand moved and push it at nearly the hand's
//! speed, where a real ball under a sliding hand, driven at its top, rolls
//! about half of the hand's travel; and nothing would touch a ball rolling
//! on under a hand that had landed on it, so it would drift on until an
//! edge met it (`surfacelab behaviours`: `ball_under_hand`,
//! `ball_stop_flat_hand`).
//!
//! **How.** While a contact is new (its first [`LANDING_FRAMES`] frames),
//! rays on a grid over its pixels find the movable objects it lands on.
//! For as long as rays from the contact still meet one of them, the
//! contact rests on it, at the height of the highest point the rays meet
//! there:
//! - its line-of-sight particles' sides start [`PAD`] below that height
//!   instead of on what their own rays meet;
//! - the grid points whose rays meet it within [`PAD`] of that height are
//!   the flat of the hand, and press on it as particles do ([`Press`]).
//!
//! **Sticking.** The paper's particles are placed where the hand is each
//! frame and given its velocity, so friction can only match the hand's
//! speed: an object that lags the hand for a moment (it had to start
//! moving, or something resisted it) is never pulled back under it, and
//! the hand slides over it for good. A fingertip's skin sticks instead, and
//! stretches until friction gives. For each resting contact the object
//! point under its centre is followed from frame to frame; while the
//! centre has slipped less than [`STICK`] over the object since it last
//! stuck, that slip is taken up by its particles on the object within the
//! step (`particle_stick`, see the Particle technique). The solver still
//! caps their friction at their press, so a pull the press cannot give
//! lets the slip grow past [`STICK`], and the contact sticks anew where it
//! is (it slipped). Measured (`surfacelab behaviours`, Particle, with and
//! without sticking): with it, pin and spin turns the box about the full
//! 90°, as Joint does, and the pinned point stays put, where without it
//! the turn falls short and the point drifts (test
//! `a_sticking_fingertip_turns_the_box_with_it_in_pin_and_spin`); two
//! fingers twisting 90°, quick or slow, turn the box the full way
//! (`two_finger_twist`, `two_finger_twist_slow`). With a smaller [`STICK`]
//! the steering cylinder dragged by its top tilts past the suite's 15°
//! bound (`cylinder_top_drag`); a larger one passes that drag but not
//! others like it, so the pad's shear decides, not that case.
//!
//! Landing decides, not covering: a fingertip that slid across the table up
//! to a tall object, and that the eye sees over the object's top in
//! perspective, still stands on the table and pushes the object's side
//! (`tests/techniques.rs`, the steering task's cylinder pushed from behind,
//! `a_fingertip_slid_up_behind_a_tall_object_still_pushes_its_side`); with
//! "whatever the contact covers" instead, that push barely moves it. Fixed
//! ground (the table, a platform) holds no hand up: there the paper's
//! particles are unchanged.
//!
//! Design: docs/design/resting-pad.md.

use super::surface_point::{least_squares_turn, move_at_height};
use crate::pipeline::surface::{PixelPoint, Sensor};
use crate::pipeline::vision::{Contact, ContactId, EdgeSample, VisionFrame};
use crate::pipeline::world::{RayHit, World};
use crate::scene::ObjectId;
use std::collections::HashMap;

/// Frames after a contact appears during which what its rays meet counts
/// as what it landed on (50 ms at 60 Hz: a hand's outline grows for a
/// frame or two as it presses down).
pub const LANDING_FRAMES: u32 = 3;

/// How far (m) the soft pad of a finger or palm wraps down over the edge
/// of what it rests on: a particle's side starts this far below the height
/// the hand rests at. A fingertip landed on a box's top and straddling its
/// back edge catches that edge within the pad: measured with `surfacelab
/// behaviours` (Particle, `flick_from_rest`), the flick throws the box as
/// far with a pad of a few millimetres as with sides from the table, less
/// far with a thinner one, and hardly at all with none; the ball cases
/// hardly depend on it.
pub const PAD: f32 = 0.005;

/// At most this many points of one hand press on what it rests on, taken
/// evenly from the grid. Measured (`surfacelab behaviours`, Particle): a
/// flat hand turning a 14 cm box in place turns it a little less far with
/// all of them (about a hundred, each another contact for the solver to
/// share the turn among) than with 16 (`flat_hand_turn`); with none, a
/// flat hand that landed on a rolling ball lets it roll on, where 16 stop
/// it (`ball_stop_flat_hand`).
const MAX_PRESSES: usize = 16;

/// How far (m) a hand's skin stretches over what it sticks to before it
/// slips: beyond it the contact sticks anew where it is. A fingertip's
/// pad shears a few millimetres before gross slip.
pub const STICK: f32 = 0.003;

/// Spacing (m) of the rays cast over a contact's pixels: a fingertip gets
/// a few, a flat hand about a hundred.
const GRID: f32 = 0.01;

/// A point of the flat of a hand pressing on what it rests on: one of the
/// grid's rays that met a landed-on object within [`PAD`] of the height
/// the hand rests at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Press {
    pub contact_id: ContactId,
    /// Pixel position `[column, row]`.
    pub px: [f32; 2],
    /// The hand's motion there over the last frame (pixels), as an outline
    /// point's flow: the rigid move fitted to the contact's measured
    /// outline flow.
    pub flow_px: [f32; 2],
    /// The contact's mean grey level (its pressure).
    pub grey: u8,
}

impl Press {
    /// The press as a sample of its contact, measured flow and all, so
    /// that it becomes a particle by the same steps as an outline point.
    pub fn sample(&self) -> EdgeSample {
        EdgeSample {
            px: self.px,
            flow_px: self.flow_px,
            magnitude: 0.0,
            grey: self.grey,
            contact_id: self.contact_id,
            has_flow: true,
        }
    }
}

/// The object point a resting contact's centre sticks to, and where it and
/// the contact's centre were when it stuck.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Anchor {
    object: ObjectId,
    /// The point in the object's frame.
    local: glam::Vec3,
    /// The point, and the contact's centre on the glass, when it stuck.
    at: glam::Vec3,
    centre: glam::Vec2,
}

/// A contact's motion over the last frame as a rigid move in the image:
/// a translation and a small turn about a centre.
#[derive(Debug, Clone, Copy, PartialEq)]
struct RigidFlow {
    centre: [f32; 2],
    velocity: [f32; 2],
    /// Radians per frame, image orientation (as `Contact::rotation_rad`).
    turn: f32,
}

impl RigidFlow {
    /// The least-squares rigid move of contact `id`'s measured outline
    /// flow, which the vision stage measures to a few hundredths of a pixel
    /// (its tracked turn is smoothed over frames, and lags a hand that
    /// starts or stops turning); `None` with fewer than three samples.
    fn fit(frame: &VisionFrame, id: ContactId) -> Option<RigidFlow> {
        let samples: Vec<_> = frame.edges.iter().filter(|e| e.contact_id == id && e.has_flow).collect();
        if samples.len() < 3 {
            return None;
        }
        let n = samples.len() as f32;
        let mean = |f: &dyn Fn(&&EdgeSample) -> f32| samples.iter().map(f).sum::<f32>() / n;
        let centre = [mean(&|e| e.px[0]), mean(&|e| e.px[1])];
        let velocity = [mean(&|e| e.flow_px[0]), mean(&|e| e.flow_px[1])];
        let turn = least_squares_turn(samples.iter().map(|e| {
            let d = glam::Vec2::new(e.px[0] - centre[0], e.px[1] - centre[1]);
            (d, glam::Vec2::new(e.flow_px[0] - velocity[0], e.flow_px[1] - velocity[1]))
        }))?;
        Some(RigidFlow { centre, velocity, turn })
    }

    /// The flow (pixels) this move gives the point `px`.
    fn at(&self, px: [f32; 2]) -> [f32; 2] {
        let (dx, dy) = (px[0] - self.centre[0], px[1] - self.centre[1]);
        [self.velocity[0] - self.turn * dy, self.velocity[1] + self.turn * dx]
    }
}

/// Per contact, the objects it landed on and the height they hold it at
/// this frame.
#[derive(Debug, Clone, Default)]
pub struct Resting {
    on: HashMap<ContactId, Vec<ObjectId>>,
    height: HashMap<ContactId, f32>,
    presses: Vec<Press>,
    /// Per resting contact, the object point its centre sticks to.
    anchors: HashMap<ContactId, Anchor>,
    /// Per resting contact, this frame's slip (m, across the table): where
    /// the hand has carried the stuck point less where the point went.
    slips: HashMap<ContactId, (ObjectId, glam::Vec2)>,
}

impl Resting {
    /// Follows this frame's contacts: new ones record what they land on,
    /// the others keep what they landed on while their rays still meet it.
    pub fn update(&mut self, frame: &VisionFrame, sensor: &Sensor, world: &World) {
        self.height.clear();
        self.presses.clear();
        self.slips.clear();
        self.on.retain(|id, _| frame.contacts.iter().any(|c| c.id == *id));
        self.anchors.retain(|id, _| frame.contacts.iter().any(|c| c.id == *id));
        for c in &frame.contacts {
            let landing = c.age_frames < LANDING_FRAMES;
            if !landing && self.on.get(&c.id).is_none_or(Vec::is_empty) {
                // It landed on nothing movable (the table, a platform) and
                // never will now: the paper's particles.
                self.on.remove(&c.id);
                continue;
            }
            let mut met: Vec<(ObjectId, f32)> = Vec::new();
            let mut rays: Vec<([f32; 2], ObjectId, f32)> = Vec::new();
            for (px, hit) in grid_hits(c, sensor, world) {
                let Some(id) = hit.object.filter(|&i| hit.soft.is_none() && world.is_movable(i)) else { continue };
                rays.push((px, id, hit.point.z));
                match met.iter_mut().find(|(o, _)| *o == id) {
                    Some((_, z)) => *z = z.max(hit.point.z),
                    None => met.push((id, hit.point.z)),
                }
            }
            let on = self.on.entry(c.id).or_default();
            if landing {
                for (id, _) in &met {
                    if !on.contains(id) {
                        on.push(*id);
                    }
                }
            }
            on.retain(|id| met.iter().any(|(o, _)| o == id));
            let top = met.iter().filter(|(o, _)| on.contains(o)).map(|(_, z)| *z).reduce(f32::max);
            if let Some(z) = top {
                self.height.insert(c.id, z);
                let motion = RigidFlow::fit(frame, c.id).unwrap_or(RigidFlow {
                    centre: c.blob.weighted_centroid,
                    velocity: c.velocity_px,
                    turn: c.rotation_rad,
                });
                let grey = c.blob.mean_grey.round().clamp(0.0, 255.0) as u8;
                let touching: Vec<[f32; 2]> =
                    rays.iter().filter(|(_, id, h)| *h >= z - PAD && on.contains(id)).map(|(px, _, _)| *px).collect();
                let (n, keep) = (touching.len(), touching.len().min(MAX_PRESSES));
                for k in 0..keep {
                    let px = touching[k * n / keep];
                    self.presses.push(Press { contact_id: c.id, px, flow_px: motion.at(px), grey });
                }
            }
            if top.is_some() {
                self.stick(c, sensor, world);
            }
        }
    }

    /// Follows the object point under contact `c`'s centre (see `slip`).
    fn stick(&mut self, c: &Contact, sensor: &Sensor, world: &World) {
        let centre = glam::Vec2::from(sensor.to_table(PixelPoint::from(c.blob.weighted_centroid)));
        let Some((id, point)) = world.cast_contact_ray(centre).and_then(|h| h.object.map(|id| (id, h.point))) else {
            self.anchors.remove(&c.id);
            return;
        };
        if !self.on.get(&c.id).is_some_and(|on| on.contains(&id)) {
            self.anchors.remove(&c.id);
            return;
        }
        let pose = world.object_pose(id);
        let fresh = Anchor { object: id, local: pose.rotation.inverse() * (point - pose.position), at: point, centre };
        let Some(a) = self.anchors.get(&c.id).filter(|a| a.object == id) else {
            self.anchors.insert(c.id, fresh);
            return;
        };
        // Where the hand has carried the stuck point: its move over the
        // glass, seen at the point's height (a hand moving over the glass
        // moves a point under it less the nearer that point is to the
        // eye). Not where the contact's ray meets the surface now: under a
        // slanted ray a surface that only sinks (a card tipping under the
        // finger) is met further out, which is no slip.
        let carried = a.at + ((centre - a.centre) * move_at_height(world, a.at.z)).extend(0.0);
        let went = pose.position + pose.rotation * a.local;
        let slip = (carried - went).truncate();
        if slip.length() > STICK {
            self.anchors.insert(c.id, fresh);
        } else {
            self.slips.insert(c.id, (id, slip));
        }
    }

    /// How far (m, across the table) contact `id` has slipped over the
    /// object `on` it sticks to since it last stuck: its particles on that
    /// object take it up as extra speed.
    pub fn slip(&self, id: ContactId, on: ObjectId) -> Option<glam::Vec2> {
        self.slips.get(&id).filter(|(o, _)| *o == on).map(|(_, s)| *s)
    }

    /// Whether contact `id` rests on object `on` this frame.
    pub fn rests_on(&self, id: ContactId, on: ObjectId) -> bool {
        self.height.contains_key(&id) && self.on.get(&id).is_some_and(|o| o.contains(&on))
    }

    /// The height (m) contact `id` rests at this frame, if it rests on an
    /// object it landed on.
    pub fn height(&self, id: ContactId) -> Option<f32> {
        self.height.get(&id).copied()
    }

    /// This frame's points of the flat of the hands pressing on what they
    /// rest on, a grid spacing apart.
    pub fn presses(&self) -> &[Press] {
        &self.presses
    }

    pub fn clear(&mut self) {
        self.anchors.clear();
        self.slips.clear();
        self.on.clear();
        self.height.clear();
        self.presses.clear();
    }
}

/// What the rays on a [`GRID`] over contact `c`'s pixels meet, with the
/// pixel each was cast at.
fn grid_hits(c: &Contact, sensor: &Sensor, world: &World) -> Vec<([f32; 2], RayHit)> {
    let step = (GRID / sensor.metres_per_pixel()).round().max(1.0) as u32;
    let mut out = Vec::new();
    for run in c.blob.runs.iter().filter(|run| run.y % step == 0) {
        let mut x = run.x0.div_ceil(step) * step;
        while x < run.x1 {
            let px = [x as f32, run.y as f32];
            if let Some(hit) = world.cast_contact_ray(glam::Vec2::from(sensor.to_table(PixelPoint::from(px)))) {
                out.push((px, hit));
            }
            x += step;
        }
    }
    out
}

/// Whether contact `c` lands on something that can move (a scene object
/// or a soft body) anywhere on its [`GRID`]: then it rests on it.
pub fn lands_on_movable(c: &Contact, sensor: &Sensor, world: &World) -> bool {
    grid_hits(c, sensor, world).iter().any(|(_, h)| h.soft.is_some() || h.object.is_some_and(|i| world.is_movable(i)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::vision::EdgeSample;

    fn sample(contact_id: ContactId, px: [f32; 2], flow_px: [f32; 2], has_flow: bool) -> EdgeSample {
        EdgeSample { px, flow_px, magnitude: 40.0, grey: 200, contact_id, has_flow }
    }

    #[test]
    fn a_rigid_move_is_recovered_from_its_outline_flow() {
        // An outline of radius 20 px about (100, 80), translated by
        // (1.5, -0.5) px and turned 0.01 rad in the frame.
        let (centre, v, turn) = ([100.0f32, 80.0f32], [1.5f32, -0.5f32], 0.01f32);
        let mut edges: Vec<EdgeSample> = (0..24)
            .map(|k| {
                let a = k as f32 * std::f32::consts::TAU / 24.0;
                let (dx, dy) = (20.0 * a.cos(), 20.0 * a.sin());
                sample(ContactId::new(7), [centre[0] + dx, centre[1] + dy], [v[0] - turn * dy, v[1] + turn * dx], true)
            })
            .collect();
        // Another contact's outline and unmeasured points do not count.
        edges.push(sample(ContactId::new(8), [100.0, 80.0], [30.0, 30.0], true));
        edges.push(sample(ContactId::new(7), [100.0, 60.0], [-9.0, 9.0], false));
        let frame =
            VisionFrame { contacts: Vec::new(), edges, timings: crate::pipeline::vision::StageTimings::default() };
        let fit = RigidFlow::fit(&frame, ContactId::new(7)).expect("enough samples");
        assert!((fit.turn - turn).abs() < 1e-5, "{fit:?}");
        // Anywhere, inside the outline too, the flow is the move's.
        for p in [[100.0, 80.0], [110.0, 75.0], [85.0, 95.0]] {
            let (dx, dy) = (p[0] - centre[0], p[1] - centre[1]);
            let want = [v[0] - turn * dy, v[1] + turn * dx];
            let got = fit.at(p);
            assert!((got[0] - want[0]).abs() < 1e-4 && (got[1] - want[1]).abs() < 1e-4, "{p:?}: {got:?} vs {want:?}");
        }
        assert_eq!(RigidFlow::fit(&frame, ContactId::new(9)), None, "no samples");
    }
}
