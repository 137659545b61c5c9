//! The study design (who does what, in which order) and its expansion into
//! trials.
//!
//! # Run order
//!
//! The paper (UIST 2008, "User study"): tasks in the same order for everyone;
//! technique order counterbalanced across participants with a Latin square;
//! "two main phases (with visual feedback of the input and without)",
//! counterbalanced across participants. We read "phases" literally, so the
//! loops nest, outermost first:
//!
//! ```text
//! participant (P1..Pn)
//!   feedback phase   the participant's feedback-order group (see below)
//!     task           fixed order, as listed in the design
//!       technique    this participant's row of the balanced Latin square
//!         practice trial (repetition 0, unmeasured), if enabled
//!         measured trials (repetition 1..=reps)
//! ```
//!
//! A participant keeps one technique order (their row of the square) in
//! every task and both phases; the square balances orders across
//! participants. Rejected alternative: feedback innermost (on and off
//! alternating within each technique) — that is not "two phases", and
//! switching feedback every few trials would blur its effect.
//!
//! # Counterbalancing
//!
//! Technique orders come from a Williams design ([`williams_square`]): every
//! technique once in every position and every technique immediately followed
//! by every other exactly once (n even), or by a doubled square with 2n rows
//! where each such pair occurs twice (n odd).
//!
//! The two orders are *crossed*, not confounded: participants are first dealt
//! into feedback-order groups (participant `p` joins group `(p - 1) % F` for
//! `F` feedback levels; with on/off, odd IDs start with feedback on), then
//! the `i`-th member of group `g` (`i = (p - 1) / F`) takes Williams row
//! `(g·n + i) % rows`. So each group walks through whole Latin squares, and
//! for odd n the groups start in different halves of the doubled square.
//! With the paper's 6 participants, 3 techniques and on/off: the on-first
//! group (P1, P3, P5) gets rows 0–2 and the off-first group (P2, P4, P6)
//! rows 3–5 — a full Latin square each (every technique once in every
//! position within each group), and all six Williams rows once over the
//! study (first-order carry-over balanced overall).
//!
//! Full balance needs a multiple of `lcm(F·n, rows)` participants (6 for the
//! paper's design, 8 for 4 techniques with on/off); other counts run, and
//! [`StudyDesign::balance_note`] says what is off.

use super::error::StudyError;
use super::trial::TrialSpec;
use crate::pipeline::technique::TechniqueKind;
use crate::scene::bounds;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// The paper's tasks, in the paper's (fixed) order.
pub const DEFAULT_TASKS: [&str; 3] = ["positioning", "sorting", "steering"];

/// A within-subject design: participants × tasks × techniques × feedback,
/// each condition repeated.
///
/// Every field is written to `run.toml`, so `study --from run.toml` rebuilds
/// the same trials with the same seeds. Missing fields in a hand-written file
/// take the defaults (the paper's design).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct StudyDesign {
    pub participants: u32,
    /// In run order (the paper keeps it fixed for everyone).
    pub tasks: Vec<String>,
    /// The conditions the Latin square orders. Default: Joint, Proxy, Particle.
    pub techniques: Vec<TechniqueKind>,
    /// Feedback levels in the phase order of participant 1; default `[true, false]`.
    pub feedback: Vec<bool>,
    /// Measured trials per condition.
    pub repetitions: u32,
    /// One unmeasured practice trial per condition, before the measured ones.
    pub practice: bool,
    /// Study seed. TOML integers are signed, so at most `i64::MAX`.
    pub seed: u64,
    /// Overrides every task's time limit (seconds). Read by the trial runner,
    /// not by the harness.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_limit_override: Option<f64>,
    /// Runner settings that change results without being part of the design
    /// proper (`[design.settings]`); recorded so `--from` reproduces the run.
    /// The harness never reads them.
    #[serde(skip_serializing_if = "RunnerSettings::is_default")]
    pub settings: RunnerSettings,
}

