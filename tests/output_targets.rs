//! Output paths are written by what they are, through the binary: a regular
//! file atomically, a symlink's target (the link kept), a FIFO and a device
//! straight through, `-` to standard output; a write that fails exits 1
//! naming the path and the OS error, and never replaces the node.

mod common;

use common::bin;
use std::io::Read as _;
use std::os::unix::fs::FileTypeExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// A one-box drag with the report going to `report`.
fn run_to(report: &str) -> Command {
    let mut c = bin();
    c.args([
        "run",
        "--task",
        "cases/one_box",
        "--technique",
        "joint",
        "--gesture",
        "fingertip_drag",
        "--report",
        report,
    ]);
    c
}

fn mkfifo(path: &Path) {
    let ok = Command::new("mkfifo").arg(path).status().expect("mkfifo runs").success();
    assert!(ok, "mkfifo {}", path.display());
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Reads the FIFO at `path` to its end on a thread, as a consumer would.
fn drain(path: PathBuf) -> std::thread::JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        std::fs::File::open(&path).expect("open the FIFO for reading").read_to_end(&mut bytes).expect("read");
        bytes
    })
}

fn report_scene(bytes: &[u8]) -> String {
    let v: serde_json::Value = serde_json::from_slice(bytes).expect("the report is JSON");
    v["scene"].as_str().expect("scene").to_string()
}

#[test]
fn a_symlinked_report_lands_in_its_target_and_the_link_stays() {
    let dir = tempfile::tempdir().expect("tmp");
    let target = dir.path().join("kept").join("report.json");
    std::fs::create_dir_all(target.parent().expect("parent")).expect("dir");
    std::fs::write(&target, "old").expect("old report");
    let link = dir.path().join("latest.json");
    std::os::unix::fs::symlink("kept/report.json", &link).expect("link");
    let out = run_to(link.to_str().expect("utf-8")).output().expect("run");
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(std::fs::symlink_metadata(&link).expect("link").file_type().is_symlink(), "the link is kept");
    assert_eq!(report_scene(&std::fs::read(&target).expect("target")), "one_box");
    // Nothing but the report folder and the link: no temporary file left.
    let names: Vec<_> =
        std::fs::read_dir(dir.path().join("kept")).expect("list").map(|e| e.expect("e").file_name()).collect();
    assert_eq!(names, ["report.json"]);
}

#[test]
fn a_dangling_symlink_creates_its_target() {
    let dir = tempfile::tempdir().expect("tmp");
    let link = dir.path().join("latest.json");
    std::os::unix::fs::symlink("made.json", &link).expect("link");
    let out = run_to(link.to_str().expect("utf-8")).output().expect("run");
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(std::fs::symlink_metadata(&link).expect("link").file_type().is_symlink());
    assert_eq!(report_scene(&std::fs::read(dir.path().join("made.json")).expect("target")), "one_box");
}

#[test]
fn a_fifo_gets_the_report_and_stays_a_fifo() {
    let dir = tempfile::tempdir().expect("tmp");
    let fifo = dir.path().join("report.pipe");
    mkfifo(&fifo);
    let reader = drain(fifo.clone());
    let out = run_to(fifo.to_str().expect("utf-8")).output().expect("run");
    assert!(out.status.success(), "{}", stderr(&out));
    // First: a FIFO replaced by a file would leave the reader waiting.
    assert!(std::fs::symlink_metadata(&fifo).expect("fifo").file_type().is_fifo());
    assert_eq!(report_scene(&reader.join().expect("reader")), "one_box");
}

#[test]
fn a_dash_writes_the_report_to_standard_output() {
    let out = run_to("-").output().expect("run");
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(report_scene(&out.stdout), "one_box");
    assert!(!Path::new("-").exists(), "no file named `-`");
}

/// A full device: a private `mknod c 1 7` copy of `/dev/full` where this
/// runs as root, `/dev/full` itself otherwise (which only root could
/// replace, so a regression would still show as a node turned file).
#[test]
fn a_full_device_exits_1_naming_the_path_and_stays_a_device() {
    let dir = tempfile::tempdir().expect("tmp");
    let private = dir.path().join("full");
    let made = Command::new("mknod").arg(&private).args(["c", "1", "7"]).stderr(Stdio::null()).status();
    let full = if made.is_ok_and(|s| s.success()) { private } else { PathBuf::from("/dev/full") };
    let out = run_to(full.to_str().expect("utf-8")).output().expect("run");
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains(&format!("writing report {}", full.display())), "{err}");
    assert!(err.contains("No space left on device"), "{err}");
    assert!(std::fs::symlink_metadata(&full).expect("node").file_type().is_char_device(), "still a device");
}

/// Standard output whose reader has gone: the write fails with EPIPE, and
/// the command exits 1 naming where it wrote, with no panic.
#[test]
fn a_closed_pipe_exits_1_without_a_panic() {
    for (what, mut command, named) in [
        ("report", run_to("-"), "writing report -"),
        ("contact", contact_to_closed_pipe(), "writing standard output"),
        ("run --list", list_runs(), "writing standard output"),
    ] {
        let (reader, writer) = std::io::pipe().expect("pipe");
        drop(reader);
        let out = command.stdout(writer).stderr(Stdio::piped()).output().expect("run");
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(1), "{what}: {err}");
        assert!(err.contains(named) && err.contains("Broken pipe"), "{what}: {err}");
        assert!(!err.contains("panicked"), "{what}: {err}");
    }
}

fn contact_to_closed_pipe() -> Command {
    // The query comes from a file, so nothing waits on standard input.
    let dir = std::env::temp_dir().join(format!("surfacelab-out-contact-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let query = dir.join("q.json");
    std::fs::write(&query, r#"{"a": [[0,0],[1,0],[1,1],[0,1]], "b": [[0.5,0.5],[1.5,0.5],[1.5,1.5],[0.5,1.5]]}"#)
        .expect("query");
    let mut c = bin();
    c.arg("contact").arg(&query);
    c
}

fn list_runs() -> Command {
    let mut c = bin();
    c.args(["run", "--list"]);
    c
}

#[test]
fn a_screenshot_goes_to_a_fifo_or_standard_output_as_png() {
    const PNG: &[u8] = b"\x89PNG\r\n\x1a\n";
    let dir = tempfile::tempdir().expect("tmp");
    let fifo = dir.path().join("shot.pipe");
    mkfifo(&fifo);
    let reader = drain(fifo.clone());
    let shot = |out: &str| {
        let mut c = bin();
        c.args(["screenshot", "--task", "cases/one_box", "--size", "64x48", "--out", out]);
        c.output().expect("screenshot")
    };
    let out = shot(fifo.to_str().expect("utf-8"));
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(std::fs::symlink_metadata(&fifo).expect("fifo").file_type().is_fifo());
    assert!(reader.join().expect("reader").starts_with(PNG));
    let out = shot("-");
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(out.stdout.starts_with(PNG), "PNG bytes on standard output");
}
