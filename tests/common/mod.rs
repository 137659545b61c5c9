//! Helpers shared by the integration tests (`mod common;` in a test file):
//! the binary under test, scratch folders, project paths, small scenes and
//! the physics thresholds the tests assert.
//!
//! Each test file compiles this module on its own and uses part of it.
#![allow(dead_code)]

pub mod filmed;
pub mod gestures;
pub mod scenes;
pub mod thresholds;

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `surfacelab` binary, run from the project root.
pub fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_surfacelab"));
    c.current_dir(env!("CARGO_MANIFEST_DIR"));
    c
}

/// The binary with the words of `line` as its arguments, as a command line
/// reads: `cli("run --task positioning --technique joint")`.
pub fn cli(line: &str) -> Command {
    let mut c = bin();
    c.args(line.split_whitespace());
    c
}

/// [`cli`]`(line)` run to its end.
pub fn run_cli(line: &str) -> Output {
    cli(line).output().expect("runs")
}

/// [`run_cli`]`(line)`, asserted to succeed: its output as text.
pub fn cli_text(line: &str) -> String {
    let o = run_cli(line);
    let t = text(&o);
    assert!(o.status.success(), "{line}: {t}");
    t
}

/// [`cli`]`(line)` with `path` as its last argument, run to its end.
pub fn run_cli_on(line: &str, path: impl AsRef<OsStr>) -> Output {
    cli(line).arg(path).output().expect("runs")
}

/// A command's standard output then standard error, as text.
pub fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

/// A path under the project root, as a string (scene, gesture and asset files).
pub fn asset(path: &str) -> String {
    format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))
}

/// A scratch folder for one test, removed with everything in it when the
/// returned guard goes out of scope.
pub fn tmp(name: &str) -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix(&format!("surfacelab-{}-{name}-", env!("CARGO_CRATE_NAME")))
        .tempdir()
        .expect("temp dir")
}

/// An empty folder for one test under cargo's test scratch space, named by
/// the test file and `name`; emptied at the start of each run and kept
/// afterwards for a look at what the test wrote.
pub fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(env!("CARGO_CRATE_NAME")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("create scratch dir");
    dir
}

/// `surfacelab study LINE --replay DIR/gestures --out DIR/run` run to its
/// end, the replay folder holding, for each `(task, gesture)`, the built-in
/// gesture file saved as `<task>.toml`. Returns the run's folder and the
/// command's output.
pub fn replayed_study(dir: &Path, tasks: &[(&str, &str)], line: &str) -> (PathBuf, Output) {
    let gestures = dir.join("gestures");
    std::fs::create_dir_all(&gestures).expect("create the replay folder");
    for (task, gesture) in tasks {
        std::fs::copy(asset(&format!("assets/gestures/{gesture}.toml")), gestures.join(format!("{task}.toml")))
            .expect("copy a gesture");
    }
    let out = dir.join("run");
    let o = cli(line).arg("--replay").arg(&gestures).arg("--out").arg(&out).output().expect("runs");
    (out, o)
}

/// Asserts the command was refused as bad input (exit 2) with a message
/// naming every one of `needles`; returns its output text.
pub fn refused(o: &Output, needles: &[&str]) -> String {
    let t = text(o);
    assert_eq!(o.status.code(), Some(2), "{t}");
    for n in needles {
        assert!(t.contains(n), "no `{n}` in: {t}");
    }
    t
}

/// A memory figure of process `pid` from `/proc/PID/status`, in kB
/// (`VmRSS`: resident now; `VmHWM`: the most it has held). `None` once
/// the process has gone or been reaped (a zombie has no memory lines).
pub fn proc_status_kb(pid: u32, key: &str) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let value = status.lines().find_map(|l| l.strip_prefix(key)?.strip_prefix(':'))?;
    value.trim().trim_end_matches("kB").trim().parse().ok()
}
