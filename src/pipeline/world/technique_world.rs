//! The world as a technique sees it: everything to read, and only what a
//! technique may change.
//!
//! A technique gets a [`TechniqueWorld`], never `&mut World`. Through it it
//! reads the whole world (it derefs to [`World`]), spawns, moves and removes
//! its own bodies and joints ([`TechniqueBody`], [`TechniqueJoint`]) and
//! pushes scene objects and soft bodies ([`ObjectPush`], [`SoftPush`]). What
//! belongs to the session, removing, placing or resetting scene objects and
//! stepping, is not reachable from it: the type system, not a comment, keeps
//! a technique from editing the scene.

use super::object::ObjectPush;
use super::soft_access::SoftPush;
use super::technique_body::{TechniqueBody, TechniqueJoint};
use super::world::World;
use crate::scene::ObjectId;
use glam::Vec3;
use rapier3d::prelude::*;
use std::ops::Deref;

/// A technique's handle on the world for one call (see the module doc).
///
/// Reading and technique bodies, yes; editing the scene, no. This does not
/// compile:
///
/// ```compile_fail
/// use surfacelab::pipeline::world::{ObjectId, TechniqueWorld};
/// fn vanish(world: &mut TechniqueWorld<'_>, id: ObjectId) {
///     world.remove_object(id);
/// }
/// ```
///
/// while the same function on the world itself does (the session's path):
///
/// ```
/// use surfacelab::pipeline::world::{ObjectId, World};
/// fn vanish(world: &mut World, id: ObjectId) {
///     world.remove_object(id);
/// }
/// ```
#[derive(Debug)]
pub struct TechniqueWorld<'w> {
    world: &'w mut World,
}

impl World {
    /// The world as a technique may use it, for one call of the technique.
    pub fn for_technique(&mut self) -> TechniqueWorld<'_> {
        TechniqueWorld { world: self }
    }
}

impl Deref for TechniqueWorld<'_> {
    type Target = World;

    fn deref(&self) -> &World {
        self.world
    }
}

impl TechniqueWorld<'_> {
    /// See [`World::spawn_body`].
    pub fn spawn_body(&mut self, body: impl Into<RigidBody>, collider: impl Into<Collider>) -> TechniqueBody {
        self.world.spawn_body(body, collider)
    }

    /// See [`World::spawn_compound`].
    pub fn spawn_compound(&mut self, body: impl Into<RigidBody>, colliders: Vec<Collider>) -> TechniqueBody {
        self.world.spawn_compound(body, colliders)
    }

    /// See [`World::set_compound`].
    pub fn set_compound(&mut self, body: TechniqueBody, colliders: Vec<ColliderBuilder>) {
        self.world.set_compound(body, colliders);
    }

    /// See [`World::spawn_anchor`].
    pub fn spawn_anchor(&mut self, at: Vec3) -> TechniqueBody {
        self.world.spawn_anchor(at)
    }

    /// See [`World::technique_body_mut`].
    pub fn technique_body_mut(&mut self, body: TechniqueBody) -> Option<&mut RigidBody> {
        self.world.technique_body_mut(body)
    }

    /// See [`World::technique_collider_mut`].
    pub fn technique_collider_mut(&mut self, body: TechniqueBody) -> Option<&mut Collider> {
        self.world.technique_collider_mut(body)
    }

    /// See [`World::drive`].
    pub fn drive(&mut self, body: TechniqueBody, velocity: Vec3) {
        self.world.drive(body, velocity);
    }

    /// See [`World::remove_body`].
    pub fn remove_body(&mut self, body: TechniqueBody) {
        self.world.remove_body(body);
    }

    /// See [`World::attach`].
    pub fn attach(
        &mut self,
        body: TechniqueBody,
        object: ObjectId,
        joint: impl Into<GenericJoint>,
    ) -> Option<TechniqueJoint> {
        self.world.attach(body, object, joint)
    }

    /// See [`World::remove_joint`].
    pub fn remove_joint(&mut self, joint: TechniqueJoint) {
        self.world.remove_joint(joint);
    }

    /// See [`World::attach_particle`].
    pub fn attach_particle(&mut self, soft: SoftBodyHandle, particle: u32, body: TechniqueBody) -> Option<()> {
        self.world.attach_particle(soft, particle, body)
    }

    /// See [`World::detach_particles`].
    pub fn detach_particles(&mut self, body: TechniqueBody) {
        self.world.detach_particles(body);
    }

    /// See [`World::push_object`].
    pub fn push_object(&mut self, id: ObjectId) -> Option<ObjectPush<'_>> {
        self.world.push_object(id)
    }

    /// See [`World::push_soft`].
    pub fn push_soft(&mut self, h: SoftBodyHandle) -> Option<SoftPush<'_>> {
        self.world.push_soft(h)
    }

    /// See [`World::reset_soft_forces`].
    pub fn reset_soft_forces(&mut self) {
        self.world.reset_soft_forces();
    }
}
