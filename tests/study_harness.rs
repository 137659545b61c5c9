//! The study harness without physics: a fake runner derives each result from
//! the trial spec alone, so every property of the machinery (order,
//! counterbalancing, determinism, resume, shards, statistics) is checked
//! exactly.

mod common;

use common::scratch;
use std::collections::{BTreeMap, HashSet};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;
use surfacelab::harness::study::{
    ParticipantRun, RunFile, RunOptions, RunnerSettings, Shard, StudyDesign, StudyError, TrialResult, TrialRow,
    TrialRunner, TrialSpec, describe, merge, resume_study, run_study, summarize, t_quantile_975, trial_seed,
    williams_square,
};
use surfacelab::harness::study::{RUN_TOML, SUMMARY_CSV, TRIALS_CSV, read_trials};
use surfacelab::pipeline::technique::TechniqueKind;

/// Results that depend only on the spec. `jitter` sleeps a seed-dependent
/// moment so parallel workers finish out of order.
#[derive(Default)]
struct FakeRunner {
    calls: AtomicUsize,
    jitter: bool,
    /// Fail (error) when `seed % fail_modulo == 0`.
    fail_modulo: Option<u64>,
    /// Panic on this order index.
    panic_at: Option<u32>,
}

impl FakeRunner {
    fn jittery() -> FakeRunner {
        FakeRunner { jitter: true, ..FakeRunner::default() }
    }
    fn calls(&self) -> usize {
        self.calls.load(Ordering::SeqCst)
    }
}

impl TrialRunner for FakeRunner {
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        self.calls.fetch_add(1, Ordering::SeqCst);
        if self.jitter {
            std::thread::sleep(Duration::from_micros(spec.seed % 700));
        }
        if self.fail_modulo.is_some_and(|m| spec.seed.is_multiple_of(m)) {
            anyhow::bail!("scripted failure for seed {}", spec.seed);
        }
        assert!(self.panic_at != Some(spec.order_index), "scripted panic");
        let base = match spec.task.as_str() {
            "positioning" => 30.0,
            "sorting" => 45.0,
            _ => 80.0,
        };
        let factor = match spec.technique {
            TechniqueKind::DIRECT => 2.0,
            TechniqueKind::JOINT => 0.8,
            TechniqueKind::PROXY => 1.1,
            TechniqueKind::HYBRID => 0.95,
            // Particle, and any registered technique.
            _ => 1.0,
        };
        let feedback = if spec.feedback { 0.9 } else { 1.0 };
        let noise = (spec.seed % 10_000) as f64 / 997.0;
        let time = base * factor * feedback + noise;
        Ok(TrialResult {
            completion_time_s: time,
            completed: !spec.seed.is_multiple_of(7),
            restarts: (spec.seed % 3) as u32,
            objects_placed: (spec.seed % 9) as u32,
            steps: (time * 60.0) as u64,
            strategy: "fingertip_1".into(),
            hands_max: 1 + (spec.seed % 2) as u32,
            fingers_max: 1 + (spec.seed % 5) as u32,
            objects_moving_max: (spec.seed % 4) as u32,
            manners: format!("fingertip_1:{:.2}:0.5;flat_hand:{:.2}:0.25", time * 0.75, time * 0.25),
        })
    }
}

/// A participant who learns: each result depends on every earlier trial of
/// the same participant (a running sum of their seeds), so only a harness
/// that replays earlier trials in order reproduces it.
#[derive(Default)]
struct LearningFake {
    runs: AtomicUsize,
    replays: AtomicUsize,
}

struct LearningSession<'a> {
    fake: &'a LearningFake,
    participant: u32,
    seen: Vec<u32>,
    memory: u64,
}

impl ParticipantRun for LearningSession<'_> {
    fn run(&mut self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        assert_eq!(spec.participant, self.participant, "one session per participant");
        assert!(self.seen.last().is_none_or(|&o| o < spec.order_index), "trials in session order");
        self.seen.push(spec.order_index);
        self.fake.runs.fetch_add(1, Ordering::SeqCst);
        self.memory = self.memory.wrapping_mul(31).wrapping_add(spec.seed % 1000);
        Ok(TrialResult {
            completion_time_s: (self.memory % 100_000) as f64 / 100.0,
            completed: true,
            ..TrialResult::default()
        })
    }

    fn replay(&mut self, spec: &TrialSpec) -> anyhow::Result<()> {
        self.fake.replays.fetch_add(1, Ordering::SeqCst);
        self.run(spec).map(|_| ())
    }
}

impl TrialRunner for LearningFake {
    fn run(&self, _spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        anyhow::bail!("the harness must go through participant()")
    }

    fn participant(&self, participant: u32) -> Box<dyn ParticipantRun + '_> {
        Box::new(LearningSession { fake: self, participant, seen: Vec::new(), memory: 0 })
    }
}

fn quiet(jobs: usize) -> RunOptions {
    RunOptions { jobs, progress: false, report_errors: false, shard: None, fsync: false }
}

/// A fresh, empty folder under the test target's temporary directory.
fn small_design() -> StudyDesign {
    StudyDesign { participants: 2, repetitions: 1, ..StudyDesign::default() }
}

fn read(path: &Path) -> Vec<u8> {
    std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

// ---------------------------------------------------------------- design

/// Each condition once per position per square; each ordered pair adjacent
/// once (n even) or twice in the doubled square (n odd).
fn assert_williams(n: usize) {
    let square = williams_square(n);
    let odd = n % 2 == 1;
    assert_eq!(square.len(), if odd { 2 * n } else { n }, "rows for n = {n}");
    for row in &square {
        let mut sorted = row.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..n).collect::<Vec<_>>(), "row {row:?} is not a permutation");
    }
    // Each half (the square, and for odd n its mirror) is a Latin square.
    for half in square.chunks(n) {
        for pos in 0..n {
            let column: HashSet<usize> = half.iter().map(|r| r[pos]).collect();
            assert_eq!(column.len(), n, "n = {n}: position {pos} repeats a condition");
        }
    }
    let mut pairs: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for row in &square {
        for w in row.windows(2) {
            *pairs.entry((w[0], w[1])).or_default() += 1;
        }
    }
    let expected = if odd { 2 } else { 1 };
    for a in 0..n {
        for b in 0..n {
            if a != b {
                assert_eq!(pairs.get(&(a, b)).copied().unwrap_or(0), expected, "n = {n}: pair {a}->{b}");
            }
        }
    }
}

