//! A run folder on disk:
//!
//! | file          | written                        | contents |
//! |---------------|--------------------------------|----------|
//! | `run.toml`    | first, atomically              | [`RunFile`]: format, version, the whole design, the shard |
//! | `trials.csv`  | one row appended per trial     | [`TrialRow`], tidy, in trial order |
//! | `errors.log`  | appended when a trial fails    | one line per failed trial |
//! | `summary.csv` | when every trial has a row     | see `summary` |
//! | `anova.csv`, `pairwise.csv` | with the summary | see `analysis` |
//! | `strategies.csv` | with the summary            | see `strategies` |
//! | `figure.png`, `figure.svg` | with the summary  | see `figure` |
//! | `report.md`, `report.html` | with the summary  | see `report` |
//!
//! `trials.csv` is crash-safe by construction: each row is serialized whole,
//! written with one `write_all` ending in `\n`, then fsync'ed. So after a
//! `kill -9` or a power cut only the last line can be damaged, and a line
//! without its `\n` is exactly a row that was not finished.
//! [`recover_trials`] cuts it off.

use super::design::{ParticipantPlan, Shard, StudyDesign};
use super::error::StudyError;
use super::trial::{TrialResult, TrialSpec};
use crate::pipeline::technique::TechniqueKind;
use serde::{Deserialize, Serialize};
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

pub use super::folder::{ERRORS_LOG, FIGURE_PNG, FIGURE_SVG, RUN_TOML, STRATEGIES_CSV, SUMMARY_CSV, TRIALS_CSV};

/// The version written into every row and into `run.toml`.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// `format` of `run.toml`; bump when the file or the trial order changes meaning.
/// 2: technique orders crossed with feedback-order groups, and
/// the design table (`[[plan]]`).
pub const RUN_FORMAT: &str = "surfacelab-study/2";

/// `trials.csv` columns, in order. They are the field names of [`TrialRow`].
pub const COLUMNS: [&str; 19] = [
    "participant",
    "order_index",
    "task",
    "technique",
    "feedback",
    "repetition",
    "practice",
    "completion_time_s",
    "completed",
    "restarts",
    "objects_placed",
    "steps",
    "seed",
    "version",
    "strategy",
    "hands_max",
    "fingers_max",
    "objects_moving_max",
    "manners",
];

/// One line of `trials.csv`: the spec and the result of one trial.
///
/// `completion_time_s` is empty when the runner failed (returned an error or
/// panicked): there is no time to report. Floats are written by `csv` in the
/// shortest form that reads back to the same number, so rewriting rows
/// (resume, merge) reproduces the same bytes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TrialRow {
    pub participant: u32,
    pub order_index: u32,
    pub task: String,
    pub technique: TechniqueKind,
    pub feedback: bool,
    pub repetition: u32,
    pub practice: bool,
    pub completion_time_s: Option<f64>,
    pub completed: bool,
    pub restarts: u32,
    pub objects_placed: u32,
    pub steps: u64,
    pub seed: u64,
    pub version: String,
    /// The manner used for the most time (empty for replays and failed runs).
    pub strategy: String,
    pub hands_max: u32,
    pub fingers_max: u32,
    pub objects_moving_max: u32,
    /// `name:time_s:net_m` per manner used, joined by `;` (see `strategies`).
    pub manners: String,
}

impl TrialRow {
    pub fn new(spec: &TrialSpec, result: &TrialResult) -> TrialRow {
        TrialRow {
            completion_time_s: result.completion_time_s.is_finite().then_some(result.completion_time_s),
            completed: result.completed,
            restarts: result.restarts,
            objects_placed: result.objects_placed,
            steps: result.steps,
            strategy: result.strategy.clone(),
            hands_max: result.hands_max,
            fingers_max: result.fingers_max,
            objects_moving_max: result.objects_moving_max,
            manners: result.manners.clone(),
            ..TrialRow::failed(spec)
        }
    }

    /// The row of a trial whose runner failed: not completed, no time.
    pub fn failed(spec: &TrialSpec) -> TrialRow {
        TrialRow {
            participant: spec.participant,
            order_index: spec.order_index,
            task: spec.task.clone(),
            technique: spec.technique,
            feedback: spec.feedback,
            repetition: spec.repetition,
            practice: spec.practice,
            completion_time_s: None,
            completed: false,
            restarts: 0,
            objects_placed: 0,
            steps: 0,
            seed: spec.seed,
            version: VERSION.to_owned(),
            strategy: String::new(),
            hands_max: 0,
            fingers_max: 0,
            objects_moving_max: 0,
            manners: String::new(),
        }
    }

    /// The spec this row was run from.
    pub fn spec(&self) -> TrialSpec {
        TrialSpec {
            participant: self.participant,
            order_index: self.order_index,
            task: self.task.clone(),
            technique: self.technique,
            feedback: self.feedback,
            repetition: self.repetition,
            practice: self.practice,
            seed: self.seed,
        }
    }

