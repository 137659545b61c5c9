//! What accuracy costs in time: sweeps of every knob that trades one for the
//! other, each measured against a high-accuracy reference run of the same
//! input, with the Pareto front of each knob (`surfacelab tradeoff`).

mod geometry;
mod pareto;
mod pipeline;
mod report;

pub use pareto::{Point, pareto_front};
pub use report::{Row, TradeoffOptions, run_tradeoff};
