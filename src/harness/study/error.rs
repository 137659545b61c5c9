//! The study layer's error: which file, and what was wrong with it.
//!
//! A failing *trial* is not an error here: it is recorded as a row (not
//! completed, no time) and logged, and the study goes on.

use std::path::{Path, PathBuf};

#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// The design cannot be run as given (no participants, duplicate technique, ...).
    #[error("invalid study design: {0}")]
    Design(String),
    /// The path alone: the I/O error, its source, follows when the chain is printed.
    #[error("{}", path.display())]
    Io { path: PathBuf, source: std::io::Error },
    #[error("{}", path.display())]
    Csv { path: PathBuf, source: csv::Error },
    #[error("{}", path.display())]
    TomlRead { path: PathBuf, source: toml::de::Error },
    #[error("cannot write the run file")]
    TomlWrite(#[from] toml::ser::Error),
    /// `--out` names a folder that already holds a run.
    #[error("{} already holds a study run (trials.csv or run.toml); resume it with --resume or pick another folder{}", path.display(), orphan_advice(path))]
    AlreadyExists { path: PathBuf },
    /// A folder's contents do not belong to the design that should have made them.
    #[error("{}: {message}", path.display())]
    Mismatch { path: PathBuf, message: String },
    /// Another process is writing to this run folder (the run folder's `.lock`).
    #[error("{} is in use by another surfacelab process ({holder}); wait for it to finish or stop it, then resume", path.display())]
    Locked { path: PathBuf, holder: String },
    #[error("merge: {0}")]
    Merge(String),
    #[error("{}: drawing the figure failed: {message}", path.display())]
    Plot { path: PathBuf, message: String },
}

impl crate::error::Kind for StudyError {
    /// A design, folder or file the user named that is wrong is bad input;
    /// writing results or drawing figures failing is a run-time failure.
    fn kind(&self) -> crate::error::ErrorKind {
        use crate::error::ErrorKind;
        match self {
            StudyError::Design(_)
            | StudyError::Csv { .. }
            | StudyError::TomlRead { .. }
            | StudyError::AlreadyExists { .. }
            | StudyError::Mismatch { .. }
            | StudyError::Locked { .. }
            | StudyError::Merge(_) => ErrorKind::BadInput,
            StudyError::Io { source, .. } => crate::error::io_kind(source),
            StudyError::TomlWrite(_) | StudyError::Plot { .. } => ErrorKind::Runtime,
        }
    }
}

impl StudyError {
    pub(crate) fn io(path: &Path) -> impl FnOnce(std::io::Error) -> StudyError + '_ {
        move |source| StudyError::Io { path: path.to_owned(), source }
    }

    pub(crate) fn csv(path: &Path) -> impl FnOnce(csv::Error) -> StudyError + '_ {
        move |source| StudyError::Csv { path: path.to_owned(), source }
    }

    pub(crate) fn mismatch(path: &Path, message: impl Into<String>) -> StudyError {
        StudyError::Mismatch { path: path.to_owned(), message: message.into() }
    }
}

/// What to do with a `trials.csv` whose `run.toml` is gone: its design is
/// unknown, so it cannot be resumed; the same flags reproduce its rows.
pub(crate) fn orphan_advice(dir: &std::path::Path) -> String {
    if dir.join(super::folder::RUN_TOML).exists() || !dir.join(super::folder::TRIALS_CSV).exists() {
        return String::new();
    }
    format!(
        ". Its run.toml is gone, so the design of its trials.csv is unknown and it cannot be resumed: \
         restore run.toml, or move trials.csv aside (mv {0}/trials.csv {0}/trials.csv.orphan) and run \
         `study --out {0}` again with the flags the run was started with; the same flags and seed reproduce \
         the same rows",
        dir.display()
    )
}