/// The trial runner's settings, `[design.settings]` in `run.toml`. Every
/// key is optional; an unknown key is an error (a typo would otherwise
/// silently change nothing).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct RunnerSettings {
    /// `frames = true` (`--frames`): write every scripted trial's frames to
    /// `frames/p<participant>_t<order>.csv`.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub frames: bool,
    /// `perception_delay_s = 0.15` switches on the perception-delay model:
    /// seconds by which a participant sees the world later when feedback is
    /// off. Absent = 0, the paper's definition.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub perception_delay_s: Option<f64>,
    /// `replay = "DIR"` (`--replay DIR`): replay recorded gesture files from
    /// this folder instead of running scripted participants.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub replay: Option<PathBuf>,
    /// `manners = "single-finger"` (`--manners`): the scripted participants'
    /// repertoire, a preset or comma-separated manner names. Absent = every
    /// manner.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub manners: Option<String>,
}

impl RunnerSettings {
    /// True when nothing is set (then `run.toml` has no settings table).
    pub fn is_default(&self) -> bool {
        *self == RunnerSettings::default()
    }
}

impl Default for StudyDesign {
    /// The paper's study: 6 participants, 3 tasks, Joint/Proxy/Particle,
    /// feedback on and off, 2 measured repetitions after one practice trial.
    fn default() -> Self {
        StudyDesign {
            participants: 6,
            tasks: DEFAULT_TASKS.iter().map(|t| (*t).to_owned()).collect(),
            techniques: vec![TechniqueKind::JOINT, TechniqueKind::PROXY, TechniqueKind::PARTICLE],
            feedback: vec![true, false],
            repetitions: 2,
            practice: true,
            seed: 2008,
            time_limit_override: None,
            settings: RunnerSettings::default(),
        }
    }
}

impl StudyDesign {
    /// Rejects designs that cannot be run or written to `run.toml`.
    pub fn validate(&self) -> Result<(), StudyError> {
        let fail = |m: String| Err(StudyError::Design(m));
        if self.participants == 0 {
            return fail("at least one participant is needed".into());
        }
        if self.tasks.is_empty() {
            return fail("at least one task is needed".into());
        }
        if let Some(t) = self.tasks.iter().find(|t| t.trim().is_empty()) {
            return fail(format!("empty task name {t:?}"));
        }
        if let Some(t) = self.tasks.iter().find(|t| t.chars().any(|c| c.is_control() || c == '"')) {
            return fail(format!("task name {t:?} contains a quote or control character"));
        }
        if let Some(t) = first_duplicate(&self.tasks) {
            return fail(format!("task {t:?} listed twice"));
        }
        if self.techniques.is_empty() {
            return fail("at least one technique is needed".into());
        }
        if let Some(t) = first_duplicate(&self.techniques) {
            return fail(format!("technique {t} listed twice"));
        }
        if self.feedback.is_empty() {
            return fail("at least one feedback level is needed".into());
        }
        if first_duplicate(&self.feedback).is_some() {
            return fail("a feedback level is listed twice".into());
        }
        if self.repetitions == 0 {
            return fail("at least one repetition is needed".into());
        }
        if self.participants > bounds::MAX_PARTICIPANTS {
            return fail(format!(
                "participants (--participants, or `participants` in run.toml): {} is out of range (1..={})",
                self.participants,
                bounds::MAX_PARTICIPANTS
            ));
        }
        if self.repetitions > bounds::MAX_REPETITIONS {
            return fail(format!(
                "repetitions (--reps, or `repetitions` in run.toml): {} is out of range (1..={})",
                self.repetitions,
                bounds::MAX_REPETITIONS
            ));
        }
        // Checked before `trials()` allocates the plan.
        let trials = u64::from(self.participants).saturating_mul(self.trials_per_participant() as u64);
        if trials > bounds::MAX_TRIALS {
            return fail(format!(
                "{trials} trials ({} participants x {} each) is more than a study may have ({})",
                self.participants,
                self.trials_per_participant(),
                bounds::MAX_TRIALS
            ));
        }
        if self.seed > i64::MAX as u64 {
            return fail(format!("seed {} does not fit a TOML integer (max {})", self.seed, i64::MAX));
        }
        if let Some(limit) = self.time_limit_override
            && !(limit.is_finite() && limit > 0.0 && limit <= f64::from(bounds::DURATION_S))
        {
            return fail(format!(
                "time limit (--time-limit): {limit} is out of range (a number of seconds, > 0 and <= {})",
                bounds::DURATION_S
            ));
        }
        if let Some(delay) = self.settings.perception_delay_s
            && !(delay.is_finite() && delay >= 0.0)
        {
            return fail(format!("settings.perception_delay_s must be a number of seconds >= 0, got {delay}"));
        }
        Ok(())
    }

