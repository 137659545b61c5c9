//! The study's command line: failures counted at the time limit
//! (scripted and replayed), and `--seeds N`, through the real binary.

mod common;

use common::{cli, refused, replayed_study, run_cli_on, text, tmp};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Column `name` of every row of a CSV file.
fn column(path: &Path, name: &str) -> Vec<String> {
    let mut r = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let k = r.headers().expect("header").iter().position(|h| h == name).unwrap_or_else(|| panic!("no {name}"));
    r.records().map(|rec| rec.expect("record")[k].to_owned()).collect()
}

fn tiny(out: &Path) -> Command {
    let mut c = cli("study --participants 1 --reps 1 --no-practice --tasks positioning --time-limit 5 --no-progress");
    c.args(["--jobs", "2", "--out"]).arg(out);
    c
}

/// A [`tiny`] study run to its end in scratch folder `name`: the folder
/// (removed when dropped), the run's folder in it, and the output's text.
fn tiny_study(name: &str) -> (tempfile::TempDir, PathBuf, String) {
    let scratch = tmp(name);
    let out = scratch.path().join("run");
    let o = tiny(&out).output().expect("runs");
    assert!(o.status.success(), "{}", text(&o));
    (scratch, out, text(&o))
}

#[test]
fn a_short_time_limit_fails_every_trial_at_the_limit() {
    let (_scratch, out, said) = tiny_study("limit");
    // Nobody places eight objects in 5 s: 3 techniques x on/off, all failed.
    assert!(said.contains("6 failed: 6 at the time limit, 0 runner errors"), "{said}");
    assert!(said.contains("x per core"), "{said}");
    let trials = out.join("trials.csv");
    assert_eq!(column(&trials, "completed"), vec!["false"; 6]);
    for t in column(&trials, "completion_time_s") {
        assert_eq!(t.parse::<f64>().expect("time"), 5.0, "recorded at the limit");
    }
    assert_eq!(column(&out.join("summary.csv"), "failed"), vec!["1"; 6]);
    assert_eq!(column(&out.join("summary.csv"), "errors"), vec!["0"; 6]);
    let report = std::fs::read_to_string(out.join("report.md")).expect("report.md");
    assert!(report.contains("a mean with failures is a lower bound"), "{report}");
}

#[test]
fn a_replayed_trial_that_does_not_finish_is_recorded_at_the_limit() {
    let dir = tmp("replay");
    // A 2 s flat-hand press in the middle of the table places nothing.
    let line = "study --participants 1 --reps 1 --no-practice --tasks positioning --techniques joint --time-limit 30";
    let (out, o) = replayed_study(dir.path(), &[("positioning", "flatten")], &format!("{line} --no-progress"));
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("2 failed: 2 at the time limit"), "{}", text(&o));
    let trials = out.join("trials.csv");
    assert_eq!(column(&trials, "completed"), vec!["false"; 2]);
    // Not the gesture's end + 2 s (about 4 s): the 30 s limit.
    for t in column(&trials, "completion_time_s") {
        assert_eq!(t.parse::<f64>().expect("time"), 30.0);
    }
}

#[test]
fn seeds_run_independent_studies_and_count_findings() {
    let scratch_out = tmp("seeds");
    let out = scratch_out.path().join("many");
    let o = tiny(&out).args(["--seed", "7", "--seeds", "2"]).output().expect("runs");
    assert!(o.status.success(), "{}", text(&o));
    for k in [1, 2] {
        let run = out.join(format!("seed-{k}"));
        for file in ["run.toml", "trials.csv", "summary.csv", "anova.csv", "pairwise.csv", "report.md", "report.html"] {
            assert!(run.join(file).is_file(), "{} missing", run.join(file).display());
        }
    }
    assert!(!out.join("seed-0").exists() && !out.join("seed-3").exists());
    // Study 1 is the --seed itself; study 2 another, derived seed.
    let seed_of = |k: u32| {
        let text = std::fs::read_to_string(out.join(format!("seed-{k}/run.toml"))).expect("run.toml");
        let v: toml::Value = toml::from_str(&text).expect("toml");
        v["design"]["seed"].as_integer().expect("seed")
    };
    assert_eq!(seed_of(1), 7);
    assert_ne!(seed_of(2), 7);
    let findings = std::fs::read_to_string(out.join("findings.csv")).expect("findings.csv");
    let mut lines = findings.lines();
    assert_eq!(lines.next(), Some("finding,seeds,reproduced,share,wilson_low,wilson_high"));
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 5, "{findings}");
    assert!(rows[0].starts_with("joint_fastest_positioning,"), "{findings}");
    // One participant cannot test anything: no seed counts, no share.
    assert!(rows.iter().all(|r| r.ends_with(",0,0,,,")), "{findings}");
    let png = std::fs::read(out.join("seeds.png")).expect("seeds.png");
    assert!(png.starts_with(b"\x89PNG"));
    // The same folder again is refused (exit 2), not overwritten.
    let again = tiny(&out).args(["--seed", "7", "--seeds", "2"]).output().expect("runs");
    assert_eq!(again.status.code(), Some(2), "{}", text(&again));
}

