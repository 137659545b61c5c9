//! How a failed command reaches the user: one line naming every cause once,
//! and the exit code the error's [`ErrorKind`] picks.

use crate::error::{ErrorKind, Kind};
use std::fmt;
use std::process::ExitCode;

/// Exit code for bad input and for features that have not landed yet.
pub const EXIT_USAGE: u8 = 2;

/// What a subcommand returns.
pub type CommandResult = Result<ExitCode, Failure>;

/// A subcommand's error with its kind, decided where the error was made
/// (each module's [`Kind`]), not guessed here.
#[derive(Debug)]
pub struct Failure {
    kind: ErrorKind,
    error: anyhow::Error,
}

impl Failure {
    /// A flag's value that cannot be used, found only once the command runs.
    pub fn bad_input(error: impl Into<anyhow::Error>) -> Self {
        Self { kind: ErrorKind::BadInput, error: error.into() }
    }

    /// Says which flag or step the error belongs to; the kind stays.
    #[must_use]
    pub fn context(self, context: impl fmt::Display + Send + Sync + 'static) -> Self {
        Self { kind: self.kind, error: self.error.context(context) }
    }

    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    pub fn exit_code(&self) -> ExitCode {
        match self.kind {
            ErrorKind::BadInput => ExitCode::from(EXIT_USAGE),
            ErrorKind::Runtime => ExitCode::FAILURE,
        }
    }
}

/// The message and each cause once: `outer: cause: root`.
impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:#}", self.error)
    }
}

/// Every module error that knows its kind converts with `?`.
impl<E: Kind + std::error::Error + Send + Sync + 'static> From<E> for Failure {
    fn from(e: E) -> Self {
        Self { kind: e.kind(), error: anyhow::Error::new(e) }
    }
}

/// What no module classified (an I/O error with its context, a plot
/// backend's error) is a run-time failure.
impl From<anyhow::Error> for Failure {
    fn from(error: anyhow::Error) -> Self {
        Self { kind: ErrorKind::Runtime, error }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::SceneError;

    #[test]
    fn the_kind_comes_from_the_module_and_survives_context() {
        let bad: Failure = SceneError::NotFound { name: "nope".into(), tried: "tasks/nope.toml".into() }.into();
        let bad = bad.context("--tasks: task `nope`");
        assert_eq!(bad.kind(), ErrorKind::BadInput);
        assert_eq!(bad.to_string(), "--tasks: task `nope`: no scene named `nope`: looked for tasks/nope.toml");
        let io = std::io::Error::new(std::io::ErrorKind::PermissionDenied, "denied");
        let runtime: Failure = anyhow::Error::new(io).context("writing report r.json").into();
        assert_eq!(runtime.kind(), ErrorKind::Runtime);
        assert_eq!(runtime.to_string(), "writing report r.json: denied");
    }

    #[test]
    fn a_source_is_printed_once() {
        let source = std::io::Error::new(std::io::ErrorKind::InvalidData, "stream did not contain valid UTF-8");
        let e: Failure = SceneError::Io { path: "bad.toml".into(), source }.into();
        assert_eq!(e.to_string(), "cannot read scene file bad.toml: stream did not contain valid UTF-8");
        assert_eq!(e.kind(), ErrorKind::BadInput);
    }
}
