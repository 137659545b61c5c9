//! The study harness: counterbalanced designs (`design`), crash-safe resumable and shardable runs (`runner`, `output`), descriptive statistics (`summary`), inferential statistics (`analysis` on `cells`, with the maths in `anova`, `pairwise`, `within_ci`) and the Figure-9 plot (`figure`).

pub mod analysis;
pub mod anova;
pub mod cells;
pub mod design;
pub mod error;
pub mod figure;
pub mod findings;
pub mod folder;
pub mod lock;
pub mod output;
pub mod pairwise;
pub mod report;
pub mod runner;
pub mod seeds;
pub mod seeds_figure;
pub mod slurm;
pub mod strategies;
pub mod summary;
mod t_quantile;
pub mod trial;
pub mod within_ci;

pub use design::{DEFAULT_TASKS, ParticipantPlan, RunnerSettings, Shard, StudyDesign, trial_seed, williams_square};
pub use error::StudyError;
pub use output::{COLUMNS, RunFile, TrialRow};
pub use runner::{MergeOutcome, RunOptions, RunOutcome, merge, resume_study, run_study, write_report};
pub use strategies::{STRATEGY_COLUMNS, StrategyRow, read_strategies, strategies};
pub use summary::{CellStats, SummaryRow, describe, summarize};
pub use t_quantile::t_quantile_975;
pub use trial::{ParticipantRun, TrialResult, TrialRunner, TrialSpec};
