//! What accuracy costs in time: sweeps of every knob that trades one for the
//! other, each measured against a high-accuracy reference run of the same
//! input, with the Pareto front of each knob (`surfacelab tradeoff`).

mod geometry;
mod pareto;
mod pipeline;
mod report;
mod row;

pub use pareto::{Point, pareto_front};
pub use report::{TradeoffOptions, run_tradeoff};
pub use row::Row;
