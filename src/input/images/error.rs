//! Why recorded camera frames or their calibration could not be used. Every
//! variant names the file (or folder) at fault.

use crate::error::{ErrorKind, Kind, io_kind};
use crate::scene::FieldError;

#[derive(Debug, thiserror::Error)]
pub enum ImagesError {
    /// A file or folder that cannot be opened or listed.
    #[error("{path}: cannot read")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    /// A file that is not a PNG the decoder can read (truncated, corrupt,
    /// another format).
    #[error("{path}: not a readable PNG image")]
    Decode {
        path: String,
        #[source]
        source: image::ImageError,
    },
    /// A readable image that does not fit: wrong size, colour, bit depth.
    #[error("{path}: {problem}")]
    Frame { path: String, problem: String },
    /// A folder with nothing to play.
    #[error("{dir}: no frames (no *.png files) in the folder")]
    NoFrames { dir: String },
    /// `frames.csv`: a row that does not parse or does not fit.
    #[error("{path}:{line}: {problem}")]
    FrameList { path: String, line: u64, problem: String },
    /// The calibration file: syntax or a bad value, with its line and field.
    #[error(transparent)]
    Calibration(#[from] FieldError),
    /// Writing an output (a synthetic frame, a calibration file) failed.
    #[error("{path}: cannot write")]
    Write {
        path: String,
        #[source]
        source: std::io::Error,
    },
    /// Encoding an output image failed.
    #[error("{path}: cannot encode the PNG")]
    Encode {
        path: String,
        #[source]
        source: image::ImageError,
    },
}

impl Kind for ImagesError {
    fn kind(&self) -> ErrorKind {
        match self {
            ImagesError::Io { source, .. } => io_kind(source),
            ImagesError::Decode { source: image::ImageError::IoError(e), .. } => io_kind(e),
            ImagesError::Decode { .. }
            | ImagesError::Frame { .. }
            | ImagesError::NoFrames { .. }
            | ImagesError::FrameList { .. }
            | ImagesError::Calibration(_) => ErrorKind::BadInput,
            ImagesError::Write { .. } | ImagesError::Encode { .. } => ErrorKind::Runtime,
        }
    }
}
