//! # surfacelab
//!
//! Tabletop physics driven by what a vision-based surface sees, after Wilson
//! et al., *Bringing Physics to the Surface* (UIST 2008), with exact 2D contact
//! geometry after Cheng et al. (2016) and a study harness.
//!
//! Data flows one way:
//!
//! ```text
//! surface ──▶ vision ──▶ technique ──▶ world ──▶ render / study
//! (synthetic   (threshold,  (Direct, Joint,  (rapier3d,   (wgpu; trials,
//!  hands →      components,  Proxy, Particle) scene goals) CSVs, plots)
//!  contact      Sobel, flow,
//!  image)       tracking)
//! ```
//!
//! - [`scene`]: scene/task files (table, camera, objects, goals, declared effects) as data.
//! - [`world`]: the rapier3d world built from a scene; steps only the declared effects.
//! - [`technique`]: the paper's four ways of mapping contacts into the world.
//! - [`render`]: the wgpu renderer, on screen or off screen.
//! - [`cli`]: the command line, which only wires these together.

pub mod app;
pub mod behaviour;
pub mod cli;
pub mod contact;
pub mod goal;
pub mod participant;
pub mod plot_font;
pub mod render;
pub mod scene;
pub mod session;
pub mod study;
pub mod surface;
pub mod technique;
pub mod tradeoff;
pub mod vision;
pub mod world;
