//! The physics world: a rapier3d simulation built from a [`crate::scene::Scene`].
//!
//! Fixed timestep, deterministic (same scene + same inputs → bit-identical
//! state on one machine), and paying only for the effects the scene declares
//! (soft bodies included: `soft.rs`).

mod config;
mod error;
mod face_friction;
mod give_way;
mod groups;
mod magnified;
mod object;
mod overlap;
mod pile_projection;
mod push;
mod ray;
mod reach;
mod scene_index;
mod soft;
mod soft_access;
mod stats;
mod technique_body;
mod technique_world;
#[allow(clippy::module_inception)]
mod world;

/// The physics engine's vocabulary that techniques build their bodies
/// with (rigid bodies, colliders, shapes, poses), re-exported so that the
/// engine is named in this module alone.
pub use rapier3d::{parry, prelude};

pub use crate::scene::{ObjectId, SoftId};
pub use config::WorldConfig;
pub use error::WorldError;
pub use groups::{Layer, collider_layer};
pub use magnified::{MAGNIFICATION, MagnifiedDispatcher};
pub use object::ObjectPush;
pub use push::Push;
pub use ray::RayHit;
pub use reach::{Bound, Reach, highest_top};
pub use soft::SoftSurface;
pub use soft_access::SoftPush;
pub use stats::WorldStats;
pub use technique_body::{TechniqueBody, TechniqueJoint};
pub use technique_world::TechniqueWorld;
pub use world::{ObjectPose, World};
