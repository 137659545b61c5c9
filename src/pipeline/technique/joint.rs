//! Joint: a spring from each contact to an anchor point on the touched object
//! (`BumpTop` style: an off-centre anchor gives torque). A contact whose
//! centroid misses every movable object grabs the one its outline overlaps,
//! at the overlap point nearest the centroid where the surface there faces
//! up, else at the middle of the overlap (`hit_test.rs`; the paper's
//! point-based variant is `hit_test = "centroid"`).
//!
//! The contact drives an invisible kinematic anchor body; a rapier spring
//! joint (rest length 0) ties it to the object at the ray-cast point. A joint
//! breaks when its spring force passes `joint_break_force`; that contact then
//! grabs nothing until it lifts.
//!
//! Side collisions: joints have no collision of their own, so, as in the
//! paper's study, contacts that grab nothing get a simple kinematic collision
//! model — a kinematic prism shaped like the contact's convex hull, standing on
//! the surface the contact started on. We chose kinematic colliders over a
//! hand-written 2D push (the contact module's exit vector) because rapier then
//! resolves side pushes, stacking and friction consistently with everything
//! else; the 2D module remains the exact footprint test used elsewhere.
//! A prism pushes only from the side: it is never created where it would
//! overlap an object (rapier would push the object out, possibly upwards: a
//! flat hand whose centroid misses a ball, its fingers over it, would lift
//! the ball), and it stands taller than any object, so it meets a resting
//! object at its widest point, where the contact normal is horizontal (a
//! 3 cm prism would meet a 6 cm ball below its equator and push it up and
//! over).
//!
//! On a soft body (cloth, a soft block, a torn piece) the contact grabs the
//! particle nearest to where its ray lands: rapier attaches that particle to
//! the kinematic anchor (a point constraint, `SoftBody::attach_particle`),
//! and the grab breaks like a joint when the attachment's force passes
//! `joint_break_force`. Several contacts grab several particles, so two hands
//! pulling apart stretch (and may tear) the sheet between them.
//!
//! Design: docs/design/techniques.md.

use super::hit_test;
use super::surface_point::{at_height, clamp_len, support_below, table_point, table_velocity};
use super::{Feedback, HitTest, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput};
use crate::pipeline::surface::PixelPoint;
use crate::pipeline::vision::{Contact, ContactId};
use crate::pipeline::world::prelude::*;
use crate::pipeline::world::{Layer, ObjectId, TechniqueBody, TechniqueJoint, TechniqueWorld, World, WorldError};
use glam::{Vec2, Vec3};
use std::collections::{BTreeMap, BTreeSet};

/// Height of the kinematic side-collision prism (m): taller than the
/// tallest object a hand meets on the table (the steering cylinder on its
/// platform reaches 11 cm), so its side meets convex objects at their widest.
const PRISM_HEIGHT: f32 = 0.25;
/// Height above the surface at which the contact's outline is placed (m):
/// where a finger beside an object meets it, about a fingertip's height.
const PRISM_TOUCH_HEIGHT: f32 = 0.015;

#[derive(Debug, Clone, Copy)]
struct Grab {
    anchor: TechniqueBody,
    joint: TechniqueJoint,
    object: ObjectId,
    /// Anchor point in the object's local frame.
    local: Vec3,
    /// Height the anchor moves at (the touched surface).
    z: f32,
    /// Hand velocity last frame (m/s), for a clean release.
    v_hand: Vec2,
    /// Where on the glass the grab point sits from the contact's centroid
    /// (m): zero for a grab under the centroid (see `grab_by_outline`).
    offset: Vec2,
}

/// A contact holding a soft-body particle through its kinematic anchor.
/// The particle is found again through the attachment (a tear renumbers
/// particles and may move it to another piece; the attachment follows).
#[derive(Debug, Clone, Copy)]
struct SoftGrab {
    anchor: TechniqueBody,
    /// Height the anchor moves at (the touched surface).
    z: f32,
}

/// What a new contact took hold of.
enum Hold {
    Object(Grab),
    Soft(SoftGrab),
}

#[derive(Debug, Clone, Copy)]
struct Pusher {
    body: TechniqueBody,
    base_z: f32,
    /// Share of the contact's hull the prism spans (about its centre): less
    /// than 1 while the whole hull would overlap an object.
    scale: f32,
}

