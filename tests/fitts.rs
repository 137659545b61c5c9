//! `surfacelab participants fitts`: the simulated participants' one-finger
//! drags against Fitts' law, through the real binary at a small size.

mod common;

use common::bin;

/// Two participants, three distances (5-60 cm) by two widths (0.5 and 4
/// cm), two drags each: movement time follows the index of difficulty
/// (R² ≥ 0.8) and the throughput lies in the band the published figures
/// bracket for finger drags on a surface (docs/design/participants.md):
/// above children's finger drag-and-drop on a tablet, 2.3 bits/s, and below
/// adults' finger tapping on a tabletop, 5.5 bits/s.
#[test]
fn joint_drags_follow_fitts_law_within_the_published_band() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("fitts");
    let o = bin()
        .args(["participants", "fitts", "--technique", "joint", "--participants", "2", "--reps", "2"])
        .args(["--distances", "0.05,0.2,0.6", "--widths", "0.005,0.04", "--out"])
        .arg(&out)
        .output()
        .expect("runs");
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{text}");

    let csv = std::fs::read_to_string(out.join("fitts.csv")).expect("fitts.csv");
    let mut lines = csv.lines();
    let head = lines.next().expect("header");
    assert!(head.starts_with("participant,technique,distance_m,width_m,id_bits,movement_s,completed"), "{head}");
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 2 * 3 * 2 * 2);
    assert!(rows.iter().all(|r| r.split(',').nth(1) == Some("joint")));
    // The index of difficulty of 60 cm to a 0.5 cm target: log2(121).
    let id = rows.iter().find(|r| r.contains(",0.6,0.005,")).and_then(|r| r.split(',').nth(4)).expect("a row");
    assert!((id.parse::<f64>().expect("number") - 121f64.log2()).abs() < 1e-9, "{id}");

    let fit: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("fitts.json")).expect("fitts.json")).expect("JSON");
    let r2 = fit["r2"].as_f64().expect("r2");
    let tp = fit["throughput_bits_s"].as_f64().expect("throughput");
    assert!(r2 >= 0.8, "R² {r2}");
    assert!((2.3..=5.5).contains(&tp), "throughput {tp} bits/s");
    assert!(fit["b_s_per_bit"].as_f64().expect("b") > 0.0);
    assert!(std::fs::read(out.join("fitts.png")).expect("fitts.png").starts_with(b"\x89PNG"));
}

#[test]
fn a_grid_off_the_table_is_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = bin()
        .args(["participants", "fitts", "--distances", "0.2,1.5", "--out"])
        .arg(dir.path().join("f"))
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("distance 1.5 m is outside (0, 0.9] m"), "{stderr}");
}
