//! Interaction techniques: how this frame's vision output acts on the world.
//!
//! The paper's four conditions (Wilson et al. 2008, "The techniques
//! compared"), plus the grasping hybrid it suggests, behind one trait, with
//! a registry of techniques by name ([`register`]) that a program outside
//! the crate adds its own to. Every technique gets the same inputs — this
//! frame's [`VisionFrame`](crate::pipeline::vision::VisionFrame), the world
//! and the timestep — applies its effect to the world before the step, tidies
//! up after it, and returns feedback geometry.

mod config;
mod contract;
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
pub use contract::{Technique, TechniqueCounts, TechniqueInput};
pub use direct::DirectForce;
pub use feedback::Feedback;
pub use hybrid::HybridTechnique;
pub use joint::JointTechnique;
pub use kind::{TechniqueKind, UnknownTechnique};
pub use particle::ParticleTechnique;
pub use proxy::ProxyTechnique;
pub use registry::{RegistryError, TechniqueFactory, TechniqueRegistry, TechniqueSpec, register};
