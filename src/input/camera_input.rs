//! Camera frames in place of hands, recorded or live: what a session sees
//! when a camera is its input.

use super::camera::{CameraError, CameraFeed};
use super::images::ImageSequence;
use crate::pipeline::surface::{ContactImage, Sensor};
use std::time::Instant;

#[derive(Debug)]
pub enum CameraInput {
    /// A frames folder, timed by session time from 0.
    Recorded(ImageSequence),
    /// A camera, its frames timed by when they arrived.
    Live(CameraFeed),
}

impl CameraInput {
    /// The contact image of the physics step at session time `t` (which
    /// times recorded frames) and instant `at` (which times a live
    /// camera's).
    pub fn image_at(&mut self, t: f64, dt: f64, at: Instant, sensor: &Sensor) -> Result<&ContactImage, CameraError> {
        match self {
            CameraInput::Recorded(frames) => Ok(frames.image_at(t, dt, sensor)?),
            CameraInput::Live(feed) => feed.image_at(at, sensor),
        }
    }
}
