//! One frame of particles: each outline sample (and each point of the flat
//! of a resting hand) becomes one [`Draft`], and a fixed sequence of named
//! steps settles where it starts, how it moves, what it presses and
//! whether it is simulated at all, as a physics engine's step is a list of
//! named stages.
//!
//! The steps, in order (see [`settle`]):
//!
//! 1. [`climb`]: a point that crossed a wall within the frame starts below it;
//! 2. [`sight`] (`particle_capsules`): whether it is a line-of-sight capsule;
//! 3. [`lift`] (`particle_rest`): whether a resting hand holds it up;
//! 4. [`slide`]: its velocity along the touched surface, capped;
//! 5. [`seat`]: its centre just touching that surface (or up where lifted);
//! 6. [`give_way`]: it gives way to a surface coming at it;
//! 7. [`stick`] (`particle_stick`): it takes up the hand's slip over what
//!    it sticks to;
//! 8. [`pad`] (`particle_pad`): it joins its contact's pad;
//! 9. [`cull`] (`particle_cull`): out of reach of anything movable, it is
//!    drawn but not simulated;
//! 10. [`clear`]: never created inside a movable object;
//! 11. [`weigh`]: its press and inertia, and the finished [`Placement`].
//!
//! Each step reads what the steps before it settled and nothing after it,
//! and the floating-point operations keep one order, so a frame's
//! particles are the same to the bit however the steps are grouped.

use super::TechniqueConfig;
use super::proxy::{pressure_weight, soft_mass};
use super::rest::{PAD, Resting};
use super::sight_reach::SightReach;
use super::surface_point::{clamp_len, project_flow, table_point};
use crate::pipeline::surface::Sensor;
use crate::pipeline::vision::{ContactId, EdgeSample};
use crate::pipeline::world::parry::shape::{Ball, Capsule};
use crate::pipeline::world::prelude::Pose;
use crate::pipeline::world::{RayHit, World};
use fnv::FnvHashMap;
use glam::{Vec2, Vec3};

/// A particle's speed along the surface it touches, at most this many times
/// the hand's speed over the table.
pub(super) const MAX_SURFACE_SPEEDUP: f32 = 1.2;

/// Flow (px) below which an outline point is not checked for a step it
/// climbed within the frame (see [`climb`]): half a pixel is under a
/// millimetre, less than a particle's radius.
const MIN_SWEEP_PX: f32 = 0.5;

/// One particle to place this frame.
#[derive(Debug, Clone, Copy)]
pub(super) struct Placement {
    pub px: [f32; 2],
    /// This frame's flow at `px` (pixels): where the sample was one frame ago.
    pub flow_px: [f32; 2],
    pub center: Vec3,
    /// Unit vector from `center` towards the eye, along the camera ray
    /// (the axis of a line-of-sight capsule, see `particle_capsules`).
    pub up: Vec3,
    /// Whether it is a line-of-sight capsule (else a ball): with
    /// `particle_capsules`, on everything but a soft body, which capsules
    /// do not meet at all (`Layer::Sight`): one landing on a soft body is
    /// a ball and presses it.
    pub sight: bool,
    pub velocity: Vec3,
    /// Press (N).
    pub weight: f32,
    /// Inertia (kg).
    pub mass: f32,
    /// The part of `velocity` that gives way to a surface coming at it
    /// (see [`give_way`]).
    pub give_way: Vec3,
    /// The contact whose pad it belongs to: it lands on the object that
    /// contact rests on (see `pad`).
    pub pad: Option<ContactId>,
}

/// What every sample of one frame shares.
pub(super) struct Frame<'a> {
    pub config: &'a TechniqueConfig,
    pub sensor: &'a Sensor,
    pub world: &'a World,
    pub dt: f32,
    /// What each hand landed on, and the flat of the hand pressing on it.
    pub resting: &'a Resting,
    /// Contacts whose particles are balls even with `particle_capsules`.
    pub ball_contacts: &'a [ContactId],
    /// Where particles can touch something movable (with `particle_cull`).
    pub reach: Option<SightReach>,
    /// Nothing movable reaches above this height: the part of a
    /// line-of-sight capsule above it cannot be inside anything to clear
    /// it out of.
    pub top: f32,
    /// Length (m) of a line-of-sight capsule.
    pub length: f32,
    /// A ball particle's shape.
    pub ball: Ball,
    /// The length of outline one particle stands for, over the reference
    /// spacing its mass and weight are given for.
    pub share: f32,
    /// Per contact: its outline samples and its presses.
    pub counts: FnvHashMap<ContactId, (u32, u32)>,
}

