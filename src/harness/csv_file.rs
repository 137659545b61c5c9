//! A harness's rows written as one CSV file, atomically.

use anyhow::Context;
use serde::Serialize;
use std::path::Path;

/// Writes `rows` with a header line to `path` (see
/// [`write_output`](crate::files::write_output)).
pub fn write_csv<T: Serialize>(path: &Path, rows: &[T]) -> anyhow::Result<()> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r)?;
    }
    let bytes = w.into_inner().map_err(|e| anyhow::anyhow!("{}", e.error()))?;
    crate::files::write_output(path, &bytes).with_context(|| format!("writing {}", path.display()))
}