#[test]
fn williams_square_is_balanced_for_3_and_4() {
    assert_williams(3);
    assert_williams(4);
    assert_eq!(williams_square(4)[0], vec![0, 1, 3, 2]);
}

#[test]
fn williams_square_is_balanced_for_other_sizes() {
    for n in [1, 2, 5, 6, 7, 8] {
        assert_williams(n);
    }
    assert!(williams_square(0).is_empty());
}

/// How often each technique sits at each position, per feedback-order group
/// (keyed by the participant's first feedback level).
fn positions_per_group(design: &StudyDesign) -> BTreeMap<(bool, usize, TechniqueKind), usize> {
    let mut counts = BTreeMap::new();
    for p in 1..=design.participants {
        let first = design.feedback_order(p)[0];
        for (pos, t) in design.technique_order(p).into_iter().enumerate() {
            *counts.entry((first, pos, t)).or_default() += 1;
        }
    }
    counts
}

#[test]
fn paper_design_counterbalances_six_participants() {
    const J: TechniqueKind = TechniqueKind::JOINT;
    const P: TechniqueKind = TechniqueKind::PROXY;
    const PA: TechniqueKind = TechniqueKind::PARTICLE;
    let design = StudyDesign::default();
    assert_eq!(design.balance_note(), None);
    // By hand from the Williams rows [J,P,PA] [P,PA,J] [PA,J,P] and their
    // mirrors [PA,P,J] [J,PA,P] [P,J,PA]: odd IDs (feedback on first) take
    // the square, even IDs (off first) the mirrored square.
    let expected = [
        (true, [J, P, PA]),
        (false, [PA, P, J]),
        (true, [P, PA, J]),
        (false, [J, PA, P]),
        (true, [PA, J, P]),
        (false, [P, J, PA]),
    ];
    for (p, (first, order)) in (1..=6).zip(expected) {
        assert_eq!(design.feedback_order(p), vec![first, !first], "P{p}");
        assert_eq!(design.technique_order(p), order.to_vec(), "P{p}");
    }
    // Within each feedback-order group, every technique once in every position.
    let counts = positions_per_group(&design);
    for first in [true, false] {
        for pos in 0..3 {
            for t in [J, P, PA] {
                assert_eq!(counts.get(&(first, pos, t)), Some(&1), "group on-first={first}: {t} at position {pos}");
            }
        }
    }
    // The design table in run.toml says the same.
    let plan = design.plan();
    assert_eq!(plan.len(), 6);
    assert_eq!((plan[3].participant, plan[3].feedback_order.clone()), (4, vec![false, true]));
    assert_eq!(plan[3].technique_order, vec![J, PA, P]);
}

#[test]
fn other_participant_counts_balance_only_in_whole_units() {
    // 12 participants: two Latin squares per group; each Williams row twice.
    let twelve = StudyDesign { participants: 12, ..StudyDesign::default() };
    assert_eq!(twelve.balance_note(), None);
    assert!(positions_per_group(&twelve).values().all(|&c| c == 2));
    // 4 techniques with on/off: a unit is 8 (a 4-row square per group).
    let four = StudyDesign {
        participants: 8,
        techniques: vec![TechniqueKind::DIRECT, TechniqueKind::JOINT, TechniqueKind::PROXY, TechniqueKind::PARTICLE],
        ..StudyDesign::default()
    };
    assert_eq!(four.balance_unit(), 8);
    assert_eq!(four.balance_note(), None);
    let counts = positions_per_group(&four);
    assert_eq!(counts.len(), 2 * 4 * 4);
    assert!(counts.values().all(|&c| c == 1));
    // One feedback level: 3 techniques need the whole doubled square (6).
    let one_level = StudyDesign { feedback: vec![true], ..StudyDesign::default() };
    assert_eq!(one_level.balance_unit(), 6);
    assert_eq!(one_level.balance_note(), None);
    // 5 participants: the off-first group (P2, P4) has only 2 of the 3 rows,
    // so a technique never comes first there. The run goes ahead; the note says so.
    let five = StudyDesign { participants: 5, ..StudyDesign::default() };
    let note = five.balance_note().expect("5 participants are unbalanced");
    assert!(note.contains("multiple of 6"), "{note}");
    let counts = positions_per_group(&five);
    let first_off: usize = [TechniqueKind::JOINT, TechniqueKind::PROXY, TechniqueKind::PARTICLE]
        .iter()
        .filter(|t| !counts.contains_key(&(false, 0, **t)))
        .count();
    assert_eq!(first_off, 1, "{counts:?}");
    // 3 participants: every group position still distinct, but not a square.
    assert!(StudyDesign { participants: 3, ..StudyDesign::default() }.balance_note().is_some());
}

