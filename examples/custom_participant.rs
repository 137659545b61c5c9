//! A participant written in Rust: a closed-loop fingertip policy driving a
//! trial through the same loop the study's participants use (`run_trial`).
//!
//! The study's scripted participants choose among a fixed repertoire of
//! manners (docs/extending.md says why it is fixed); a new way of moving is
//! written as a policy like this one: each step it looks at the session and
//! returns the hands on the glass.
//!
//! `cargo run --release --example custom_participant` runs the policy under
//! Joint and Particle, prints each trial's result, and exits 1 unless both
//! placed the puck.

use std::process::ExitCode;
use surfacelab::harness::participant::{TrialStep, run_trial};
use surfacelab::pipeline::surface::{Hand, HandKind};
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::scene::{Effect, SceneBuilder, ShapeSpec};
use surfacelab::session::{Session, SessionOptions};

/// Hand speed while dragging (m/s): an unhurried drag.
const SPEED: f32 = 0.2;
/// How close the puck's centre must come to the target before the finger lifts (m).
const CLOSE: f32 = 0.005;

fn main() -> anyhow::Result<ExitCode> {
    let target = glam::Vec2::new(0.2, 0.1);
    let scene = SceneBuilder::new("one_puck")
        .effects(&[Effect::Gravity, Effect::Friction, Effect::Joints])
        .object("puck", ShapeSpec::Cylinder { radius: 0.04, height: 0.02 }, [-0.1, -0.05], 0.1, "red")
        .positioning_target("puck", target.to_array(), 0.015)
        .build()?;
    let puck = scene.object_id("puck").expect("declared above");

    let mut all_placed = true;
    for technique in [TechniqueKind::JOINT, TechniqueKind::PARTICLE] {
        let mut session = Session::new(&scene, technique, SessionOptions::default())?;
        let dt = session.world().dt();
        // The finger: where it is, and whether it is down.
        let mut finger: Option<glam::Vec2> = None;
        let policy = |s: &Session| {
            let at = s.world().object_pose(puck).position.truncate();
            let error = target - at;
            // Aim past the target by the puck's remaining error (at most 3 cm),
            // so a puck that trails the finger still ends on the target.
            let aim = target + error.clamp_length_max(0.03);
            finger = match finger {
                // Close enough and the finger has arrived: lift, and let the
                // goal's dwell time pass with the puck at rest.
                Some(p) if error.length() < CLOSE && p.distance(aim) < 0.002 => None,
                Some(p) => Some(p + (aim - p).clamp_length_max(SPEED * dt)),
                // Down on the puck's centre while it is off target.
                None if error.length() >= CLOSE => Some(at),
                None => None,
            };
            match finger {
                Some(p) => TrialStep {
                    hands: vec![Hand::new(1, HandKind::Fingertips(1), p.x, p.y)],
                    hands_down: 1,
                    fingers_down: 1,
                },
                None => TrialStep::default(),
            }
        };
        let result = run_trial(&mut session, 20.0, 20.0, policy, None)?;
        println!(
            "{:<9} placed: {:<5} in {:.2} s ({} steps)",
            technique.label(),
            result.completed,
            result.completion_time_s,
            result.steps
        );
        all_placed &= result.completed;
    }
    Ok(if all_placed { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}