/// Hull scales tried, largest first, when the whole hull would overlap an
/// object: a forearm landing with one gather piece under its edge still
/// pushes the others with the rest of its outline (without this, the
/// `sweep_gather` forearm on the far side never got a prism).
const PRISM_SCALES: [f32; 4] = [1.0, 0.75, 0.5, 0.25];

/// The least upward component of the surface normal under an outline
/// grab's overlap point for the hand to rest there (cos 45°): a ball's
/// flank at the rim of its silhouette is tilted about 70°, a box's top 0°.
const MIN_REST_NORMAL_Z: f32 = std::f32::consts::FRAC_1_SQRT_2;

#[derive(Debug)]
pub struct JointTechnique {
    config: TechniqueConfig,
    grabs: BTreeMap<ContactId, Grab>,
    soft_grabs: BTreeMap<ContactId, SoftGrab>,
    pushers: BTreeMap<ContactId, Pusher>,
    /// Contacts whose joint broke: they grab nothing until lifted.
    broken: BTreeSet<ContactId>,
    contacts: usize,
}

impl JointTechnique {
    pub fn new(config: TechniqueConfig) -> Self {
        JointTechnique {
            config,
            grabs: BTreeMap::new(),
            soft_grabs: BTreeMap::new(),
            pushers: BTreeMap::new(),
            broken: BTreeSet::new(),
            contacts: 0,
        }
    }

    fn try_grab(&self, world: &mut TechniqueWorld<'_>, target: Vec2, v_hand: Vec2) -> Option<Hold> {
        let hit = world.cast_contact_ray(target)?;
        if let Some((h, particle)) = hit.soft {
            let at = world.soft_particle_position(h, particle)?;
            let anchor = world.spawn_anchor(at);
            world.attach_particle(h, particle, anchor)?;
            return Some(Hold::Soft(SoftGrab { anchor, z: at.z }));
        }
        let object = hit.object?;
        let body = world.object_rigid_body(object)?;
        if !body.is_dynamic() {
            return None;
        }
        let local = body.position().inverse_transform_point(hit.point);
        let anchor = world.spawn_anchor(hit.point);
        let joint = SpringJointBuilder::new(0.0, self.config.joint_stiffness, self.config.joint_damping)
            .local_anchor1(Vec3::ZERO)
            .local_anchor2(local)
            .build();
        let joint = world.attach(anchor, object, joint)?;
        Some(Hold::Object(Grab { anchor, joint, object, local, z: hit.point.z, v_hand, offset: Vec2::ZERO }))
    }

    /// A grab where the contact's outline overlaps an object its centroid
    /// misses: of the objects it overlaps, the one whose overlap point is
    /// nearest the centroid (`hit_test`), held at that point where the
    /// surface there faces up (the hand rests on a top), else at the middle
    /// of the overlap, over the part of the object the hand lies on; the
    /// anchor then keeps that offset from the centroid.
    ///
    /// The overlap point is on the silhouette's rim, and on a ball that is
    /// its steep flank, where no finger lying over it rests. A spring tied
    /// there leaves the ball free to swing round the anchor (every pose with
    /// that flank point at the anchor costs the spring nothing), so a drag
    /// across the line from palm to ball swings it 4.9 cm to the side of the
    /// hand's 20 cm path; from the middle of fingers covering it, 0.2 cm
    /// (`docs/design/techniques.md`). On a flat top the rim point is where
    /// the hand's edge rests, and a box held there pivots about it as the
    /// paper's point-based joint does (the behaviour suite's `grip_block`).
    fn grab_by_outline(
        &self,
        world: &mut TechniqueWorld<'_>,
        c: &Contact,
        input: &TechniqueInput<'_>,
        centroid: Vec2,
        v_hand: Vec2,
    ) -> Option<Hold> {
        if self.config.hit_test != HitTest::Outline {
            return None;
        }
        let outline = hit_test::outline(c, input.sensor);
        let nearest = hit_test::overlaps(world, &outline, centroid)
            .into_iter()
            .min_by(|a, b| (a.point - centroid).length().total_cmp(&(b.point - centroid).length()))?;
        let steep = world.cast_contact_ray(nearest.point).is_none_or(|h| h.normal.z < MIN_REST_NORMAL_Z);
        let at = if steep { nearest.middle } else { nearest.point };
        match self.try_grab(world, at, v_hand)? {
            Hold::Object(g) => Some(Hold::Object(Grab { offset: at - centroid, ..g })),
            soft @ Hold::Soft(_) => Some(soft),
        }
    }

