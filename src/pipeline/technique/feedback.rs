//! What a technique shows the user when feedback is on (paper, "Feedback").

use glam::Vec3;

/// Feedback geometry in world coordinates.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Feedback {
    /// Joint: a line from each contact to its anchor (gone when the joint
    /// breaks): what holds an object, which a participant watches.
    pub lines: Vec<(Vec3, Vec3)>,
    /// Joint: the edges of its side-collision prisms, the bodies a sweep
    /// pushes with. Drawn, but they hold nothing, so they are kept apart
    /// from `lines`.
    pub edges: Vec<(Vec3, Vec3)>,
    /// Proxy: a cube at each contact centre; Particle: a small cube per particle.
    pub cubes: Vec<(Vec3, f32)>,
}

impl Feedback {
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty() && self.edges.is_empty() && self.cubes.is_empty()
    }
}
