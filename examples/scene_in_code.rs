//! A scene built in Rust (no TOML), a gesture replayed on it, and the run
//! report printed: what `surfacelab run` does, from a program.
//!
//! `cargo run --release --example scene_in_code` prints the report as JSON
//! and exits 1 unless the fingertip carried the puck at least 5 cm.

use std::process::ExitCode;
use surfacelab::input::Gesture;
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::scene::{Effect, SceneBuilder, ShapeSpec};
use surfacelab::session::{RunReport, Session, SessionOptions};

fn main() -> anyhow::Result<ExitCode> {
    // A puck where the built-in `fingertip_drag` gesture lands (5 cm left of
    // centre), with a target 10 cm to its right, where the drag ends.
    let scene = SceneBuilder::new("puck")
        .effects(&[Effect::Gravity, Effect::Friction])
        .table(1.0, 0.75)
        .object("puck", ShapeSpec::Cylinder { radius: 0.05, height: 0.02 }, [-0.05, 0.0], 0.1, "purple")
        .positioning_target("puck", [0.05, 0.0], 0.02)
        .build()?;
    // A gesture by its built-in name resolves without a checkout.
    let gesture = Gesture::load("assets/gestures/fingertip_drag.toml")?;

    let mut session = Session::new(&scene, TechniqueKind::PARTICLE, SessionOptions::default())?;
    let t0 = std::time::Instant::now();
    session.replay_until(&gesture, gesture.duration() + 1.0)?;
    let report = RunReport::from_session(&session, false, "fingertip_drag", t0.elapsed().as_secs_f64());
    println!("{}", serde_json::to_string_pretty(&report)?);

    let puck = &report.objects[0];
    let moved = (puck.position[0] - puck.start_position[0]).hypot(puck.position[1] - puck.start_position[1]);
    println!("puck moved {:.1} cm; goal complete: {}", moved * 100.0, report.completion.complete);
    Ok(if moved >= 0.05 && report.nan_count == 0 { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}