    /// The soft particle held by `anchor` (its position) and the force (N)
    /// the attachment applied over the last step; `None` once it is gone.
    fn soft_held(world: &World, anchor: TechniqueBody, dt: f32) -> Option<(Vec3, f32)> {
        world.physics().soft_bodies.iter().find_map(|(_, b)| {
            let a = b.particle_attachments().iter().find(|a| a.body == anchor.handle())?;
            Some((b.particle_position(a.particle as usize), a.impulse().length() / dt))
        })
    }

    fn release_soft(world: &mut TechniqueWorld<'_>, g: SoftGrab) {
        world.detach_particles(g.anchor);
        world.remove_body(g.anchor);
    }

    fn release(world: &mut TechniqueWorld<'_>, g: Grab) {
        world.remove_joint(g.joint);
        world.remove_body(g.anchor);
        // No slingshot: the object leaves with the hand's velocity, not with
        // energy stored in the stretched spring.
        if let Some(mut b) = world.push_object(g.object) {
            let v = b.linvel();
            let cap = g.v_hand.length() * 1.2 + 0.05;
            let horiz = Vec2::new(v.x, v.y);
            if horiz.length() > cap {
                let c = clamp_len(horiz, cap);
                b.set_linvel(Vec3::new(c.x, c.y, v.z));
            }
        }
    }

    fn update_pusher(&mut self, world: &mut TechniqueWorld<'_>, c: &Contact, input: &TechniqueInput<'_>, screen: Vec2) {
        let max_step = self.config.max_contact_speed * input.dt;
        if let Some(mut p) = self.pushers.get(&c.id).copied() {
            let (target, shape) = pusher_shape(world, c, input, screen, p.base_z, p.scale);
            let cur = world.technique_body(p.body).map_or(target.extend(p.base_z), RigidBody::translation);
            let next = (cur.truncate() + clamp_len(target - cur.truncate(), max_step)).extend(p.base_z);
            // Grow back towards the whole hull only where that overlaps nothing.
            let grown = PRISM_SCALES.iter().copied().rev().find(|&k| k > p.scale).unwrap_or(p.scale);
            let shape = if grown > p.scale {
                let (_, bigger) = pusher_shape(world, c, input, screen, p.base_z, grown);
                if overlaps_object(world, &bigger, next) {
                    shape
                } else {
                    p.scale = grown;
                    self.pushers.insert(c.id, p);
                    bigger
                }
            } else {
                shape
            };
            if let Some(b) = world.technique_body_mut(p.body) {
                b.set_next_kinematic_translation(next);
            }
            if let Some(col) = world.technique_collider_mut(p.body) {
                col.set_shape(shape);
            }
        } else {
            // Stand on the surface under the finger (beside an object, that
            // is the surface next to it, not the object's side).
            let base_z = support_below(world, screen).map_or(0.0, |h| h.point.z) + 0.001;
            // Never where it would overlap an object (rapier would shove the
            // object out, maybe upwards): the largest part of the hull that
            // is clear, or none this frame.
            let Some((scale, target, shape)) = PRISM_SCALES.iter().find_map(|&k| {
                let (target, shape) = pusher_shape(world, c, input, screen, base_z, k);
                (!overlaps_object(world, &shape, target.extend(base_z))).then_some((k, target, shape))
            }) else {
                return;
            };
            let body = RigidBodyBuilder::kinematic_position_based().translation(target.extend(base_z)).build();
            let col = ColliderBuilder::new(shape)
                .friction(self.config.friction)
                .collision_groups(Layer::Proxy.groups())
                .build();
            let body = world.spawn_body(body, col);
            self.pushers.insert(c.id, Pusher { body, base_z, scale });
        }
    }
}

