//! Running a study into a folder: fresh, resumed, sharded, merged.
//!
//! Invariants that make runs reproducible and crash-safe:
//! - `trials.csv` always holds the folder's trials as a prefix in trial
//!   order: workers take trials in order, finished results wait in a buffer
//!   until every earlier trial is written. So a seed and a design give a
//!   byte-identical file whatever `jobs` is and however often the run was
//!   interrupted.
//! - Participants learn, so each participant's trials run in session order
//!   on one [`ParticipantRun`]; workers take whole participants. A trial of
//!   that participant not run now (already in `trials.csv`) is *replayed*
//!   first, so a resumed run rebuilds the participant's state exactly and
//!   writes the same bytes as an uninterrupted one.
//! - Shards split the study by participant (see [`in_shard`]), so a shard
//!   never has to replay another shard's trials.
//! - A trial is identified by (`participant`, `order_index`); a row is accepted
//!   on resume only if its whole spec (task, technique, feedback,
//!   repetition, practice, seed) matches the design's — a folder cannot
//!   silently mix two designs.
//! - A trial whose runner returns an error (or panics) gets a row anyway:
//!   not completed, no time, the error in `errors.log`. It is not retried on
//!   resume; delete its row to rerun it.

use super::analysis::{ANOVA_CSV, PAIRWISE_CSV, analyze, write_anova, write_pairwise};
use super::design::{Shard, StudyDesign};
use super::error::StudyError;
use super::figure::write_figure;
use super::lock::RunLock;
use super::output::{
    FIGURE_PNG, FIGURE_SVG, RUN_TOML, RunFile, STRATEGIES_CSV, SUMMARY_CSV, TRIALS_CSV, TrialRow, TrialsWriter,
    log_error, read_trials, recover_trials, write_trials,
};
use super::report::write_run_report;
use super::strategies::{strategies, write_strategies};
use super::summary::{summarize, write_summary};
use super::trial::{ParticipantRun, TrialRunner, TrialSpec};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::collections::{BTreeMap, HashMap};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// How to run; none of it changes the results.
#[derive(Debug, Clone)]
pub struct RunOptions {
    /// Worker threads; 0 = one per available core.
    pub jobs: usize,
    /// Show a progress bar (only ever on a terminal's stderr).
    pub progress: bool,
    /// Print failed trials to stderr (they always go to `errors.log`).
    pub report_errors: bool,
    /// Run only this slice of the trials. On resume, `None` takes the
    /// folder's own shard and `Some` must equal it.
    pub shard: Option<Shard>,
    /// fsync `trials.csv` after each row. Off only for tests and benchmarks.
    pub fsync: bool,
}

impl Default for RunOptions {
    fn default() -> Self {
        RunOptions { jobs: 0, progress: true, report_errors: true, shard: None, fsync: true }
    }
}

/// What a run did.
#[derive(Debug, Clone, PartialEq)]
pub struct RunOutcome {
    pub dir: PathBuf,
    /// Trials this folder holds when complete (its shard's share).
    pub trials: usize,
    /// Rows found in `trials.csv` before running.
    pub already_done: usize,
    /// Trials run now.
    pub ran: usize,
    /// Of those, trials that did not complete: the time limit ended them,
    /// or their runner failed.
    pub failed: usize,
    /// Of `failed`, trials whose runner failed (error or panic; no time).
    pub errors: usize,
    /// Simulated seconds of the trials run now (the sum of their recorded
    /// times), for the real-time factor.
    pub simulated_s: f64,
    /// Worker threads used.
    pub jobs: usize,
    /// Bytes of a cut-off last row removed on resume.
    pub dropped_bytes: u64,
    /// `summary.csv` and the figure were written (whole, unsharded runs).
    pub reported: bool,
    pub elapsed: Duration,
}

/// Starts a run in `out_dir` (created if missing). Refuses a folder that
/// already holds a run: use [`resume_study`] for that.
pub fn run_study(
    design: &StudyDesign,
    out_dir: &Path,
    runner: &dyn TrialRunner,
    options: &RunOptions,
) -> Result<RunOutcome, StudyError> {
    design.validate()?;
    std::fs::create_dir_all(out_dir).map_err(StudyError::io(out_dir))?;
    // Locked before looking: of two runs started at once on one folder, the
    // second is told the folder is in use, not that a file is missing.
    let _lock = RunLock::acquire(out_dir)?;
    if out_dir.join(RUN_TOML).exists() || out_dir.join(TRIALS_CSV).exists() {
        return Err(StudyError::AlreadyExists { path: out_dir.to_owned() });
    }
    let run = RunFile::new(design.clone(), options.shard);
    run.save(&out_dir.join(RUN_TOML))?;
    execute(out_dir, &run, runner, options)
}