/// A resume started while the run is still writing is refused
/// (exit 2, naming the process), and after the run is killed with SIGKILL
/// the lock it left is taken over and the run completes with one row per
/// trial.
#[test]
fn a_running_study_locks_its_folder_and_a_killed_one_does_not() {
    let scratch_out = tmp("lock");
    let out = scratch_out.path().join("run");
    let mut running = cli("study --participants 2 --reps 2 --no-progress --jobs 1 --out")
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("starts");
    let trials = out.join("trials.csv");
    let started = std::time::Instant::now();
    while !trials.exists() {
        assert!(started.elapsed().as_secs() < 120, "the study never wrote trials.csv");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let o = run_cli_on("study --no-progress --resume", &out);
    let still_running = running.try_wait().expect("wait").is_none();
    assert!(still_running, "the study finished before the resume could race it; make it longer");
    refused(&o, &[&format!("pid {}", running.id())]);
    running.kill().expect("SIGKILL");
    running.wait().expect("reaped");

    let o = run_cli_on("study --no-progress --resume", &out);
    assert!(o.status.success(), "the dead run's lock is taken over: {}", text(&o));
    let keys: Vec<(String, String)> =
        column(&trials, "participant").into_iter().zip(column(&trials, "order_index")).collect();
    let mut unique = keys.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), keys.len(), "one row per trial");
    // 2 participants x 3 tasks x 3 techniques x 2 feedback x (2 reps + 1 practice).
    assert_eq!(keys.len(), 108);
}

/// `--resume` runs exactly the recorded design: edited designs and
/// conflicting flags are refused (exit 2, naming the flag or the file), a
/// torn last row is reported when dropped, a folder without run.toml gets a
/// way forward, and a run.toml from before the design hash still resumes.
#[test]
fn resume_refuses_a_changed_design_and_says_what_it_drops() {
    let (_scratch, out, _) = tiny_study("resume");
    let run_toml = out.join("run.toml");
    let original = std::fs::read_to_string(&run_toml).expect("run.toml");
    assert!(original.contains("design_hash = \""), "{original}");
    let resume =
        |extra: &[&str]| cli("study --no-progress --jobs 2 --resume").arg(&out).args(extra).output().expect("runs");

    // Flags that would change the design.
    for (flag, value) in [("--seed", "99"), ("--participants", "2"), ("--time-limit", "9"), ("--replay", "assets")] {
        let o = resume(&[flag, value]);
        assert_eq!(o.status.code(), Some(2), "{flag}: {}", text(&o));
        assert!(text(&o).contains(&format!("{flag} {value} conflicts with the run being resumed")), "{}", text(&o));
    }
    // The same value as recorded is no conflict.
    let o = resume(&["--participants", "1", "--time-limit", "5"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o));

    // A hand-edited design.
    std::fs::write(&run_toml, original.replace("time_limit_override = 5.0", "time_limit_override = 7.0"))
        .expect("edit");
    let o = resume(&[]);
    refused(&o, &["run.toml: the design was edited after the run started"]);

    // A run.toml from before the hash resumes, with a note; a torn last row
    // is dropped, said, and its trial run again.
    let old: Vec<&str> = original.lines().filter(|l| !l.starts_with("design_hash")).collect();
    let old = old.join("\n") + "\n";
    std::fs::write(&run_toml, old).expect("old run.toml");
    let csv = out.join("trials.csv");
    let whole = std::fs::read(&csv).expect("trials.csv");
    let last_start = whole[..whole.len() - 1].iter().rposition(|&b| b == b'\n').expect("rows") + 1;
    std::fs::write(&csv, &whole[..last_start + 10]).expect("tear the last row");
    let o = resume(&[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o));
    assert!(text(&o).contains("written before run.toml carried a design hash"), "{}", text(&o));
    assert!(text(&o).contains("ended in a torn row (10 bytes"), "{}", text(&o));
    assert_eq!(std::fs::read(&csv).expect("trials.csv"), whole, "the torn trial ran again to the same row");

    // run.toml gone: resume and a fresh run both say what to do.
    std::fs::remove_file(&run_toml).expect("remove");
    let o = resume(&[]);
    refused(&o, &["run.toml is missing", "trials.csv.orphan"]);
    let o = tiny(&out).output().expect("runs");
    refused(&o, &["Its run.toml is gone", "trials.csv.orphan"]);
}

