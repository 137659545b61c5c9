//! `surfacelab run`: replay one gesture headless and write a JSON report.

use super::RunArgs;
use crate::input::Gesture;
use crate::scene;
use crate::session::{RunReport, Session, SessionOptions};
use anyhow::Context;
use std::process::ExitCode;
use std::time::Instant;

pub fn run(args: &RunArgs) -> super::CommandResult {
    let scene = scene::load(&args.task)?;
    let gesture = Gesture::load(&args.gesture)?;
    let options = SessionOptions { measure_penetration: true, ..SessionOptions::default() };
    let mut session = Session::new(&scene, args.technique, options)?;
    let t0 = Instant::now();
    // The whole gesture, then a short settle so released objects come to rest.
    session.replay_until(&gesture, gesture.duration() + f64::from(args.settle))?;
    let report = RunReport::from_session(
        &session,
        args.feedback,
        &args.gesture.display().to_string(),
        t0.elapsed().as_secs_f64(),
    );
    let json = serde_json::to_string_pretty(&report).context("writing the JSON report")?;
    match &args.report {
        Some(path) => {
            // Atomic: a full disk leaves the earlier report whole, not truncated.
            crate::files::write_atomic(path, (json + "\n").as_bytes())
                .with_context(|| format!("writing report {}", path.display()))?;
            eprintln!(
                "surfacelab run: {} steps, complete: {}, max speed {:.2} m/s, NaN {}; report in {}",
                report.steps,
                report.completion.complete,
                report.max_speed,
                report.nan_count,
                path.display()
            );
        }
        None => println!("{json}"),
    }
    Ok(ExitCode::SUCCESS)
}