/// Continues the run in `dir` from its `run.toml` and `trials.csv`: drops a
/// row cut short by a crash, then runs exactly the trials without a row.
pub fn resume_study(dir: &Path, runner: &dyn TrialRunner, options: &RunOptions) -> Result<RunOutcome, StudyError> {
    let _lock = if dir.is_dir() { Some(RunLock::acquire(dir)?) } else { None };
    let run = RunFile::load(&dir.join(RUN_TOML))?;
    run.check_unedited(&dir.join(RUN_TOML))?;
    if let Some(shard) = options.shard
        && Some(shard) != run.shard
    {
        let theirs = run.shard.map_or_else(|| "none".to_owned(), |s| s.to_string());
        return Err(StudyError::mismatch(dir, format!("asked for shard {shard}, the folder holds shard {theirs}")));
    }
    execute(dir, &run, runner, options)
}

/// What [`merge`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct MergeOutcome {
    pub trials: usize,
    /// Trials that did not complete (time limit or runner failure).
    pub failed: usize,
}

/// Combines the folders of a sharded run into `out_dir`: one `trials.csv`
/// in trial order (the same bytes a single run would have written), the
/// design's `run.toml` without a shard, `summary.csv` and the figure. Every
/// trial must be present exactly once. Whole-run folders (no shard) may be
/// merged too. `out_dir` may be overwritten only if it holds the same design.
pub fn merge(out_dir: &Path, shard_dirs: &[PathBuf]) -> Result<MergeOutcome, StudyError> {
    let Some(first) = shard_dirs.first() else {
        return Err(StudyError::Merge("no folders to merge".into()));
    };
    let design = RunFile::load(&first.join(RUN_TOML))?.design;
    let trials = design.trials();
    let index_of = index_by_key(&trials);
    let mut placed: Vec<Option<TrialRow>> = vec![None; trials.len()];
    for dir in shard_dirs {
        let run = RunFile::load(&dir.join(RUN_TOML))?;
        if run.design != design {
            return Err(StudyError::Merge(format!(
                "{} was run from a different design than {}",
                dir.display(),
                first.display()
            )));
        }
        let shard = run.shard.unwrap_or(Shard::WHOLE);
        let path = dir.join(TRIALS_CSV);
        for row in read_trials(&path)? {
            let index = check_row(&path, &trials, &index_of, shard, &row)?;
            if placed[index].is_some() {
                return Err(StudyError::Merge(format!(
                    "trial P{} #{} appears twice (again in {})",
                    row.participant,
                    row.order_index,
                    path.display()
                )));
            }
            placed[index] = Some(row);
        }
    }
    let missing = placed.iter().filter(|r| r.is_none()).count();
    if let Some(i) = placed.iter().position(Option::is_none) {
        let t = &trials[i];
        return Err(StudyError::Merge(format!(
            "{missing} of {} trials missing, the first being P{} #{} (trial index {i}); \
             resume the shard holding it, or pass its folder",
            trials.len(),
            t.participant,
            t.order_index
        )));
    }
    let rows: Vec<TrialRow> = placed.into_iter().flatten().collect();

    std::fs::create_dir_all(out_dir).map_err(StudyError::io(out_dir))?;
    let _lock = RunLock::acquire(out_dir)?;
    let out_run = out_dir.join(RUN_TOML);
    if out_run.exists() {
        if RunFile::load(&out_run)?.design != design {
            return Err(StudyError::AlreadyExists { path: out_dir.to_owned() });
        }
    } else if out_dir.join(TRIALS_CSV).exists() {
        return Err(StudyError::AlreadyExists { path: out_dir.to_owned() });
    }
    RunFile::new(design.clone(), None).save(&out_run)?;
    write_trials(&out_dir.join(TRIALS_CSV), &rows)?;
    write_report_from(out_dir, &design, &rows)?;
    Ok(MergeOutcome { trials: rows.len(), failed: rows.iter().filter(|r| !r.completed).count() })
}

/// (Re)writes `summary.csv`, `anova.csv`, `pairwise.csv`, `figure.png`,
/// `figure.svg`, `report.md` and `report.html` of a folder from its
/// `run.toml` and `trials.csv` (which may be incomplete).
pub fn write_report(dir: &Path) -> Result<(), StudyError> {
    let run = RunFile::load(&dir.join(RUN_TOML))?;
    let rows = read_trials(&dir.join(TRIALS_CSV))?;
    write_report_from(dir, &run.design, &rows)
}

