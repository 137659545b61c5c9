//! `surfacelab study --slurm N` through the real binary, and on a
//! real Slurm: `scripts/local-slurm.sh` starts a single-node cluster on
//! localhost (installing Debian's `slurm-wlm`, `munge`, `slurmdbd` and
//! `mariadb-server-core` if missing), the tests submit job arrays to it, wait,
//! and compare the merged folder byte for byte with an unsharded run. When
//! the cluster cannot start, the cluster tests fail with the script's output:
//! they never skip.

mod common;

use common::{bin, text};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// The small study every test here runs: 3 participants (one per shard of
/// 3), one task, two repetitions, no practice, a 40 s limit (some trials
/// finish, some fail at it): 36 trials, seconds of CPU.
const STUDY: [&str; 11] = [
    "--participants",
    "3",
    "--reps",
    "2",
    "--no-practice",
    "--tasks",
    "positioning",
    "--time-limit",
    "40",
    "--seed",
    "21",
];

/// How long a sweep may take on the local cluster before the test gives up.
const WAIT: Duration = Duration::from_mins(5);

/// A fresh scratch folder; its name holds a space and a quote, so every
/// path in the scripts must be quoted right.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("surfacelab slurm's-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("scratch dir");
    d
}

/// The unsharded run of [`STUDY`], made once.
fn unsharded() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = scratch("unsharded").join("run");
        let o = bin().arg("study").args(STUDY).args(["--no-progress", "--out"]).arg(&dir).output().expect("run");
        assert!(o.status.success(), "unsharded run failed:\n{}", text(&o));
        dir
    })
}

/// `SLURM_CONF` of the local cluster, started once (the script is idempotent).
fn cluster() -> &'static str {
    static CONF: OnceLock<String> = OnceLock::new();
    CONF.get_or_init(|| {
        let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/local-slurm.sh");
        let o = Command::new("bash").arg(&script).output().expect("bash");
        let out = text(&o);
        let conf = String::from_utf8_lossy(&o.stdout)
            .lines()
            .rev()
            .find_map(|l| l.strip_prefix("export SLURM_CONF=").map(str::to_owned));
        match conf {
            Some(conf) if o.status.success() => conf,
            _ => panic!(
                "the local Slurm cluster did not start (scripts/local-slurm.sh exited {}); it needs root or sudo, \
                 apt access on a first run, and ports 6817-6820 free. Its output:\n{out}",
                o.status
            ),
        }
    })
}

/// A Slurm client command against the local cluster.
fn slurm(program: &str, args: &[&str]) -> Output {
    Command::new(program)
        .args(args)
        .env("SLURM_CONF", cluster())
        .output()
        .unwrap_or_else(|e| panic!("cannot run {program}: {e}"))
}

fn slurm_ok(program: &str, args: &[&str]) -> String {
    let o = slurm(program, args);
    assert!(o.status.success(), "{program} {args:?} failed:\n{}", text(&o));
    String::from_utf8_lossy(&o.stdout).trim().to_owned()
}

/// `JobID|State` of every job or array task of these jobs, from `sacct`
/// (the command docs/cluster.md gives for finding failed tasks).
fn sacct_states(jobs: &str) -> Vec<(String, String)> {
    slurm_ok("sacct", &["-X", "-n", "-P", "-j", jobs, "--format=JobID,State"])
        .lines()
        .filter_map(|l| l.split_once('|').map(|(a, b)| (a.to_owned(), b.to_owned())))
        .collect()
}

/// Polls `sacct` until `want(states)` holds; fails after [`WAIT`] with the
/// queue, the states and the run folder's Slurm logs.
fn wait_until(jobs: &str, logs: &Path, what: &str, want: impl Fn(&[(String, String)]) -> bool) {
    let start = Instant::now();
    loop {
        let states = sacct_states(jobs);
        if want(&states) {
            return;
        }
        if start.elapsed() > WAIT {
            let queue = text(&slurm("squeue", &["-j", jobs]));
            let _ = slurm("scancel", &jobs.split(',').collect::<Vec<_>>());
            let mut out = String::new();
            for e in std::fs::read_dir(logs).into_iter().flatten().flatten() {
                if e.path().extension().is_some_and(|x| x == "out") {
                    let _ = write!(
                        out,
                        "--- {}\n{}",
                        e.path().display(),
                        std::fs::read_to_string(e.path()).unwrap_or_default()
                    );
                }
            }
            panic!("timed out after {WAIT:?} waiting for {what}; sacct: {states:?}\nsqueue:\n{queue}\nlogs:\n{out}");
        }
        std::thread::sleep(Duration::from_millis(500));
    }
}

fn all_completed(n: usize) -> impl Fn(&[(String, String)]) -> bool {
    move |s| s.len() == n && s.iter().all(|(_, state)| state == "COMPLETED")
}