    /// Rows of the technique square (n or 2n for n techniques).
    pub fn square_rows(&self) -> usize {
        williams_rows(self.techniques.len())
    }

    /// Participants a fully balanced study needs a multiple of: each
    /// feedback-order group gets whole Latin squares (`F·n`), and the study
    /// uses every Williams row equally often (`rows`).
    pub fn balance_unit(&self) -> usize {
        let n = self.techniques.len().max(1);
        let groups = self.feedback.len().max(1);
        lcm(groups * n, self.square_rows().max(1))
    }

    /// `None` when the participants balance the design fully (see the
    /// module docs); otherwise a sentence for the user saying what is off and
    /// how many participants would balance it.
    pub fn balance_note(&self) -> Option<String> {
        let k = self.balance_unit();
        (!(self.participants as usize).is_multiple_of(k)).then(|| {
            format!(
                "{} participants do not balance the design: technique positions are balanced within each \
                 feedback-order group only when each of the {} groups holds a multiple of {} participants, \
                 and the {} Williams rows are used equally often only for a multiple of {k} participants; \
                 use a multiple of {k}",
                self.participants,
                self.feedback.len(),
                self.techniques.len(),
                self.square_rows(),
            )
        })
    }

    /// The feedback-order group of a participant (1-based ID): `(p - 1) % F`.
    pub fn feedback_group(&self, participant: u32) -> usize {
        (participant.saturating_sub(1) as usize) % self.feedback.len().max(1)
    }

    /// The Williams row a participant (1-based ID) takes: the `i`-th member
    /// of group `g` takes row `(g·n + i) % rows` (see the module docs).
    pub fn square_row(&self, participant: u32) -> usize {
        let groups = self.feedback.len().max(1);
        let member = (participant.saturating_sub(1) as usize) / groups;
        let rows = self.square_rows().max(1);
        (self.feedback_group(participant) * self.techniques.len() + member) % rows
    }

    /// Technique order for a participant (1-based ID): a row of the square.
    pub fn technique_order(&self, participant: u32) -> Vec<TechniqueKind> {
        let square = williams_square(self.techniques.len());
        if square.is_empty() {
            return Vec::new();
        }
        square[self.square_row(participant)].iter().map(|&i| self.techniques[i]).collect()
    }

    /// Every participant's orders, as recorded in `run.toml`.
    pub fn plan(&self) -> Vec<ParticipantPlan> {
        (1..=self.participants)
            .map(|participant| ParticipantPlan {
                participant,
                feedback_order: self.feedback_order(participant),
                technique_order: self.technique_order(participant),
            })
            .collect()
    }

    /// Feedback phase order for a participant (1-based ID): the design's
    /// levels rotated by the participant's group.
    pub fn feedback_order(&self, participant: u32) -> Vec<bool> {
        let mut order = self.feedback.clone();
        if !order.is_empty() {
            order.rotate_left(self.feedback_group(participant));
        }
        order
    }

    /// Trials per participant, practice included.
    pub fn trials_per_participant(&self) -> usize {
        let per_condition = self.repetitions as usize + usize::from(self.practice);
        self.tasks.len() * self.techniques.len() * self.feedback.len() * per_condition
    }

    pub fn trial_count(&self) -> usize {
        self.participants as usize * self.trials_per_participant()
    }

    /// Every trial in run order (see the module docs for the nesting). A
    /// trial's position in this list is its *trial index*, used by shards.
    pub fn trials(&self) -> Vec<TrialSpec> {
        let mut out = Vec::with_capacity(self.trial_count());
        for participant in 1..=self.participants {
            let techniques = self.technique_order(participant);
            let mut order_index = 0u32;
            for feedback in self.feedback_order(participant) {
                for task in &self.tasks {
                    for &technique in &techniques {
                        let first_rep = u32::from(!self.practice);
                        for repetition in first_rep..=self.repetitions {
                            out.push(TrialSpec {
                                participant,
                                order_index,
                                task: task.clone(),
                                technique,
                                feedback,
                                repetition,
                                practice: repetition == 0,
                                seed: trial_seed(self.seed, participant, order_index),
                            });
                            order_index += 1;
                        }
                    }
                }
            }
        }
        out
    }
}