fn write_report_from(dir: &Path, design: &StudyDesign, rows: &[TrialRow]) -> Result<(), StudyError> {
    let summary = summarize(design, rows);
    write_summary(&dir.join(SUMMARY_CSV), &summary)?;
    write_strategies(&dir.join(STRATEGIES_CSV), &strategies(rows, &dir.join(TRIALS_CSV))?)?;
    let analysis = analyze(design, rows);
    write_anova(&dir.join(ANOVA_CSV), &analysis.anova)?;
    write_pairwise(&dir.join(PAIRWISE_CSV), &analysis.pairwise)?;
    write_figure(design, &summary, &dir.join(FIGURE_PNG), &dir.join(FIGURE_SVG))?;
    write_run_report(dir, design, &summary, &analysis)
}

type Key = (u32, u32);

/// A trial of a participant's session: its trial index, and its position
/// among the trials to run now (`None`: replayed, its row exists).
type SessionStep = (usize, Option<usize>);

/// Shard `i/n` holds every trial of the participants whose 0-based index
/// `p - 1` has `(p - 1) % n == i`: participants learn from trial to trial,
/// so a participant's session is never split across machines.
pub fn in_shard(shard: Shard, spec: &TrialSpec) -> bool {
    shard.contains(spec.participant.saturating_sub(1) as usize)
}

fn index_by_key(trials: &[TrialSpec]) -> HashMap<Key, usize> {
    trials.iter().enumerate().map(|(i, t)| ((t.participant, t.order_index), i)).collect()
}

/// The trial index of a row, if the row belongs to this design and shard.
fn check_row(
    path: &Path,
    trials: &[TrialSpec],
    index_of: &HashMap<Key, usize>,
    shard: Shard,
    row: &TrialRow,
) -> Result<usize, StudyError> {
    let name = format!("row P{} #{}", row.participant, row.order_index);
    let Some(&index) = index_of.get(&(row.participant, row.order_index)) else {
        return Err(StudyError::mismatch(path, format!("{name} is not a trial of this run's design")));
    };
    if row.spec() != trials[index] {
        return Err(StudyError::mismatch(
            path,
            format!("{name} differs from the design's trial ({:?} vs {:?})", row.spec(), trials[index]),
        ));
    }
    if !in_shard(shard, &trials[index]) {
        return Err(StudyError::mismatch(
            path,
            format!("{name} (participant {}) is not in shard {shard}", row.participant),
        ));
    }
    Ok(index)
}

