//! Particle proxies: one small body per high-gradient (Sobel) pixel.
//!
//! Each edge sample is ray-cast to the surface it touches, moved by the flow
//! at that pixel projected onto that surface's tangent plane (paper, Figure
//! 6), and pushed down by gravity. Particles never collide with each other.
//!
//! Two variants behave the same: the paper's own (`particle_pooled = false`),
//! which creates every particle before the step and destroys it after, and a
//! pooled one that keeps bodies and re-places them. Pooling keeps each body on
//! a stable point of the outline (matched by position through the flow), so
//! rapier's broad phase keeps its pairs: pooling without such coherence,
//! bodies jumping between outline points, is *slower* than create/destroy.
//!
//! By default each particle is the paper's alternative proxy shape, a thin
//! capsule along its camera ray from the touched point up towards the eye
//! (`particle_capsules`). Seen in perspective, the top of a tall object off
//! the table's centre hides the table beside its far wall, so a ball
//! particle on the table there is centimetres from the wall it appears to
//! touch, and the outline sliding in lands on the top and needs friction
//! there: pushes from the far side barely move the steering cylinder. A
//! line-of-sight capsule meets the rim the user sees and pushes it, all
//! the way when particles also predict their contacts and a point that
//! climbed a step within the frame starts below it (see `particle_frame`;
//! `surfacelab behaviours`, the `side_push_*` cases). Its frame cost
//! against ball particles is the last line of `cargo bench --bench frame`.
//!
//! Six departures from the paper, each measured by `surfacelab behaviours`
//! and `cargo bench --bench frame`: a particle that can
//! touch nothing movable during its step is drawn but not simulated
//! (`particle_cull`), a particle never slides along a surface faster than
//! [`MAX_SURFACE_SPEEDUP`] times the hand moves over the table, a particle
//! gives way to a surface that comes at it, a particle is never created
//! inside a movable object (both in `particle_frame`), a hand rests on what it
//! landed on: its sides start up there, the flat of the hand presses it and
//! its skin sticks to it (`particle_rest`, `particle_stick`, see `rest`),
//! and the particles it lays on what it rests on move as one pad
//! (`particle_pad`, see `pad`).
//!
//! Design: docs/design/particles.md.

use super::pad::{PadParticle, Pads};
use super::particle_frame::{Draft, Frame, MAX_SURFACE_SPEEDUP, Placement, Settled, settle};
use super::proxy::gravity_scale_for;
use super::rest::{Press, Resting};
use super::sight_reach::SightReach;
use super::surface_point::{move_at_height, table_velocity};
use super::{Feedback, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput};
use crate::pipeline::surface::Sensor;
use crate::pipeline::vision::{ContactId, EdgeSample, FlowInterest};
use crate::pipeline::world::parry::shape::Ball;
use crate::pipeline::world::prelude::*;
use crate::pipeline::world::{Layer, TechniqueBody, TechniqueWorld, World, WorldError, highest_top};
use fnv::FnvHashMap;
use glam::Vec3;
use std::collections::BTreeMap;

/// Outline spacing (m) that `particle_mass` and `particle_weight` are given
/// for: the default stride (3 px) on the default sensor (1.5625 mm pixels).
/// Particles stand for a length of outline, so at a finer spacing each one
/// weighs proportionally less: resolution and stride trade accuracy for
/// time without changing how hard a hand presses.
pub const REFERENCE_SPACING: f32 = 3.0 * 0.001_562_5;

/// Extra distance (m) at which a particle is still simulated near a
/// movable body, beyond what both can travel in the step. Particles are
/// created clear of movable objects, so hands carry what they touch instead
/// of shoving it out of their outline and many bodies stay near them; a
/// small slack keeps the culled share, and so the frame's saving over the
/// paper's create/destroy, large (`cargo bench --bench frame`, `simulated`
/// against `sensed`), while the culled and full paths still agree to within
/// the test's bound (`culled_particles_change_nothing_the_objects_feel`).
const CULL_SLACK: f32 = 0.005;

