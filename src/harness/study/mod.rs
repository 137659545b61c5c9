//! The study harness: counterbalanced designs, crash-safe resumable and
//! shardable runs, descriptive statistics (`summary`), inferential
//! statistics (`analysis`, with the maths in `anova`, `pairwise`,
//! `within_ci`), the Figure-9 plot, the report, many seeds (`seeds`), the
//! repertoire ablation (`ablation`) and Slurm sweeps (`slurm`).
//!
//! The public surface is what a program outside the crate needs to design,
//! run and read a study: the re-exports below and the modules that hold a
//! file format of the run folder. The rest (cells, figures, the lock, the
//! runner's internals) is the harness's own.

pub mod ablation;
pub mod analysis;
pub mod anova;
mod cells;
mod design;
pub(crate) mod error;
mod explain;
mod figure;
pub mod findings;
mod folder;
mod lock;
pub mod output;
pub mod pairwise;
pub mod report;
mod runner;
pub mod seeds;
mod seeds_figure;
pub mod slurm;
mod strategies;
pub mod summary;
mod t_quantile;
mod trial;
pub mod within_ci;

pub use design::{DEFAULT_TASKS, ParticipantPlan, RunnerSettings, Shard, StudyDesign, trial_seed, williams_square};
pub use error::StudyError;
pub use output::{COLUMNS, RunFile, TrialRow};
pub use runner::{MergeOutcome, RunOptions, RunOutcome, merge, resume_study, run_study, write_report};
pub use strategies::{STRATEGY_COLUMNS, StrategyRow, read_strategies, strategies};
pub use summary::{CellStats, SummaryRow, describe, summarize};
pub use t_quantile::t_quantile_975;
pub use trial::{ParticipantRun, TrialResult, TrialRunner, TrialSpec};
