//! Collision layers. Particles must never collide with each other (thousands
//! of overlapping particles would cost quadratic pairs), and scene ray casts
//! must see only the scene, never the technique's own bodies.

use rapier3d::prelude::{Collider, Group, InteractionGroups, InteractionTestMode};

/// What a collider belongs to, stored in its collision-group membership.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layer {
    /// The table, its rim walls and fixed scene objects.
    Environment,
    /// Dynamic scene objects.
    Object,
    /// A technique's proxy bodies (one per contact).
    Proxy,
    /// A technique's particles (one per edge pixel).
    Particle,
    /// Line-of-sight particles (thin capsules up a camera ray): they meet
    /// rigid scene bodies only. A soft body gives way round what presses
    /// it, and a capsule standing beside it would hold its rim up by
    /// friction on its side: a flat hand could not press the jelly block
    /// down, nor flat hands smooth a crumpled cloth (`tests/soft_bodies.rs`).
    /// Particles that land on a soft body are balls (`Particle`).
    Sight,
    /// Soft bodies' deformable surfaces (cloth, volumes, torn pieces): part
    /// of the scene for contacts and ray casts alike.
    Soft,
}

impl Layer {
    fn group(self) -> Group {
        match self {
            Layer::Environment => Group::GROUP_1,
            Layer::Object => Group::GROUP_2,
            Layer::Proxy => Group::GROUP_3,
            Layer::Particle => Group::GROUP_4,
            Layer::Soft => Group::GROUP_5,
            Layer::Sight => Group::GROUP_6,
        }
    }

    /// The interaction groups a collider on this layer gets.
    pub fn groups(self) -> InteractionGroups {
        // Soft bodies are scene too: proxies, particles and objects all meet them.
        let scene = Group::GROUP_1 | Group::GROUP_2 | Group::GROUP_5;
        let filter = match self {
            Layer::Environment | Layer::Object => scene | Group::GROUP_3 | Group::GROUP_4 | Group::GROUP_6,
            Layer::Soft => scene | Group::GROUP_3 | Group::GROUP_4,
            // Proxies touch the scene and each other (two fingers can pinch).
            Layer::Proxy => scene | Group::GROUP_3,
            // Particles touch the scene only.
            Layer::Particle => scene,
            Layer::Sight => Group::GROUP_1 | Group::GROUP_2,
        };
        InteractionGroups::new(self.group(), filter, InteractionTestMode::And)
    }
}

/// The layer a collider was created on.
pub fn collider_layer(c: &Collider) -> Layer {
    let m = c.collision_groups().memberships;
    if m.contains(Group::GROUP_6) {
        Layer::Sight
    } else if m.contains(Group::GROUP_5) {
        Layer::Soft
    } else if m.contains(Group::GROUP_4) {
        Layer::Particle
    } else if m.contains(Group::GROUP_3) {
        Layer::Proxy
    } else if m.contains(Group::GROUP_2) {
        Layer::Object
    } else {
        Layer::Environment
    }
}
