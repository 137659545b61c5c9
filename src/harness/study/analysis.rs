//! `anova.csv` and `pairwise.csv`: the inferential statistics of a run.
//!
//! Per task, on the cell table of the cells module (subject = participant,
//! value = mean of the participant's measured repetitions in the cell;
//! timed-out trials at the time limit; participants missing a cell left out):
//! - a technique × feedback repeated-measures ANOVA ([`super::anova`]): one
//!   row per effect, `technique`, `feedback`, `technique:feedback`;
//! - paired t-tests between every two techniques on each participant's mean
//!   over the feedback levels, Holm-corrected over the technique pairs of the
//!   task ([`super::pairwise`]).
//!
//! Empty fields: the statistic cannot be computed (fewer than two complete
//! participants, one level of a factor, no variance).

use super::anova::{EffectTest, TwoWayData, rm_anova};
use super::cells::{TaskCells, task_cells};
use super::csv_rows::{read_rows, write_rows};
use super::design::StudyDesign;
use super::error::StudyError;
use super::output::TrialRow;
use super::pairwise::{holm, paired_t};
use crate::pipeline::technique::TechniqueKind;
use serde::{Deserialize, Serialize};
use std::path::Path;

pub const ANOVA_CSV: &str = "anova.csv";
pub const PAIRWISE_CSV: &str = "pairwise.csv";

/// The effect names in `anova.csv`, in the order written.
pub const EFFECTS: [&str; 3] = ["technique", "feedback", "technique:feedback"];

/// One line of `anova.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AnovaRow {
    pub task: String,
    pub effect: String,
    pub df1: u32,
    pub df2: u32,
    #[serde(rename = "F")]
    pub f: Option<f64>,
    pub p: Option<f64>,
    pub epsilon_gg: Option<f64>,
    pub p_gg: Option<f64>,
    pub eta_p2: Option<f64>,
}

/// One line of `pairwise.csv`: technique `a` against `b` (in design order),
/// `mean_diff_s` = mean over participants of `a − b` (negative: `a` faster).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PairwiseRow {
    pub task: String,
    pub a: TechniqueKind,
    pub b: TechniqueKind,
    pub mean_diff_s: Option<f64>,
    pub t: Option<f64>,
    pub df: u32,
    pub p_holm: Option<f64>,
    pub dz: Option<f64>,
}

/// Everything the statistics of a run computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// One per task, in design order.
    pub cells: Vec<TaskCells>,
    pub anova: Vec<AnovaRow>,
    pub pairwise: Vec<PairwiseRow>,
}

impl Analysis {
    pub fn task(&self, task: &str) -> Option<&TaskCells> {
        self.cells.iter().find(|c| c.task == task)
    }

    /// The pairwise row of two techniques in a task, whichever way round it
    /// was written, with its mean difference turned to `first − second`.
    pub fn pair(&self, task: &str, first: TechniqueKind, second: TechniqueKind) -> Option<(Option<f64>, &PairwiseRow)> {
        self.pairwise.iter().find_map(|r| {
            if r.task != task {
                None
            } else if (r.a, r.b) == (first, second) {
                Some((r.mean_diff_s, r))
            } else if (r.a, r.b) == (second, first) {
                Some((r.mean_diff_s.map(|d| -d), r))
            } else {
                None
            }
        })
    }
}

/// Runs the statistics of every task of the design.
pub fn analyze(design: &StudyDesign, rows: &[TrialRow]) -> Analysis {
    let mut out = Analysis { cells: Vec::new(), anova: Vec::new(), pairwise: Vec::new() };
    for task in &design.tasks {
        let cells = task_cells(design, rows, task);
        let data = TwoWayData {
            levels_a: cells.techniques.len(),
            levels_b: cells.feedback.len(),
            subjects: cells.values.clone(),
        };
        // The table is built complete and finite, so the ANOVA cannot refuse it;
        // should it, the rows stay empty rather than failing the report.
        let empty = EffectTest {
            df1: 0,
            df2: 0,
            ss: 0.0,
            ss_error: 0.0,
            f: None,
            p: None,
            epsilon_gg: None,
            p_gg: None,
            eta_p2: None,
        };
        let effects = rm_anova(&data).map_or([empty; 3], |a| [a.a, a.b, a.ab]);
        for (name, e) in EFFECTS.iter().zip(effects) {
            out.anova.push(AnovaRow {
                task: task.clone(),
                effect: (*name).to_owned(),
                df1: e.df1,
                df2: e.df2,
                f: e.f,
                p: e.p,
                epsilon_gg: e.epsilon_gg,
                p_gg: e.p_gg,
                eta_p2: e.eta_p2,
            });
        }
        let mut tests = Vec::new();
        for i in 0..cells.techniques.len() {
            for j in i + 1..cells.techniques.len() {
                tests.push((i, j, paired_t(&cells.technique_means(i), &cells.technique_means(j))));
            }
        }
        let adjusted = holm(&tests.iter().map(|(_, _, t)| t.and_then(|t| t.p)).collect::<Vec<_>>());
        for ((i, j, test), p_holm) in tests.into_iter().zip(adjusted) {
            out.pairwise.push(PairwiseRow {
                task: task.clone(),
                a: cells.techniques[i],
                b: cells.techniques[j],
                mean_diff_s: test.map(|t| t.mean_diff),
                t: test.and_then(|t| t.t),
                df: test.map_or(0, |t| t.df),
                p_holm,
                dz: test.and_then(|t| t.dz),
            });
        }
        out.cells.push(cells);
    }
    out
}

/// `anova.csv` columns.
pub const ANOVA_COLUMNS: [&str; 9] = ["task", "effect", "df1", "df2", "F", "p", "epsilon_gg", "p_gg", "eta_p2"];
/// `pairwise.csv` columns.
pub const PAIRWISE_COLUMNS: [&str; 8] = ["task", "a", "b", "mean_diff_s", "t", "df", "p_holm", "dz"];

pub fn write_anova(path: &Path, rows: &[AnovaRow]) -> Result<(), StudyError> {
    write_rows(path, Some(&ANOVA_COLUMNS), rows)
}

pub fn write_pairwise(path: &Path, rows: &[PairwiseRow]) -> Result<(), StudyError> {
    write_rows(path, Some(&PAIRWISE_COLUMNS), rows)
}

pub fn read_anova(path: &Path) -> Result<Vec<AnovaRow>, StudyError> {
    read_rows(path)
}
