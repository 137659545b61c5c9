//! Errors of the render layer.

use std::path::PathBuf;

use crate::render::gpu::GpuError;

#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error(transparent)]
    Gpu(#[from] GpuError),
    /// The caller's draw list is inconsistent (e.g. an overlay whose pixel
    /// count does not match its size, a triangle index out of range).
    #[error("invalid draw list: {0}")]
    InvalidDrawList(String),
    /// Renderer options the device cannot honour.
    #[error("invalid renderer options: {0}")]
    InvalidOptions(String),
    #[error("target size {width}x{height} is not in 1..={max}")]
    TargetSize { width: u32, height: u32, max: u32 },
    /// wgpu reported a validation error (a bug in this module, or a device
    /// lacking something the renderer assumed).
    #[error("GPU validation failed while {during}: {message}")]
    Validation { during: &'static str, message: String },
    #[error("reading the frame back failed: {0}")]
    Readback(String),
    #[error("could not write {}", path.display())]
    Png {
        path: PathBuf,
        #[source]
        source: image::ImageError,
    },
}

impl crate::error::Kind for RenderError {
    /// Only a PNG path that cannot hold a file and a size the device cannot
    /// draw are the user's; the rest is the GPU or this module failing.
    fn kind(&self) -> crate::error::ErrorKind {
        use crate::error::ErrorKind;
        match self {
            RenderError::TargetSize { .. } => ErrorKind::BadInput,
            RenderError::Png { source: image::ImageError::IoError(io), .. } => crate::error::io_kind(io),
            RenderError::Gpu(_)
            | RenderError::InvalidDrawList(_)
            | RenderError::InvalidOptions(_)
            | RenderError::Validation { .. }
            | RenderError::Readback(_)
            | RenderError::Png { .. } => ErrorKind::Runtime,
        }
    }
}
