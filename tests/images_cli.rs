//! The image commands through the real binary: `synth-images`, `run
//! --images`, `calibrate`, and their bad-input exits.

mod common;

use common::{bin, cli, refused, run_cli, text};
use std::path::{Path, PathBuf};
use std::process::Output;

/// A scratch folder (removed when dropped) and, in it, the frames of the
/// edge push over the one-box case filmed by a synthetic `kind` camera
/// (`ir` or `depth`), in a folder named after the kind.
fn synthesized(kind: &str) -> (tempfile::TempDir, PathBuf) {
    let tmp = tempfile::tempdir().expect("dir");
    let frames = tmp.path().join(kind);
    let line = "synth-images --task tasks/cases/one_box.toml --gesture assets/gestures/edge_push.toml --kind";
    let o = cli(line).args([kind, "--out"]).arg(&frames).output().expect("runs");
    assert!(o.status.success(), "{}", text(&o));
    (tmp, frames)
}

fn run_images(dir: &Path, calibration: &Path, report: &Path) -> Output {
    cli("run --task tasks/cases/one_box.toml --technique joint --images")
        .arg(dir)
        .arg("--calibration")
        .arg(calibration)
        .arg("--report")
        .arg(report)
        .output()
        .expect("runs")
}

fn box_y(report: &Path) -> f64 {
    let r: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(report).expect("report")).expect("json");
    r["objects"][0]["position"][1].as_f64().expect("y")
}

/// Filmed depth frames push the box forward as the edge push does (the
/// library test, tests/images.rs, bounds the gap to the gesture at 10%).
#[test]
fn synthesized_frames_run_and_push_the_box() {
    let (tmp, frames) = synthesized("depth");
    let n = std::fs::read_dir(&frames)
        .expect("dir")
        .filter(|e| e.as_ref().is_ok_and(|e| e.file_name().to_string_lossy().starts_with("frame_")));
    assert_eq!(n.count(), 108, "1.8 s at 60 Hz, both ends included");
    let report = tmp.path().join("r.json");
    let o = run_images(&frames, &frames.join("calibration.toml"), &report);
    assert!(o.status.success(), "{}", text(&o));
    let y = box_y(&report);
    assert!((0.15..0.19).contains(&y), "the box ended at y = {y}");
}

/// `calibrate --points` writes a file equivalent to the camera's own: the
/// same frames then move the box to the same place.
#[test]
fn calibrate_writes_a_file_run_reads() {
    let (tmp, frames) = synthesized("ir");
    let out = frames.join("mine.toml");
    let o = bin()
        .args(["calibrate", "--images"])
        .arg(&frames)
        .arg("--out")
        .arg(&out)
        // The synthetic IR camera's corners (mirrored keystone), table corners from --task.
        .args(["--points", "566,38 84,46 26,452 616,440", "--task", "tasks/cases/one_box.toml"])
        .args(["--background", "background.png", "--threshold", "40"])
        .output()
        .expect("runs");
    assert!(o.status.success(), "{}", text(&o));
    let written = std::fs::read_to_string(&out).expect("file");
    assert!(written.contains("kind = \"ir\"") && written.contains("image_size = [640, 480]"), "{written}");
    let (a, b) = (tmp.path().join("a.json"), tmp.path().join("b.json"));
    assert!(run_images(&frames, &frames.join("calibration.toml"), &a).status.success());
    assert!(run_images(&frames, &out, &b).status.success());
    assert!((box_y(&a) - box_y(&b)).abs() < 1e-6, "{} vs {}", box_y(&a), box_y(&b));

    let bad = bin()
        .args(["calibrate", "--images"])
        .arg(&frames)
        .arg("--out")
        .arg(tmp.path().join("bad.toml"))
        .args(["--points", "566,38 26,452 84,46 616,440"])
        .output()
        .expect("runs");
    assert_eq!(bad.status.code(), Some(2), "{}", text(&bad));
    assert!(
        text(&bad).contains("field `image_points`: the 4 points must be the corners of a convex quadrilateral"),
        "{}",
        text(&bad)
    );
    assert!(!tmp.path().join("bad.toml").exists());
}

