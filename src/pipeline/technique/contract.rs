//! The contract every technique honours, and what it sees each frame.

use super::{Feedback, TechniqueConfig};
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
/// bookkeeping. Register an implementation with [`register`](super::register) (see
/// [`TechniqueSpec`](super::TechniqueSpec)) to use it from the command line, the study, the
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
