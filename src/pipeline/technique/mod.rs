//! Interaction techniques: how this frame's vision output acts on the world.
//!
//! The paper's four conditions, plus the grasping hybrid it suggests, (PAPERS.md, "The techniques compared") behind
//! one trait. Every technique gets the same inputs — this frame's
//! [`VisionFrame`], the world and the timestep — applies its effect to the
//! world before the step, tidies up after it, and returns feedback geometry.

mod config;
mod direct;
mod feedback;
pub mod hit_test;
mod hybrid;
mod joint;
mod kind;
mod pad;
mod particle;
mod proxy;
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

use crate::pipeline::surface::Sensor;
use crate::pipeline::vision::{FlowInterest, VisionFrame};
use crate::pipeline::world::{TechniqueWorld, World, WorldError};
use crate::scene::{Effect, EffectSet};

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

/// The contract all four techniques honour.
pub trait Technique: Send {
    fn kind(&self) -> TechniqueKind;

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

impl TechniqueKind {
    /// Effects this technique needs on top of the scene's declaration.
    pub fn required_effects(self) -> EffectSet {
        match self {
            TechniqueKind::Joint => EffectSet::empty().with(Effect::Joints),
            TechniqueKind::Direct | TechniqueKind::Proxy | TechniqueKind::Particle | TechniqueKind::Hybrid => {
                EffectSet::empty()
            }
        }
    }

    /// Builds the technique with a configuration.
    pub fn build(self, config: TechniqueConfig) -> Box<dyn Technique> {
        match self {
            TechniqueKind::Direct => Box::new(DirectForce::new(config)),
            TechniqueKind::Joint => Box::new(JointTechnique::new(config)),
            TechniqueKind::Proxy => Box::new(ProxyTechnique::new(config)),
            TechniqueKind::Particle => Box::new(ParticleTechnique::new(config)),
            TechniqueKind::Hybrid => Box::new(HybridTechnique::new(config)),
        }
    }
}
