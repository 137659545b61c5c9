//! `surfacelab bench`: the scaling curves' files, what they hold, and its
//! refusals.

mod common;

use common::{bin, refused, text, tmp};
use surfacelab::harness::scaling::{Curve, ScalingRow};

/// The rows of `DIR/scaling.csv`.
fn rows_of(dir: &std::path::Path) -> Vec<ScalingRow> {
    let reader = csv::Reader::from_path(dir.join("scaling.csv")).expect("scaling.csv");
    reader.into_deserialize().collect::<Result<_, _>>().expect("rows read back")
}

#[test]
fn a_quick_bench_writes_every_frame_curve_with_its_slope() {
    let dir = tmp("bench");
    let out = dir.path().join("b");
    let o = bin().args(["bench", "--quick", "--participants", "none", "--out"]).arg(&out).output().expect("runs");
    assert!(o.status.success(), "{}", text(&o));
    let rows = rows_of(&out);
    let curve = |c: Curve| rows.iter().filter(|r| r.curve == c).collect::<Vec<_>>();
    assert_eq!(curve(Curve::Hands).len(), 4);
    assert_eq!(curve(Curve::Objects).len(), 3, "no 10,000-box point in a quick bench");
    assert_eq!(curve(Curve::RateHz).len(), 3);
    assert_eq!(curve(Curve::ImageSide).len(), 4);
    assert!(curve(Curve::Participants).is_empty());
    for r in &rows {
        let stages = [r.rasterize_us, r.vision_us, r.technique_us, r.step_us].map(|v| v.expect("frame stage"));
        let total = r.total_us.expect("total");
        assert!((stages.iter().sum::<f64>() - total).abs() < 1e-6 * total, "{r:?}");
        assert!(stages.iter().all(|&us| us > 0.0), "{r:?}");
    }
    // Eight separate flat hands press eight times one hand's pixels; an
    // image of twice the side holds about four times the pixels of a hand.
    let hands = curve(Curve::Hands);
    let px = |r: &ScalingRow| r.contact_pixels.expect("pixels");
    let eight = px(hands[3]) / px(hands[0]);
    assert!((7.6..8.4).contains(&eight), "8 hands: {eight}× one hand's pixels");
    let image = curve(Curve::ImageSide);
    let quad = px(image[1]) / px(image[0]);
    assert!((3.0..5.0).contains(&quad), "512² against 256²: {quad}× the pixels");
    // Objects on the reference table keep the hands' pixels.
    assert!(curve(Curve::Objects).iter().all(|r| (px(r) - px(hands[1])).abs() < 1.0));
    let md = std::fs::read_to_string(out.join("scaling.md")).expect("scaling.md");
    for name in ["hands", "objects", "rate_hz", "image_side"] {
        assert!(md.lines().any(|l| l.starts_with(&format!("| {name} | frame time"))), "{name} slope row in\n{md}");
    }
    let png = image::open(out.join("scaling.png")).expect("scaling.png decodes");
    assert_eq!((png.width(), png.height()), (1500, 900));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("| hands |") && stdout.contains("scaling.png"), "{stdout}");
}

#[test]
fn a_bad_participant_list_is_refused() {
    for bad in ["0", "6,x", "6,,60", "100000"] {
        let o = bin().args(["bench", "--participants", bad]).output().expect("runs");
        refused(&o, &["--participants", "participant count"]);
    }
    for (bad, why) in [("objects", "CURVE=X"), ("fingers=2", "not a frame curve"), ("image_side=10000", "64 to 2048")] {
        let o = bin().args(["bench", "--point", bad]).output().expect("runs");
        refused(&o, &["--point", why]);
    }
}

#[test]
fn one_point_is_measured_alone() {
    let dir = tmp("bench-point");
    let out = dir.path().join("p");
    let o = bin().args(["bench", "--point", "objects=20", "--out"]).arg(&out).output().expect("runs");
    assert!(o.status.success(), "{}", text(&o));
    let rows = rows_of(&out);
    assert_eq!(rows.len(), 1, "{rows:?}");
    assert_eq!((rows[0].curve, rows[0].x), (Curve::Objects, 20.0));
}
