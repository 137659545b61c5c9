//! Knobs of the surface → vision → technique → world pipeline, each swept
//! on one fixed input (a flat hand sweeping over a box, Particle technique:
//! the paper's most resolution-hungry condition) and compared against a
//! high-accuracy reference run of the same input.
//!
//! The input has one object on purpose. With two hands gathering the
//! eleven sorting objects, objects colliding with each other make the
//! outcome chaotic: moving the particle radius by 0.1 µm moves an object by
//! centimetres, so errors are not monotone in any knob and defaults fall
//! off their fronts by noise. A hand dragging and pushing one box diverges
//! smoothly (`tests/techniques.rs`).

use super::row::Row;
use crate::harness::participant::{ScriptedTrial, Skill};
use crate::input::Gesture;
use crate::pipeline::technique::{TechniqueConfig, TechniqueKind};
use crate::pipeline::vision::VisionParams;
use crate::scene::{self, Scene};
use crate::session::{Session, SessionOptions};
use glam::Vec3;

/// The scene and gesture every knob is measured on.
pub const FIXTURE_SCENE: &str = "cases/one_box";
pub const FIXTURE_GESTURE: &str = "assets/gestures/flat_hand_sweep.toml";

/// Object positions sampled at this rate, so runs at different timesteps compare.
const SAMPLE_HZ: f64 = 30.0;

/// One setting of the pipeline.
#[derive(Debug, Clone)]
pub struct Setup {
    pub scene: Scene,
    pub options: SessionOptions,
    pub kind: TechniqueKind,
}

/// What one replay produced.
#[derive(Debug, Clone)]
pub struct Replay {
    /// Median over repeats of the mean time per frame (µs), all stages.
    pub frame_us: f64,
    /// Object positions at `SAMPLE_HZ`.
    pub track: Vec<Vec<Vec3>>,
}

fn replay_once(setup: &Setup, gesture: &Gesture, settle: f64) -> anyhow::Result<Replay> {
    let mut s = Session::new(&setup.scene, setup.kind, setup.options.clone())?;
    let end = gesture.duration() + settle;
    let mut track = Vec::new();
    let mut next_sample = 0.0;
    while s.time() < end {
        let hands = gesture.sample(s.time());
        s.step(&hands)?;
        if s.time() + 1e-9 >= next_sample {
            track.push(s.world().object_poses().iter().map(|p| p.position).collect());
            next_sample += 1.0 / SAMPLE_HZ;
        }
    }
    Ok(Replay { frame_us: s.mean_times().total_us(), track })
}

/// Replays `repeats` times (timing median; the track is deterministic).
pub fn replay(setup: &Setup, gesture: &Gesture, settle: f64, repeats: usize) -> anyhow::Result<Replay> {
    let mut runs = Vec::new();
    for _ in 0..repeats.max(1) {
        runs.push(replay_once(setup, gesture, settle)?);
    }
    let mut times: Vec<f64> = runs.iter().map(|r| r.frame_us).collect();
    times.sort_by(f64::total_cmp);
    let mut r = runs.swap_remove(0);
    r.frame_us = times[times.len() / 2];
    Ok(r)
}

/// Mean distance (cm) between two runs' objects over the common samples.
pub fn deviation_cm(a: &Replay, b: &Replay) -> f64 {
    let n = a.track.len().min(b.track.len());
    let mut sum = 0.0;
    let mut count = 0usize;
    for k in 0..n {
        for (p, q) in a.track[k].iter().zip(&b.track[k]) {
            sum += f64::from((*p - *q).length());
            count += 1;
        }
    }
    if count == 0 { 0.0 } else { sum / count as f64 * 100.0 }
}

/// A knob: its name, and the settings to try as (label, is default, setup).
pub struct Knob {
    pub name: &'static str,
    pub reference: Setup,
    pub values: Vec<(String, bool, Setup)>,
    /// Also time a scripted positioning trial (physics knobs only).
    pub scripted: bool,
}