impl Frame<'_> {
    /// A hand presses no harder for resting on something: a contact with
    /// presses spreads the press its outline alone had over outline and
    /// flat alike. Added on top instead, the extra friction tips a small
    /// box dragged from just behind its leading edge
    /// (`a_fingertip_drags_a_box_from_anywhere_on_its_top`) and the
    /// steering cylinder dragged by its top (`cylinder_top_drag`).
    fn spread(&self, id: ContactId) -> f32 {
        self.counts.get(&id).map_or(1.0, |&(n, m)| if n == 0 { 1.0 } else { n as f32 / (n + m) as f32 })
    }
}

/// A sample on its way to a particle: what it was sensed as, and what the
/// steps before the current one settled.
#[derive(Debug, Clone, Copy)]
pub(super) struct Draft {
    sample: EdgeSample,
    /// A point of the flat of a resting hand rather than of its outline.
    interior: bool,
    /// The sample's table point now.
    here: Vec2,
    /// Where it is cast to and moves towards (its table point a frame on).
    next: Vec2,
    /// Where it starts this frame over the table.
    start: Vec2,
    /// The surface its camera ray meets.
    hit: RayHit,
    /// How fast the hand moves over the table there (m/s).
    hand_speed: f32,
    /// The height a resting hand holds it at, less a pad's depth.
    rest: Option<f32>,
    sight: bool,
    /// Held up in the air by a resting hand (see [`lift`]).
    lifted: bool,
    /// Its velocity along the touched surface, capped.
    slide: Vec3,
    center: Vec3,
    up: Vec3,
    give_way: Vec3,
    velocity: Vec3,
    pad: Option<ContactId>,
}

impl Draft {
    /// The sample cast to the surface its camera ray meets, or `None` when
    /// the ray meets nothing.
    pub(super) fn cast(frame: &Frame<'_>, sample: EdgeSample, interior: bool) -> Option<Draft> {
        let here = table_point(frame.sensor, sample.px);
        let hit = frame.world.cast_contact_ray(here)?;
        let next = table_point(frame.sensor, [sample.px[0] + sample.flow_px[0], sample.px[1] + sample.flow_px[1]]);
        let hand_speed = (next - here).length() / frame.dt;
        Some(Draft {
            sample,
            interior,
            here,
            next,
            start: here,
            hit,
            hand_speed,
            rest: None,
            sight: false,
            lifted: false,
            slide: Vec3::ZERO,
            center: Vec3::ZERO,
            up: Vec3::Z,
            give_way: Vec3::ZERO,
            velocity: Vec3::ZERO,
            pad: None,
        })
    }
}

/// What becomes of one sample.
pub(super) enum Settled {
    Placed(Placement),
    /// Drawn, not simulated, at this centre.
    Culled(Vec3),
}

/// The frame's steps in order, each switch turning its own step on or off.
pub(super) fn settle(frame: &Frame<'_>, mut d: Draft) -> Settled {
    let config = frame.config;
    climb(frame, &mut d);
    if config.particle_capsules {
        sight(frame, &mut d);
    }
    if config.particle_rest {
        lift(frame, &mut d);
    }
    slide(frame, &mut d);
    seat(frame, &mut d);
    give_way(frame, &mut d);
    if config.particle_stick {
        stick(frame, &mut d);
    }
    if config.particle_pad {
        pad(frame, &mut d);
    }
    if config.particle_cull && cull(frame, &d) {
        return Settled::Culled(d.center);
    }
    clear(frame, &mut d);
    Settled::Placed(weigh(frame, &d))
}