/// Every file of the unsharded run is in `merged` with the same bytes.
fn assert_same_as_unsharded(merged: &Path) {
    let mut compared = Vec::new();
    for e in std::fs::read_dir(unsharded()).expect("unsharded dir").flatten() {
        let name = e.file_name();
        let theirs =
            std::fs::read(merged.join(&name)).unwrap_or_else(|err| panic!("{}: {err}", merged.join(&name).display()));
        assert!(
            std::fs::read(e.path()).expect("read") == theirs,
            "{} differs from the unsharded run's",
            name.display()
        );
        compared.push(name.to_string_lossy().into_owned());
    }
    for must in ["trials.csv", "summary.csv", "anova.csv", "run.toml", "figure.png", "report.md"] {
        assert!(compared.iter().any(|c| c == must), "{must} not compared: {compared:?}");
    }
}

fn rows(path: &Path) -> Vec<String> {
    std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .lines()
        .map(str::to_owned)
        .collect()
}

// ------------------------------------------------------------ no cluster

#[test]
fn slurm_writes_the_run_files_and_scripts_before_anything_runs() {
    let dir = scratch("written").join("run");
    let o = bin()
        .arg("study")
        .args(STUDY)
        .args(["--slurm", "3", "--time", "1-00:30:00", "--cpus", "2", "--partition", "short", "--out"])
        .arg(&dir)
        .output()
        .expect("run");
    assert!(o.status.success(), "{}", text(&o));
    // run.toml everywhere, trials nowhere yet.
    let whole = std::fs::read_to_string(dir.join("run.toml")).expect("run.toml");
    assert!(!whole.contains("[shard]"), "the study's own run.toml is whole:\n{whole}");
    for i in 0..3 {
        let shard = std::fs::read_to_string(dir.join(format!("shard-{i}/run.toml"))).expect("shard run.toml");
        assert!(shard.contains(&format!("[shard]\nindex = {i}\ncount = 3")), "{shard}");
        assert!(!dir.join(format!("shard-{i}/trials.csv")).exists());
    }
    assert!(!dir.join("shard-3").exists());
    assert!(!dir.join("trials.csv").exists());
    let array = std::fs::read_to_string(dir.join("slurm/array.sbatch")).expect("array.sbatch");
    for line in [
        "#SBATCH --array=0-2",
        "#SBATCH --time=1-00:30:00",
        "#SBATCH --cpus-per-task=2",
        "#SBATCH --partition=short",
        &format!("exe='{}'", env!("CARGO_BIN_EXE_surfacelab")),
        &format!("dir='{}'", dir.display().to_string().replace('\'', r"'\''")),
    ] {
        assert!(array.lines().any(|l| l == line), "no `{line}` in\n{array}");
    }
    let merge = std::fs::read_to_string(dir.join("slurm/merge.sbatch")).expect("merge.sbatch");
    assert!(merge.contains(r#"study merge "$dir" "$dir/shard-0" "$dir/shard-1" "$dir/shard-2""#), "{merge}");
    assert!(text(&o).contains("--dependency=afterok:"), "prints how to submit: {}", text(&o));

    // The same folder again: refused, like a second `study --out`.
    let again = bin().arg("study").args(STUDY).args(["--slurm", "3", "--out"]).arg(&dir).output().expect("run");
    assert_eq!(again.status.code(), Some(2), "{}", text(&again));
    assert!(text(&again).contains("already holds a study run"), "{}", text(&again));
}

#[test]
fn slurm_flags_with_bad_values_exit_2_naming_the_flag() {
    let dir = scratch("bad").join("run");
    let cases: [(&[&str], &str); 7] = [
        (&["--slurm", "3", "--time", "90:00"], "--time"),
        (&["--slurm", "3", "--time", "00:61:00"], "--time"),
        (&["--slurm", "3", "--time", "2-24:00:00"], "--time"),
        (&["--slurm", "0"], "--slurm"),
        (&["--slurm", "3", "--cpus", "0"], "--cpus"),
        (&["--slurm", "3", "--partition", "a b"], "--partition"),
        (&["--submit"], "--slurm"),
    ];
    for (args, flag) in cases {
        let o = bin().arg("study").args(args).arg("--out").arg(&dir).output().expect("run");
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o));
        assert!(String::from_utf8_lossy(&o.stderr).contains(flag), "{args:?} should name {flag}: {}", text(&o));
        assert!(!dir.exists(), "{args:?} wrote files");
    }
    let o = bin().args(["study", "--slurm", "2", "--shard", "0/2", "--out"]).arg(&dir).output().expect("run");
    assert_eq!(o.status.code(), Some(2), "--slurm with --shard: {}", text(&o));
}

// ------------------------------------------------------------ on a local Slurm

