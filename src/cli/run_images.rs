//! `surfacelab run --images DIR --calibration FILE`: a recorded camera
//! sequence played headless, one frame per physics step, and the same JSON
//! report as a gesture replay (its `gesture` field names the folder).

use super::RunArgs;
use crate::input::images::ImageSequence;
use crate::pipeline::technique::TechniqueKind;
use crate::scene;
use crate::session::{RunReport, Session, SessionOptions};
use std::path::Path;
use std::time::Instant;

/// Plays the frames in `dir` through the `--task` scene and reports.
pub fn play(
    args: &RunArgs,
    task: &str,
    technique: TechniqueKind,
    dir: &Path,
    calibration: &Path,
) -> Result<RunReport, super::Failure> {
    let scene = scene::load(task)?;
    // Every frame's header is checked here, before the first step.
    let mut frames = ImageSequence::open(dir, calibration)?;
    let options = SessionOptions { measure_penetration: true, ..SessionOptions::default() };
    let mut session = Session::new(&scene, technique, options)?;
    let dt = f64::from(session.world().dt());
    let sensor = *session.sensor();
    let t0 = Instant::now();
    // The whole sequence, then a short settle (an empty table) so released
    // objects come to rest: the steps a gesture of the same length gets.
    let until = frames.duration(dt) + f64::from(args.settle);
    while session.time() + 0.5 * dt < until {
        let image = frames.image_at(session.time(), dt, &sensor)?;
        session.step_image(image)?;
    }
    Ok(RunReport::from_session(&session, args.feedback, &dir.display().to_string(), t0.elapsed().as_secs_f64()))
}
