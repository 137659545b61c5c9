//! One trial: what to run ([`TrialSpec`]), what came out ([`TrialResult`]), and
//! the seam between the harness and the physics ([`TrialRunner`]).
//!
//! Numbering conventions (they show up verbatim in `trials.csv`):
//! - `participant` is an ID starting at 1 (P1..Pn), as in a study log;
//! - `order_index` is the 0-based position of the trial in that participant's
//!   session, practice trials included;
//! - `repetition` is 0 for the practice trial of a condition and 1..=reps for
//!   the measured ones.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// A study condition's interaction technique. Kept local to the study layer
/// (the harness needs no physics); the CLI maps it to the technique module's kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Technique {
    /// Piloted, then dropped by the paper; optional here.
    Direct,
    Joint,
    Proxy,
    Particle,
    /// Per-frame plus persistent particles (grasping); not in the paper's study.
    Hybrid,
}

impl Technique {
    pub const ALL: [Technique; 5] =
        [Technique::Direct, Technique::Joint, Technique::Proxy, Technique::Particle, Technique::Hybrid];

    /// The name used in files and on the command line (`joint`).
    pub fn name(self) -> &'static str {
        match self {
            Technique::Direct => "direct",
            Technique::Joint => "joint",
            Technique::Proxy => "proxy",
            Technique::Particle => "particle",
            Technique::Hybrid => "hybrid",
        }
    }

    /// The name used on plots (`Joint`).
    pub fn label(self) -> &'static str {
        match self {
            Technique::Direct => "Direct",
            Technique::Joint => "Joint",
            Technique::Proxy => "Proxy",
            Technique::Particle => "Particle",
            Technique::Hybrid => "Hybrid",
        }
    }
}

impl fmt::Display for Technique {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown technique name.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown technique {0:?} (expected one of: direct, joint, proxy, particle, hybrid)")]
pub struct UnknownTechnique(pub String);

impl FromStr for Technique {
    type Err = UnknownTechnique;

    /// Case-insensitive; surrounding spaces ignored.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let t = s.trim();
        Technique::ALL
            .into_iter()
            .find(|k| k.name().eq_ignore_ascii_case(t))
            .ok_or_else(|| UnknownTechnique(s.to_owned()))
    }
}

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
    pub technique: Technique,
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
}

/// Runs one trial through the physics. Implemented by the CLI; the harness
/// calls it from several threads at once, hence `Sync`.
pub trait TrialRunner: Sync {
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult>;
}
