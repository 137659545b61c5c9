//! # surfacelab
//!
//! Tabletop physics driven by what a vision-based surface sees, after Wilson
//! et al., *Bringing Physics to the Surface* (UIST 2008), with exact 2D contact
//! geometry after Cheng et al. (2016) and a study harness that reproduces the
//! paper's user study with simulated participants.
//!
//! ## Extending it
//!
//! A technique, a scene or a participant of your own needs no fork:
//!
//! - [`pipeline::technique::Technique`]: the trait a technique implements;
//!   [`pipeline::technique::TechniqueSpec`] and
//!   [`pipeline::technique::register`] add it under a name, and from then on
//!   the command line, the session, the study, the behaviour suite and the
//!   demo take that name like a built-in one.
//! - [`cli::main_with`]: the whole `surfacelab` command line with your
//!   techniques added ([`pipeline::technique::TechniqueRegistry`]), for a
//!   ten-line `main.rs` in your own crate.
//! - [`scene::SceneBuilder`]: a scene built in Rust, validated as a scene
//!   file is.
//! - [`session::Session`]: one scene running through the pipeline, stepped
//!   with hands or contact images; [`harness::participant::run_trial`] runs
//!   a trial with a hand policy of your own.
//! - [`harness::study::run_study`] with a [`harness::study::StudyDesign`]:
//!   a study from code, writing the same folder `surfacelab study` does.
//! - [`harness::behaviour::run_suite`]: the paper's manipulations under any
//!   registered technique.
//!
//! The user guide's `docs/extending.md` walks through writing a technique,
//! with the crate's `examples/` as its code.
//!
//! ## Layout
//!
//! Data flows one way: input → contact image → vision → technique → world →
//! session → harness, render and app; a module reads only the ones before
//! it. `ARCHITECTURE.md` is the module map: where each concept lives and
//! what each layer may read.

pub mod app;
pub mod cli;
pub mod contact;
pub mod error;
pub mod files;
pub mod harness;
pub mod input;
pub mod pipeline;
pub mod render;
pub mod scene;
pub mod session;