#[test]
fn trials_follow_the_documented_order() {
    let design = StudyDesign::default();
    let trials = design.trials();
    assert_eq!(trials.len(), 6 * 3 * 3 * 2 * 3);
    for p in 1..=design.participants {
        let mine: Vec<&TrialSpec> = trials.iter().filter(|t| t.participant == p).collect();
        assert_eq!(mine.len(), design.trials_per_participant());
        for (i, t) in mine.iter().enumerate() {
            assert_eq!(t.order_index as usize, i);
            assert_eq!(t.seed, trial_seed(design.seed, p, t.order_index));
        }
        // Feedback is the outermost loop: two phases.
        let (first, second) = mine.split_at(mine.len() / 2);
        let fb = design.feedback_order(p);
        assert!(first.iter().all(|t| t.feedback == fb[0]));
        assert!(second.iter().all(|t| t.feedback == fb[1]));
        for phase in [first, second] {
            // Tasks in the fixed order; techniques in the participant's order;
            // a practice trial, then repetitions 1 and 2.
            let per_task = phase.len() / 3;
            for (k, task) in design.tasks.iter().enumerate() {
                let block = &phase[k * per_task..(k + 1) * per_task];
                assert!(block.iter().all(|t| t.task == *task));
                for (j, tech) in design.technique_order(p).iter().enumerate() {
                    let cond = &block[j * 3..(j + 1) * 3];
                    assert!(cond.iter().all(|t| t.technique == *tech));
                    let reps: Vec<(u32, bool)> = cond.iter().map(|t| (t.repetition, t.practice)).collect();
                    assert_eq!(reps, vec![(0, true), (1, false), (2, false)]);
                }
            }
        }
    }
    let seeds: HashSet<u64> = trials.iter().map(|t| t.seed).collect();
    assert_eq!(seeds.len(), trials.len(), "per-trial seeds are distinct");
}

#[test]
fn trial_seed_is_pinned() {
    // Changing the derivation silently changes every study: pin it.
    assert_ne!(trial_seed(2008, 1, 0), trial_seed(2008, 2, 0));
    assert_ne!(trial_seed(2008, 1, 0), trial_seed(2008, 1, 1));
    assert_ne!(trial_seed(2008, 1, 0), trial_seed(2009, 1, 0));
    // SplitMix64 reference values (checked against an independent implementation).
    assert_eq!(trial_seed(0, 0, 0), 2_558_736_989_570_252_433);
    assert_eq!(trial_seed(2008, 1, 0), 11_557_530_948_959_760_072);
    assert_eq!(trial_seed(2008, 6, 17), 1_909_189_887_271_887_205);
}

#[test]
fn invalid_designs_are_rejected() {
    let ok = StudyDesign::default();
    assert!(ok.validate().is_ok());
    let bad = [
        StudyDesign { participants: 0, ..ok.clone() },
        StudyDesign { tasks: vec![], ..ok.clone() },
        StudyDesign { tasks: vec!["sorting".into(), "sorting".into()], ..ok.clone() },
        StudyDesign { techniques: vec![TechniqueKind::JOINT, TechniqueKind::JOINT], ..ok.clone() },
        StudyDesign { feedback: vec![], ..ok.clone() },
        StudyDesign { repetitions: 0, ..ok.clone() },
        StudyDesign { seed: u64::MAX, ..ok.clone() },
        StudyDesign { time_limit_override: Some(-1.0), ..ok.clone() },
    ];
    for d in bad {
        assert!(matches!(d.validate(), Err(StudyError::Design(_))), "{d:?}");
    }
}

#[test]
fn technique_and_shard_parse_and_print() {
    // The names are file contracts: trials.csv and run.toml spell them so.
    let names: Vec<String> = TechniqueKind::BUILT_IN.iter().map(ToString::to_string).collect();
    assert_eq!(names, ["direct", "joint", "proxy", "particle", "hybrid"]);
    for t in TechniqueKind::BUILT_IN {
        assert_eq!(t.to_string().parse::<TechniqueKind>().ok(), Some(t));
    }
    assert_eq!(" Particle ".parse::<TechniqueKind>().ok(), Some(TechniqueKind::PARTICLE));
    assert!("spring".parse::<TechniqueKind>().is_err());
    let s: Shard = "1/4".parse().expect("shard");
    assert_eq!(s, Shard { index: 1, count: 4 });
    assert_eq!(s.to_string(), "1/4");
    for bad in ["4/4", "1", "a/b", "0/0", "-1/3"] {
        assert!(bad.parse::<Shard>().is_err(), "{bad}");
    }
}

// ---------------------------------------------------------------- files

#[test]
fn csv_header_matches_row_fields() {
    let spec = &StudyDesign::default().trials()[0];
    let row = TrialRow::failed(spec);
    let mut w = csv::Writer::from_writer(Vec::new());
    w.serialize(&row).expect("serialize");
    let text = String::from_utf8(w.into_inner().expect("flush")).expect("utf8");
    // The file format is a contract: renaming or reordering a column must fail here.
    assert_eq!(
        text.lines().next(),
        Some(
            "participant,order_index,task,technique,feedback,repetition,practice,completion_time_s,completed,\
             restarts,objects_placed,steps,seed,version,strategy,hands_max,fingers_max,objects_moving_max,manners"
        )
    );
    // A failed trial has an empty time.
    assert!(text.lines().nth(1).expect("row").contains(",,false,"));
}

#[test]
fn row_counts_match_the_design() {
    let dir = scratch("row_counts");
    let design = StudyDesign::default();
    let runner = FakeRunner::default();
    let out = run_study(&design, &dir, &runner, &quiet(2)).expect("run");
    assert_eq!(out.trials, 324);
    assert_eq!(out.ran, 324);
    assert!(out.reported);
    let rows = read_trials(&dir.join(TRIALS_CSV)).expect("rows");
    assert_eq!(rows.len(), 324);
    assert_eq!(rows.iter().filter(|r| !r.practice).count(), 216, "6 x 3 x 3 x 2 x 2 measured");
    assert_eq!(rows.iter().filter(|r| r.practice).count(), 108, "one practice per condition");
    assert_eq!(String::from_utf8(read(&dir.join(TRIALS_CSV))).expect("utf8").lines().count(), 325);
    for name in [RUN_TOML, SUMMARY_CSV, "figure.png", "figure.svg"] {
        assert!(dir.join(name).is_file(), "{name} written");
    }
    let png = read(&dir.join("figure.png"));
    assert!(png.starts_with(b"\x89PNG") && png.len() > 10_000);

    let dir = scratch("row_counts_no_practice");
    let design = StudyDesign { practice: false, ..StudyDesign::default() };
    run_study(&design, &dir, &FakeRunner::default(), &quiet(2)).expect("run");
    let rows = read_trials(&dir.join(TRIALS_CSV)).expect("rows");
    assert_eq!(rows.len(), 216);
    assert!(rows.iter().all(|r| !r.practice && r.repetition >= 1));
}

