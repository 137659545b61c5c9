//! What runs sessions to measure them: nothing in the pipeline reads these.
//!
//! - [`participant`]: simulated participants who choose how to use their hands and learn.
//! - [`study`]: the study design, its trials, CSVs, statistics, figures and report.
//! - [`behaviour`]: the paper's manipulations as cases, measured per technique.
//! - [`fitts`]: a Fitts' law check of the simulated participants against published drag data.
//! - [`tradeoff`]: what contact accuracy costs in time.
//! - [`scaling`]: how the frame's and the study's cost grow with the work.
//! - `plot_font`: the one font the figures use.

pub mod behaviour;
mod csv_file;
pub mod fitts;
pub mod participant;
mod plot_font;
mod plot_png;
mod pool;
pub mod scaling;
pub mod study;
pub mod tradeoff;