/// Length (m) of a line-of-sight capsule (see `particle_capsules`). The
/// paper's reaches the camera's near plane; this one reaches a quarter
/// metre up its ray, over twice the highest top a hand touches in the
/// shipped tasks (the steering cylinder on its platform, 11 cm), because
/// a longer one only adds broad-phase pairs: reaching most of the way to
/// the eye, the many unculled capsules of `tests/stability.rs` take minutes
/// a step. Something stacked higher is met from above only.
const SIGHT_LENGTH: f32 = 0.25;

/// Grid cell (px) for matching pooled particles to this frame's samples.
const CELL: f32 = 4.0;
/// A pooled particle is re-used for a sample within this many pixels of its
/// flow-predicted position.
const MATCH_PX: f32 = 3.0;

#[derive(Debug, Clone, Copy)]
struct Slot {
    body: TechniqueBody,
    /// Pixel position it sat on last frame.
    px: [f32; 2],
    active: bool,
    /// The mass its collider was given.
    mass: f32,
    /// Whether its collider is a line-of-sight capsule (else a ball).
    sight: bool,
}

#[derive(Debug)]
pub struct ParticleTechnique {
    config: TechniqueConfig,
    /// Pooled bodies (pooled variant) or this frame's bodies (per-frame variant).
    slots: Vec<Slot>,
    positions: Vec<Vec3>,
    /// This frame's culled particles (feedback only, see `particle_cull`).
    sensed_only: Vec<Vec3>,
    /// The movable bodies' reach, computed for `flow_interest` and used
    /// again by `apply` in the same frame (the world has not stepped since).
    reach: Option<SightReach>,
    contacts: usize,
    /// Contacts whose particles are balls this frame even with
    /// `particle_capsules` (see [`ParticleTechnique::set_ball_contacts`]).
    ball_contacts: Vec<ContactId>,
    /// What each contact landed on, which holds its line-of-sight
    /// particles' sides up off the table and is pressed by the flat of the
    /// hand (see `rest`).
    resting: Resting,
    /// Each resting contact's particles on what it rests on, as one body
    /// (see `pad`).
    pads: Pads,
}

impl ParticleTechnique {
    pub fn new(config: TechniqueConfig) -> Self {
        ParticleTechnique {
            config,
            slots: Vec::new(),
            positions: Vec::new(),
            sensed_only: Vec::new(),
            reach: None,
            contacts: 0,
            ball_contacts: Vec::new(),
            resting: Resting::default(),
            pads: Pads::default(),
        }
    }

    /// Makes the particles of these contacts balls, not line-of-sight
    /// capsules, from the next `apply` on: Hybrid's gripping contacts,
    /// whose contact from the side is their grips (see `HybridTechnique`).
    pub(super) fn set_ball_contacts(&mut self, ids: impl IntoIterator<Item = ContactId>) {
        self.ball_contacts.clear();
        self.ball_contacts.extend(ids);
    }

    pub(super) fn config(&self) -> &TechniqueConfig {
        &self.config
    }

    /// Length (m) of a line-of-sight capsule, the same for every particle
    /// so that pooled bodies keep their collider; never past the eye.
    fn sight_length(world: &World) -> f32 {
        SIGHT_LENGTH.min(0.8 * world.eye().z)
    }

    /// Where particles can touch something movable this step. A particle
    /// moves at most `max_contact_speed` in each of its velocity's planar
    /// and vertical parts.
    fn sight_reach(&self, world: &World, dt: f32) -> SightReach {
        let travel = self.config.max_contact_speed * std::f32::consts::SQRT_2 * dt;
        SightReach::new(world, dt, self.config.particle_radius, CULL_SLACK, travel)
    }

    /// The collision layer of a line-of-sight capsule or a ball.
    fn layer(sight: bool) -> Layer {
        if sight { Layer::Sight } else { Layer::Particle }
    }

    /// A particle's pose: at its centre, its local z along its line of sight
    /// (only a capsule cares about the turn).
    fn pose(p: &Placement) -> Pose {
        if p.sight {
            Pose::from_parts(p.center, glam::Quat::from_rotation_arc(Vec3::Z, p.up))
        } else {
            Pose::from_translation(p.center)
        }
    }