#[test]
fn same_seed_gives_byte_identical_trials_csv() {
    let design = StudyDesign { participants: 3, ..StudyDesign::default() };
    let a = scratch("determinism_a");
    let b = scratch("determinism_b");
    run_study(&design, &a, &FakeRunner::default(), &quiet(1)).expect("run a");
    run_study(&design, &b, &FakeRunner::jittery(), &quiet(4)).expect("run b");
    assert_eq!(read(&a.join(TRIALS_CSV)), read(&b.join(TRIALS_CSV)));
    assert_eq!(read(&a.join(SUMMARY_CSV)), read(&b.join(SUMMARY_CSV)));
    let c = scratch("determinism_c");
    run_study(&StudyDesign { seed: 7, ..design }, &c, &FakeRunner::default(), &quiet(2)).expect("run c");
    assert_ne!(read(&a.join(TRIALS_CSV)), read(&c.join(TRIALS_CSV)));
}

#[test]
fn an_existing_run_is_not_overwritten() {
    let dir = scratch("no_overwrite");
    run_study(&small_design(), &dir, &FakeRunner::default(), &quiet(1)).expect("run");
    let again = run_study(&small_design(), &dir, &FakeRunner::default(), &quiet(1));
    assert!(matches!(again, Err(StudyError::AlreadyExists { .. })));
}

/// [`small_design`] run to its end by the default fake runner in scratch
/// folder `name`: the folder and the bytes of its `trials.csv`.
fn reference_run(name: &str) -> (PathBuf, Vec<u8>) {
    let reference = scratch(name);
    run_study(&small_design(), &reference, &FakeRunner::default(), &quiet(1)).expect("reference");
    let full = read(&reference.join(TRIALS_CSV));
    (reference, full)
}

/// Copies a run's `run.toml` and the first `cut` bytes of its `trials.csv`
/// into a new folder, as a `kill -9` at that byte would leave it.
fn killed_copy(reference: &Path, name: &str, cut: usize) -> PathBuf {
    let dir = scratch(name);
    std::fs::copy(reference.join(RUN_TOML), dir.join(RUN_TOML)).expect("copy run.toml");
    std::fs::write(dir.join(TRIALS_CSV), &read(&reference.join(TRIALS_CSV))[..cut]).expect("write partial");
    dir
}

#[test]
fn resume_after_kill_runs_only_missing_trials() {
    let design = small_design();
    let (reference, full) = reference_run("resume_reference");
    let total = design.trial_count();
    let line_ends: Vec<usize> = full.iter().enumerate().filter(|(_, b)| **b == b'\n').map(|(i, _)| i + 1).collect();
    assert_eq!(line_ends.len(), total + 1);

    // Cut: inside the header, right after it, mid-row at several places,
    // exactly at a row boundary, one byte before the end, and nothing missing.
    let mid = |k: usize| line_ends[k] + (line_ends[k + 1] - line_ends[k]) / 2;
    let cuts = [0, 5, line_ends[0], mid(0), mid(7), line_ends[10], mid(total - 1), full.len() - 1, full.len()];
    for (i, &cut) in cuts.iter().enumerate() {
        let dir = killed_copy(&reference, &format!("resume_cut_{i}"), cut);
        let complete_rows = line_ends.iter().filter(|&&e| e <= cut).count().saturating_sub(1);
        let runner = FakeRunner::jittery();
        let options = RunOptions { fsync: true, ..quiet(3) };
        let out = resume_study(&dir, &runner, &options).expect("resume");
        assert_eq!(runner.calls(), total - complete_rows, "cut {cut}: only missing trials run");
        assert_eq!(out.already_done, complete_rows);
        assert_eq!(out.ran, total - complete_rows);
        let partial = cut > line_ends[0] && !line_ends.contains(&cut);
        assert_eq!(out.dropped_bytes > 0, partial || (cut > 0 && cut < line_ends[0]), "cut {cut}");
        assert_eq!(read(&dir.join(TRIALS_CSV)), full, "cut {cut}: same bytes as an uninterrupted run");
        assert!(out.reported);
    }
}

#[test]
fn resume_drops_an_unreadable_last_row_and_rejects_other_damage() {
    let design = small_design();
    let (reference, full) = reference_run("damage_reference");

    // A whole line of garbage at the end (e.g. a power cut leaving zeros).
    let dir = scratch("damage_last");
    std::fs::copy(reference.join(RUN_TOML), dir.join(RUN_TOML)).expect("copy");
    let mut bytes = full[..full.len() / 2].to_vec();
    let keep = bytes.iter().rposition(|&b| b == b'\n').expect("newline") + 1;
    bytes.truncate(keep);
    bytes.extend_from_slice(b"1,2,pos\0\0\0\n");
    std::fs::write(dir.join(TRIALS_CSV), &bytes).expect("write");
    resume_study(&dir, &FakeRunner::default(), &quiet(2)).expect("resume");
    assert_eq!(read(&dir.join(TRIALS_CSV)), full);

    // Damage before the last row is not what a crash leaves: refuse.
    let dir = scratch("damage_middle");
    std::fs::copy(reference.join(RUN_TOML), dir.join(RUN_TOML)).expect("copy");
    let mut text = String::from_utf8(full.clone()).expect("utf8");
    let second_row = text.match_indices('\n').nth(1).expect("rows").0 + 1;
    text.insert_str(second_row, "garbage\n");
    std::fs::write(dir.join(TRIALS_CSV), text).expect("write");
    assert!(resume_study(&dir, &FakeRunner::default(), &quiet(2)).is_err());

    // Rows from another design (another seed) are refused.
    let dir = scratch("damage_design");
    let other = RunFile::new(StudyDesign { seed: 99, ..design }, None);
    other.save(&dir.join(RUN_TOML)).expect("save");
    std::fs::write(dir.join(TRIALS_CSV), &full).expect("write");
    assert!(matches!(resume_study(&dir, &FakeRunner::default(), &quiet(2)), Err(StudyError::Mismatch { .. })));
}

