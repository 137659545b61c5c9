//! One scripted trial: a planner drives a session until the goal is met or
//! the time limit ends it as failed (never a hang).

use super::learner::Learner;
use super::manner::Manner;
use super::planner::{Planner, PlannerOptions};
use super::skill::Skill;
use super::usage::Usage;
use crate::pipeline::technique::TechniqueKind;
use crate::scene::Scene;
use crate::session::{Session, SessionError, SessionOptions};

/// Speed above which an object counts as moving for `objects_moving_max`
/// (m/s): well above the jitter of a resting body (< 1 mm/s), below the
/// slowest deliberate push.
pub const MOVING_SPEED: f32 = 0.02;

/// What a trial produced. Completion time is simulated time, not wall time,
/// so the same seed gives the same numbers on any load.
#[derive(Debug, Clone, PartialEq)]
pub struct TrialOutcome {
    pub completion_time_s: f64,
    pub completed: bool,
    pub restarts: u32,
    pub objects_placed: u32,
    pub steps: u64,
    /// The manner used for the most time.
    pub strategy: Option<Manner>,
    /// Most hands on the table at once.
    pub hands_max: u32,
    /// Most fingertips on the table at once (a flat hand counts five).
    pub fingers_max: u32,
    /// Most objects moving at once (faster than [`MOVING_SPEED`]).
    pub objects_moving_max: u32,
    /// Time and net progress per manner.
    pub usage: Usage,
}

/// Objects of the session moving faster than [`MOVING_SPEED`] now.
pub fn objects_moving(session: &Session) -> u32 {
    session.world().object_poses().iter().filter(|p| p.active && p.linvel.length() > MOVING_SPEED).count() as u32
}

/// Runs one scripted trial with a fresh participant whose habit is
/// `skill`'s, exploiting its priors (the tradeoff benchmark uses this).
pub fn run_scripted(
    scene: &Scene,
    kind: TechniqueKind,
    feedback: bool,
    skill: Skill,
    seed: u64,
    time_limit_s: f64,
) -> Result<TrialOutcome, SessionError> {
    let learner = Learner::new(skill.habit());
    Ok(run_scripted_with(scene, kind, feedback, skill, seed, time_limit_s, learner, PlannerOptions::default(), None)?.0)
}

/// Runs one scripted trial for a participant who has learned `learner` so
/// far; returns what it learned too. Writes every frame to `frames` when
/// given (the study's `--frames` option).
#[allow(clippy::too_many_arguments)]
pub fn run_scripted_with(
    scene: &Scene,
    kind: TechniqueKind,
    feedback: bool,
    skill: Skill,
    seed: u64,
    time_limit_s: f64,
    learner: Learner,
    options: PlannerOptions,
    mut frames: Option<&mut FrameLog>,
) -> Result<(TrialOutcome, Learner), SessionError> {
    let mut session = Session::new(scene, kind, SessionOptions::default())?;
    let mut planner = Planner::new(skill, feedback, seed, learner, options);
    let (mut hands_max, mut fingers_max, mut moving_max) = (0, 0, 0);
    while session.time() < time_limit_s && !session.progress().complete {
        let hands = planner.hands(&session);
        let (n, f) = planner.hands_down();
        hands_max = hands_max.max(n);
        fingers_max = fingers_max.max(f);
        session.step(&hands)?;
        moving_max = moving_max.max(objects_moving(&session));
        if let Some(log) = frames.as_deref_mut() {
            log.record(&session);
        }
    }
    let p = session.progress();
    let (learner, usage) = planner.finish(session.time());
    let outcome = TrialOutcome {
        completion_time_s: p.completed_at.unwrap_or(session.time()),
        completed: p.complete,
        restarts: p.restarts,
        objects_placed: p.placed as u32,
        steps: session.frames(),
        strategy: usage.main(),
        hands_max,
        fingers_max,
        objects_moving_max: moving_max,
        usage,
    };
    Ok((outcome, learner))
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