    /// Where each particle goes this frame, and where the culled ones sit
    /// (pure given the frame and world): the frame's shared values, then
    /// each sample through the steps of `particle_frame`, in sample order.
    fn placements(&mut self, input: &TechniqueInput<'_>, world: &World) -> (Vec<Placement>, Vec<Vec3>) {
        // Stride and edge threshold were applied by the vision stage, which
        // the session configures from `particle_stride` and
        // `particle_edge_threshold`: one knob each, not two.
        let mut samples: Vec<_> = input.frame.edges.iter().collect();
        if samples.len() > self.config.particle_cap {
            // Drop evenly, never the tail of the list only.
            let keep = self.config.particle_cap;
            let n = samples.len();
            samples = (0..keep).map(|k| samples[k * n / keep]).collect();
        }
        let reach = match self.reach.take() {
            Some(r) => Some(r),
            None if self.config.particle_cull => Some(self.sight_reach(world, input.dt)),
            None => None,
        };
        let top = reach.as_ref().map_or_else(|| highest_top(&world.movable_reach()), SightReach::highest_top);
        // What each hand landed on, and the flat of the hand pressing on it
        // (see `rest`).
        if self.config.particle_rest {
            self.resting.update(input.frame, input.sensor, world);
        } else {
            self.resting.clear();
        }
        let presses: Vec<EdgeSample> = self.resting.presses().iter().map(Press::sample).collect();
        let mut counts: FnvHashMap<ContactId, (u32, u32)> = FnvHashMap::default();
        for e in &samples {
            counts.entry(e.contact_id).or_default().0 += 1;
        }
        for p in &presses {
            counts.entry(p.contact_id).or_default().1 += 1;
        }
        let frame = Frame {
            config: &self.config,
            sensor: input.sensor,
            world,
            dt: input.dt,
            resting: &self.resting,
            ball_contacts: &self.ball_contacts,
            reach,
            top,
            length: Self::sight_length(world),
            ball: Ball::new(self.config.particle_radius),
            share: self.config.particle_stride as f32 * input.sensor.metres_per_pixel() / REFERENCE_SPACING,
            counts,
        };
        let mut out = Vec::with_capacity(samples.len());
        let mut culled = Vec::new();
        let outline = samples.into_iter().map(|e| (*e, false));
        for (e, interior) in outline.chain(presses.iter().map(|e| (*e, true))) {
            match Draft::cast(&frame, e, interior).map(|d| settle(&frame, d)) {
                Some(Settled::Placed(p)) => out.push(p),
                Some(Settled::Culled(center)) => culled.push(center),
                None => {}
            }
        }
        (out, culled)
    }

    /// A particle's collider, placed relative to its body at `Self::pose(p)`.
    fn collider(&self, world: &World, p: &Placement) -> ColliderBuilder {
        let r = self.config.particle_radius;
        let shape = if p.sight {
            // From the touched point (the body's origin) up its line of sight.
            let half = 0.5 * Self::sight_length(world);
            ColliderBuilder::capsule_z(half, r).translation(Vec3::new(0.0, 0.0, half))
        } else {
            ColliderBuilder::ball(r)
        };
        shape
            .mass(p.mass)
            .friction(self.config.friction)
            .friction_combine_rule(CoefficientCombineRule::Max)
            .restitution(0.0)
            .collision_groups(Self::layer(p.sight).groups())
    }

    fn new_body(&self, world: &mut TechniqueWorld<'_>, p: &Placement) -> TechniqueBody {
        // Rotations locked: a rolling ball would transmit no friction.
        let body = RigidBody::from(
            RigidBodyBuilder::dynamic()
                .pose(Self::pose(p))
                .linvel(p.velocity)
                .gravity_scale(gravity_scale_for(p.mass, p.weight))
                .lock_rotations()
                .can_sleep(false)
                // Contacts predicted along the step's motion: a particle
                // placed beside a wall closer than it moves in the step
                // meets it in this step rather than ending inside it. Pushes
                // at the steering cylinder from the far side, which reach
                // its rim only late, carry it most of their travel only with
                // it (`surfacelab behaviours`, side_push_floor_000 and _090).
                .soft_ccd_prediction(self.config.max_contact_speed * world.dt()),
        );
        let col = self.collider(world, p).build();
        world.spawn_body(body, col)
    }