/// The edges of a pusher prism where its collider is now.
fn prism_edges(col: &crate::pipeline::world::prelude::Collider) -> Vec<(Vec3, Vec3)> {
    let pose = col.position();
    let at = |p: Vec3| pose.transform_point(p);
    let shape = col.shape();
    if let Some(poly) = shape.as_convex_polyhedron() {
        let points = poly.points();
        return poly
            .edges()
            .iter()
            .map(|e| (at(points[e.vertices[0] as usize]), at(points[e.vertices[1] as usize])))
            .collect();
    }
    let h = shape.compute_local_aabb().half_extents();
    let corner = |i: usize| {
        Vec3::new(
            if i & 1 == 0 { -h.x } else { h.x },
            if i & 2 == 0 { -h.y } else { h.y },
            if i & 4 == 0 { -h.z } else { h.z },
        )
    };
    // The 12 edges of a box: corners differing in exactly one axis bit.
    (0..8)
        .flat_map(|i| [1, 2, 4].into_iter().filter(move |b| i & b == 0).map(move |b| (i, i | b)))
        .map(|(i, j)| (at(corner(i)), at(corner(j))))
        .collect()
}

/// Where a pusher standing at `base_z` goes and its shape: the contact's
/// hull where it appears at touch height (perspective), relative to the
/// contact's own point there, scaled by `scale` about that point.
fn pusher_shape(
    world: &World,
    c: &Contact,
    input: &TechniqueInput<'_>,
    screen: Vec2,
    base_z: f32,
    scale: f32,
) -> (Vec2, SharedShape) {
    let mid = base_z + PRISM_TOUCH_HEIGHT;
    let target = at_height(world, screen, mid);
    let hull: Vec<Vec2> = c
        .blob
        .hull
        .iter()
        .map(|q| {
            (at_height(world, Vec2::from(input.sensor.to_table(PixelPoint::new(q[0] as f32, q[1] as f32))), mid)
                - target)
                * scale
        })
        .collect();
    (target, prism(&hull, input.sensor.metres_per_pixel()))
}

/// Whether a prism of `shape` standing at `base` would overlap a dynamic
/// scene object.
fn overlaps_object(world: &World, shape: &SharedShape, base: Vec3) -> bool {
    let physics = world.physics();
    let pose = Pose::from_translation(base);
    world.object_ids().filter(|&id| world.is_active(id)).any(|id| {
        let dynamic = physics.bodies.get(world.object_body(id)).is_some_and(RigidBody::is_dynamic);
        dynamic
            && physics.colliders.get(world.object_collider(id)).is_some_and(|c| {
                crate::pipeline::world::parry::query::intersection_test(&pose, shape.as_ref(), c.position(), c.shape())
                    .is_ok_and(|hit| hit.intersecting)
            })
    })
}

/// A prism over a contact hull (points relative to its centroid), from the
/// surface up `PRISM_HEIGHT`; a small square one for tiny or degenerate hulls.
fn prism(hull: &[Vec2], pixel: f32) -> SharedShape {
    let extrude = |outline: &[Vec2]| {
        let pts: Vec<Vec3> = outline.iter().flat_map(|p| [p.extend(0.0), p.extend(PRISM_HEIGHT)]).collect();
        SharedShape::convex_hull(&pts)
    };
    if hull.len() >= 3
        && let Some(s) = extrude(hull)
    {
        return s;
    }
    let r = hull.iter().map(|p| p.length()).fold(pixel * 2.0, f32::max);
    let square = [Vec2::new(-r, -r), Vec2::new(r, -r), Vec2::new(r, r), Vec2::new(-r, r)];
    extrude(&square).unwrap_or_else(|| SharedShape::cuboid(r, r, PRISM_HEIGHT / 2.0))
}

