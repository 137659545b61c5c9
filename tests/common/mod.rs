//! Helpers shared by the integration tests (`mod common;` in a test file):
//! the binary under test, scratch folders, project paths, small scenes and
//! the physics thresholds the tests assert.
//!
//! Each test file compiles this module on its own and uses part of it.
#![allow(dead_code)]

pub mod gestures;
pub mod scenes;
pub mod thresholds;

use std::path::PathBuf;
use std::process::{Command, Output};

/// The `surfacelab` binary, run from the project root.
pub fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_surfacelab"));
    c.current_dir(env!("CARGO_MANIFEST_DIR"));
    c
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
