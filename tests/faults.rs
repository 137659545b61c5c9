//! Faults a long job meets, through the binary: SIGKILL at random moments
//! of a study, a disk that fills mid-study, and Ctrl-C in a long run. Each
//! leaves what was written whole, and `--resume` (or the report written at
//! the stop) carries on exactly.

mod common;

use common::{bin, text};
use std::io::BufRead as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// A small design whose trials end at a 5 s limit: 4 participants × 2
/// tasks × 3 techniques × 2 feedback = 48 trials, a few seconds in all.
fn small_study(out: &Path) -> Command {
    let mut c = bin();
    c.args(["study", "--participants", "4", "--reps", "1", "--no-practice", "--tasks", "positioning,sorting"])
        .args(["--time-limit", "5", "--no-progress", "--jobs", "2", "--out"])
        .arg(out)
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    c
}

fn resume(out: &Path) -> Output {
    bin().args(["study", "--no-progress", "--resume"]).arg(out).output().expect("resume runs")
}

/// Files a failed atomic write could have left behind.
fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .expect("list")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| std::path::Path::new(n).extension().is_some_and(|e| e == "tmp"))
        .collect()
}

/// Lines in a CSV file's bytes.
fn lines(bytes: &[u8]) -> usize {
    bytes.split(|&b| b == b'\n').count() - 1
}

/// The uninterrupted run's trials.csv and its wall time.
fn reference(scratch: &Path) -> (Vec<u8>, Duration) {
    let out = scratch.join("reference");
    let t0 = Instant::now();
    let o = small_study(&out).output().expect("study runs");
    assert!(o.status.success(), "{}", text(&o));
    (std::fs::read(out.join("trials.csv")).expect("trials.csv"), t0.elapsed())
}

/// SIGKILL at 20 moments spread over the run, each run then resumed:
/// every trials.csv is byte-identical to the uninterrupted run's.
#[test]
fn a_study_killed_at_random_moments_resumes_to_the_same_bytes() {
    let scratch = tempfile::tempdir().expect("tmp");
    let (expected, took) = reference(scratch.path());
    assert_eq!(lines(&expected), 49, "a header and 48 rows");
    // Moments from a fixed linear congruential sequence: the same 20 each
    // time, spread over 5%..95% of the uninterrupted run's wall time.
    let mut state: u64 = 2008;
    let mut resumed = 0;
    for k in 0..20 {
        state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        let fraction = 0.05 + 0.9 * ((state >> 11) as f64 / (1u64 << 53) as f64);
        let out = scratch.path().join(format!("killed-{k}"));
        let mut child = small_study(&out).spawn().expect("study starts");
        std::thread::sleep(took.mul_f64(fraction));
        child.kill().expect("SIGKILL");
        child.wait().expect("reaped");
        // Killed before run.toml existed, the folder holds no run to
        // resume and the study is simply started again.
        let o = if out.join("run.toml").exists() {
            resumed += 1;
            resume(&out)
        } else {
            small_study(&out).output().expect("study runs")
        };
        assert!(o.status.success(), "kill {k} at {fraction:.2} of the run: {}", text(&o));
        let got = std::fs::read(out.join("trials.csv")).expect("trials.csv");
        assert!(got == expected, "kill {k} at {fraction:.2}: trials.csv differs from the uninterrupted run");
        assert_eq!(temporaries(&out), Vec::<String>::new(), "kill {k}");
    }
    assert!(resumed >= 15, "only {resumed} of 20 kills came after run.toml was written");
}

/// A small tmpfs mounted for one test and unmounted when dropped.
struct Tmpfs(PathBuf);

impl Tmpfs {
    fn mount(at: PathBuf, size: &str) -> Tmpfs {
        std::fs::create_dir_all(&at).expect("mount point");
        let o = Command::new("mount")
            .args(["-t", "tmpfs", "-o", &format!("size={size}"), "tmpfs"])
            .arg(&at)
            .output()
            .expect("mount runs");
        assert!(
            o.status.success(),
            "this test fills a small tmpfs, which needs `mount` as root (CAP_SYS_ADMIN): {}",
            String::from_utf8_lossy(&o.stderr)
        );
        Tmpfs(at)
    }
}

