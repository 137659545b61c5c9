//! The sensing-to-physics pipeline, one stage per module, each reading only
//! the stages before it:
//!
//! ```text
//! surface ──▶ vision ──▶ technique ──▶ world
//! ```
//!
//! - [`surface`]: hands and tangibles drawn into the contact image.
//! - [`vision`]: threshold, connected components, Sobel, block-matching flow, tracking.
//! - [`technique`]: Direct Force, Joint, Proxy, Particle and Hybrid: contacts into bodies and forces.
//! - [`world`]: the rapier3d world built from a scene; steps only the declared effects.

pub mod surface;
pub mod technique;
pub mod vision;
pub mod world;