/// A step climbed within the frame: where this outline point was a frame
/// ago its ray met a lower surface, so the hand crossed a wall on its way
/// here. Start the particle down there, moving to where the point is now,
/// so that it meets the wall in the step as the hand did. Placed where the
/// point is now, it would sit on the top and only rub it: a fingertip going
/// from rest to 1.6 m/s in one frame (half a box's width) would leave the
/// box it flicks almost where it was (`surfacelab behaviours`,
/// `flick_from_rest`).
fn climb(frame: &Frame<'_>, d: &mut Draft) {
    let e = &d.sample;
    if !d.interior && e.flow_px[0].hypot(e.flow_px[1]) > MIN_SWEEP_PX {
        let before = table_point(frame.sensor, [e.px[0] - e.flow_px[0], e.px[1] - e.flow_px[1]]);
        if let Some(low) = frame.world.cast_contact_ray(before)
            && low.point.z < d.hit.point.z - 2.0 * frame.config.particle_radius
        {
            d.hit = low;
            d.next = d.here;
            d.start = before;
        }
    }
}

/// A line-of-sight capsule (see `particle_capsules`): every outline particle
/// but one on a soft body, which capsules do not meet, and but those of the
/// contacts made balls (Hybrid's grips).
fn sight(frame: &Frame<'_>, d: &mut Draft) {
    d.sight = !d.interior && d.hit.soft.is_none() && !frame.ball_contacts.contains(&d.sample.contact_id);
}

/// A hand resting on something it landed on holds its sides up there (see
/// `rest`): a line-of-sight particle whose ray meets something lower starts
/// a pad's depth below that height, in the air on its own ray, and moves as
/// the hand does over the table.
fn lift(frame: &Frame<'_>, d: &mut Draft) {
    d.rest = frame.resting.height(d.sample.contact_id).map(|z| z - PAD);
    let hit_z = d.hit.point.z;
    d.lifted = d.sight && d.rest.is_some_and(|z| hit_z < z);
}

/// The velocity along the touched surface: the paper's projected flow
/// (Figure 6), tangential only, or the hand's motion over the table where
/// it is lifted. Never faster than the hand over the table (plus
/// perspective's scale-up): on a face the camera sees edge-on, like a
/// ball's far side, the projection turns a millimetre of flow into a
/// centimetre of slide down the face, and a particle driven down into the
/// wedge under a ball would shoot it backwards.
fn slide(frame: &Frame<'_>, d: &mut Draft) {
    let (hit, dt) = (&d.hit, frame.dt);
    let mut v = if d.lifted {
        (d.next - d.start).extend(0.0) / dt
    } else {
        let p_next = project_flow(frame.world, hit, d.next);
        // Tangential only: the plane projection already removed the normal part.
        let v = (p_next - hit.point) / dt;
        v - hit.normal * v.dot(hit.normal)
    };
    v = v.clamp_length_max(d.hand_speed * MAX_SURFACE_SPEEDUP);
    let max = frame.config.max_contact_speed;
    let vt = clamp_len(Vec2::new(v.x, v.y), max);
    let vz = if v.z.abs() > max { v.z.signum() * max } else { v.z };
    d.slide = Vec3::new(vt.x, vt.y, vz);
}

/// Just touching the surface its ray meets, or, lifted, up its own ray at
/// the height the hand rests at.
fn seat(frame: &Frame<'_>, d: &mut Draft) {
    let r = frame.config.particle_radius;
    let mut center = d.hit.point + d.hit.normal * (r - 0.0001);
    let up = (frame.world.eye() - center).normalize_or(Vec3::Z);
    if let Some(z) = d.rest.filter(|_| d.lifted) {
        center += up * ((z + r - center.z) / up.z.max(0.1));
    }
    d.center = center;
    d.up = up;
}

/// Along the touched surface's normal, the particle moves at least as fast
/// as that surface does where it touches it: a surface coming towards it
/// pushes it back, so it presses by its weight alone (one going away is not
/// followed: gravity brings the particle down after it). The tangent-plane
/// velocity assumed a still surface, so whatever moved into a particle was
/// pressed with any impulse the solver needed: a ball rolling into a light
/// fingertip on its far flank would be pressed by many times the
/// particles' weight and roll back within a step (variants of
/// `ball_light_touch` in `tests/techniques.rs`).
fn give_way(frame: &Frame<'_>, d: &mut Draft) {
    let hit = &d.hit;
    let coming = if d.lifted {
        0.0
    } else {
        hit.object.map_or(0.0, |id| frame.world.object_point_velocity(id, hit.point).dot(hit.normal))
    };
    d.give_way = hit.normal * coming.max(0.0);
    d.velocity = d.slide + d.give_way;
}

