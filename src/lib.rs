//! # surfacelab
//!
//! Tabletop physics driven by what a vision-based surface sees, after Wilson
//! et al., *Bringing Physics to the Surface* (UIST 2008), with exact 2D contact
//! geometry after Cheng et al. (2016) and a study harness.
//!
//! Data flows one way, top to bottom; a module reads only the ones above it
//! (see `ARCHITECTURE.md`):
//!
//! ```text
//! scene, contact, error      data, pure geometry and error kinds every layer may read
//! input                      mouse, TUIO, gesture files ──▶ hands
//! pipeline                   surface ──▶ vision ──▶ technique ──▶ world
//! session                    one scene running through the pipeline; its goals measured
//! harness                    participants, study, behaviours, trade-off
//! render                     a draw list ──▶ pixels (wgpu), on screen or off
//! app                        the demo window; how a session looks
//! cli                        the command line, which only wires these together
//! ```
//!
//! - [`scene`]: scene/task files (table, camera, objects, goals, declared effects) as data.
//! - [`contact`]: exact 2D contact geometry (Contact Theory, Cheng et al. 2016); pure.
//! - [`error`]: the kind every module's errors share (bad input or runtime), which picks the exit code.
//! - [`files`]: input files read with a size cap, output files written atomically.
//! - [`input`]: every source of hands (mouse, TUIO, gesture files, scripts).
//! - [`pipeline`]: the contact image, vision, the paper's techniques, and the rapier3d world.
//! - [`session`]: the frame loop that drives the pipeline, and the goal tracker.
//! - [`harness`]: what measures sessions: participants, the study, behaviours, the trade-off.
//! - [`render`]: the wgpu renderer; knows draw lists, not sessions.
//! - [`app`]: the desktop demo, and the mapping from a session to a draw list.
//! - [`cli`]: the command line.

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
