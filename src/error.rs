//! The one thing every layer's errors share: what *kind* of failure they are.
//!
//! Each module keeps its own `thiserror` error type (it knows its files and
//! fields best) and says, through [`Kind`], whether an error is the user's
//! input being wrong or the program failing at run time. The command line
//! picks its exit code from that alone (`cli::Failure`), so a new error type
//! needs no edit there. Messages follow one rule: a variant's text never
//! repeats its `#[source]`; printing the chain (`{:#}` through anyhow, or
//! [`chain`]) shows every cause exactly once.

use std::error::Error;
use std::fmt::Write as _;

/// Whose fault a failure is, which decides the exit code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// A file, field or flag the user gave is wrong (exit 2, like a usage error).
    BadInput,
    /// The input was fine but running failed: the GPU, the disk, a bug (exit 1).
    Runtime,
}

/// Errors at module borders say which [`ErrorKind`] they are.
pub trait Kind {
    fn kind(&self) -> ErrorKind;
}

/// The kind of an I/O failure on a path the user named: a path that does not
/// exist or holds the wrong thing (not UTF-8, a folder where a file should
/// be) is bad input; a file system that refuses (permissions, a full disk)
/// is a run-time failure.
pub fn io_kind(e: &std::io::Error) -> ErrorKind {
    use std::io::ErrorKind as Io;
    match e.kind() {
        // A file that ends early (a truncated frame or file) is bad input too.
        Io::NotFound | Io::InvalidData | Io::UnexpectedEof | Io::IsADirectory | Io::NotADirectory => {
            ErrorKind::BadInput
        }
        _ => ErrorKind::Runtime,
    }
}

/// An error and all its causes on one line, `outer: cause: root`, each said
/// once (what anyhow's `{:#}` prints), for errors shown without anyhow.
pub fn chain(e: &(dyn Error + 'static)) -> String {
    let mut out = e.to_string();
    let mut cause = e.source();
    while let Some(c) = cause {
        let _ = write!(out, ": {c}");
        cause = c.source();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, thiserror::Error)]
    #[error("cannot read notes.toml")]
    struct Outer(#[source] std::io::Error);

    #[test]
    fn chain_names_each_cause_once() {
        let e = Outer(std::io::Error::new(std::io::ErrorKind::NotFound, "no such file"));
        assert_eq!(chain(&e), "cannot read notes.toml: no such file");
    }

    #[test]
    fn missing_or_malformed_files_are_bad_input_and_refusals_are_not() {
        let io = |k| std::io::Error::new(k, "x");
        assert_eq!(io_kind(&io(std::io::ErrorKind::NotFound)), ErrorKind::BadInput);
        assert_eq!(io_kind(&io(std::io::ErrorKind::InvalidData)), ErrorKind::BadInput);
        assert_eq!(io_kind(&io(std::io::ErrorKind::UnexpectedEof)), ErrorKind::BadInput, "a truncated file");
        assert_eq!(io_kind(&io(std::io::ErrorKind::PermissionDenied)), ErrorKind::Runtime);
        assert_eq!(io_kind(&io(std::io::ErrorKind::StorageFull)), ErrorKind::Runtime);
    }
}
