//! The names of the files in a study run folder (`study --out DIR`), which
//! docs/file-formats.md ("Study run folder") documents: the writers, the readers and
//! the error messages that name them all take them from here.

pub const RUN_TOML: &str = "run.toml";
pub const TRIALS_CSV: &str = "trials.csv";
pub const ERRORS_LOG: &str = "errors.log";
pub const SUMMARY_CSV: &str = "summary.csv";
pub const STRATEGIES_CSV: &str = "strategies.csv";
pub const FIGURE_PNG: &str = "figure.png";
pub const FIGURE_SVG: &str = "figure.svg";
