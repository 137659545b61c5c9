//! Scene errors: each names the file, and where it can, the line and the field.

use std::path::PathBuf;

#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("cannot read scene file {}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// Syntax errors, unknown fields, unknown shapes/effects, missing fields
    /// and wrong types; and values that parse but make no sense (negative
    /// mass, target off the table, ...): file, line and field.
    #[error(transparent)]
    Field(#[from] super::fields::FieldError),
    #[error("no scene named `{name}`: looked for {tried}")]
    NotFound { name: String, tried: String },
}

impl crate::error::Kind for SceneError {
    /// A scene that is missing or malformed is bad input; a file the
    /// system refuses to read is a run-time failure.
    fn kind(&self) -> crate::error::ErrorKind {
        match self {
            SceneError::Io { source, .. } => crate::error::io_kind(source),
            SceneError::Field(_) | SceneError::NotFound { .. } => crate::error::ErrorKind::BadInput,
        }
    }
}