    fn place_pooled(&mut self, world: &mut TechniqueWorld<'_>, placements: &[Placement]) {
        // Index last frame's active slots by where they sat.
        let key = |px: [f32; 2]| ((px[0] / CELL).floor() as i32, (px[1] / CELL).floor() as i32);
        // Only looked up, never iterated, so the hasher cannot change an
        // answer; FNV rather than std's SipHash, which costs a few per cent of
        // the frame at nine lookups a particle.
        let mut grid: FnvHashMap<(i32, i32), Vec<usize>> = FnvHashMap::default();
        for (i, s) in self.slots.iter().enumerate() {
            if s.active {
                grid.entry(key(s.px)).or_default().push(i);
            }
        }
        let mut taken = vec![false; self.slots.len()];
        let mut assignment = vec![usize::MAX; placements.len()];
        for (k, p) in placements.iter().enumerate() {
            // Where this outline point was last frame, by its flow.
            let prev = [p.px[0] - p.flow_px[0], p.px[1] - p.flow_px[1]];
            let (cx, cy) = key(prev);
            let mut best = (MATCH_PX * MATCH_PX, usize::MAX);
            for dx in -1..=1 {
                for dy in -1..=1 {
                    for &i in grid.get(&(cx + dx, cy + dy)).map_or(&[][..], Vec::as_slice) {
                        if taken[i] {
                            continue;
                        }
                        let s = self.slots[i].px;
                        let d2 = (s[0] - prev[0]).powi(2) + (s[1] - prev[1]).powi(2);
                        if d2 <= best.0 {
                            best = (d2, i);
                        }
                    }
                }
            }
            if best.1 != usize::MAX {
                taken[best.1] = true;
                assignment[k] = best.1;
            }
        }
        // Unmatched samples take a free slot, else a new body.
        let mut free: Vec<usize> = (0..self.slots.len()).filter(|&i| !taken[i]).rev().collect();
        for (k, p) in placements.iter().enumerate() {
            if assignment[k] != usize::MAX {
                continue;
            }
            if let Some(i) = free.pop() {
                taken[i] = true;
                assignment[k] = i;
            } else {
                let body = self.new_body(world, p);
                self.slots.push(Slot { body, px: p.px, active: true, mass: p.mass, sight: p.sight });
                taken.push(true);
                assignment[k] = self.slots.len() - 1;
            }
        }
        let mut used = vec![false; self.slots.len()];
        for (k, p) in placements.iter().enumerate() {
            let pose = Self::pose(p);
            let i = assignment[k];
            used[i] = true;
            let s = &mut self.slots[i];
            s.px = p.px;
            s.active = true;
            if let Some(b) = world.technique_body_mut(s.body) {
                b.set_enabled(true);
                b.set_position(pose, true);
                b.set_linvel(p.velocity, true);
                b.set_gravity_scale(gravity_scale_for(p.mass, p.weight), true);
                // Moving between a soft body and rigid ground changes its mass
                // (see `soft_mass`); rapier applies it at the next step.
            }
            if s.sight != p.sight {
                // Moving between a soft body and anything else (see `Placement::sight`).
                s.sight = p.sight;
                let half = 0.5 * Self::sight_length(world);
                let r = self.config.particle_radius;
                if let Some(col) = world.technique_collider_mut(s.body) {
                    col.set_collision_groups(Self::layer(p.sight).groups());
                    if p.sight {
                        col.set_shape(SharedShape::capsule_z(half, r));
                        col.set_translation_wrt_parent(Vec3::new(0.0, 0.0, half));
                    } else {
                        col.set_shape(SharedShape::ball(r));
                        col.set_translation_wrt_parent(Vec3::ZERO);
                    }
                }
            }
            if (s.mass - p.mass).abs() > 1e-7 {
                s.mass = p.mass;
                if let Some(col) = world.technique_collider_mut(s.body) {
                    col.set_mass(p.mass);
                }
            }
        }
        // Spare bodies are disabled (cheap) rather than removed.
        for (i, s) in self.slots.iter_mut().enumerate() {
            if !used[i] && s.active {
                s.active = false;
                if let Some(b) = world.technique_body_mut(s.body) {
                    b.set_enabled(false);
                }
            }
        }
    }
}