#[test]
fn resume_of_a_complete_run_runs_nothing() {
    let dir = scratch("resume_complete");
    run_study(&small_design(), &dir, &FakeRunner::default(), &quiet(2)).expect("run");
    let before = read(&dir.join(TRIALS_CSV));
    let runner = FakeRunner::default();
    let out = resume_study(&dir, &runner, &quiet(2)).expect("resume");
    assert_eq!((runner.calls(), out.ran), (0, 0));
    assert_eq!(read(&dir.join(TRIALS_CSV)), before);
}

#[test]
fn resume_restores_trial_order_of_a_hand_edited_file() {
    // Someone deleted a row in the middle to rerun that trial.
    let (reference, full) = reference_run("edited_reference");
    let full = String::from_utf8(full).expect("utf8");
    let mut lines: Vec<&str> = full.lines().collect();
    lines.remove(5);
    let dir = scratch("edited");
    std::fs::copy(reference.join(RUN_TOML), dir.join(RUN_TOML)).expect("copy");
    std::fs::write(dir.join(TRIALS_CSV), lines.join("\n") + "\n").expect("write");
    let runner = FakeRunner::default();
    resume_study(&dir, &runner, &quiet(2)).expect("resume");
    assert_eq!(runner.calls(), 1);
    assert_eq!(String::from_utf8(read(&dir.join(TRIALS_CSV))).expect("utf8"), full);
}

#[test]
fn failing_trials_are_recorded_not_fatal() {
    let dir = scratch("failures");
    let design = small_design();
    let runner = FakeRunner { fail_modulo: Some(5), panic_at: Some(3), ..FakeRunner::default() };
    let out = run_study(&design, &dir, &runner, &quiet(2)).expect("a failing trial does not abort the study");
    let trials = design.trials();
    let expected: usize = trials.iter().filter(|t| t.seed % 5 == 0 || t.order_index == 3).count();
    assert!(expected > 2, "the test needs some failures");
    assert_eq!(out.errors, expected);
    let rows = read_trials(&dir.join(TRIALS_CSV)).expect("rows");
    assert_eq!(rows.len(), trials.len());
    for (row, spec) in rows.iter().zip(&trials) {
        let failed = spec.seed % 5 == 0 || spec.order_index == 3;
        assert_eq!(row.completion_time_s.is_none(), failed);
        if failed {
            assert!(!row.completed && row.steps == 0);
        }
    }
    let log = std::fs::read_to_string(dir.join("errors.log")).expect("errors.log");
    assert_eq!(log.lines().count(), expected);
    assert!(log.contains("scripted failure") && log.contains("panicked: scripted panic"));
    // Failed = not completed: the runner's errors plus the fake's timeouts.
    assert_eq!(out.failed, rows.iter().filter(|r| !r.completed).count());
    assert!(out.failed > out.errors);
    let summary = summarize(&design, &rows);
    assert_eq!(
        summary.iter().map(|s| s.errors as usize).sum::<usize>(),
        rows.iter().filter(|r| !r.practice && r.completion_time_s.is_none()).count()
    );
    assert_eq!(
        summary.iter().map(|s| s.failed as usize).sum::<usize>(),
        rows.iter().filter(|r| !r.practice && !r.completed).count()
    );
}

// ---------------------------------------------------------------- statistics

#[test]
fn t_quantiles() {
    assert!((t_quantile_975(1) - 12.706_204_736).abs() < 1e-9);
    assert!((t_quantile_975(5) - 2.570_581_836).abs() < 1e-9);
    // Beyond the table: the expansion, against known values.
    assert!((t_quantile_975(40) - 2.021_075_390).abs() < 2e-6);
    assert!((t_quantile_975(120) - 1.979_930_405).abs() < 1e-6);
    assert!((t_quantile_975(100_000) - 1.959_963_984).abs() < 1e-4);
    for df in 1..300 {
        assert!(t_quantile_975(df + 1) < t_quantile_975(df), "decreasing at {df}");
    }
}

#[test]
fn describe_hand_made_sample() {
    let s = describe(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]).expect("stats");
    assert_eq!(s.n, 8);
    assert!((s.mean - 5.0).abs() < 1e-12);
    assert!((s.sd.expect("sd") - 2.138_089_935_299_395).abs() < 1e-12);
    assert!((s.ci95_half_width.expect("ci") - 1.787_487_918_544).abs() < 1e-9);
    let one = describe(&[3.0]).expect("stats");
    assert_eq!((one.mean, one.sd, one.ci95_half_width), (3.0, None, None));
    assert!(describe(&[]).is_none());
}

