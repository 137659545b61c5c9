//! A command's results on standard output, where a failed write is a
//! run-time failure and not a panic.

use super::Failure;

/// `print!` for a command's results: a write that fails (EPIPE once the
/// reader of a pipe has gone, ENOSPC) is a run-time [`Failure`] naming
/// standard output, returned with `?`, where `print!` would panic.
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        write!(std::io::stdout().lock(), $($arg)*).map_err($crate::cli::stdout::stdout_failure)
    }};
}

/// `println!` for a command's results; see [`out!`].
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout().lock(), $($arg)*).map_err($crate::cli::stdout::stdout_failure)
    }};
}

/// A failed write to standard output, as the run-time failure it is.
pub(super) fn stdout_failure(e: std::io::Error) -> Failure {
    Failure::from(anyhow::Error::new(e).context("writing standard output"))
}