/// Bad frames and bad calibrations exit 2 naming the file; nothing is written.
#[test]
fn bad_frames_are_named_and_exit_2() {
    let (tmp, frames) = synthesized("ir");
    let calibration = frames.join("calibration.toml");
    let report = tmp.path().join("r.json");
    let expect_2 = |dir: &Path, cal: &Path, want: &str| {
        let o = run_images(dir, cal, &report);
        let t = refused(&o, &[want]);
        assert!(!t.contains("panicked"), "{t}");
        assert!(!report.exists());
    };
    // Wrong size.
    let frame = frames.join("frame_00050.png");
    image::GrayImage::new(320, 240).save(&frame).expect("save");
    expect_2(&frames, &calibration, "frame_00050.png: 320x240 pixels; the calibration's image_size is 640x480");
    // Colour.
    image::RgbImage::new(640, 480).save(&frame).expect("save");
    expect_2(&frames, &calibration, "frame_00050.png: Rgb8 pixels; frames must be 8- or 16-bit grey");
    // Unreadable.
    std::fs::write(&frame, b"\x89PNG\r\n\x1a\ntruncated").expect("write");
    expect_2(&frames, &calibration, "frame_00050.png: not a readable PNG image");
    // Cut short after a whole header: found while playing, still bad input.
    let whole = std::fs::read(frames.join("frame_00049.png")).expect("read");
    std::fs::write(&frame, &whole[..100]).expect("write");
    expect_2(&frames, &calibration, "frame_00050.png: not a readable PNG image");
    // Missing, named by frames.csv.
    std::fs::write(frames.join("frames.csv"), "file,t_s\nframe_00000.png,0\nframe_99999.png,0.1\n").expect("csv");
    expect_2(&frames, &calibration, "frame_99999.png: cannot read");
    // 8-bit frames for a depth calibration.
    std::fs::remove_file(frames.join("frames.csv")).expect("rm");
    image::GrayImage::new(640, 480).save(&frame).expect("save");
    let depth = tmp.path().join("depth.toml");
    std::fs::write(
        &depth,
        std::fs::read_to_string(&calibration)
            .expect("read")
            .replace("kind = \"ir\"", "kind = \"depth\"")
            .replace("background = \"background.png\"\nthreshold = 40", "table_depth_mm = 1000.0"),
    )
    .expect("write");
    expect_2(&frames, &depth, "8-bit grey; depth frames must be 16-bit millimetres");
    // A calibration with a bad field, and none at all.
    let bad = tmp.path().join("bad.toml");
    std::fs::write(
        &bad,
        std::fs::read_to_string(&calibration).expect("read").replace("threshold = 40", "threshold = 300"),
    )
    .expect("write");
    expect_2(&frames, &bad, "bad.toml:9: field `threshold`: 300 is out of range (0..=254)");
    expect_2(&frames, &tmp.path().join("none.toml"), "none.toml: cannot read");
    expect_2(&tmp.path().join("no_frames"), &calibration, "no_frames: cannot read");
}

#[test]
fn gesture_and_images_are_one_choice() {
    let both = run_cli(
        "run --task one_box --technique joint --gesture assets/gestures/edge_push.toml --images x --calibration c.toml",
    );
    assert_eq!(both.status.code(), Some(2), "{}", text(&both));
    assert!(text(&both).contains("cannot be used with"), "{}", text(&both));
    let neither = run_cli("run --task one_box --technique joint");
    assert_eq!(neither.status.code(), Some(2), "{}", text(&neither));
    let no_calibration = run_cli("run --task one_box --technique joint --images x");
    assert_eq!(no_calibration.status.code(), Some(2), "{}", text(&no_calibration));
    assert!(text(&no_calibration).contains("--calibration"), "{}", text(&no_calibration));
}
