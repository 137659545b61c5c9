//! `summary.csv`: completion time per task × technique × feedback.
//!
//! As in the paper ("each task twice ... to provide an average completion
//! time for each condition"), a participant's measured repetitions of a
//! condition are averaged first; mean, SD and the 95% confidence interval
//! are then taken over participants (n = participants, df = n - 1), since
//! repetitions by one person are not independent samples.
//!
//! Which trials count: measured ones (not practice) that have a time. A trial
//! that ran out of time (`completed = false`) enters with the time the runner
//! recorded for it — the time limit, a lower bound of the true time — so a
//! condition nobody could finish still shows up, and its mean is a lower
//! bound. `failed` counts every measured trial that did not complete: ran out
//! of time, or its runner failed; `errors` counts the latter (no time).
//!
//! Two CIs: `ci95_*` is the between-subject interval above;
//! `ci95_within_*` is the within-subject (Cousineau–Morey) interval the
//! figure draws, over the participants with every condition of the task
//! (see `within_ci`), centred on their mean.

use super::cells::task_cells;
use super::design::StudyDesign;
use super::error::StudyError;
use super::output::TrialRow;
use super::t_quantile::t_quantile_975;
use super::within_ci::cousineau_morey_half_widths;
use crate::pipeline::technique::TechniqueKind;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// One line of `summary.csv`. Statistics that need more participants than
/// there are (SD and CI need two) are empty.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SummaryRow {
    pub task: String,
    pub technique: TechniqueKind,
    pub feedback: bool,
    /// Participants with at least one timed measured trial in this condition.
    pub participants: u32,
    /// Measured trials in this condition.
    pub trials: u32,
    pub completed: u32,
    /// Trials that did not complete: time limit reached or runner failed.
    pub failed: u32,
    pub mean_s: Option<f64>,
    pub sd_s: Option<f64>,
    pub ci95_low_s: Option<f64>,
    pub ci95_high_s: Option<f64>,
    /// Of `failed`, trials whose runner failed (no time).
    pub errors: u32,
    /// Within-subject (Cousineau–Morey) 95% CI.
    pub ci95_within_low_s: Option<f64>,
    pub ci95_within_high_s: Option<f64>,
}

/// Mean, sample SD (n - 1) and 95% CI half-width of a sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellStats {
    pub n: usize,
    pub mean: f64,
    /// `None` for n < 2.
    pub sd: Option<f64>,
    /// `t(0.975, n-1) * sd / sqrt(n)`; `None` for n < 2.
    pub ci95_half_width: Option<f64>,
}

/// `None` for an empty sample.
pub fn describe(values: &[f64]) -> Option<CellStats> {
    let n = values.len();
    if n == 0 {
        return None;
    }
    let mean = values.iter().sum::<f64>() / n as f64;
    if n < 2 {
        return Some(CellStats { n, mean, sd: None, ci95_half_width: None });
    }
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    let sd = var.sqrt();
    let half = t_quantile_975((n - 1) as u32) * sd / (n as f64).sqrt();
    Some(CellStats { n, mean, sd: Some(sd), ci95_half_width: Some(half) })
}

/// One summary row per task × technique × feedback of the design, in design
/// order (tasks, then techniques as listed, then feedback levels as listed).
/// Rows of other conditions are ignored.
pub fn summarize(design: &StudyDesign, rows: &[TrialRow]) -> Vec<SummaryRow> {
    let mut out = Vec::new();
    for task in &design.tasks {
        let cells = task_cells(design, rows, task);
        let half_widths = cousineau_morey_half_widths(&cells.values);
        for (ti, &technique) in design.techniques.iter().enumerate() {
            for (fi, &feedback) in design.feedback.iter().enumerate() {
                let k = cells.cell(ti, fi);
                let column = cells.column(ti, fi);
                let within = half_widths.get(k).copied().flatten().map(|h| {
                    let mean = column.iter().sum::<f64>() / column.len() as f64;
                    (mean - h, mean + h)
                });
                let cell: Vec<&TrialRow> = rows
                    .iter()
                    .filter(|r| !r.practice && r.task == *task && r.technique == technique && r.feedback == feedback)
                    .collect();
                let mut per_participant: BTreeMap<u32, Vec<f64>> = BTreeMap::new();
                for r in &cell {
                    if let Some(t) = r.completion_time_s {
                        per_participant.entry(r.participant).or_default().push(t);
                    }
                }
                let means: Vec<f64> =
                    per_participant.values().map(|ts| ts.iter().sum::<f64>() / ts.len() as f64).collect();
                let stats = describe(&means);
                let count = |f: fn(&TrialRow) -> bool| cell.iter().filter(|r| f(r)).count() as u32;
                out.push(SummaryRow {
                    task: task.clone(),
                    technique,
                    feedback,
                    participants: means.len() as u32,
                    trials: cell.len() as u32,
                    completed: count(|r| r.completed),
                    failed: count(|r| !r.completed),
                    mean_s: stats.map(|s| s.mean),
                    sd_s: stats.and_then(|s| s.sd),
                    ci95_low_s: stats.and_then(|s| s.ci95_half_width.map(|h| s.mean - h)),
                    ci95_high_s: stats.and_then(|s| s.ci95_half_width.map(|h| s.mean + h)),
                    errors: count(|r| r.completion_time_s.is_none()),
                    ci95_within_low_s: within.map(|w| w.0),
                    ci95_within_high_s: within.map(|w| w.1),
                });
            }
        }
    }
    out
}

pub fn write_summary(path: &Path, rows: &[SummaryRow]) -> Result<(), StudyError> {
    super::csv_rows::write_rows(path, None, rows)
}

pub fn read_summary(path: &Path) -> Result<Vec<SummaryRow>, StudyError> {
    super::csv_rows::read_rows(path)
}