impl Knob {
    /// A knob swept over `values`, each labelled by its value and set up by
    /// `setup`, against the setup at `reference`.
    fn sweep<T: Copy + std::fmt::Display>(
        name: &'static str,
        reference: T,
        values: &[T],
        is_default: impl Fn(T) -> bool,
        setup: impl Fn(T) -> Setup,
    ) -> Self {
        Knob {
            name,
            reference: setup(reference),
            values: values.iter().map(|&v| (v.to_string(), is_default(v), setup(v))).collect(),
            scripted: false,
        }
    }

    /// Also times a scripted positioning trial at each value.
    fn scripted(self, scripted: bool) -> Self {
        Knob { scripted, ..self }
    }
}

/// A sensor resolution, labelled `WxH`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Pixels(u32, u32);

impl std::fmt::Display for Pixels {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}x{}", self.0, self.1)
    }
}

fn base() -> anyhow::Result<Setup> {
    Ok(Setup { scene: scene::load(FIXTURE_SCENE)?, options: SessionOptions::default(), kind: TechniqueKind::PARTICLE })
}

fn with_config(mut s: Setup, f: impl FnOnce(&mut TechniqueConfig)) -> Setup {
    let mut c = s.options.config.clone().unwrap_or_else(|| TechniqueConfig::from_scene(&s.scene).unwrap_or_default());
    f(&mut c);
    s.options.config = Some(c);
    s
}

fn with_vision(mut s: Setup, f: impl FnOnce(&mut VisionParams)) -> Setup {
    f(&mut s.options.vision);
    s
}

/// Every pipeline knob. `quick` trims the value lists.
pub fn knobs(quick: bool) -> anyhow::Result<Vec<Knob>> {
    let b = base()?;
    let mut out = sensing_knobs(&b, quick);
    out.extend(physics_knobs(&b, quick));
    out.extend(switch_knobs(&b));
    Ok(out)
}

/// The knobs of the camera and the vision stage: resolution, outline
/// stride and threshold, flow block and search radius.
fn sensing_knobs(b: &Setup, quick: bool) -> Vec<Knob> {
    let defaults = TechniqueConfig::default();
    let dv = VisionParams::default();
    let res: &[Pixels] = if quick {
        &[Pixels(160, 120), Pixels(320, 240), Pixels(640, 480), Pixels(960, 720)]
    } else {
        &[Pixels(160, 120), Pixels(320, 240), Pixels(480, 360), Pixels(640, 480), Pixels(960, 720)]
    };
    let resolution =
        |Pixels(w, h)| Setup { options: SessionOptions { sensor_px: (w, h), ..b.options.clone() }, ..b.clone() };
    let strides: &[usize] = if quick { &[1, 2, 3, 6] } else { &[1, 2, 3, 4, 6, 8] };
    let stride = |n| with_config(b.clone(), |c| c.particle_stride = n);
    let thresholds: &[f32] = if quick { &[6.0, 12.0, 24.0, 48.0] } else { &[4.0, 6.0, 12.0, 24.0, 36.0, 48.0] };
    let threshold = |t| with_config(b.clone(), |c| c.particle_edge_threshold = t);
    let blocks: &[usize] = if quick { &[3, 5, 7, 11] } else { &[3, 5, 7, 9, 11, 15] };
    let block = |n| with_vision(b.clone(), |v| v.block_size = n);
    let radii: &[usize] = if quick { &[1, 2, 3, 5] } else { &[1, 2, 3, 4, 6, 8] };
    let radius = |n| with_vision(b.clone(), |v| v.search_radius = n);
    vec![
        Knob::sweep("resolution", Pixels(1280, 960), res, |p| p == Pixels(640, 480), resolution),
        Knob::sweep("particle_stride", 1, strides, |n| n == defaults.particle_stride, stride),
        Knob::sweep("edge_threshold", 4.0, thresholds, |t| t == defaults.particle_edge_threshold, threshold),
        Knob::sweep("flow_block", 15, blocks, |n| n == dv.block_size, block),
        Knob::sweep("flow_radius", 8, radii, |n| n == dv.search_radius, radius),
    ]
}