    /// Serialized as one CSV line, `\n`-terminated, no header.
    pub fn to_csv_line(&self) -> Result<Vec<u8>, csv::Error> {
        let mut w = csv::WriterBuilder::new().has_headers(false).from_writer(Vec::with_capacity(128));
        w.serialize(self)?;
        w.into_inner().map_err(|e| csv::Error::from(e.into_error()))
    }
}

fn header_line() -> String {
    let mut h = COLUMNS.join(",");
    h.push('\n');
    h
}

/// `run.toml`: everything needed to redo or resume the run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunFile {
    /// `RUN_FORMAT` (`surfacelab-study/2`).
    pub format: String,
    /// The version that created the folder (rows carry their own).
    pub version: String,
    pub design: StudyDesign,
    /// `design_hash` of `design` when the folder was made: resume
    /// refuses a run.toml whose design was edited since (rows of two
    /// designs would share one file). Absent in folders made before it
    /// existed; those resume with a note.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub design_hash: Option<String>,
    /// `None` for a whole run (or a merged one).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// The design table: each participant's feedback and technique order,
    /// derived from `design` and written for the reader (a hand-written
    /// file may leave it out; if given, it must match the design).
    #[serde(default)]
    pub plan: Vec<ParticipantPlan>,
}

impl RunFile {
    pub fn new(design: StudyDesign, shard: Option<Shard>) -> RunFile {
        let plan = design.plan();
        let design_hash = Some(design_hash(&design));
        RunFile { format: RUN_FORMAT.to_owned(), version: VERSION.to_owned(), design, design_hash, shard, plan }
    }

    /// Whether `design` is still the one the folder was made with: `Ok(true)`
    /// when the recorded hash matches, `Ok(false)` when the file predates
    /// the hash (nothing to check), an error naming the file when it was
    /// edited.
    pub fn check_unedited(&self, path: &Path) -> Result<bool, StudyError> {
        let Some(recorded) = &self.design_hash else { return Ok(false) };
        let now = design_hash(&self.design);
        if *recorded == now {
            return Ok(true);
        }
        Err(StudyError::mismatch(
            path,
            format!(
                "the design was edited after the run started (design_hash {recorded}, the design now hashes to {now}); \
                 resuming would mix rows of two designs in one trials.csv. To run the edited design, start a new \
                 folder: study --from {} --out NEW_FOLDER",
                path.display()
            ),
        ))
    }

    pub fn to_toml(&self) -> Result<String, StudyError> {
        Ok(toml::to_string(self)?)
    }

    /// Reads and validates a run file (format and design).
    pub fn load(path: &Path) -> Result<RunFile, StudyError> {
        let text = crate::files::read_capped(path).map_err(StudyError::io(path))?;
        let run: RunFile =
            toml::from_str(&text).map_err(|source| StudyError::TomlRead { path: path.to_owned(), source })?;
        if run.format != RUN_FORMAT {
            return Err(StudyError::mismatch(path, format!("format {:?} is not {RUN_FORMAT:?}", run.format)));
        }
        run.design.validate()?;
        if !run.plan.is_empty() && run.plan != run.design.plan() {
            let first = run.plan.iter().zip(run.design.plan()).find(|(a, b)| *a != b).map_or_else(
                || format!("{} rows for {} participants", run.plan.len(), run.design.participants),
                |(a, _)| format!("participant {}", a.participant),
            );
            return Err(StudyError::mismatch(
                path,
                format!("the design table ([[plan]]) does not match the design ({first}); delete it to rebuild it"),
            ));
        }
        Ok(run)
    }

    /// Writes atomically (temporary file, fsync, rename).
    pub fn save(&self, path: &Path) -> Result<(), StudyError> {
        write_atomically(path, self.to_toml()?.as_bytes())
    }
}

/// A stable hash of a design (FNV-1a, 64 bits, over its TOML text), as 16
/// hex digits: the same design gives the same hash on every machine and
/// build, so a shard made on a cluster node resumes anywhere.
pub fn design_hash(design: &StudyDesign) -> String {
    use std::hash::Hasher as _;
    let mut h = fnv::FnvHasher::default();
    h.write(toml::to_string(design).unwrap_or_default().as_bytes());
    format!("{:016x}", h.finish())
}

/// Appends rows to `trials.csv`, one fsync'ed write per row.
#[derive(Debug)]
pub struct TrialsWriter {
    file: File,
    path: PathBuf,
    fsync: bool,
}

impl TrialsWriter {
    /// Opens `path` for appending, writing the header if the file is new or
    /// empty. Call [`recover_trials`] first on a file a crash may have cut.
    pub fn open(path: &Path, fsync: bool) -> Result<TrialsWriter, StudyError> {
        let file = OpenOptions::new().create(true).append(true).open(path).map_err(StudyError::io(path))?;
        let empty = file.metadata().map_err(StudyError::io(path))?.len() == 0;
        let mut w = TrialsWriter { file, path: path.to_owned(), fsync };
        if empty {
            w.write_line(header_line().as_bytes())?;
        }
        Ok(w)
    }