#[test]
fn summary_of_hand_made_rows() {
    let design = StudyDesign {
        participants: 3,
        tasks: vec!["sorting".into()],
        techniques: vec![TechniqueKind::PROXY],
        feedback: vec![true],
        ..StudyDesign::default()
    };
    let spec = |participant, repetition, practice| TrialSpec {
        participant,
        order_index: repetition,
        task: "sorting".into(),
        technique: TechniqueKind::PROXY,
        feedback: true,
        repetition,
        practice,
        seed: 0,
    };
    let done = |t: f64, completed| TrialResult { completion_time_s: t, completed, ..TrialResult::default() };
    let rows = vec![
        TrialRow::new(&spec(1, 0, true), &done(500.0, true)), // practice: ignored
        TrialRow::new(&spec(1, 1, false), &done(10.0, true)),
        TrialRow::new(&spec(1, 2, false), &done(12.0, true)),
        TrialRow::new(&spec(2, 1, false), &done(20.0, false)), // timed out: counts with its time
        TrialRow::failed(&spec(2, 2, false)),                  // no time
        TrialRow::new(&spec(3, 1, false), &done(14.0, true)),
        TrialRow::new(&spec(3, 2, false), &done(16.0, true)),
        // Another condition: ignored.
        TrialRow::new(&TrialSpec { feedback: false, ..spec(3, 3, false) }, &done(99.0, true)),
    ];
    let summary = summarize(&design, &rows);
    assert_eq!(summary.len(), 1);
    let s = &summary[0];
    // Failed: the timed-out trial and the runner failure; errors: the latter.
    assert_eq!((s.participants, s.trials, s.completed, s.failed, s.errors), (3, 6, 4, 2, 1));
    // Participant means 11, 20, 15.
    let close = |a: Option<f64>, b: f64| (a.expect("value") - b).abs() < 1e-9;
    assert!(close(s.mean_s, 15.333_333_333_333_334));
    assert!(close(s.sd_s, 4.509_249_752_822_894));
    assert!(close(s.ci95_low_s, 4.131_735_969_992_873));
    assert!(close(s.ci95_high_s, 26.534_930_696_673_797));

    let dir = scratch("summary_file");
    let path = dir.join(SUMMARY_CSV);
    surfacelab::harness::study::write_summary(&path, &summary).expect("write");
    assert_eq!(surfacelab::harness::study::read_summary(&path).expect("read"), summary);
    let text = std::fs::read_to_string(&path).expect("text");
    assert!(text.starts_with(
        "task,technique,feedback,participants,trials,completed,failed,mean_s,sd_s,ci95_low_s,ci95_high_s,errors,ci95_within_low_s,ci95_within_high_s\n"
    ));
}

#[test]
fn learning_participants_resume_and_shard_to_the_same_bytes() {
    let design = StudyDesign { participants: 4, repetitions: 1, ..StudyDesign::default() };
    let reference = scratch("learning_reference");
    let fake = LearningFake::default();
    run_study(&design, &reference, &fake, &quiet(3)).expect("reference");
    assert_eq!(fake.runs.load(Ordering::SeqCst), design.trial_count());
    assert_eq!(fake.replays.load(Ordering::SeqCst), 0, "an uninterrupted run replays nothing");
    let full = read(&reference.join(TRIALS_CSV));
    let line_ends: Vec<usize> = full.iter().enumerate().filter(|(_, b)| **b == b'\n').map(|(i, _)| i + 1).collect();
    let per = design.trials_per_participant();
    // Killed in the middle of participant 2: their first `done` trials are
    // replayed, the rest run; participants 3 and 4 run from scratch.
    for done in [1, per / 2, per - 1] {
        let cut = line_ends[per + done];
        let dir = killed_copy(&reference, &format!("learning_cut_{done}"), cut);
        let fake = LearningFake::default();
        let out = resume_study(&dir, &fake, &quiet(2)).expect("resume");
        assert_eq!(out.already_done, per + done);
        assert_eq!(fake.replays.load(Ordering::SeqCst), done, "participant 2's finished trials replayed once");
        assert_eq!(read(&dir.join(TRIALS_CSV)), full, "resumed after {done}: same bytes");
    }
    // Shards hold whole participants: no replays, and the merge is the run.
    let mut dirs = Vec::new();
    for i in 0..2 {
        let dir = scratch(&format!("learning_shard_{i}"));
        let fake = LearningFake::default();
        let options = RunOptions { shard: Some(Shard::new(i, 2).expect("shard")), ..quiet(2) };
        run_study(&design, &dir, &fake, &options).expect("shard");
        assert_eq!(fake.replays.load(Ordering::SeqCst), 0);
        dirs.push(dir);
    }
    let merged = scratch("learning_merged");
    merge(&merged, &dirs).expect("merge");
    assert_eq!(read(&merged.join(TRIALS_CSV)), full);
}

#[test]
fn strategies_csv_sums_manner_time_per_condition() {
    let dir = scratch("strategies");
    let design =
        StudyDesign { participants: 2, repetitions: 2, tasks: vec!["sorting".into()], ..StudyDesign::default() };
    run_study(&design, &dir, &FakeRunner::default(), &quiet(2)).expect("run");
    let text = String::from_utf8(read(&dir.join("strategies.csv"))).expect("utf8");
    assert_eq!(text.lines().next(), Some("participant,task,technique,feedback,manner,time_s,time_share,payoff"));
    let rows = surfacelab::harness::study::read_strategies(&dir.join("strategies.csv")).expect("read");
    // 2 participants x 3 techniques x 2 feedback levels, two manners each.
    assert_eq!(rows.len(), 2 * 3 * 2 * 2);
    let trials = read_trials(&dir.join(TRIALS_CSV)).expect("trials");
    for r in &rows {
        let measured: Vec<&TrialRow> = trials
            .iter()
            .filter(|t| {
                !t.practice && t.participant == r.participant && t.technique == r.technique && t.feedback == r.feedback
            })
            .collect();
        assert_eq!(measured.len(), 2);
        // FakeRunner spends 3/4 of each trial in the finger, 1/4 in the hand,
        // at net 0.5 m and 0.25 m per trial.
        let total: f64 = measured.iter().map(|t| t.completion_time_s.expect("time")).sum();
        let (share, net) = if r.manner == "fingertip_1" { (0.75, 1.0) } else { (0.25, 0.5) };
        assert!((r.time_share - share).abs() < 1e-3, "{r:?}");
        assert!((r.time_s - total * share).abs() < 0.02, "{r:?}");
        assert!((r.payoff - net / (total * share)).abs() < 1e-3, "{r:?}");
    }
}

// ---------------------------------------------------------------- shards