fn execute(
    dir: &Path,
    run: &RunFile,
    runner: &dyn TrialRunner,
    options: &RunOptions,
) -> Result<RunOutcome, StudyError> {
    let started = Instant::now();
    let trials = run.design.trials();
    let shard = run.shard.unwrap_or(Shard::WHOLE);
    let mine: Vec<usize> = (0..trials.len()).filter(|&i| in_shard(shard, &trials[i])).collect();
    let index_of = index_by_key(&trials);

    let csv_path = dir.join(TRIALS_CSV);
    let mut recovered = recover_trials(&csv_path)?;
    let (mut done, in_order) =
        rows_by_index(&csv_path, std::mem::take(&mut recovered.rows), &trials, &index_of, shard, &mine)?;
    let already_done = done.len();
    let todo_index: Vec<usize> = mine.iter().copied().filter(|i| !done.contains_key(i)).collect();
    let todo: Vec<&TrialSpec> = todo_index.iter().map(|&i| &trials[i]).collect();

    let mut writer = TrialsWriter::open(&csv_path, options.fsync)?;
    let progress = progress_bar(options.progress, todo.len() as u64, already_done);
    let mut plain = (options.progress && !std::io::stderr().is_terminal()).then(|| PlainProgress::new(todo.len()));
    let mut failed = 0usize;
    let mut written = 0usize;
    if !todo.is_empty() {
        let sessions = session_plan(&trials, &todo_index);
        let jobs = jobs_for(options, sessions.len());
        let next = AtomicUsize::new(0);
        let stop = AtomicBool::new(false);
        let (tx, rx) = mpsc::channel::<Measured>();
        std::thread::scope(|scope| -> Result<(), StudyError> {
            for _ in 0..jobs {
                let tx = tx.clone();
                let (next, stop, sessions, trials) = (&next, &stop, &sessions, &trials);
                scope.spawn(move || work(runner, sessions, trials, (next, stop), &tx));
            }
            drop(tx);
            // Results arrive in any order; rows leave in trial order.
            let mut pending: BTreeMap<usize, (TrialRow, Option<String>)> = BTreeMap::new();
            let result = (|| {
                for (k, row, error) in &rx {
                    pending.insert(k, (row, error));
                    while let Some((row, error)) = pending.remove(&written) {
                        writer.append(&row)?;
                        if !in_order {
                            done.insert(todo_index[written], row.clone());
                        }
                        if let Some(error) = error {
                            failed += 1;
                            let line = failure_line(&row, &error);
                            log_error(dir, &line)?;
                            if options.report_errors {
                                progress.suspend(|| eprintln!("trial failed: {line}"));
                            }
                        }
                        written += 1;
                        progress.set_message(format!("P{} {} {}", row.participant, row.task, row.technique));
                        progress.inc(1);
                        if let Some(plain) = &mut plain {
                            plain.tick(written);
                        }
                    }
                }
                Ok(())
            })();
            if result.is_err() {
                stop.store(true, Ordering::Relaxed);
            }
            drop(rx);
            result
        })?;
    }
    progress.finish_and_clear();
    if !in_order {
        // Not written by this harness (rows out of order or with gaps, e.g. a
        // row deleted by hand to rerun that trial): new rows were appended at
        // the end, so put the file back into trial order, as an
        // uninterrupted run would have written it.
        let rows: Vec<TrialRow> = done.into_values().collect();
        write_trials(&csv_path, &rows)?;
    }

    let complete = already_done + written == mine.len();
    let reported = complete && run.shard.is_none();
    if reported {
        write_report(dir)?;
    }
    let (not_completed, simulated_s) = ran_now_totals(&csv_path, &todo[..written])?;
    Ok(RunOutcome {
        dir: dir.to_owned(),
        trials: mine.len(),
        already_done,
        ran: written,
        failed: not_completed,
        errors: failed,
        simulated_s,
        jobs: jobs_for(options, todo.len()),
        dropped_bytes: recovered.dropped_bytes,
        reported,
        elapsed: started.elapsed(),
    })
}

/// Worker threads for `work` pieces of work: as asked (0 = one per core),
/// at least one and no more than there is work.
fn jobs_for(options: &RunOptions, work: usize) -> usize {
    let jobs =
        if options.jobs == 0 { std::thread::available_parallelism().map_or(1, usize::from) } else { options.jobs };
    jobs.clamp(1, work.max(1))
}

/// A measured trial's row, sent from a worker: its place among the trials
/// to run, the row, and the runner's error if it failed.
type Measured = (usize, TrialRow, Option<String>);

/// One worker thread: takes the next participant's session until none is
/// left or `stop` is set, and runs its trials in session order (replaying
/// the ones before, which a participant's learning needs), sending each
/// measured row.
fn work(
    runner: &dyn TrialRunner,
    sessions: &[(u32, Vec<SessionStep>)],
    trials: &[TrialSpec],
    (next, stop): (&AtomicUsize, &AtomicBool),
    tx: &mpsc::Sender<Measured>,
) {
    while !stop.load(Ordering::Relaxed) {
        let s = next.fetch_add(1, Ordering::Relaxed);
        let Some((participant, steps)) = sessions.get(s) else { break };
        let mut session = runner.participant(*participant);
        for &(index, k) in steps {
            if stop.load(Ordering::Relaxed) {
                return;
            }
            let spec = &trials[index];
            match k {
                None => replay_one(session.as_mut(), spec),
                Some(k) => {
                    let (row, error) = run_one(session.as_mut(), spec);
                    if tx.send((k, row, error)).is_err() {
                        return;
                    }
                }
            }
        }
    }
}

/// The `errors.log` line of a failed trial.
fn failure_line(row: &TrialRow, error: &str) -> String {
    format!(
        "P{} #{} {} {} feedback={} rep {}: {error}",
        row.participant, row.order_index, row.task, row.technique, row.feedback, row.repetition
    )
}

/// The rows already in `trials.csv`, by trial index, each checked against
/// the design; and whether they are exactly this shard's first trials in
/// order (as this harness writes them).
fn rows_by_index(
    csv_path: &Path,
    rows: Vec<TrialRow>,
    trials: &[TrialSpec],
    index_of: &HashMap<Key, usize>,
    shard: Shard,
    mine: &[usize],
) -> Result<(BTreeMap<usize, TrialRow>, bool), StudyError> {
    let mut done: BTreeMap<usize, TrialRow> = BTreeMap::new();
    let mut in_order = true;
    for (k, row) in rows.into_iter().enumerate() {
        let index = check_row(csv_path, trials, index_of, shard, &row)?;
        in_order &= mine.get(k) == Some(&index);
        if done.insert(index, row).is_some() {
            return Err(StudyError::mismatch(csv_path, format!("trial index {index} has two rows")));
        }
    }
    Ok((done, in_order))
}

