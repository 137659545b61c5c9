//! Recorded camera frames as input: a vision-based table's infrared camera
//! or a depth camera above the table, calibrated onto the table and
//! rectified into the contact image, which the session then sees as it
//! sees drawn hands (`Session::step_image`).
//!
//! ```text
//! frames folder ─▶ FrameList ─▶ CameraImage ─▶ Rectifier (Calibration: Homography, levels) ─▶ ContactImage
//! ```
//!
//! - [`Calibration`]: the calibration file (format and grey-level rules there).
//! - [`Homography`]: camera pixels to table metres from four point pairs.
//! - [`CameraImage`]: an 8- or 16-bit grey PNG frame.
//! - [`FrameList`]: which frame shows when (name order or `frames.csv`).
//! - [`Rectifier`]: a frame into the contact image.
//! - [`ImageSequence`]: all of it against a session's clock.
//! - [`Synthesizer`]: camera frames made from a gesture, for tests and `synth-images`.

mod calibration;
mod camera_image;
mod error;
mod frames;
mod homography;
mod rectify;
mod sequence;
mod synth;

pub use calibration::{
    Background, Calibration, CameraKind, Conversion, DEFAULT_THRESHOLD, DEFAULT_TOUCH_BAND_MM, FORMAT, MAX_SIDE_PX,
    VERSION,
};
pub use camera_image::{BitDepth, CameraImage, Pixels};
pub use error::ImagesError;
pub use frames::{FRAMES_CSV, FrameList, check_frame, first_frame};
pub use homography::{Homography, convex_in_order};
pub use rectify::Rectifier;
pub use sequence::ImageSequence;
pub use synth::{Synthesizer, Written, write_sequence};
