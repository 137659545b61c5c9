//! Participant mode: the task runs as study trials with a real person at
//! the table. Each trial is a fresh session with the study's defaults; it
//! starts at the first touch, ends when the goal is met or the scene's time
//! limit passes (the study's rules), and appends one row to `trials.csv`
//! in the study's format, flushed at once.
//!
//! Numbering continues what the file already holds for the participant:
//! `order_index` counts their earlier rows, `repetition` their earlier
//! measured rows of the same task and condition. So a session can be run
//! condition by condition, one `demo --participant` call each.

use crate::harness::study::{TrialResult, TrialSpec};
use crate::harness::study::{TrialRow, TrialsWriter, recover_trials};
use crate::pipeline::technique::TechniqueKind;
use anyhow::Context;
use std::path::PathBuf;

/// Who, what condition, how many trials, where the rows go.
#[derive(Debug, Clone, PartialEq)]
pub struct ParticipantOptions {
    /// 1-based participant ID, as in the study's files.
    pub id: u32,
    pub technique: TechniqueKind,
    pub feedback: bool,
    /// Trials to run in this sitting.
    pub repetitions: u32,
    pub trials_csv: PathBuf,
    /// Folder the trials' gestures are recorded to, named as
    /// `study --replay` looks for them; `None` records nothing.
    pub gestures: Option<PathBuf>,
}

/// Where a trial stands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Phase {
    /// Waiting for the first touch; the session does not step.
    Ready,
    Running,
    /// Finished (completed or timed out) at this wall-clock second of the
    /// app; the next trial comes after a short pause.
    Finished {
        completed: bool,
        time_s: f64,
        at: f64,
    },
    /// Every trial of this sitting is done.
    Done,
}

/// The trials of one sitting.
#[derive(Debug)]
pub struct Trials {
    pub options: ParticipantOptions,
    /// The task as given (name or path), written into every row.
    pub task: String,
    writer: TrialsWriter,
    /// Trials finished in this sitting.
    pub done: u32,
    next_order: u32,
    next_repetition: u32,
    pub phase: Phase,
}

impl Trials {
    /// Opens (or creates) the trials file and works out the numbering.
    pub fn open(options: ParticipantOptions, task: &str) -> anyhow::Result<Self> {
        let path = &options.trials_csv;
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        }
        let technique = options.technique;
        let recovered = recover_trials(path).with_context(|| format!("reading {}", path.display()))?;
        let mine = recovered.rows.iter().filter(|r| r.participant == options.id);
        let next_order = mine.clone().count() as u32;
        let next_repetition = 1 + mine
            .filter(|r| !r.practice && r.task == task && r.technique == technique && r.feedback == options.feedback)
            .map(|r| r.repetition)
            .max()
            .unwrap_or(0);
        let writer = TrialsWriter::open(path, true)?;
        Ok(Self { options, task: task.to_owned(), writer, done: 0, next_order, next_repetition, phase: Phase::Ready })
    }

    /// The spec of the trial now running (or about to).
    pub fn spec(&self) -> TrialSpec {
        TrialSpec {
            participant: self.options.id,
            order_index: self.next_order,
            task: self.task.clone(),
            technique: self.options.technique,
            feedback: self.options.feedback,
            repetition: self.next_repetition,
            practice: false,
            seed: 0,
        }
    }

    /// Where this trial's gesture goes: the first name `study --replay`
    /// tries, `DIR/p<id>/<task>_<technique>_<on|off>_r<rep>.toml`.
    pub fn gesture_path(&self) -> Option<PathBuf> {
        let dir = self.options.gestures.as_ref()?;
        let spec = self.spec();
        let fb = if spec.feedback { "on" } else { "off" };
        let task = super::record::task_stem(&spec.task);
        Some(
            dir.join(format!("p{}", spec.participant))
                .join(format!("{task}_{}_{fb}_r{}.toml", spec.technique, spec.repetition)),
        )
    }

    /// Writes the row of the trial that just ended and moves the numbering on.
    pub fn finish(&mut self, result: &TrialResult, wall_s: f64) -> anyhow::Result<()> {
        let row = TrialRow::new(&self.spec(), result);
        self.writer.append(&row).with_context(|| format!("appending to {}", self.options.trials_csv.display()))?;
        self.done += 1;
        self.next_order += 1;
        self.next_repetition += 1;
        self.phase = Phase::Finished { completed: result.completed, time_s: result.completion_time_s, at: wall_s };
        Ok(())
    }

    /// After the pause: the next trial, or done.
    pub fn next(&mut self) {
        self.phase = if self.done >= self.options.repetitions { Phase::Done } else { Phase::Ready };
    }

    /// Trial number (1-based) in this sitting, and how many there are.
    pub fn position(&self) -> (u32, u32) {
        ((self.done + 1).min(self.options.repetitions), self.options.repetitions)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::harness::study::read_trials;

    #[test]
    fn rows_continue_the_numbering_of_the_file() {
        let dir = std::env::temp_dir().join(format!("surfacelab-participant-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let options = ParticipantOptions {
            id: 3,
            technique: TechniqueKind::PROXY,
            feedback: true,
            repetitions: 2,
            trials_csv: dir.join("trials.csv"),
            gestures: Some(dir.join("gestures")),
        };
        let result = TrialResult {
            completion_time_s: 12.5,
            completed: true,
            restarts: 0,
            objects_placed: 8,
            steps: 750,
            ..TrialResult::default()
        };
        let mut t = Trials::open(options.clone(), "positioning").expect("opens");
        assert_eq!(t.gesture_path().expect("set"), dir.join("gestures/p3/positioning_proxy_on_r1.toml"));
        t.finish(&result, 1.0).expect("writes");
        t.next();
        assert_eq!(t.phase, Phase::Ready);
        t.finish(&TrialResult { completed: false, ..result.clone() }, 2.0).expect("writes");
        t.next();
        assert_eq!(t.phase, Phase::Done);
        drop(t);
        // A second sitting, another condition, then the same one again.
        let mut t =
            Trials::open(ParticipantOptions { feedback: false, ..options.clone() }, "positioning").expect("opens");
        assert_eq!((t.spec().order_index, t.spec().repetition), (2, 1));
        t.finish(&result, 1.0).expect("writes");
        drop(t);
        let t = Trials::open(options, "positioning").expect("opens");
        assert_eq!((t.spec().order_index, t.spec().repetition), (3, 3));
        let rows = read_trials(&dir.join("trials.csv")).expect("a whole study file");
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[0].spec().participant, 3);
        assert_eq!(rows[1].completion_time_s, Some(12.5));
        assert!(!rows[1].completed && rows.iter().all(|r| r.seed == 0 && !r.practice));
        let _ = std::fs::remove_dir_all(dir);
    }
}
