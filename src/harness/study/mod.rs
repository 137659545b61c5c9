//! The study harness: counterbalanced designs, crash-safe resumable and
//! shardable runs, descriptive statistics (`summary`), inferential
//! statistics (`analysis`, with the maths in `anova`, `pairwise`,
//! `within_ci`), the Figure-9 plot, the report, many seeds (`seeds`), the
//! repertoire ablation (`ablation`) and Slurm sweeps (`slurm`).
//!
//! The public surface is what a program outside the crate needs to design,
//! run and read a study: the re-exports below, and `slurm`, the cluster
//! sweep's own namespace. The rest (cells, figures, the lock, the runner's
//! internals) is the harness's own.

mod ablation;
mod analysis;
mod anova;
mod cells;
mod csv_rows;
mod design;
mod error;
mod explain;
mod figure;
mod findings;
mod folder;
mod lock;
mod output;
mod pairwise;
mod report;
mod runner;
mod seeds;
mod seeds_figure;
pub mod slurm;
mod strategies;
mod summary;
mod t_quantile;
mod trial;
mod within_ci;

pub use ablation::{Arm, write_ablation};
pub use analysis::{analyze, read_anova, write_anova, write_pairwise};
pub use anova::{TwoWayData, rm_anova};
pub use design::{DEFAULT_TASKS, ParticipantPlan, RunnerSettings, Shard, StudyDesign, trial_seed, williams_square};
pub use error::StudyError;
pub(crate) use error::orphan_advice;
pub use findings::{FINDINGS, FindingVerdict};
pub use output::{
    COLUMNS, RUN_TOML, RunFile, SUMMARY_CSV, TRIALS_CSV, TrialRow, TrialsWriter, read_trials, recover_trials,
};
pub use pairwise::{holm, paired_t};
pub use report::{Block, REPORT_HTML, REPORT_MD, report_blocks, strategy_counts};
pub use runner::{MergeOutcome, RunOptions, RunOutcome, merge, resume_study, run_study, write_report};
pub use seeds::{FindingsRow, seed_dir, seed_for, summarize_seeds};
pub use strategies::{STRATEGY_COLUMNS, StrategyRow, read_strategies, strategies};
pub use summary::{CellStats, SummaryRow, describe, read_summary, summarize, write_summary};
pub use t_quantile::t_quantile_975;
pub use trial::{ParticipantRun, TrialResult, TrialRunner, TrialSpec};
pub use within_ci::cousineau_morey_half_widths;
