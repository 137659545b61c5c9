//! Study participants: a scripted, technique-agnostic planner that drives
//! the synthetic hand in closed loop, and replayed gesture recordings.

mod planner;
mod runner;
mod skill;
mod trial;

pub use planner::{Intent, Planner};
pub use runner::{ReplayRunner, ScriptedRunner, participant_skill, technique_kind};
pub use skill::{HandMode, Skill};
pub use trial::{FrameLog, TrialOutcome, run_scripted, run_scripted_logged};
