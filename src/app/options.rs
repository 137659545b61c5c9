//! What the demo is asked to do: the choices the command line validates
//! and hands to the window.

use super::ParticipantOptions;
use crate::input::Gesture;
use crate::pipeline::technique::TechniqueKind;
use std::net::SocketAddr;
use std::path::PathBuf;

/// Window size in logical pixels when none is asked for.
pub const DEFAULT_WINDOW: [u32; 2] = [1280, 800];

/// The demo's validated choices (the CLI builds them from its flags).
#[derive(Debug)]
pub struct DemoOptions {
    /// A scene name under `tasks/` or a path.
    pub task: String,
    pub technique: TechniqueKind,
    pub feedback: bool,
    /// Show the sensed contact image as a hand shadow.
    pub contact_overlay: bool,
    /// Logical pixels.
    pub window_size: [u32; 2],
    /// Listen for TUIO 1.1 on this UDP address.
    pub tuio: Option<SocketAddr>,
    /// A gesture replayed as live input from session time 0.
    pub script: Option<Gesture>,
    /// Camera frames seen in place of hands: recorded (from session time
    /// 0) or live. The window hands it to its lab (the session and its panel state).
    pub camera: Option<crate::input::CameraInput>,
    /// Save what the window shows once this many seconds have passed.
    pub screenshot_after: Option<Screenshot>,
    /// Close after this many seconds (wall clock).
    pub quit_after: Option<f64>,
    pub participant: Option<ParticipantOptions>,
    /// Recordings go to `out_dir/gestures`, screenshots to `out_dir/screenshots`.
    pub out_dir: PathBuf,
    /// At most this many frames per second; `None`: the display's refresh rate.
    pub max_fps: Option<f64>,
    /// Record every touch from the start to this gesture file.
    pub record: Option<PathBuf>,
    /// Write the run report (JSON) of the session here on close.
    pub report: Option<PathBuf>,
}

/// `--screenshot-after SECONDS PATH`.
#[derive(Debug, Clone, PartialEq)]
pub struct Screenshot {
    pub after_s: f64,
    pub path: PathBuf,
}

impl DemoOptions {
    /// The researcher's demo of a task with a technique, nothing else on.
    pub fn new(task: impl Into<String>, technique: TechniqueKind) -> Self {
        Self {
            task: task.into(),
            technique,
            feedback: false,
            contact_overlay: true,
            window_size: DEFAULT_WINDOW,
            tuio: None,
            camera: None,
            script: None,
            screenshot_after: None,
            quit_after: None,
            participant: None,
            out_dir: PathBuf::from("out"),
            max_fps: None,
            record: None,
            report: None,
        }
    }
}
