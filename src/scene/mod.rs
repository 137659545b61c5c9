//! Scene files: the table, camera, objects, goals and declared effects of a task, as data.
//!
//! A scene is read once from TOML ([`load`]), validated, and handed out as a
//! plain [`Scene`] value that the world, the renderer, the study harness, the
//! benchmarks and the tests all share — one scene definition, many uses.

pub mod bounds;
mod builder;
pub mod builtin;
mod defaults;
mod effects;
mod error;
mod fields;
mod file;
mod id;
mod model;
mod outline;
#[cfg(test)]
pub(crate) mod test_scenes;
mod validate;
mod work;

pub use builder::{SceneBuilder, ShapeSpec};
pub use effects::{Effect, EffectSet};
pub use error::SceneError;
pub use fields::{FieldError, FieldReader, human};
pub use id::{ObjectId, SoftId};
pub use model::{
    BodyKind, CameraSpec, Color, Goal, ObjectSpec, PhysicsSpec, Scene, Shape, SoftBodySpec, SoftKind, SortingZone,
    SteeringGoal, Table, Target,
};
pub use outline::{Ring, footprint, solid_outline};
pub use validate::{load, parse, resolve_path};
pub use work::{MAX_OBJECT_STEPS, MAX_PARTICLE_STEPS, Work};
