//! `surfacelab synth-images`: a gesture filmed by a synthetic infrared or
//! depth camera (see `input::images::Synthesizer`), for checking the image
//! path against the gesture it came from.

use super::SynthImagesArgs;
use crate::input::Gesture;
use crate::input::images::{Synthesizer, write_sequence};
use crate::pipeline::surface::Sensor;
use crate::scene;
use crate::session::SessionOptions;
use std::process::ExitCode;

pub fn run(args: &SynthImagesArgs) -> super::CommandResult {
    let scene = scene::load(&args.task)?;
    let gesture = Gesture::load(&args.gesture)?;
    // The sensor and drawing of a default session: the contact image that
    // `run --gesture` sees, which the frames should give back.
    let options = SessionOptions::default();
    let (w, h) = options.sensor_px;
    let sensor = Sensor::new(w, h, scene.table.width, scene.table.depth);
    let synth = Synthesizer::new(args.kind, &sensor, [args.size.0, args.size.1], args.seed)?;
    let written = write_sequence(&gesture, &sensor, &options.raster, f64::from(scene.physics.dt), &synth, &args.out)?;
    eprintln!(
        "surfacelab synth-images: {} {} frames ({:.2} s) and calibration.toml in {}",
        written.frames,
        args.kind.name(),
        written.duration_s,
        args.out.display()
    );
    Ok(ExitCode::SUCCESS)
}
