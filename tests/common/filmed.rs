//! A gesture over the one-box case filmed by a synthetic camera: the frames
//! and calibration the camera and image tests play back.

use surfacelab::input::Gesture;
use surfacelab::input::images::{CameraKind, ImageSequence, Synthesizer, write_sequence};
use surfacelab::pipeline::surface::Sensor;
use surfacelab::scene::{self, Scene};
use surfacelab::session::SessionOptions;

/// The scene, the gesture and its filmed frames, read back from a scratch
/// folder that lives as long as this.
pub struct Filmed {
    pub scene: Scene,
    pub gesture: Gesture,
    /// The contact sensor of the default options, over the scene's table.
    pub sensor: Sensor,
    /// The scene's step (s).
    pub dt: f64,
    /// How many frames the camera wrote.
    pub written: usize,
    /// The frames and their calibration.
    pub frames: ImageSequence,
    _dir: tempfile::TempDir,
}

/// Built-in gesture `gesture` over `tasks/cases/one_box.toml`, filmed at
/// 640 × 480 by a synthetic `kind` camera whose noise is seeded by `seed`.
pub fn one_box(gesture: &str, kind: CameraKind, seed: u64) -> Filmed {
    let scene = scene::load(&super::asset("tasks/cases/one_box.toml")).expect("scene");
    let g = Gesture::load(super::asset(&format!("assets/gestures/{gesture}.toml"))).expect("gesture");
    let options = SessionOptions::default();
    let sensor = Sensor::new(options.sensor_px.0, options.sensor_px.1, scene.table.width, scene.table.depth);
    let dir = tempfile::tempdir().expect("dir");
    let synth = Synthesizer::new(kind, &sensor, [640, 480], seed).expect("camera");
    let dt = f64::from(scene.physics.dt);
    let written = write_sequence(&g, &sensor, &options.raster, dt, &synth, dir.path()).expect("frames").frames;
    let frames = ImageSequence::open(dir.path(), &dir.path().join("calibration.toml")).expect("sequence");
    Filmed { scene, gesture: g, sensor, dt, written, frames, _dir: dir }
}