#[test]
fn shards_merge_into_the_single_run() {
    let design = StudyDesign { participants: 3, ..StudyDesign::default() };
    let single = scratch("shard_single");
    run_study(&design, &single, &FakeRunner::default(), &quiet(2)).expect("single");

    let mut dirs = Vec::new();
    let mut ran = 0;
    for i in 0..3 {
        let dir = scratch(&format!("shard_{i}"));
        let options = RunOptions { shard: Some(Shard::new(i, 3).expect("shard")), ..quiet(2) };
        let out = run_study(&design, &dir, &FakeRunner::jittery(), &options).expect("shard");
        assert!(!out.reported, "a shard alone writes no summary");
        ran += out.ran;
        let rows = read_trials(&dir.join(TRIALS_CSV)).expect("rows");
        let trials = design.trials();
        for row in &rows {
            assert!(trials.contains(&row.spec()), "known trial");
            assert_eq!((row.participant - 1) % 3, i, "shards split by participant");
        }
        assert_eq!(rows.len(), design.trials_per_participant(), "one participant per shard");
        dirs.push(dir);
    }
    assert_eq!(ran, design.trial_count());

    let merged = scratch("shard_merged");
    dirs.reverse(); // order of the folders does not matter
    let out = merge(&merged, &dirs).expect("merge");
    assert_eq!(out.trials, design.trial_count());
    assert_eq!(read(&merged.join(TRIALS_CSV)), read(&single.join(TRIALS_CSV)));
    assert_eq!(read(&merged.join(SUMMARY_CSV)), read(&single.join(SUMMARY_CSV)));
    assert_eq!(read(&merged.join(RUN_TOML)), read(&single.join(RUN_TOML)));
    // Merging again into the same folder is allowed (same design).
    merge(&merged, &dirs).expect("merge again");

    // A missing shard, a duplicated shard, or a foreign design: refused.
    assert!(matches!(merge(&scratch("shard_missing"), &dirs[..2]), Err(StudyError::Merge(_))));
    let twice = vec![dirs[0].clone(), dirs[0].clone(), dirs[1].clone(), dirs[2].clone()];
    assert!(matches!(merge(&scratch("shard_twice"), &twice), Err(StudyError::Merge(_))));
    let foreign = scratch("shard_foreign");
    run_study(&small_design(), &foreign, &FakeRunner::default(), &quiet(2)).expect("foreign");
    let mixed = vec![dirs[0].clone(), dirs[1].clone(), foreign];
    assert!(matches!(merge(&scratch("shard_mixed"), &mixed), Err(StudyError::Merge(_))));
}

#[test]
fn a_shard_resumes_as_itself() {
    let design = small_design();
    let dir = scratch("shard_resume");
    let shard = Shard::new(1, 2).expect("shard");
    let options = RunOptions { shard: Some(shard), ..quiet(2) };
    run_study(&design, &dir, &FakeRunner::default(), &options).expect("run");
    let full = read(&dir.join(TRIALS_CSV));
    std::fs::write(dir.join(TRIALS_CSV), &full[..full.len() * 2 / 3]).expect("cut");
    let runner = FakeRunner::default();
    resume_study(&dir, &runner, &quiet(2)).expect("resume takes the shard from run.toml");
    assert!(runner.calls() > 0);
    assert_eq!(read(&dir.join(TRIALS_CSV)), full);
    let wrong = RunOptions { shard: Some(Shard::new(0, 2).expect("shard")), ..quiet(2) };
    assert!(resume_study(&dir, &FakeRunner::default(), &wrong).is_err());
}

// ---------------------------------------------------------------- run.toml

#[test]
fn run_toml_settings_keep_their_on_disk_format() {
    // `[design.settings]` as earlier versions wrote it (`--frames`,
    // `--replay`) and as docs/file-formats.md tells people to write it (an integer
    // delay is a number of seconds too).
    let dir = scratch("run_toml_settings");
    let head = "format = \"surfacelab-study/2\"\nversion = \"0\"\n[design]\nparticipants = 2\n[design.settings]\n";
    std::fs::write(dir.join("old.toml"), format!("{head}frames = true\nreplay = \"rec\"\nperception_delay_s = 0.15\n"))
        .expect("write");
    let settings = RunFile::load(&dir.join("old.toml")).expect("an existing run.toml loads").design.settings;
    assert_eq!(
        settings,
        RunnerSettings {
            frames: true,
            perception_delay_s: Some(0.15),
            replay: Some(PathBuf::from("rec")),
            manners: None
        }
    );
    std::fs::write(dir.join("int.toml"), format!("{head}perception_delay_s = 1\n")).expect("write");
    let settings = RunFile::load(&dir.join("int.toml")).expect("integer seconds").design.settings;
    assert_eq!(settings.perception_delay_s, Some(1.0));
    assert!(!settings.frames && settings.replay.is_none());
    // Written back under the same keys, and not at all when nothing is set.
    let text = RunFile::new(StudyDesign { settings: settings.clone(), ..StudyDesign::default() }, None)
        .to_toml()
        .expect("toml");
    assert!(text.contains("[design.settings]\nperception_delay_s = 1.0\n"), "{text}");
    let text = RunFile::new(StudyDesign::default(), None).to_toml().expect("toml");
    assert!(!text.contains("settings"), "{text}");
    // A misspelt or mistyped setting is refused, not silently ignored.
    for bad in ["frame = true\n", "frames = \"yes\"\n"] {
        std::fs::write(dir.join("bad.toml"), format!("{head}{bad}")).expect("write");
        let err = RunFile::load(&dir.join("bad.toml")).expect_err(bad);
        assert!(matches!(err, StudyError::TomlRead { .. }), "{bad}: {err}");
    }
    let negative = StudyDesign {
        settings: RunnerSettings { perception_delay_s: Some(-0.1), ..RunnerSettings::default() },
        ..StudyDesign::default()
    };
    assert!(negative.validate().is_err());
}