impl Technique for ParticleTechnique {
    /// With culling, flow is needed only where a particle could reach
    /// something movable (see `SightReach::flow_interest`); the reach is
    /// kept for `apply` in the same frame (the world has not stepped since).
    fn flow_interest(&mut self, world: &World, sensor: &Sensor, dt: f32) -> FlowInterest {
        if !self.config.particle_cull {
            self.reach = None;
            return FlowInterest::All;
        }
        let reach = self.sight_reach(world, dt);
        let interest = reach.flow_interest(sensor, MAX_SURFACE_SPEEDUP);
        self.reach = Some(reach);
        interest
    }

    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError> {
        self.contacts = input.frame.contacts.len();
        let (all, culled) = self.placements(input, world);
        self.sensed_only = culled;
        // A resting contact's particles on what it rests on move as one pad
        // (see `pad`), by contact in id order (deterministic).
        let mut pads: BTreeMap<ContactId, Vec<PadParticle>> = BTreeMap::new();
        let mut placements = Vec::with_capacity(all.len());
        for p in all {
            match p.pad {
                Some(id) => {
                    let mut collider = self.collider(world, &p);
                    // Relative to the particle's centre, not rotated: the
                    // pad is level.
                    collider.position = Pose::from_translation(-p.center) * Self::pose(&p) * collider.position;
                    pads.entry(id).or_default().push(PadParticle {
                        center: p.center,
                        velocity: p.velocity - Vec3::new(0.0, 0.0, p.give_way.z),
                        rise: p.give_way.z,
                        glass: table_velocity(input.sensor, p.flow_px, input.dt) * move_at_height(world, p.center.z),
                        weight: p.weight,
                        mass: p.mass,
                        collider,
                    });
                }
                None => placements.push(p),
            }
        }
        let ccd = self.config.max_contact_speed * world.dt();
        self.pads.place(world, pads, ccd, self.config.particle_pooled);
        if self.config.particle_pooled {
            self.place_pooled(world, &placements);
        } else {
            // The paper's way: every particle is created now and destroyed after the step.
            for p in &placements {
                let body = self.new_body(world, p);
                self.slots.push(Slot { body, px: p.px, active: true, mass: p.mass, sight: p.sight });
            }
        }
        Ok(())
    }

    fn after_step(&mut self, world: &mut TechniqueWorld<'_>) {
        self.positions.clear();
        for s in self.slots.iter().filter(|s| s.active) {
            if let Some(b) = world.technique_body(s.body) {
                self.positions.push(b.translation());
            }
        }
        self.positions.extend(self.pads.positions(world));
        if !self.config.particle_pooled {
            // The paper's way: created before the step, destroyed after it.
            self.pads.clear(world);
        }
        if !self.config.particle_pooled {
            for s in std::mem::take(&mut self.slots) {
                world.remove_body(s.body);
            }
        }
    }

    fn feedback(&self, _world: &World) -> Feedback {
        let half = self.config.particle_radius;
        let all = self.positions.iter().chain(&self.sensed_only);
        Feedback { lines: Vec::new(), edges: Vec::new(), cubes: all.map(|p| (*p, half)).collect() }
    }

    fn counts(&self) -> TechniqueCounts {
        TechniqueCounts { contacts: self.contacts, bodies: self.positions.len(), joints: 0 }
    }

    fn clear(&mut self, world: &mut TechniqueWorld<'_>) {
        for s in std::mem::take(&mut self.slots) {
            world.remove_body(s.body);
        }
        self.positions.clear();
        self.sensed_only.clear();
        self.reach = None;
        self.resting.clear();
        self.pads.clear(world);
    }

    fn config_mut(&mut self) -> &mut TechniqueConfig {
        &mut self.config
    }
}
