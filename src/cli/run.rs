//! `surfacelab run`: replay one gesture headless and write a JSON report.

use super::RunArgs;
use crate::input::Gesture;
use crate::scene;
use crate::session::{RunReport, Session, SessionOptions};
use anyhow::Context;
use std::process::ExitCode;
use std::time::Instant;

pub fn run(args: &RunArgs) -> super::CommandResult {
    if let (Some(dir), Some(calibration)) = (&args.images, &args.calibration) {
        return super::run_images::run(args, dir, calibration);
    }
    let Some(gesture_path) = &args.gesture else {
        eprintln!("surfacelab run: give --gesture or --images");
        return Ok(ExitCode::from(super::EXIT_USAGE));
    };
    let scene = scene::load(&args.task)?;
    let gesture = Gesture::load(gesture_path)?;
    let options = SessionOptions { measure_penetration: true, ..SessionOptions::default() };
    let mut session = Session::new(&scene, args.technique, options)?;
    let t0 = Instant::now();
    // The whole gesture, then a short settle so released objects come to rest.
    session.replay_until(&gesture, gesture.duration() + f64::from(args.settle))?;
    let report = RunReport::from_session(
        &session,
        args.feedback,
        &gesture_path.display().to_string(),
        t0.elapsed().as_secs_f64(),
    );
    write_report(&report, args.report.as_deref())
}

/// The report as JSON, to `path` (atomically) or standard output.
pub(super) fn write_report(report: &RunReport, path: Option<&std::path::Path>) -> super::CommandResult {
    let json = serde_json::to_string_pretty(report).context("writing the JSON report")?;
    match path {
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
