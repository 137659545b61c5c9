//! One trial: what to run ([`TrialSpec`]), what came out ([`TrialResult`]), and
//! the seam between the harness and the physics ([`TrialRunner`]).
//!
//! Numbering conventions (they show up verbatim in `trials.csv`):
//! - `participant` is an ID starting at 1 (P1..Pn), as in a study log;
//! - `order_index` is the 0-based position of the trial in that participant's
//!   session, practice trials included;
//! - `repetition` is 0 for the practice trial of a condition and 1..=reps for
//!   the measured ones.

use crate::pipeline::technique::TechniqueKind;
use crate::session::Progress;
use serde::{Deserialize, Serialize};

/// Everything the runner needs to run one trial. The same spec always gives
/// the same trial: `seed` drives all randomness of the scripted participant.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct TrialSpec {
    /// 1-based participant ID.
    pub participant: u32,
    /// 0-based position in the participant's session.
    pub order_index: u32,
    /// Task name from the design (`positioning`, `sorting`, `steering`).
    pub task: String,
    pub technique: TechniqueKind,
    /// Visual feedback of the input shown.
    pub feedback: bool,
    /// 0 for the practice trial, 1..=reps for measured ones.
    pub repetition: u32,
    /// Unmeasured practice trial (left out of the summary and the figure).
    pub practice: bool,
    /// Derived from (study seed, participant, order index); see `design::trial_seed`.
    pub seed: u64,
}

/// What one trial produced.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct TrialResult {
    /// Seconds of simulated time until the goal was met, or until the runner
    /// gave up (time limit) when `completed` is false.
    pub completion_time_s: f64,
    pub completed: bool,
    /// Task restarts (steering: the cylinder fell off the platform).
    pub restarts: u32,
    pub objects_placed: u32,
    /// Physics steps taken.
    pub steps: u64,
    /// The manner used for the most time (empty when unknown, e.g. replays).
    pub strategy: String,
    /// Most hands on the table at once.
    pub hands_max: u32,
    /// Most fingertips on the table at once (a flat hand counts five).
    pub fingers_max: u32,
    /// Most objects moving at once.
    pub objects_moving_max: u32,
    /// Time and net progress per manner: `name:time_s:net_m` joined by `;`.
    pub manners: String,
}

impl TrialResult {
    /// Where a trial ended, as a result: the one place that turns a goal's
    /// progress into a row. A trial that did not meet its goal is recorded
    /// at `limit_s`, whether the time limit or the end of its input ended
    /// it (the loop stops up to one step past the limit). The per-frame
    /// maxima, strategy and manners are left for the runner to fill in.
    pub fn from_progress(progress: &Progress, steps: u64, limit_s: f64) -> TrialResult {
        TrialResult {
            completion_time_s: progress.completed_at.filter(|_| progress.complete).unwrap_or(limit_s),
            completed: progress.complete,
            restarts: progress.restarts,
            objects_placed: progress.placed as u32,
            steps,
            ..TrialResult::default()
        }
    }
}

/// Runs trials through the physics. Implemented by the CLI's runners.
///
/// Participants may learn: the harness runs each participant's trials in
/// their session order on one [`ParticipantRun`] (from [`Self::participant`]),
/// different participants on different threads (hence `Sync`). A trial of
/// that participant which this run does not execute (already in
/// `trials.csv`, or in another shard's folder) is passed to
/// [`ParticipantRun::replay`] in its place, so a resumed or sharded run
/// leaves the participant in the same state as an uninterrupted one.
pub trait TrialRunner: Sync {
    /// Runs one trial on its own: a runner whose participants learn must
    /// first bring the participant up to this trial.
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult>;

    /// A participant's session. The default keeps no state: every trial
    /// goes to [`Self::run`].
    fn participant(&self, _participant: u32) -> Box<dyn ParticipantRun + '_> {
        Box::new(Stateless(self))
    }
}

/// One participant's trials, run in session order.
pub trait ParticipantRun {
    /// Runs the participant's next trial.
    fn run(&mut self, spec: &TrialSpec) -> anyhow::Result<TrialResult>;

    /// A trial of this participant that ran elsewhere or earlier: let it
    /// shape the participant as it did then. The default does nothing.
    fn replay(&mut self, _spec: &TrialSpec) -> anyhow::Result<()> {
        Ok(())
    }
}

struct Stateless<'a, R: TrialRunner + ?Sized>(&'a R);

impl<R: TrialRunner + ?Sized> ParticipantRun for Stateless<'_, R> {
    fn run(&mut self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        self.0.run(spec)
    }
}
