//! Interaction techniques: how this frame's vision output acts on the world.
//!
//! The paper's four conditions (Wilson et al. 2008, "The techniques
//! compared"), plus the grasping hybrid it suggests, behind one trait, with
//! a registry of techniques by name ([`register`]) that a program outside
//! the crate adds its own to. Every technique gets the same inputs — this frame's
//! [`VisionFrame`], the world and the timestep — applies its effect to the
//! world before the step, tidies up after it, and returns feedback geometry.

mod config;
mod direct;
mod feedback;
mod hit_test;
mod hybrid;
mod joint;
mod kind;
mod pad;
mod particle;
mod particle_frame;
mod proxy;
mod registry;
mod rest;
mod sight_reach;
mod surface_point;

pub use config::{ConfigError, HitTest, PressureMode, ProxyShape, TechniqueConfig};
pub use direct::DirectForce;
pub use feedback::Feedback;
pub use hybrid::HybridTechnique;
pub use joint::JointTechnique;
pub use kind::{TechniqueKind, UnknownTechnique};
pub use particle::ParticleTechnique;
pub use proxy::ProxyTechnique;
pub use registry::{RegistryError, TechniqueFactory, TechniqueRegistry, TechniqueSpec, register};

use crate::pipeline::surface::Sensor;
use crate::pipeline::vision::{FlowInterest, VisionFrame};
use crate::pipeline::world::{TechniqueWorld, World, WorldError};

/// What every technique sees each frame.
#[derive(Debug, Clone, Copy)]
pub struct TechniqueInput<'a> {
    pub frame: &'a VisionFrame,
    /// Maps contact-image pixels to table metres.
    pub sensor: &'a Sensor,
    /// The physics timestep the frame will be stepped with (s).
    pub dt: f32,
}

/// Counts for statistics and reports.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TechniqueCounts {
    pub contacts: usize,
    /// Bodies the technique has in the world now (proxies, particles, anchors).
    pub bodies: usize,
    pub joints: usize,
}

/// The contract every technique honours, built-in or registered.
///
/// A frame runs `flow_interest`, then the vision stage, then `apply`, the
/// physics step, and `after_step`. A technique acts on the world only
/// through the [`TechniqueWorld`] handle: it spawns, moves and removes its
/// own bodies and joints and pushes scene objects, and it cannot remove,
/// place or step them, so a new technique cannot break the session's
/// bookkeeping. Register an implementation with [`register`] (see
/// [`TechniqueSpec`]) to use it from the command line, the study, the
/// behaviour suite and the demo.
pub trait Technique: Send {
    /// Where this technique will read outline flow this frame (asked once
    /// per frame, before the vision stage runs, so it measures nothing
    /// else). Only Particle reads flow.
    fn flow_interest(&mut self, _world: &World, _sensor: &Sensor, _dt: f32) -> FlowInterest {
        FlowInterest::None
    }

    /// Applies this frame's effect to the world, before the step.
    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError>;

    /// Runs after the step (the paper's per-frame particles are destroyed here).
    fn after_step(&mut self, _world: &mut TechniqueWorld<'_>) {}

    /// Feedback geometry as of the last step, in world coordinates.
    fn feedback(&self, world: &World) -> Feedback;

    fn counts(&self) -> TechniqueCounts;

    /// Removes everything the technique added to the world.
    fn clear(&mut self, world: &mut TechniqueWorld<'_>);

    /// Live parameter changes (the demo's sliders).
    fn config_mut(&mut self) -> &mut TechniqueConfig;
}
