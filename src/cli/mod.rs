//! The command line: the contract outside checks drive. Each subcommand's
//! arguments are parsed once into a validated struct; the work lives in the
//! library modules, this layer only wires them together.

/// `print!` for a command's results: a write that fails (EPIPE once the
/// reader of a pipe has gone, ENOSPC) is a run-time [`Failure`] naming
/// standard output, returned with `?`, where `print!` would panic.
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        write!(std::io::stdout().lock(), $($arg)*).map_err($crate::cli::stdout_failure)
    }};
}

/// `println!` for a command's results; see [`out!`].
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout().lock(), $($arg)*).map_err($crate::cli::stdout_failure)
    }};
}

mod args;
mod behaviours;
mod calibrate;
mod contact;
mod demo;
mod display;
mod doctor;
mod entry;
mod failure;
mod long_run;
mod participants;
mod run;
mod run_images;
mod screenshot;
mod study;
mod synth_images;
mod tradeoff;

pub use args::{
    BehavioursArgs, CalibrateArgs, Cli, Command, ContactArgs, DemoArgs, FittsArgs, ParticipantsAction,
    ParticipantsArgs, RunArgs, ScreenshotAfter, ScreenshotArgs, StudyAction, StudyArgs, SynthImagesArgs, TradeoffArgs,
};
pub(crate) use entry::headless_main;
pub use entry::{command, main, main_with};
pub use failure::{CommandResult, EXIT_USAGE, Failure};

/// A failed write to standard output, as the run-time failure it is.
fn stdout_failure(e: std::io::Error) -> Failure {
    Failure::from(anyhow::Error::new(e).context("writing standard output"))
}