/// Each participant's trials up to their last one to run, in session
/// order; `Some(k)` marks the k-th trial to run, `None` one to replay (a
/// participant's learning needs the trials before).
fn session_plan(trials: &[TrialSpec], todo_index: &[usize]) -> Vec<(u32, Vec<SessionStep>)> {
    let mut sessions: Vec<(u32, Vec<SessionStep>)> = Vec::new();
    for &index in todo_index {
        let p = trials[index].participant;
        if sessions.last().is_none_or(|(q, _)| *q != p) {
            sessions.push((p, Vec::new()));
        }
    }
    for (p, steps) in &mut sessions {
        let last = todo_index.iter().rev().find(|&&i| trials[i].participant == *p).copied().unwrap_or(0);
        for i in (0..=last).filter(|&i| trials[i].participant == *p) {
            steps.push((i, todo_index.binary_search(&i).ok()));
        }
    }
    sessions
}

/// Of the rows in `trials.csv` for these trials: how many did not complete,
/// and their recorded seconds in total. Read back from the file so the
/// scheduling loop needs no bookkeeping of its own for it.
fn ran_now_totals(csv_path: &Path, ran: &[&TrialSpec]) -> Result<(usize, f64), StudyError> {
    if ran.is_empty() {
        return Ok((0, 0.0));
    }
    let keys: std::collections::HashSet<Key> = ran.iter().map(|t| (t.participant, t.order_index)).collect();
    let rows = read_trials(csv_path)?;
    let mine = rows.iter().filter(|r| keys.contains(&(r.participant, r.order_index)));
    Ok(mine.fold((0, 0.0), |(n, s), r| (n + usize::from(!r.completed), s + r.completion_time_s.unwrap_or(0.0))))
}

/// Replays a trial that already has its row; its errors were recorded then.
fn replay_one(session: &mut dyn ParticipantRun, spec: &TrialSpec) {
    let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| session.replay(spec)));
}

/// Runs one trial; an error or a panic becomes a failed row and a message.
fn run_one(session: &mut dyn ParticipantRun, spec: &TrialSpec) -> (TrialRow, Option<String>) {
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| session.run(spec)));
    match outcome {
        Ok(Ok(result)) => (TrialRow::new(spec, &result), None),
        Ok(Err(error)) => (TrialRow::failed(spec), Some(format!("{error:#}"))),
        Err(panic) => {
            let message = panic
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_owned());
            (TrialRow::failed(spec), Some(format!("panicked: {message}")))
        }
    }
}

/// How often a study whose standard error is not a terminal says how far
/// it has come.
const PLAIN_EVERY: std::time::Duration = std::time::Duration::from_secs(10);

/// Progress where no bar can be drawn (a log file, a pipe, a batch job's
/// output): a plain line every [`PLAIN_EVERY`], so that a long study is
/// never silent for long.
struct PlainProgress {
    start: std::time::Instant,
    next: std::time::Instant,
    todo: usize,
}

impl PlainProgress {
    fn new(todo: usize) -> PlainProgress {
        let start = std::time::Instant::now();
        PlainProgress { start, next: start + PLAIN_EVERY, todo }
    }

    /// `done` of the trials to do have their rows.
    fn tick(&mut self, done: usize) {
        let now = std::time::Instant::now();
        if now < self.next || done >= self.todo {
            return;
        }
        let share = done as f64 / self.todo as f64;
        let left = self.start.elapsed().as_secs_f64() * (1.0 - share) / share.max(1e-9);
        eprintln!("surfacelab study: {done} of {} trials ({:.0}%), about {left:.0} s left", self.todo, 100.0 * share);
        self.next = now + PLAIN_EVERY;
    }
}

fn progress_bar(wanted: bool, todo: u64, already_done: usize) -> ProgressBar {
    if !wanted || todo == 0 || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(todo), ProgressDrawTarget::stderr());
    let style =
        ProgressStyle::with_template("{prefix}[{elapsed_precise}] {wide_bar} {pos}/{len} trials, ETA {eta} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style);
    if already_done > 0 {
        bar.set_prefix(format!("(resumed after {already_done}) "));
    }
    bar
}
