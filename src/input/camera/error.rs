//! Why a camera could not be used. Every variant names the device, or the
//! frame's format, at fault.

use crate::error::{ErrorKind, Kind, io_kind};
use crate::input::images::ImagesError;

#[derive(Debug, thiserror::Error)]
pub enum CameraError {
    /// This build has no V4L2 capture (the `camera` cargo feature is off).
    #[error(
        "this surfacelab was built without camera capture; build it with `cargo build --release --features camera` \
         (V4L2 through the v4l crate, whose bindings need libclang at build time: apt-get install libclang-dev)"
    )]
    NotBuilt,
    /// The device file cannot be opened (missing, not permitted).
    #[error("{device}: cannot open")]
    Open {
        device: String,
        #[source]
        source: std::io::Error,
    },
    /// Opened, but not something frames can be captured from.
    #[error("{device}: {problem}")]
    Device { device: String, problem: String },
    /// The driver's format cannot be read (see `RawFormat::check`).
    #[error("camera format: {problem}")]
    Format { problem: String },
    /// A delivered buffer smaller than its format needs.
    #[error("a frame of {got} bytes; {format} needs {need}")]
    ShortFrame { got: usize, need: usize, format: String },
    /// Capturing failed after it started (unplugged, driver error).
    #[error("{device}: capture failed")]
    Capture {
        device: String,
        #[source]
        source: std::io::Error,
    },
    /// The stream ended: no more frames will come.
    #[error("{device}: the camera stopped delivering frames")]
    Stopped { device: String },
    /// The calibration does not fit what the camera delivers.
    #[error("{device}: {problem}")]
    Mismatch { device: String, problem: String },
    /// Recorded frames that cannot be used, or a calibration made for the
    /// camera's first frame that was refused.
    #[error(transparent)]
    Images(#[from] ImagesError),
}

impl Kind for CameraError {
    fn kind(&self) -> ErrorKind {
        match self {
            CameraError::NotBuilt | CameraError::Device { .. } | CameraError::Mismatch { .. } => ErrorKind::BadInput,
            CameraError::Open { source, .. } => io_kind(source),
            CameraError::Images(e) => e.kind(),
            CameraError::Format { .. }
            | CameraError::ShortFrame { .. }
            | CameraError::Capture { .. }
            | CameraError::Stopped { .. } => ErrorKind::Runtime,
        }
    }
}
