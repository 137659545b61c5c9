//! The drags themselves: the design (distances × widths, participants,
//! technique), one trial per cell and participant on a one-puck scene,
//! the rows they give and the files they are written to.

use super::figure;
use super::fit::{FittsFit, index_of_difficulty};
use crate::harness::participant::{Learner, Manner, Planner, PlannerOptions, Repertoire, Skill, TrialStep, run_trial};
use crate::harness::study::trial_seed;
use crate::pipeline::technique::TechniqueKind;
use crate::scene::{Effect, SceneBuilder, SceneError, ShapeSpec};
use crate::session::{Session, SessionError, SessionOptions};
use glam::Vec2;
use serde::{Deserialize, Serialize};

/// `fitts.csv` columns: the first seven are the documented contract; the
/// end point and the repetition follow.
pub const FITTS_COLUMNS: [&str; 9] = [
    "participant",
    "technique",
    "distance_m",
    "width_m",
    "id_bits",
    "movement_s",
    "completed",
    "end_error_m",
    "repetition",
];

/// One trial.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FittsRow {
    pub participant: u32,
    pub technique: TechniqueKind,
    /// Nominal distance from start to target centre (m).
    pub distance_m: f64,
    /// Nominal target width (m): the goal counts the puck's centre within
    /// half of it.
    pub width_m: f64,
    /// `log2(distance / width + 1)`.
    pub id_bits: f64,
    /// From touch-down to the last lift (s); for a trial that did not
    /// complete, until the time limit.
    pub movement_s: f64,
    pub completed: bool,
    /// Where the puck ended along the movement axis, past the target
    /// positive (m).
    pub end_error_m: f64,
    pub repetition: u32,
}

/// The grid and the participants.
#[derive(Debug, Clone, PartialEq)]
pub struct FittsDesign {
    pub technique: TechniqueKind,
    /// Distances (m), 0.05 to 0.6 by default.
    pub distances_m: Vec<f64>,
    /// Target widths (m), 0.005 to 0.04 by default.
    pub widths_m: Vec<f64>,
    pub participants: u32,
    /// Trials per participant and condition; alternate trials run in
    /// opposite directions, as in a reciprocal task.
    pub repetitions: u32,
    /// Skills and noise derive from it, as in a study.
    pub seed: u64,
}

impl Default for FittsDesign {
    fn default() -> Self {
        FittsDesign {
            technique: TechniqueKind::JOINT,
            distances_m: vec![0.05, 0.1, 0.2, 0.4, 0.6],
            widths_m: vec![0.005, 0.01, 0.02, 0.04],
            participants: 6,
            repetitions: 4,
            seed: 2008,
        }
    }
}

/// The longest distance the table (1 m wide, the puck's radius and a margin
/// at each end) allows (m).
pub const MAX_DISTANCE_M: f64 = 0.9;
/// Target widths accepted (m): below 2 mm the goal is finer than the
/// contact image's pixels; above 10 cm it is no target.
pub const WIDTH_RANGE_M: (f64, f64) = (0.002, 0.1);
/// Seconds before a trial counts as failed.
pub const TIME_LIMIT_S: f64 = 30.0;
/// The puck: 3 cm across, as a draughts piece, light.
const PUCK_RADIUS_M: f32 = 0.015;
const PUCK_HEIGHT_M: f32 = 0.01;
const PUCK_MASS_KG: f32 = 0.05;
/// The goal's dwell: the puck must rest this long in the target (s).
const DWELL_S: f32 = 0.5;

/// Why a design cannot run.
#[derive(Debug, thiserror::Error)]
pub enum FittsError {
    #[error("{0}")]
    Design(String),
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Session(#[from] SessionError),
}

impl crate::error::Kind for FittsError {
    fn kind(&self) -> crate::error::ErrorKind {
        match self {
            FittsError::Design(_) => crate::error::ErrorKind::BadInput,
            FittsError::Scene(e) => e.kind(),
            FittsError::Session(e) => e.kind(),
        }
    }
}

impl FittsDesign {
    pub fn validate(&self) -> Result<(), FittsError> {
        let bad = |m: String| Err(FittsError::Design(m));
        if self.distances_m.is_empty() || self.widths_m.is_empty() {
            return bad("give at least one distance and one width".into());
        }
        if let Some(d) = self.distances_m.iter().find(|d| !(d.is_finite() && **d > 0.0 && **d <= MAX_DISTANCE_M)) {
            return bad(format!("distance {d} m is outside (0, {MAX_DISTANCE_M}] m"));
        }
        let (lo, hi) = WIDTH_RANGE_M;
        if let Some(w) = self.widths_m.iter().find(|w| !(w.is_finite() && (lo..=hi).contains(*w))) {
            return bad(format!("width {w} m is outside [{lo}, {hi}] m"));
        }
        if !(1..=crate::scene::bounds::MAX_PARTICIPANTS).contains(&self.participants) {
            return bad(format!("participants must be 1..={}", crate::scene::bounds::MAX_PARTICIPANTS));
        }
        if !(1..=crate::scene::bounds::MAX_REPETITIONS).contains(&self.repetitions) {
            return bad(format!("repetitions must be 1..={}", crate::scene::bounds::MAX_REPETITIONS));
        }
        Ok(())
    }

