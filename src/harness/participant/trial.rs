//! One trial: an input (a scripted planner, a replayed gesture) drives a
//! session until the goal is met or the time limit ends it as failed (never
//! a hang); [`run_trial`] is that loop for every runner.

use super::learner::Learner;
use super::planner::{Planner, PlannerOptions};
use super::skill::Skill;
use crate::harness::study::TrialResult;
use crate::pipeline::surface::Hand;
use crate::pipeline::technique::TechniqueKind;
use crate::scene::Scene;
pub use crate::session::MOVING_SPEED;
use crate::session::{Session, SessionError, SessionOptions};

/// Objects of the session moving faster than [`MOVING_SPEED`] now (for
/// `objects_moving_max`).
pub fn objects_moving(session: &Session) -> u32 {
    session.objects_moving()
}

/// What the input does on one step of a trial: the hands, and how many
/// hands and fingertips are down (for `hands_max` and `fingers_max`).
#[derive(Debug, Clone, Default)]
pub struct TrialStep {
    pub hands: Vec<Hand>,
    pub hands_down: u32,
    pub fingers_down: u32,
}

/// The one run-until-done loop of every trial: steps `session` with the
/// hands `next` gives until the goal is met or `end_s` of simulated time
/// has passed, then records it against the time limit `limit_s` (see
/// [`TrialResult::from_progress`]) with the per-frame maxima. Writes every
/// frame to `frames` when given (the study's `--frames` option).
pub fn run_trial(
    session: &mut Session,
    end_s: f64,
    limit_s: f64,
    mut next: impl FnMut(&Session) -> TrialStep,
    mut frames: Option<&mut FrameLog>,
) -> Result<TrialResult, SessionError> {
    let (mut hands_max, mut fingers_max, mut moving_max) = (0, 0, 0);
    while session.time() < end_s && !session.progress().complete {
        let step = next(session);
        hands_max = hands_max.max(step.hands_down);
        fingers_max = fingers_max.max(step.fingers_down);
        session.step(&step.hands)?;
        moving_max = moving_max.max(objects_moving(session));
        if let Some(log) = frames.as_deref_mut() {
            log.record(session);
        }
    }
    Ok(TrialResult {
        hands_max,
        fingers_max,
        objects_moving_max: moving_max,
        ..TrialResult::from_progress(&session.progress(), session.frames(), limit_s)
    })
}

/// One scripted trial: the scene, the technique and whether the input is
/// shown, the participant's skill, the seed of its noise and the time limit.
#[derive(Debug, Clone, Copy)]
pub struct ScriptedTrial<'a> {
    pub scene: &'a Scene,
    pub kind: TechniqueKind,
    pub feedback: bool,
    pub skill: Skill,
    pub seed: u64,
    pub time_limit_s: f64,
}

impl ScriptedTrial<'_> {
    /// Runs it with a fresh participant whose habit is the skill's,
    /// exploiting its priors (the tradeoff benchmark uses this).
    pub fn run(&self) -> Result<TrialResult, SessionError> {
        let learner = Learner::new(self.skill.habit());
        Ok(self.run_with(learner, PlannerOptions::default(), None)?.0)
    }

    /// Runs it for a participant who has learned `learner` so far; returns
    /// what it learned too. The result names the manner used for the most
    /// time (`strategy`) and each manner's time and net progress
    /// (`manners`). Writes every frame to `frames` when given.
    pub fn run_with(
        &self,
        learner: Learner,
        options: PlannerOptions,
        frames: Option<&mut FrameLog>,
    ) -> Result<(TrialResult, Learner), SessionError> {
        let mut session = Session::new(self.scene, self.kind, SessionOptions::default())?;
        let mut planner = Planner::new(self.skill, self.feedback, self.seed, learner, options);
        let next = |s: &Session| {
            let hands = planner.hands(s);
            let (hands_down, fingers_down) = planner.hands_down();
            TrialStep { hands, hands_down, fingers_down }
        };
        let result = run_trial(&mut session, self.time_limit_s, self.time_limit_s, next, frames)?;
        let (learner, usage) = planner.finish(session.time());
        let result = TrialResult {
            strategy: usage.main().map(|m| m.name().to_owned()).unwrap_or_default(),
            manners: usage.to_column(),
            ..result
        };
        Ok((result, learner))
    }
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