    pub fn append(&mut self, row: &TrialRow) -> Result<(), StudyError> {
        let line = row.to_csv_line().map_err(StudyError::csv(&self.path))?;
        self.write_line(&line)
    }

    fn write_line(&mut self, line: &[u8]) -> Result<(), StudyError> {
        self.file.write_all(line).map_err(StudyError::io(&self.path))?;
        self.file.flush().map_err(StudyError::io(&self.path))?;
        if self.fsync {
            self.file.sync_data().map_err(StudyError::io(&self.path))?;
        }
        Ok(())
    }
}

/// What [`recover_trials`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct Recovered {
    pub rows: Vec<TrialRow>,
    /// Bytes cut from the end of the file (a partial or unreadable last row).
    pub dropped_bytes: u64,
}

/// Reads `trials.csv` after a possible crash: a last line without its `\n`,
/// or a last line that does not parse, is cut from the file (in place), and
/// the remaining rows are returned. Damage anywhere else is an error: that
/// is not what a crash leaves. A missing file is an empty run.
pub fn recover_trials(path: &Path) -> Result<Recovered, StudyError> {
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Ok(Recovered { rows: Vec::new(), dropped_bytes: 0 });
        }
        Err(e) => return Err(StudyError::io(path)(e)),
    };
    let complete = bytes.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let (rows, keep) = if complete == 0 {
        // Not even a whole header: start the file over.
        (Vec::new(), 0)
    } else {
        parse_rows(path, &bytes[..complete], true)?
    };
    let dropped_bytes = (bytes.len() - keep) as u64;
    if dropped_bytes > 0 {
        let file = OpenOptions::new().write(true).open(path).map_err(StudyError::io(path))?;
        file.set_len(keep as u64).map_err(StudyError::io(path))?;
        file.sync_all().map_err(StudyError::io(path))?;
    }
    Ok(Recovered { rows, dropped_bytes })
}

/// Reads a `trials.csv` that must be whole (merge, report): no partial or
/// unreadable row anywhere.
pub fn read_trials(path: &Path) -> Result<Vec<TrialRow>, StudyError> {
    let bytes = std::fs::read(path).map_err(StudyError::io(path))?;
    if !bytes.is_empty() && !bytes.ends_with(b"\n") {
        return Err(StudyError::mismatch(path, "the last row is cut short; resume this run first"));
    }
    Ok(parse_rows(path, &bytes, false)?.0)
}

/// Parses complete lines; returns the rows and how many bytes they span.
/// With `drop_bad_last`, an unreadable last row is left out instead of failing.
fn parse_rows(path: &Path, bytes: &[u8], drop_bad_last: bool) -> Result<(Vec<TrialRow>, usize), StudyError> {
    let mut reader = csv::ReaderBuilder::new().has_headers(true).from_reader(bytes);
    let headers = reader.byte_headers().map_err(StudyError::csv(path))?.clone();
    if headers.iter().ne(COLUMNS.iter().map(|c| c.as_bytes())) {
        return Err(StudyError::mismatch(path, format!("unexpected header; expected {}", COLUMNS.join(","))));
    }
    let mut rows = Vec::new();
    let mut record = csv::ByteRecord::new();
    loop {
        let start = reader.position().byte() as usize;
        let parsed = match reader.read_byte_record(&mut record) {
            Ok(false) => break,
            Ok(true) => record.deserialize::<TrialRow>(Some(&headers)),
            Err(e) => Err(e),
        };
        match parsed {
            Ok(row) => rows.push(row),
            Err(e) => {
                let is_last = reader.is_done() || {
                    let mut rest = csv::ByteRecord::new();
                    matches!(reader.read_byte_record(&mut rest), Ok(false))
                };
                if drop_bad_last && is_last {
                    return Ok((rows, start));
                }
                return Err(StudyError::csv(path)(e));
            }
        }
    }
    Ok((rows, bytes.len()))
}

/// Replaces `trials.csv` with exactly these rows (header included), atomically.
pub fn write_trials(path: &Path, rows: &[TrialRow]) -> Result<(), StudyError> {
    let mut bytes = header_line().into_bytes();
    for row in rows {
        bytes.extend(row.to_csv_line().map_err(StudyError::csv(path))?);
    }
    write_atomically(path, &bytes)
}

/// Appends one line to `errors.log`.
pub fn log_error(dir: &Path, line: &str) -> Result<(), StudyError> {
    let path = dir.join(ERRORS_LOG);
    let mut f = OpenOptions::new().create(true).append(true).open(&path).map_err(StudyError::io(&path))?;
    writeln!(f, "{line}").map_err(StudyError::io(&path))
}

/// A regular file (or a symlink's target) by temporary file beside it,
/// fsync, rename, so readers see the old file or the new one, never half of
/// one; a FIFO or device straight through (`files::write_output`; a
/// failure leaves no temporary file).
pub(crate) fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), StudyError> {
    crate::files::write_output(path, bytes).map_err(StudyError::io(path))
}
