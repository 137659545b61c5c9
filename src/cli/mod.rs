//! The command line: the contract outside checks drive. Each subcommand's
//! arguments are parsed once into a validated struct; the work lives in the
//! library modules, this layer only wires them together.

#[macro_use]
mod stdout;

mod args;
mod behaviours;
mod bench;
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
    BehavioursArgs, BenchArgs, CalibrateArgs, Cli, Command, ContactArgs, DemoArgs, FittsArgs, ParticipantsAction,
    ParticipantsArgs, RunArgs, ScreenshotAfter, ScreenshotArgs, StudyAction, StudyArgs, SynthImagesArgs, TradeoffArgs,
};
pub(crate) use entry::headless_main;
pub use entry::{command, main, main_with};
pub use failure::{CommandResult, EXIT_USAGE, Failure};
