//! The study's trial runners: scripted participants and replayed recordings.
//! The harness (`crate::harness::study`) calls these once per trial.

use super::Skill;
use super::learner::{EXPLORE_MEASURED, EXPLORE_PRACTICE, Learner};
use super::manner::fingers;
use super::planner::PlannerOptions;
use super::trial::{TrialStep, run_trial};
use crate::harness::study::{ParticipantRun, StudyDesign, TrialResult, TrialRunner, TrialSpec, trial_seed};
use crate::input::Gesture;
use crate::pipeline::technique::TechniqueKind;
use crate::scene;
use crate::session::{Session, SessionOptions};
use anyhow::Context;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The skill of one participant: fixed for all their trials.
pub fn participant_skill(design: &StudyDesign, participant: u32) -> Skill {
    Skill::draw(trial_seed(design.seed, participant, u32::MAX))
}

/// Scripted participants: the closed-loop planner with a learner that
/// carries from trial to trial within a participant.
#[derive(Debug, Clone)]
pub struct ScriptedRunner {
    pub design: StudyDesign,
    /// Write every trial's frames here (`--frames`), one CSV per trial.
    pub frames_dir: Option<PathBuf>,
    /// Techniques run under another study label (`label -> technique`);
    /// labels not listed run their own technique. The guard against tuning
    /// registers one technique under two labels.
    pub relabel: BTreeMap<TechniqueKind, TechniqueKind>,
}

impl ScriptedRunner {
    pub fn new(design: StudyDesign, frames_dir: Option<PathBuf>) -> ScriptedRunner {
        ScriptedRunner { design, frames_dir, relabel: BTreeMap::new() }
    }

    fn kind(&self, t: TechniqueKind) -> TechniqueKind {
        self.relabel.get(&t).copied().unwrap_or(t)
    }

    /// The manners the design allows (`[design.settings] manners`); absent =
    /// the full repertoire.
    fn repertoire(&self) -> anyhow::Result<super::Repertoire> {
        match &self.design.settings.manners {
            None => Ok(super::Repertoire::FULL),
            Some(spec) => Ok(super::Repertoire::parse(spec)?),
        }
    }

    /// The perception-delay setting; absent = 0, the paper's definition.
    fn perception_delay_s(&self) -> f32 {
        self.design.settings.perception_delay_s.unwrap_or(0.0) as f32
    }

    fn session(&self, participant: u32) -> ScriptedParticipant<'_> {
        let skill = participant_skill(&self.design, participant);
        ScriptedParticipant { runner: self, skill, learner: Learner::new(skill.habit()) }
    }
}

impl TrialRunner for ScriptedRunner {
    /// Brings a fresh participant up to this trial by re-running their
    /// earlier trials of the design, then runs it.
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        let mut p = self.session(spec.participant);
        for earlier in self
            .design
            .trials()
            .iter()
            .filter(|t| t.participant == spec.participant && t.order_index < spec.order_index)
        {
            p.replay(earlier)?;
        }
        p.run(spec)
    }

    fn participant(&self, participant: u32) -> Box<dyn ParticipantRun + '_> {
        Box::new(self.session(participant))
    }
}

/// One scripted participant's session: their skill and what they learned.
struct ScriptedParticipant<'a> {
    runner: &'a ScriptedRunner,
    skill: Skill,
    learner: Learner,
}

impl ScriptedParticipant<'_> {
    fn trial(&mut self, spec: &TrialSpec, log_frames: bool) -> anyhow::Result<TrialResult> {
        let runner = self.runner;
        let scene = scene::load(&spec.task)?;
        let limit = runner.design.time_limit_override.unwrap_or(f64::from(scene.time_limit_s));
        let mut log = match runner.frames_dir.as_ref().filter(|_| log_frames) {
            Some(dir) => {
                std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
                let path = dir.join(format!("p{}_t{}.csv", spec.participant, spec.order_index));
                Some(super::FrameLog::create(&path).with_context(|| format!("writing {}", path.display()))?)
            }
            None => None,
        };
        let options = PlannerOptions {
            explore: if spec.practice { EXPLORE_PRACTICE } else { EXPLORE_MEASURED },
            perception_delay_s: runner.perception_delay_s(),
            repertoire: runner.repertoire()?,
        };
        let trial = super::ScriptedTrial {
            scene: &scene,
            kind: runner.kind(spec.technique),
            feedback: spec.feedback,
            skill: self.skill,
            seed: spec.seed,
            time_limit_s: limit,
        };
        let (result, learner) = trial.run_with(self.learner.clone(), options, log.as_mut())?;
        self.learner = learner;
        if let Some(log) = log {
            log.finish().context("writing the trial's frames")?;
        }
        Ok(result)
    }
}

impl ParticipantRun for ScriptedParticipant<'_> {
    fn run(&mut self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        self.trial(spec, true)
    }

    fn replay(&mut self, spec: &TrialSpec) -> anyhow::Result<()> {
        self.trial(spec, false).map(|_| ())
    }
}

/// Replayed participants: gesture files recorded in the demo.
///
/// For each trial the most specific file that exists is used:
/// `DIR/p<participant>/<task>_<technique>_<on|off>_r<repetition>.toml`, then
/// `DIR/p<participant>/<task>.toml`, then `DIR/<task>.toml`. The gesture is
/// replayed until the goal is met, the time limit passes, or two seconds
/// after the gesture ends; a trial not done by then is failed and recorded
/// at the time limit.
#[derive(Debug, Clone)]
pub struct ReplayRunner {
    pub dir: PathBuf,
    pub design: StudyDesign,
}

impl ReplayRunner {
    fn gesture_path(&self, spec: &TrialSpec) -> anyhow::Result<PathBuf> {
        let task = Path::new(&spec.task).file_stem().map_or(spec.task.clone(), |s| s.to_string_lossy().into_owned());
        let p = self.dir.join(format!("p{}", spec.participant));
        let fb = if spec.feedback { "on" } else { "off" };
        let candidates = [
            p.join(format!("{task}_{}_{fb}_r{}.toml", spec.technique, spec.repetition)),
            p.join(format!("{task}.toml")),
            self.dir.join(format!("{task}.toml")),
        ];
        candidates.iter().find(|c| c.is_file()).cloned().with_context(|| {
            format!(
                "no gesture for this trial; looked for {}",
                candidates.iter().map(|c| c.display().to_string()).collect::<Vec<_>>().join(", ")
            )
        })
    }
}

impl TrialRunner for ReplayRunner {
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        let scene = scene::load(&spec.task)?;
        let gesture = Gesture::load(self.gesture_path(spec)?)?;
        let limit = self.design.time_limit_override.unwrap_or(f64::from(scene.time_limit_s));
        let end = limit.min(gesture.duration() + 2.0);
        let mut session = Session::new(&scene, spec.technique, SessionOptions::default())?;
        let next = |s: &Session| {
            let hands = gesture.sample(s.time());
            let down: Vec<_> = hands.iter().filter(|h| h.pressure > 0.0).collect();
            let (hands_down, fingers_down) = (down.len() as u32, down.iter().map(|h| fingers(h.kind)).sum());
            TrialStep { hands, hands_down, fingers_down }
        };
        // Not done when the gesture (plus 2 s) ran out: nothing more will
        // happen, so the trial is failed and recorded at the time limit, as
        // a scripted one is, not at the gesture's end.
        Ok(run_trial(&mut session, end, limit, next, None)?)
    }
}