    /// Every (distance, width) pair, distances outer.
    pub fn conditions(&self) -> Vec<(f64, f64)> {
        self.distances_m.iter().flat_map(|&d| self.widths_m.iter().map(move |&w| (d, w))).collect()
    }
}

/// Runs every trial, `jobs` participants at a time (each participant's
/// trials are deterministic and independent of the others', so the result
/// does not depend on `jobs`); rows in participant, condition, repetition
/// order.
pub fn run(design: &FittsDesign, jobs: usize) -> Result<Vec<FittsRow>, FittsError> {
    design.validate()?;
    let participants: Vec<u32> = (1..=design.participants).collect();
    let per_participant = crate::harness::pool::map_in_order(&participants, jobs, |&p| participant_trials(design, p));
    let mut rows = Vec::new();
    for r in per_participant {
        rows.extend(r?);
    }
    Ok(rows)
}

fn participant_trials(design: &FittsDesign, participant: u32) -> Result<Vec<FittsRow>, FittsError> {
    // The same skill a study draws for this participant and seed.
    let skill = Skill::draw(trial_seed(design.seed, participant, u32::MAX));
    let mut rows = Vec::new();
    let mut index = 0;
    for (d, w) in design.conditions() {
        for repetition in 0..design.repetitions {
            index += 1;
            let seed = trial_seed(design.seed, participant, index);
            rows.push(trial(design.technique, skill, seed, participant, d, w, repetition)?);
        }
    }
    Ok(rows)
}

/// One drag of `distance` to a target `width` wide; odd repetitions run
/// right to left.
fn trial(
    technique: TechniqueKind,
    skill: Skill,
    seed: u64,
    participant: u32,
    distance: f64,
    width: f64,
    repetition: u32,
) -> Result<FittsRow, FittsError> {
    let dir = if repetition.is_multiple_of(2) { 1.0 } else { -1.0 };
    let start = Vec2::new(-(distance as f32) / 2.0 * dir, 0.0);
    let target = Vec2::new(distance as f32 / 2.0 * dir, 0.0);
    let scene = SceneBuilder::new("fitts_drag")
        .effects(&[Effect::Gravity, Effect::Friction, Effect::Sleeping])
        .table_friction(0.3)
        .time_limit(TIME_LIMIT_S as f32)
        .object(
            "puck",
            ShapeSpec::Cylinder { radius: PUCK_RADIUS_M, height: PUCK_HEIGHT_M },
            start.to_array(),
            PUCK_MASS_KG,
            "red",
        )
        .positioning_target("puck", target.to_array(), width as f32 / 2.0)
        .dwell(DWELL_S)
        .build()?;
    let puck = scene.object_id("puck").ok_or_else(|| FittsError::Design("the puck is missing".into()))?;
    let mut session = Session::new(&scene, technique, SessionOptions::default())?;
    let options = PlannerOptions {
        // A drag with one finger: the movement Fitts' law is fitted to.
        repertoire: Repertoire::only(Manner::Fingertips(1)),
        ..PlannerOptions::default()
    };
    let mut planner = Planner::new(skill, true, seed, Learner::new(skill.habit()), options);
    // Touch-down, the last lift while the puck was still on the table, and
    // where the puck lay then. A placed puck leaves the table (the goal
    // removes it), so a lift after that ends nothing.
    let (mut touched, mut lift, mut was_down) = (None::<f64>, None::<(f64, Vec2)>, false);
    let mut last_seen = start;
    let next = |s: &Session| {
        let hands = planner.hands(s);
        let down = !hands.is_empty();
        let pose = s.world().object_pose(puck);
        if down && touched.is_none() {
            touched = Some(s.time());
        }
        if down && !was_down {
            // Touched again: the movement goes on.
            lift = None;
        }
        if pose.active {
            last_seen = pose.position.truncate();
            if was_down && !down {
                lift = Some((s.time(), last_seen));
            }
        }
        was_down = down;
        let (hands_down, fingers_down) = planner.hands_down();
        TrialStep { hands, hands_down, fingers_down }
    };
    let result = run_trial(&mut session, TIME_LIMIT_S, TIME_LIMIT_S, next, None)?;
    // Placed with the finger still down: the movement ended when the puck
    // came to rest in the target, the goal's dwell before it was placed.
    let rested = (result.completion_time_s - f64::from(DWELL_S)).max(0.0);
    let (end_t, end_p) = match lift {
        Some((t, p)) if !result.completed || t <= rested => (t, p),
        _ if result.completed => (rested, last_seen),
        _ => (session.time(), last_seen),
    };
    let movement_s = touched.map_or(session.time(), |t0| (end_t - t0).max(0.0));
    let axis = (target - start).normalize_or_zero();
    Ok(FittsRow {
        participant,
        technique,
        distance_m: distance,
        width_m: width,
        id_bits: index_of_difficulty(distance, width),
        movement_s,
        completed: result.completed && touched.is_some(),
        end_error_m: f64::from((end_p - target).dot(axis)),
        repetition,
    })
}

/// Writes `fitts.csv`, `fitts.json` (the fit) and `fitts.png` into `dir`
/// (created), each atomically.
pub fn write(dir: &std::path::Path, rows: &[FittsRow], fit: &FittsFit) -> anyhow::Result<()> {
    use anyhow::Context;
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let mut w = csv::WriterBuilder::new().has_headers(false).from_writer(Vec::new());
    w.write_record(FITTS_COLUMNS)?;
    for r in rows {
        w.serialize(r)?;
    }
    let csv = w.into_inner().map_err(|e| anyhow::anyhow!("{}", e.error()))?;
    let write = |name: &str, bytes: &[u8]| {
        let path = dir.join(name);
        crate::files::write_output(&path, bytes).with_context(|| format!("writing {}", path.display()))
    };
    write("fitts.csv", &csv)?;
    write("fitts.json", (serde_json::to_string_pretty(fit)? + "\n").as_bytes())?;
    let technique = rows.first().map_or("", |r| r.technique.label());
    let png = figure::png(rows, fit, technique).map_err(|e| anyhow::anyhow!("drawing fitts.png: {e}"))?;
    write("fitts.png", &png)
}
