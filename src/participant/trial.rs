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
pub fn run_scripted(
    scene: &Scene,
    kind: TechniqueKind,
    feedback: bool,
    skill: Skill,
    seed: u64,
    time_limit_s: f64,
) -> Result<TrialOutcome, SessionError> {
    run_scripted_logged(scene, kind, feedback, skill, seed, time_limit_s, None)
}

/// Runs one scripted trial, writing every frame to `frames` when given
/// (the study's `--frames` option).
pub fn run_scripted_logged(
    scene: &Scene,
    kind: TechniqueKind,
    feedback: bool,
    skill: Skill,
    seed: u64,
    time_limit_s: f64,
    mut frames: Option<&mut FrameLog>,
) -> Result<TrialOutcome, SessionError> {
    let mut session = Session::new(scene, kind, SessionOptions::default())?;
    let mut planner = Planner::new(skill, feedback, seed);
    while session.time() < time_limit_s && !session.progress().complete {
        let hands = planner.hands(&session);
        session.step(&hands)?;
        if let Some(log) = frames.as_deref_mut() {
            log.record(&session);
        }
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

/// Per-frame rows of one trial (`frames/p<participant>_t<order>.csv`): tidy,
/// one row per object per frame: `step, time_s, contacts, technique_bodies,
/// object, x, y, z, active`. Write errors are kept and reported once.
#[derive(Debug)]
pub struct FrameLog {
    writer: csv::Writer<std::fs::File>,
    error: Option<csv::Error>,
}

impl FrameLog {
    pub fn create(path: &std::path::Path) -> Result<FrameLog, csv::Error> {
        let mut writer = csv::Writer::from_path(path)?;
        writer.write_record(["step", "time_s", "contacts", "technique_bodies", "object", "x", "y", "z", "active"])?;
        Ok(FrameLog { writer, error: None })
    }

    fn record(&mut self, s: &Session) {
        if self.error.is_some() {
            return;
        }
        let c = s.counts();
        for (i, p) in s.world().object_poses().iter().enumerate() {
            let row = [
                s.frames().to_string(),
                format!("{:.4}", s.time()),
                c.contacts.to_string(),
                c.bodies.to_string(),
                s.scene().objects[i].name.clone(),
                format!("{:.5}", p.position.x),
                format!("{:.5}", p.position.y),
                format!("{:.5}", p.position.z),
                p.active.to_string(),
            ];
            if let Err(e) = self.writer.write_record(&row) {
                self.error = Some(e);
                return;
            }
        }
    }

    /// Flushes the file; the first write error, if any.
    pub fn finish(mut self) -> Result<(), csv::Error> {
        if let Some(e) = self.error.take() {
            return Err(e);
        }
        self.writer.flush()?;
        Ok(())
    }
}