/// Where the hand's skin sticks to the object under it, the particles on
/// that object take up the hand's slip over it within the step (see
/// `rest`): friction, capped by the solver at the particles' press, pulls
/// the stuck point back under the hand, as a fingertip's stretched skin
/// does.
fn stick(frame: &Frame<'_>, d: &mut Draft) {
    if !d.lifted
        && let Some(slip) = d.hit.object.and_then(|o| frame.resting.slip(d.sample.contact_id, o))
    {
        d.velocity += (slip / frame.dt).extend(0.0);
    }
}

/// A particle on the object its contact rests on belongs to that contact's
/// pad (see `pad`).
fn pad(frame: &Frame<'_>, d: &mut Draft) {
    let id = d.sample.contact_id;
    d.pad = d.hit.object.filter(|&o| !d.lifted && d.hit.soft.is_none() && frame.resting.rests_on(id, o)).map(|_| id);
}

/// Whether the particle can touch nothing movable during its step (drawn,
/// not simulated). No flow measured means the vision stage found it out of
/// reach of everything movable (see `flow_interest`).
fn cull(frame: &Frame<'_>, d: &Draft) -> bool {
    let travel = d.velocity.length() * frame.dt;
    let out_of_reach = !d.sample.has_flow
        || frame
            .reach
            .as_ref()
            .is_some_and(|r| if d.sight { !r.may_touch(d.start, travel) } else { !r.ball_may_touch(d.center, travel) });
    d.hit.soft.is_none() && out_of_reach
}

/// Never created inside something movable, which the solver would shove it
/// out of, and the object with it: a fingertip's outline crossing a box's
/// edge lands on the table against the box's side, so a fingertip dragging
/// a 100 g box from 1 cm behind its leading edge would brake it with the
/// particles beside that edge and carry it a fraction of the way
/// (`a_fingertip_drags_a_box_from_anywhere_on_its_top`). What it is placed
/// on it stays 0.1 mm into on purpose (see [`weigh`]), even on a slope; a
/// capsule is tested only up to the highest movable top.
fn clear(frame: &Frame<'_>, d: &mut Draft) {
    if d.hit.soft.is_some() {
        return;
    }
    let (r, center, up) = (frame.config.particle_radius, d.center, d.up);
    let rise = ((frame.top - center.z).max(0.0) / up.z.max(0.1)).min(frame.length);
    let shift = if d.sight && rise > 0.0 {
        let turn = glam::Quat::from_rotation_arc(Vec3::Z, up);
        let capsule = Capsule::new_z(0.5 * rise, r);
        frame.world.clearance(
            &capsule,
            Pose::from_parts(center + turn * Vec3::new(0.0, 0.0, 0.5 * rise), turn),
            d.hit.object,
        )
    } else {
        frame.world.clearance(&frame.ball, Pose::from_translation(center), d.hit.object)
    };
    d.center += shift;
}

/// Its press and inertia. The centre stays just touching (0.1 mm in):
/// rapier's soft contact (30 Hz) does not give a new contact its full press
/// in one step: particles resting on a box get well under half the normal
/// impulse their weight calls for in their first step; pooled ones,
/// re-placed like this, all of it within a few steps (warm-started).
/// Created afresh every step (the paper's variant) they overshoot as the
/// box under them sinks into its own soft contact (`tests/particle_press.rs`).
fn weigh(frame: &Frame<'_>, d: &Draft) -> Placement {
    let config = frame.config;
    let e = &d.sample;
    let weight =
        pressure_weight(config, config.particle_weight, f32::from(e.grey)) * frame.share * frame.spread(e.contact_id);
    Placement {
        px: e.px,
        flow_px: e.flow_px,
        center: d.center,
        up: d.up,
        sight: d.sight,
        velocity: d.velocity,
        weight,
        // On a soft body a particle weighs what it presses (see `soft_mass`).
        mass: if d.hit.soft.is_some() { soft_mass(weight) } else { config.particle_mass * frame.share },
        give_way: d.give_way,
        pad: d.pad,
    }
}
