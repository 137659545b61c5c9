//! How cost grows with the work (`surfacelab bench`): frame time by stage
//! against hands, objects, the physics rate and the contact-image size, and a
//! study's wall time and peak memory against its participants, each curve
//! with its log-log slope and the stage that dominates at its large end.

mod curve;
mod frame;
mod participants;
mod plot;
mod report;

pub use curve::{Curve, Measured, ScalingRow};
pub use report::{BenchOptions, CurveSummary, run_bench};
