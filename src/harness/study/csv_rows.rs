//! Whole CSV files of serde rows (`summary.csv`, `anova.csv`,
//! `strategies.csv`, `findings.csv`, …): written at once and atomically,
//! read back in one go. `trials.csv`, appended a row at a time, has its own
//! writer in `output`.

use super::error::StudyError;
use super::output::write_atomically;
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::path::Path;

/// Writes `rows` to `path`, atomically. With `header`, that line comes first
/// even for no rows, so the file always says its columns; without, the
/// header is the rows' field names, and no rows make an empty file.
pub(crate) fn write_rows<T: Serialize>(path: &Path, header: Option<&[&str]>, rows: &[T]) -> Result<(), StudyError> {
    let mut w = csv::WriterBuilder::new().has_headers(header.is_none()).from_writer(Vec::new());
    if let Some(header) = header {
        w.write_record(header).map_err(StudyError::csv(path))?;
    }
    for row in rows {
        w.serialize(row).map_err(StudyError::csv(path))?;
    }
    let bytes = w.into_inner().map_err(|e| StudyError::io(path)(e.into_error()))?;
    write_atomically(path, &bytes)
}

/// Every row of a CSV file with a header line.
pub(crate) fn read_rows<T: DeserializeOwned>(path: &Path) -> Result<Vec<T>, StudyError> {
    let mut r = csv::Reader::from_path(path).map_err(StudyError::csv(path))?;
    r.deserialize().collect::<Result<_, _>>().map_err(StudyError::csv(path))
}