/// The knobs of the physics step: solver and PGS iterations, timestep.
fn physics_knobs(b: &Setup, quick: bool) -> Vec<Knob> {
    let dp = b.scene.physics;
    let with_physics = |set: &dyn Fn(&mut scene::PhysicsSpec)| {
        let mut s = b.clone();
        set(&mut s.scene.physics);
        s
    };
    let iters: &[usize] = if quick { &[1, 2, 4, 8] } else { &[1, 2, 4, 8, 16] };
    let solver = |n| with_physics(&|p| p.solver_iterations = n);
    let pgs = |n| with_physics(&|p| p.pgs_iterations = n);
    let rates: &[f32] = if quick { &[30.0, 60.0, 120.0] } else { &[30.0, 60.0, 90.0, 120.0, 240.0] };
    let rate = |hz: f32| with_physics(&|p| p.dt = 1.0 / hz);
    vec![
        Knob::sweep("solver_iterations", 32, iters, |n| n == dp.solver_iterations, solver).scripted(!quick),
        Knob::sweep("pgs_iterations", 8, &[1, 2, 4], |n| n == dp.pgs_iterations, pgs),
        Knob::sweep("timestep_hz", 480.0, rates, |hz: f32| (1.0 / hz - dp.dt).abs() < 1e-6, rate).scripted(!quick),
    ]
}

/// Switches whose "off" is the paper's way, which is also the reference.
fn switch_knobs(b: &Setup) -> Vec<Knob> {
    let defaults = TechniqueConfig::default();
    let switch = |name, labels: [&str; 2], default: bool, set: fn(&mut TechniqueConfig, bool)| Knob {
        name,
        reference: with_config(b.clone(), |c| set(c, false)),
        values: [false, true]
            .iter()
            .map(|&on| (labels[usize::from(on)].to_string(), on == default, with_config(b.clone(), |c| set(c, on))))
            .collect(),
        scripted: false,
    };
    vec![
        switch("particle_pooling", ["per_frame", "pooled"], defaults.particle_pooled, |c, on| {
            c.particle_pooled = on;
        }),
        switch("particle_cull", ["off", "on"], defaults.particle_cull, |c, on| c.particle_cull = on),
    ]
}

/// Completion time of one scripted positioning trial under a setup's physics.
pub fn scripted_trial_s(setup: &Setup) -> anyhow::Result<f64> {
    let mut scene = scene::load("positioning")?;
    scene.physics = setup.scene.physics;
    let trial = ScriptedTrial {
        scene: &scene,
        kind: TechniqueKind::JOINT,
        feedback: true,
        skill: Skill::draw(1),
        seed: 1,
        time_limit_s: 120.0,
    };
    let o = trial.run()?;
    Ok(o.completion_time_s)
}

/// Measures one knob: every value against the reference.
pub fn measure(knob: &Knob, gesture: &Gesture, repeats: usize, mut progress: impl FnMut()) -> anyhow::Result<Vec<Row>> {
    let reference = replay(&knob.reference, gesture, 1.0, 1)?;
    let ref_trial = if knob.scripted { Some(scripted_trial_s(&knob.reference)?) } else { None };
    let mut rows = Vec::new();
    for (label, default, setup) in &knob.values {
        let r = replay(setup, gesture, 1.0, repeats)?;
        let mut row = Row::new(
            knob.name,
            label.clone(),
            *default,
            r.frame_us,
            "us/frame",
            deviation_cm(&r, &reference),
            "cm",
            "high-accuracy run",
        );
        if let Some(t_ref) = ref_trial {
            let t = scripted_trial_s(setup)?;
            row.trial_time_diff_s = Some((t - t_ref).abs());
        }
        rows.push(row);
        progress();
    }
    Ok(rows)
}
