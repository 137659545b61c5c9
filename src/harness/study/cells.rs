//! From trial rows to the numbers the statistics use: per task, one value
//! per participant and technique × feedback cell.
//!
//! A cell value is the mean of the participant's measured (not practice)
//! trials in that cell that have a time. A trial that ran out of time counts
//! with the time recorded for it — the time limit — so a cell with failures
//! has a mean that is a lower bound of the true one; a trial whose runner
//! failed has no time and is left out. The repeated-measures statistics need
//! every cell of a task for each participant: a participant missing one is
//! left out of that task's statistics (listwise) and listed in `incomplete`.

use super::design::StudyDesign;
use super::output::TrialRow;
use crate::pipeline::technique::TechniqueKind;
use std::collections::BTreeMap;

/// One task's cell values.
#[derive(Debug, Clone, PartialEq)]
pub struct TaskCells {
    pub task: String,
    /// In design order.
    pub techniques: Vec<TechniqueKind>,
    /// In design order (the design's feedback levels).
    pub feedback: Vec<bool>,
    /// Participants with every cell, ascending.
    pub participants: Vec<u32>,
    /// Participants with some but not all cells (left out).
    pub incomplete: Vec<u32>,
    /// `values[s][t · feedback.len() + f]` for `participants[s]`.
    pub values: Vec<Vec<f64>>,
}

impl TaskCells {
    /// Index of a cell in a participant's row.
    pub fn cell(&self, technique: usize, feedback: usize) -> usize {
        technique * self.feedback.len() + feedback
    }

    /// Every complete participant's value in one cell.
    pub fn column(&self, technique: usize, feedback: usize) -> Vec<f64> {
        let k = self.cell(technique, feedback);
        self.values.iter().map(|row| row[k]).collect()
    }

    /// Every complete participant's mean over the feedback levels of a technique.
    pub fn technique_means(&self, technique: usize) -> Vec<f64> {
        let f = self.feedback.len().max(1) as f64;
        self.values
            .iter()
            .map(|row| (0..self.feedback.len()).map(|j| row[self.cell(technique, j)]).sum::<f64>() / f)
            .collect()
    }

    /// Position of a technique in this task's table.
    pub fn technique_index(&self, technique: TechniqueKind) -> Option<usize> {
        self.techniques.iter().position(|&t| t == technique)
    }

    /// Position of a feedback level in this task's table.
    pub fn feedback_index(&self, feedback: bool) -> Option<usize> {
        self.feedback.iter().position(|&f| f == feedback)
    }
}

/// The cell table of one task (see the module docs for which trials count).
pub fn task_cells(design: &StudyDesign, rows: &[TrialRow], task: &str) -> TaskCells {
    let techniques = design.techniques.clone();
    let feedback = design.feedback.clone();
    let cells = techniques.len() * feedback.len();
    // participant -> cell -> times
    let mut times: BTreeMap<u32, Vec<Vec<f64>>> = BTreeMap::new();
    for r in rows.iter().filter(|r| !r.practice && r.task == task) {
        let (Some(t), Some(f), Some(time)) = (
            techniques.iter().position(|&x| x == r.technique),
            feedback.iter().position(|&x| x == r.feedback),
            r.completion_time_s,
        ) else {
            continue;
        };
        times.entry(r.participant).or_insert_with(|| vec![Vec::new(); cells])[t * feedback.len() + f].push(time);
    }
    let mut out = TaskCells {
        task: task.to_owned(),
        techniques,
        feedback,
        participants: Vec::new(),
        incomplete: Vec::new(),
        values: Vec::new(),
    };
    for (participant, cell_times) in times {
        if cell_times.iter().any(Vec::is_empty) {
            out.incomplete.push(participant);
            continue;
        }
        out.participants.push(participant);
        out.values.push(cell_times.iter().map(|ts| ts.iter().sum::<f64>() / ts.len() as f64).collect());
    }
    out
}