/// One participant's line of the design table (`[[plan]]` in `run.toml`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParticipantPlan {
    pub participant: u32,
    /// Feedback phases in run order (`true` = feedback on).
    pub feedback_order: Vec<bool>,
    /// Techniques in run order (the same in every task and phase).
    pub technique_order: Vec<TechniqueKind>,
}

/// A slice of a design's trials, run into its own folder so that several
/// machines (or processes) share a study: shard `i/n` holds every trial of
/// the participants `p` with `(p - 1) % n == i` (participants learn, so a
/// session is never split; see `runner::in_shard`). `merge` puts the slices
/// back together.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl Shard {
    pub fn new(index: u32, count: u32) -> Result<Shard, StudyError> {
        if count == 0 || index >= count {
            return Err(StudyError::Design(format!("shard {index}/{count}: need 0 <= i < n")));
        }
        Ok(Shard { index, count })
    }

    /// The shard holding every trial (`0/1`).
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// Whether the `k`-th item (0-based; the harness passes `p - 1`) is in this shard.
    pub fn contains(self, k: usize) -> bool {
        k % self.count as usize == self.index as usize
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl std::str::FromStr for Shard {
    type Err = StudyError;

    /// `i/n`, e.g. `0/4`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let bad = || StudyError::Design(format!("shard {s:?}: expected i/n with 0 <= i < n, e.g. 0/4"));
        let (i, n) = s.trim().split_once('/').ok_or_else(bad)?;
        let i = i.trim().parse().map_err(|_| bad())?;
        let n = n.trim().parse().map_err(|_| bad())?;
        Shard::new(i, n)
    }
}

/// The per-trial seed: `SplitMix64` (Steele et al. 2014) chained over the study
/// seed, the participant and the order index. Hand-written rather than taken
/// from `rand` so seeds never change with a dependency update.
pub fn trial_seed(seed: u64, participant: u32, order_index: u32) -> u64 {
    splitmix64(splitmix64(splitmix64(seed) ^ u64::from(participant)) ^ u64::from(order_index))
}

fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

fn williams_rows(n: usize) -> usize {
    if n.is_multiple_of(2) { n } else { 2 * n }
}

/// A balanced Latin square (Williams 1949) over conditions `0..n`.
///
/// The first row is `0, 1, n-1, 2, n-2, ...`; row `i` adds `i` to it (mod n).
/// For even `n` these n rows are balanced: each condition once per position,
/// each ordered pair of conditions adjacent exactly once. For odd `n` no
/// n-row square can be, so the n mirrored rows are appended (2n rows, each
/// pair adjacent exactly twice). `n = 0` gives no rows; `n = 1` gives `[[0], [0]]`.
pub fn williams_square(n: usize) -> Vec<Vec<usize>> {
    if n == 0 {
        return Vec::new();
    }
    let first: Vec<usize> = (0..n)
        .map(|j| match j {
            0 => 0,
            j if j % 2 == 1 => j.div_ceil(2),
            j => n - j / 2,
        })
        .collect();
    let mut rows: Vec<Vec<usize>> = (0..n).map(|i| first.iter().map(|&c| (c + i) % n).collect()).collect();
    if !n.is_multiple_of(2) {
        let mirrored: Vec<Vec<usize>> = rows.iter().map(|r| r.iter().rev().copied().collect()).collect();
        rows.extend(mirrored);
    }
    rows
}

fn first_duplicate<T: PartialEq>(items: &[T]) -> Option<&T> {
    items.iter().enumerate().find(|(i, a)| items[..*i].contains(a)).map(|(_, a)| a)
}

fn lcm(a: usize, b: usize) -> usize {
    fn gcd(a: usize, b: usize) -> usize {
        if b == 0 { a } else { gcd(b, a % b) }
    }
    a / gcd(a, b) * b
}