/// `--manners`: the study under the full repertoire and under the
/// restriction, each in its own folder, and every finding under both in
/// ablation.csv and ablation.md; the restricted participants use only the
/// manners allowed.
#[test]
fn the_manners_ablation_runs_each_repertoire_and_tabulates_the_findings() {
    let scratch = tmp("ablation");
    let out = scratch.path().join("abl");
    let o = run_cli_on(
        "study --participants 2 --reps 1 --no-practice --tasks positioning --techniques joint,particle --manners single-finger --no-progress --out",
        &out,
    );
    assert!(o.status.success(), "{}", text(&o));
    for arm in ["full", "single-finger"] {
        assert!(out.join(arm).join("seed-1/trials.csv").is_file(), "{arm}");
        assert!(out.join(arm).join("findings.csv").is_file(), "{arm}");
    }
    let manners = column(&out.join("single-finger/seed-1/trials.csv"), "manners");
    assert!(!manners.is_empty());
    for cell in &manners {
        assert!(cell.split(';').all(|item| item.starts_with("fingertip_1:")), "{cell}");
    }
    let full = column(&out.join("full/seed-1/trials.csv"), "manners");
    assert!(full.iter().any(|c| c.split(';').any(|item| !item.starts_with("fingertip_1:"))), "{full:?}");
    let run_toml = std::fs::read_to_string(out.join("single-finger/seed-1/run.toml")).expect("run.toml");
    assert!(run_toml.contains("manners = \"single-finger\""), "{run_toml}");

    let csv = std::fs::read_to_string(out.join("ablation.csv")).expect("ablation.csv");
    assert!(csv.starts_with("repertoire,finding,seeds,reproduced,share,wilson_low,wilson_high\n"), "{csv}");
    // Five findings under each of the two repertoires.
    assert_eq!(csv.lines().count(), 1 + 2 * 5, "{csv}");
    let md = std::fs::read_to_string(out.join("ablation.md")).expect("ablation.md");
    assert!(md.contains("| finding | full | single-finger |"), "{md}");
    // The sorting finding needs the sorting task: not tested here.
    assert!(md.contains("| Proxy and Particle are faster than Joint for sorting | not tested | not tested |"), "{md}");

    // A restriction that could leave a participant idle is refused.
    let o = run_cli_on("study --manners pinch --participants 1 --out", scratch.path().join("never"));
    let t = text(&o);
    assert_eq!(o.status.code(), Some(2), "{t}");
    assert!(t.contains("--manners") && t.contains("`pinch` leaves no manner"), "{t}");
}

/// A study's memory does not grow with its simulation: 24 participants
/// (1,296 trials, each cut at 2 s) peak under 100 MB (measured 29 MB for
/// 60 participants and 55 MB for 600, `docs/performance.md`).
#[test]
fn a_larger_study_keeps_its_memory_small() {
    let scratch_out = tmp("memory");
    let mut child = cli("study --participants 24 --time-limit 2 --no-progress --out")
        .arg(scratch_out.path().join("run"))
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("starts");
    // VmHWM, the process's peak resident memory (kB), read until it exits.
    let mut peak_kb = 0_u64;
    while child.try_wait().expect("wait").is_none() {
        if let Some(kb) = common::proc_status_kb(child.id(), "VmHWM") {
            peak_kb = peak_kb.max(kb);
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let trials = scratch_out.path().join("run").join("trials.csv");
    assert_eq!(column(&trials, "participant").len(), 24 * 54, "every trial has its row");
    assert!(peak_kb > 0, "no memory sample was read");
    assert!(peak_kb < 100 * 1024, "peak resident memory {} MB", peak_kb / 1024);
}

/// With standard error not a terminal (a log, a pipe, a batch job) and
/// progress wanted, a study that runs past ten seconds says how far it has
/// come in plain lines instead of a bar (18 participants take about 30 s
/// on two cores; a line comes every 10 s).
#[test]
fn a_long_study_into_a_log_prints_plain_progress_lines() {
    let scratch_out = tmp("plain-progress");
    let o = run_cli_on("study --participants 18 --time-limit 10 --out", scratch_out.path().join("run"));
    assert!(o.status.success(), "{}", text(&o));
    let err = String::from_utf8_lossy(&o.stderr);
    let line =
        err.lines().find(|l| l.contains(" of 972 trials (")).unwrap_or_else(|| panic!("no progress line: {err}"));
    assert!(line.starts_with("surfacelab study: ") && line.ends_with(" s left"), "{line}");
}