#[test]
fn a_sweep_submitted_to_a_local_slurm_merges_to_the_unsharded_bytes() {
    let conf = cluster();
    let dir = scratch("sweep").join("run");
    let o = bin()
        .env("SLURM_CONF", conf)
        .arg("study")
        .args(STUDY)
        .args(["--slurm", "3", "--submit", "--time", "00:10:00", "--out"])
        .arg(&dir)
        .output()
        .expect("run");
    let out = text(&o);
    assert!(o.status.success(), "--submit failed:\n{out}");
    // "submitted: array job A (3 tasks), merge job M (afterok:A)"
    let ids: Vec<&str> = out.lines().find_map(|l| l.strip_prefix("submitted: array job ")).map_or_else(
        || panic!("no job ids in:\n{out}"),
        |l| l.split(|c: char| !c.is_ascii_digit()).filter(|s| !s.is_empty()).collect(),
    );
    let (array, merge) = (ids[0], ids[2]);
    assert_eq!(ids[1], "3", "{out}");
    assert!(out.contains(&format!("merge job {merge} (afterok:{array})")), "{out}");

    wait_until(&format!("{array},{merge}"), &dir.join("slurm"), "the array and its merge", all_completed(4));
    let states = sacct_states(array);
    let tasks: Vec<&str> = states.iter().map(|(id, _)| id.as_str()).collect();
    assert_eq!(tasks, [format!("{array}_0"), format!("{array}_1"), format!("{array}_2")], "one task per shard");
    for i in 0..3 {
        let shard = rows(&dir.join(format!("shard-{i}/trials.csv")));
        assert_eq!(shard.len(), 1 + 12, "shard {i}: a header and participant {}'s 12 trials", i + 1);
        assert!(shard[1..].iter().all(|r| r.starts_with(&format!("{},", i + 1))), "shard {i}: {shard:?}");
    }
    assert_same_as_unsharded(&dir);
}

#[test]
fn a_task_cancelled_while_running_resubmitted_alone_continues_its_shard() {
    cluster();
    let dir = scratch("restart").join("run");
    let o = bin().arg("study").args(STUDY).args(["--slurm", "3", "--out"]).arg(&dir).output().expect("run");
    assert!(o.status.success(), "{}", text(&o));
    let (array_sh, merge_sh) = (dir.join("slurm/array.sbatch"), dir.join("slurm/merge.sbatch"));
    let (array_sh, merge_sh) = (array_sh.to_str().expect("utf-8"), merge_sh.to_str().expect("utf-8"));
    let shard_csv = dir.join("shard-1/trials.csv");
    let rows_written = || std::fs::read_to_string(&shard_csv).map_or(0, |t| t.matches('\n').count().saturating_sub(1));

    // Submitted as docs/cluster.md's two sbatch lines do it; task 1 is cancelled
    // once it has written two of its 12 rows.
    let array = slurm_ok("sbatch", &["--parsable", array_sh]);
    let merge = slurm_ok("sbatch", &["--parsable", &format!("--dependency=afterok:{array}"), merge_sh]);
    let start = Instant::now();
    while rows_written() < 2 {
        assert!(start.elapsed() < WAIT, "task 1 wrote no rows in {WAIT:?}");
        std::thread::sleep(Duration::from_millis(20));
    }
    slurm_ok("scancel", &[&format!("{array}_1")]);
    wait_until(&array, &dir.join("slurm"), "tasks 0 and 2 to complete, task 1 to be cancelled", |s| {
        // sacct says `CANCELLED by <uid>`.
        s.len() == 3
            && s.iter().all(
                |(id, state)| {
                    if id.ends_with("_1") { state.starts_with("CANCELLED") } else { state == "COMPLETED" }
                },
            )
    });
    let done = rows_written();
    assert!((2..12).contains(&done), "task 1 was cancelled mid-shard ({done} of 12 rows)");
    // The merge can no longer start (afterok); docs/cluster.md says to cancel it.
    let start = Instant::now();
    loop {
        let reason = slurm_ok("squeue", &["-h", "-j", &merge, "-o", "%r"]);
        if reason == "DependencyNeverSatisfied" {
            break;
        }
        assert!(start.elapsed() < WAIT, "the merge job waits for `{reason}`, not DependencyNeverSatisfied");
        std::thread::sleep(Duration::from_millis(500));
    }
    slurm_ok("scancel", &[&merge]);

    // Resubmitted alone, then the merge after it.
    let again = slurm_ok("sbatch", &["--parsable", "--array=1", array_sh]);
    let merge = slurm_ok("sbatch", &["--parsable", &format!("--dependency=afterok:{again}"), merge_sh]);
    wait_until(&format!("{again},{merge}"), &dir.join("slurm"), "the resubmitted task and the merge", all_completed(2));
    let log = std::fs::read_to_string(dir.join(format!("slurm/array-{again}_1.out"))).expect("task log");
    assert!(
        log.contains(&format!("12 trials ({done} already done, {} run", 12 - done)),
        "the task continued its shard after {done} rows:\n{log}"
    );
    assert_same_as_unsharded(&dir);
}
