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
    /// and wrong types: toml's own message already carries line, column and field.
    #[error("{origin}: {message}")]
    Parse { origin: String, message: String },
    /// A value that parses but makes no sense (negative mass, target off the table, ...).
    #[error("{origin}:{line}: field `{field}`: {message}")]
    Invalid { origin: String, line: usize, field: String, message: String },
    #[error("no scene named `{name}`: looked for {tried}")]
    NotFound { name: String, tried: String },
}

impl crate::error::Kind for SceneError {
    /// A scene that is missing or malformed is bad input; a file the
    /// system refuses to read is a run-time failure.
    fn kind(&self) -> crate::error::ErrorKind {
        match self {
            SceneError::Io { source, .. } => crate::error::io_kind(source),
            SceneError::Parse { .. } | SceneError::Invalid { .. } | SceneError::NotFound { .. } => {
                crate::error::ErrorKind::BadInput
            }
        }
    }
}
