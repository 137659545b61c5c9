//! One scripted trial: a planner drives a session until the goal is met or
//! the time limit ends it as failed (never a hang).

use super::{Planner, Skill};
use crate::scene::Scene;
use crate::session::{Session, SessionError, SessionOptions};
use crate::technique::TechniqueKind;

/// What a trial produced. Completion time is simulated time, not wall time,
/// so the same seed gives the same numbers on any load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrialOutcome {
    pub completion_time_s: f64,
    pub completed: bool,
    pub restarts: u32,
    pub objects_placed: u32,
    pub steps: u64,
}

/// Runs one scripted trial.
pub fn run_scripted(scene: &Scene, kind: TechniqueKind, feedback: bool, skill: Skill, seed: u64, time_limit_s: f64) -> Result<TrialOutcome, SessionError> {
    let mut session = Session::new(scene, kind, SessionOptions::default())?;
    let mut planner = Planner::new(skill, feedback, seed);
    while session.time() < time_limit_s && !session.progress().complete {
        let hands = planner.hands(&session);
        session.step(&hands)?;
    }
    let p = session.progress();
    Ok(TrialOutcome {
        completion_time_s: p.completed_at.unwrap_or(session.time()),
        completed: p.complete,
        restarts: p.restarts,
        objects_placed: p.placed as u32,
        steps: session.frames(),
    })
}
