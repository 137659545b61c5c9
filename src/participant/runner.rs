//! The study's trial runners: scripted participants and replayed recordings.
//! The harness (`crate::study`) calls these once per trial.

use super::Skill;
use crate::scene;
use crate::session::{Session, SessionOptions};
use crate::study::{StudyDesign, Technique, TrialResult, TrialRunner, TrialSpec, trial_seed};
use crate::surface::Gesture;
use crate::technique::TechniqueKind;
use anyhow::Context;
use std::path::{Path, PathBuf};

/// Maps the harness's technique names onto the techniques.
pub fn technique_kind(t: Technique) -> TechniqueKind {
    match t {
        Technique::Direct => TechniqueKind::Direct,
        Technique::Joint => TechniqueKind::Joint,
        Technique::Proxy => TechniqueKind::Proxy,
        Technique::Particle => TechniqueKind::Particle,
        Technique::Hybrid => TechniqueKind::Hybrid,
    }
}

/// The skill of one participant: fixed for all their trials.
pub fn participant_skill(design: &StudyDesign, participant: u32) -> Skill {
    Skill::draw(trial_seed(design.seed, participant, u32::MAX))
}

/// Scripted participants: the closed-loop planner, one per trial.
#[derive(Debug, Clone)]
pub struct ScriptedRunner {
    pub design: StudyDesign,
    /// Write every trial's frames here (`--frames`), one CSV per trial.
    pub frames_dir: Option<PathBuf>,
}

impl TrialRunner for ScriptedRunner {
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        let scene = scene::load(&spec.task)?;
        let limit = self.design.time_limit_override.unwrap_or(f64::from(scene.time_limit_s));
        let skill = participant_skill(&self.design, spec.participant);
        let mut log = match &self.frames_dir {
            Some(dir) => {
                std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
                let path = dir.join(format!("p{}_t{}.csv", spec.participant, spec.order_index));
                Some(super::FrameLog::create(&path).with_context(|| format!("writing {}", path.display()))?)
            }
            None => None,
        };
        let o = super::run_scripted_logged(
            &scene,
            technique_kind(spec.technique),
            spec.feedback,
            skill,
            spec.seed,
            limit,
            log.as_mut(),
        )?;
        if let Some(log) = log {
            log.finish().context("writing the trial's frames")?;
        }
        Ok(TrialResult {
            // A trial the limit ended is recorded at the limit (the loop
            // stops up to one step past it).
            completion_time_s: if o.completed { o.completion_time_s } else { limit },
            completed: o.completed,
            restarts: o.restarts,
            objects_placed: o.objects_placed,
            steps: o.steps,
        })
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
        let mut session = Session::new(&scene, technique_kind(spec.technique), SessionOptions::default())?;
        while session.time() < end && !session.progress().complete {
            let hands = gesture.sample(session.time());
            session.step(&hands)?;
        }
        let p = session.progress();
        Ok(TrialResult {
            // Not done when the gesture (plus 2 s) ran out: nothing more will
            // happen, so the trial is failed and recorded at the time limit,
            // as a scripted one is, not at the gesture's end.
            completion_time_s: p.completed_at.filter(|_| p.complete).unwrap_or(limit),
            completed: p.complete,
            restarts: p.restarts,
            objects_placed: p.placed as u32,
            steps: session.frames(),
        })
    }
}