#[test]
fn run_toml_round_trips() {
    let settings = RunnerSettings {
        frames: true,
        perception_delay_s: Some(0.15),
        replay: Some("gestures/p1".into()),
        manners: None,
    };
    let design = StudyDesign {
        participants: 4,
        tasks: vec!["steering".into(), "positioning".into()],
        techniques: vec![TechniqueKind::DIRECT, TechniqueKind::PARTICLE],
        feedback: vec![false, true],
        repetitions: 3,
        practice: false,
        seed: 123_456_789,
        time_limit_override: Some(42.5),
        settings,
    };
    let run = RunFile::new(design.clone(), Some(Shard::new(2, 5).expect("shard")));
    let text = run.to_toml().expect("toml");
    let back: RunFile = toml::from_str(&text).expect("parse");
    assert_eq!(back, run);

    let dir = scratch("run_toml");
    run.save(&dir.join(RUN_TOML)).expect("save");
    assert_eq!(RunFile::load(&dir.join(RUN_TOML)).expect("load"), run);

    // A hand-written file may give only some fields; the rest are the paper's.
    std::fs::write(
        dir.join("mine.toml"),
        "format = \"surfacelab-study/2\"\nversion = \"0\"\n[design]\nparticipants = 12\ntechniques = [\"joint\", \"particle\"]\n",
    )
    .expect("write");
    let mine = RunFile::load(&dir.join("mine.toml")).expect("load partial");
    assert_eq!(mine.design.participants, 12);
    assert_eq!(mine.design.techniques, vec![TechniqueKind::JOINT, TechniqueKind::PARTICLE]);
    assert_eq!(mine.design.tasks, StudyDesign::default().tasks);

    // The design table is written, and a table that contradicts the design is refused.
    let saved = std::fs::read_to_string(dir.join(RUN_TOML)).expect("text");
    assert_eq!(saved.matches("[[plan]]").count(), 4, "{saved}");
    let mut wrong = run.clone();
    wrong.plan[1].technique_order.reverse();
    wrong.save(&dir.join("wrong.toml")).expect("save");
    let err = RunFile::load(&dir.join("wrong.toml")).expect_err("a wrong table is refused");
    assert!(matches!(err, StudyError::Mismatch { .. }) && err.to_string().contains("participant 2"), "{err}");

    // Typos are errors, not silently ignored.
    std::fs::write(
        dir.join("typo.toml"),
        "format = \"surfacelab-study/2\"\nversion = \"0\"\n[design]\nparticipant = 12\n",
    )
    .expect("write");
    assert!(matches!(RunFile::load(&dir.join("typo.toml")), Err(StudyError::TomlRead { .. })));
}

#[test]
fn a_run_from_its_own_run_toml_reproduces_it() {
    let design = StudyDesign { participants: 2, seed: 77, ..StudyDesign::default() };
    let first = scratch("from_first");
    run_study(&design, &first, &FakeRunner::default(), &quiet(2)).expect("first");
    let again = RunFile::load(&first.join(RUN_TOML)).expect("load").design;
    assert_eq!(again, design);
    let second = scratch("from_second");
    run_study(&again, &second, &FakeRunner::default(), &quiet(1)).expect("second");
    assert_eq!(read(&first.join(TRIALS_CSV)), read(&second.join(TRIALS_CSV)));
}

// ---------------------------------------------------------------- figure

/// Fails every Direct trial: that condition has no time at all.
struct NoDirect(FakeRunner);

impl TrialRunner for NoDirect {
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        anyhow::ensure!(spec.technique != TechniqueKind::DIRECT, "direct force is not scripted");
        self.0.run(spec)
    }
}

#[test]
fn figure_copes_with_sparse_data() {
    // One participant (no SD, no CI), one feedback level, a technique with
    // no data, two tasks: the figure is still drawn, in both formats.
    let design = StudyDesign {
        participants: 1,
        tasks: vec!["sorting".into(), "steering".into()],
        techniques: TechniqueKind::BUILT_IN.to_vec(),
        feedback: vec![false],
        ..StudyDesign::default()
    };
    let dir = scratch("figure_sparse");
    let out = run_study(&design, &dir, &NoDirect(FakeRunner::default()), &quiet(2)).expect("run");
    assert!(out.reported && out.failed > 0);
    let png = read(&dir.join("figure.png"));
    assert!(png.starts_with(b"\x89PNG"));
    let svg = String::from_utf8(read(&dir.join("figure.svg"))).expect("svg text");
    assert!(svg.contains("Particle") && svg.contains("Feedback off") && !svg.contains("Feedback on"));
    let summary = surfacelab::harness::study::read_summary(&dir.join(SUMMARY_CSV)).expect("summary");
    // Two tasks, every technique.
    assert_eq!(summary.len(), 2 * 5);
    assert!(
        summary.iter().filter(|s| s.technique == TechniqueKind::DIRECT).all(|s| s.mean_s.is_none() && s.failed == 2)
    );
    assert!(summary.iter().all(|s| s.sd_s.is_none()));
}

/// Every CSV the study writes keeps its header: the columns are a contract
/// with whoever reads the files, so they are pinned here as literal text
/// (not through the constants the writers use).
#[test]
fn every_study_file_header_is_pinned() {
    let dir = scratch("headers");
    let design = StudyDesign { participants: 2, repetitions: 1, ..StudyDesign::default() };
    run_study(&design, &dir, &FakeRunner::default(), &quiet(2)).expect("run");
    let header = |name: &str| {
        let text = String::from_utf8(read(&dir.join(name))).unwrap_or_else(|e| panic!("{name}: {e}"));
        text.lines().next().unwrap_or_default().to_owned()
    };
    assert_eq!(
        header("trials.csv"),
        "participant,order_index,task,technique,feedback,repetition,practice,completion_time_s,completed,\
         restarts,objects_placed,steps,seed,version,strategy,hands_max,fingers_max,objects_moving_max,manners"
    );
    assert_eq!(
        header("summary.csv"),
        "task,technique,feedback,participants,trials,completed,failed,mean_s,sd_s,ci95_low_s,ci95_high_s,\
         errors,ci95_within_low_s,ci95_within_high_s"
    );
    assert_eq!(header("anova.csv"), "task,effect,df1,df2,F,p,epsilon_gg,p_gg,eta_p2");
    assert_eq!(header("pairwise.csv"), "task,a,b,mean_diff_s,t,df,p_holm,dz");
    assert_eq!(header("strategies.csv"), "participant,task,technique,feedback,manner,time_s,time_share,payoff");
}
