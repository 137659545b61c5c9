//! The particle frame holds its numbers: every behaviour case under the
//! techniques built on particles (Particle, and Hybrid, which uses them for
//! its non-gripping contacts), each measurement to the bit, against
//! `tests/snapshots/particle_frame.txt`.
//!
//! The particle frame is a sequence of floating-point steps whose order
//! decides the last bits of every result; this snapshot is what keeps a
//! change to how the steps are written from changing what they compute.
//! A run whose numbers differ on purpose rewrites the file with
//! `UPDATE_SNAPSHOTS=1 cargo test --release --test particle_frame`.

use std::fmt::Write as _;
use std::path::Path;
use surfacelab::harness::behaviour::{cases, run_case};
use surfacelab::pipeline::technique::TechniqueKind;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// One line per case, technique and metric: the value's bits, then the
/// value itself for a reader.
fn measured() -> String {
    let kinds: Vec<TechniqueKind> =
        ["particle", "hybrid"].iter().map(|n| n.parse().unwrap_or_else(|e| panic!("{n}: {e}"))).collect();
    let mut out = String::new();
    for case in cases() {
        for &kind in &kinds {
            let m = run_case(&case, kind, root()).unwrap_or_else(|e| panic!("{} under {kind}: {e}", case.name));
            for (metric, value) in &m.values {
                let _ = writeln!(out, "{} {kind} {metric:?} {:08x} {value:?}", case.name, value.to_bits());
            }
            let _ = writeln!(out, "{} {kind} nan_count {}", case.name, m.nan_count);
        }
    }
    out
}

#[test]
fn particle_frame_matches_its_snapshot() {
    let path = root().join("tests/snapshots/particle_frame.txt");
    let got = measured();
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some() {
        std::fs::write(&path, &got).expect("write the snapshot");
        return;
    }
    let want = std::fs::read_to_string(&path).expect("tests/snapshots/particle_frame.txt");
    for (g, w) in got.lines().zip(want.lines()) {
        assert_eq!(g, w, "first differing line of the particle frame's snapshot");
    }
    assert_eq!(got.lines().count(), want.lines().count(), "snapshot line count");
}