impl Drop for Tmpfs {
    fn drop(&mut self) {
        let _ = Command::new("umount").arg(&self.0).status();
    }
}

/// The disk fills while trials are written: the study exits 1 naming the
/// file and the OS error and leaves no temporary file; once space is freed,
/// `--resume` completes with every row exactly once, byte for byte the
/// uninterrupted run's.
#[test]
fn a_full_disk_mid_study_exits_1_and_resume_completes_once_space_is_freed() {
    let scratch = tempfile::tempdir().expect("tmp");
    let (expected, _) = reference(scratch.path());
    let disk = Tmpfs::mount(scratch.path().join("disk"), "1m");
    // Three 4 KiB pages left: the study folder, run.toml, and the first
    // ~20 rows; freed, the megabyte holds the summary files too.
    let filler = disk.0.join("filler");
    std::fs::write(&filler, vec![0u8; 1024 * 1024 - 12 * 1024]).expect("filler");
    let out = disk.0.join("study");
    let o = small_study(&out).output().expect("study runs");
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let err = text(&o);
    assert!(err.contains(&out.display().to_string()) && err.contains("No space left on device"), "{err}");
    assert_eq!(temporaries(&out), Vec::<String>::new());
    let written = std::fs::read(out.join("trials.csv")).expect("trials.csv");
    let rows = lines(&written);
    assert!((2..49).contains(&rows), "the disk filled mid-study: {rows} lines were written");

    std::fs::remove_file(&filler).expect("space freed");
    let o = resume(&out);
    assert!(o.status.success(), "{}", text(&o));
    let got = std::fs::read(out.join("trials.csv")).expect("trials.csv");
    assert!(got == expected, "trials.csv after the resume differs from the uninterrupted run");
}

/// A run long enough to want it says how far it has come, and Ctrl-C stops
/// it with the report written and saying so (exit 130).
#[test]
fn a_long_run_shows_progress_and_ctrl_c_writes_the_report_so_far() {
    let scratch = tempfile::tempdir().expect("tmp");
    // The built-in cloth at 240 Hz with a long settle: a minute of work or more.
    let scene = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tasks/cloth.toml"))
        .expect("cloth")
        .replacen("[table]", "[physics]\ntimestep_hz = 240\n\n[table]", 1);
    let task = scratch.path().join("cloth240.toml");
    std::fs::write(&task, scene).expect("scene");
    let report = scratch.path().join("report.json");
    let mut child = bin()
        .args(["run", "--technique", "particle", "--gesture", "flatten", "--settle", "10", "--task"])
        .arg(&task)
        .arg("--report")
        .arg(&report)
        .stderr(Stdio::piped())
        .spawn()
        .expect("run starts");
    let mut lines = std::io::BufReader::new(child.stderr.take().expect("stderr")).lines();
    let first = lines.next().expect("a line before the run ends").expect("text");
    assert!(first.contains("s simulated (") && first.contains("Ctrl-C stops"), "{first}");
    let ok = Command::new("kill").args(["-INT", &child.id().to_string()]).status().expect("kill runs");
    assert!(ok.success());
    let rest: Vec<String> = lines.map(|l| l.expect("text")).collect();
    let status = child.wait().expect("reaped");
    assert_eq!(status.code(), Some(130), "{rest:?}");
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&report).expect("report")).expect("json");
    let why = v["completion"]["incomplete"].as_str().expect("incomplete");
    assert!(why.starts_with("stopped by Ctrl-C at "), "{why}");
    // The gesture's 2 s and the 10 s settle were not all simulated.
    assert!(why.ends_with(" of 12.00 s") && v["sim_time_s"].as_f64().expect("time") < 12.0, "{why}");
}