impl Technique for JointTechnique {
    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError> {
        world.require_joints("the Joint technique")?;
        self.contacts = input.frame.contacts.len();
        let dt = input.dt;
        let max_step = self.config.max_contact_speed * dt;
        let mut seen = BTreeSet::new();
        for c in &input.frame.contacts {
            seen.insert(c.id);
            let target = table_point(input.sensor, c.blob.centroid);
            let v_hand = clamp_len(table_velocity(input.sensor, c.velocity_px, dt), self.config.max_contact_speed);
            if let Some(g) = self.soft_grabs.get(&c.id).copied() {
                let goal = at_height(world, target, g.z);
                let held = Self::soft_held(world, g.anchor, dt);
                let cur = world.technique_body(g.anchor).map_or(Vec3::ZERO, RigidBody::translation);
                let next = cur.truncate() + clamp_len(goal - cur.truncate(), max_step);
                if let Some(a) = world.technique_body_mut(g.anchor) {
                    a.set_next_kinematic_translation(next.extend(g.z));
                }
                if held.is_none_or(|(_, force)| force > self.config.joint_break_force) {
                    self.soft_grabs.remove(&c.id);
                    self.broken.insert(c.id);
                    Self::release_soft(world, g);
                }
                continue;
            }
            if let Some(mut g) = self.grabs.get(&c.id).copied() {
                g.v_hand = v_hand;
                let goal = at_height(world, target + g.offset, g.z);
                let cur = world.technique_body(g.anchor).map_or(Vec3::ZERO, RigidBody::translation);
                let next = cur.truncate() + clamp_len(goal - cur.truncate(), max_step);
                if let Some(a) = world.technique_body_mut(g.anchor) {
                    a.set_next_kinematic_translation(next.extend(g.z));
                }
                // The spring's pull: stiffness × stretch. Past the break force it snaps.
                let obj = world.object_rigid_body(g.object).map(|b| b.position().transform_point(g.local));
                let stretch = obj.map_or(0.0, |p| (p - next.extend(g.z)).length());
                if self.config.joint_stiffness * stretch > self.config.joint_break_force || !world.is_active(g.object) {
                    self.grabs.remove(&c.id);
                    self.broken.insert(c.id);
                    Self::release(world, g);
                } else {
                    self.grabs.insert(c.id, g);
                }
                continue;
            }
            if !self.broken.contains(&c.id)
                && !self.pushers.contains_key(&c.id)
                && let Some(hold) = self
                    .try_grab(world, target, v_hand)
                    .or_else(|| self.grab_by_outline(world, c, input, target, v_hand))
            {
                match hold {
                    Hold::Object(g) => self.grabs.insert(c.id, g).map(|_| ()),
                    Hold::Soft(g) => self.soft_grabs.insert(c.id, g).map(|_| ()),
                };
                continue;
            }
            self.update_pusher(world, c, input, target);
        }
        let lifted: Vec<ContactId> = self.grabs.keys().copied().filter(|id| !seen.contains(id)).collect();
        for id in lifted {
            if let Some(g) = self.grabs.remove(&id) {
                Self::release(world, g);
            }
        }
        let lifted: Vec<ContactId> = self.soft_grabs.keys().copied().filter(|id| !seen.contains(id)).collect();
        for id in lifted {
            if let Some(g) = self.soft_grabs.remove(&id) {
                Self::release_soft(world, g);
            }
        }
        let lifted: Vec<ContactId> = self.pushers.keys().copied().filter(|id| !seen.contains(id)).collect();
        for id in lifted {
            if let Some(p) = self.pushers.remove(&id) {
                world.remove_body(p.body);
            }
        }
        self.broken.retain(|id| seen.contains(id));
        Ok(())
    }

    fn feedback(&self, world: &World) -> Feedback {
        let mut lines: Vec<(Vec3, Vec3)> = self
            .grabs
            .values()
            .filter_map(|g| {
                let a = world.technique_body(g.anchor)?.translation();
                let o = world.object_rigid_body(g.object)?.position().transform_point(g.local);
                Some((a, o))
            })
            .collect();
        lines.extend(self.soft_grabs.values().filter_map(|g| {
            let a = world.technique_body(g.anchor)?.translation();
            let (p, _) = Self::soft_held(world, g.anchor, world.dt())?;
            Some((a, p))
        }));
        // The side-collision prisms are what a sweep pushes with: without
        // their outline a Joint sweep looks like an invisible wall.
        let edges =
            self.pushers.values().filter_map(|p| world.technique_collider(p.body)).flat_map(prism_edges).collect();
        Feedback { lines, edges, cubes: Vec::new() }
    }

    fn counts(&self) -> TechniqueCounts {
        let held = self.grabs.len() + self.soft_grabs.len();
        TechniqueCounts { contacts: self.contacts, bodies: held + self.pushers.len(), joints: held }
    }

    fn clear(&mut self, world: &mut TechniqueWorld<'_>) {
        for (_, g) in std::mem::take(&mut self.grabs) {
            Self::release(world, g);
        }
        for (_, g) in std::mem::take(&mut self.soft_grabs) {
            Self::release_soft(world, g);
        }
        for (_, p) in std::mem::take(&mut self.pushers) {
            world.remove_body(p.body);
        }
        self.broken.clear();
    }

    fn config_mut(&mut self) -> &mut TechniqueConfig {
        &mut self.config
    }
}
