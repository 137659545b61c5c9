//! A live camera's path, with filmed frames standing in for the device: the
//! frames a synthetic camera films of a gesture, delivered as a V4L2 driver
//! would (packed YUYV for infrared, Z16 for depth, padded rows) through the
//! capture thread, move the box exactly as the same frames read from PNG
//! files do. What no test here can try is the device itself (these machines
//! have no camera); `demo --camera` says so in a build without the feature.

mod common;

use common::{filmed, thresholds};
use std::process::Command;
use std::time::{Duration, Instant};
use surfacelab::input::camera::{CameraFeed, ChannelCamera, PixelFormat, RawFormat, encode};
use surfacelab::input::images::{CameraImage, CameraKind};
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::scene::ObjectId;
use surfacelab::session::{Session, SessionOptions};

/// The box's final position after `gesture` filmed by a `kind` camera:
/// read from the PNG files, and streamed through the camera path.
fn both_ways(gesture: &str, kind: CameraKind, pixel: PixelFormat) -> (glam::Vec2, glam::Vec2, f32) {
    let mut film = filmed::one_box(gesture, kind, 5);
    let (scene, sensor, dt, files) = (&film.scene, &film.sensor, film.dt, &mut film.frames);
    let options = SessionOptions::default();

    // Rows padded to a multiple of 64 bytes, as drivers align them.
    let row = 640 * pixel.bytes_per_pixel();
    let format = RawFormat { stride: row.div_ceil(64) * 64 + 64, ..RawFormat::packed(640, 480, pixel) };
    let (camera, tx) = ChannelCamera::new("filmed", format);
    let mut feed = CameraFeed::start(Box::new(camera), Some(files.calibration().clone())).expect("starts");

    let box_at = |s: &Session| s.world().object_pose(ObjectId::new(0)).position.truncate();
    let mut read = Session::new(scene, TechniqueKind::PARTICLE, SessionOptions::default()).expect("session");
    let mut streamed = Session::new(scene, TechniqueKind::PARTICLE, SessionOptions::default()).expect("session");
    let until = files.duration(dt) + 0.5;
    let mut sent = None;
    while read.time() + 0.5 * dt < until {
        let t = read.time();
        read.step_image(files.image_at(t, dt, sensor).expect("frame")).expect("step");
        // The camera delivers the frame due now, if it is a new one; the
        // step then runs at an instant after it arrived.
        let due = files.frames().at(t, dt);
        if let Some(i) = due
            && due != sent
        {
            let frame = CameraImage::read(files.frames().path(i)).expect("png");
            tx.send(encode(&frame, &format).expect("encodes")).expect("the capture thread runs");
            sent = due;
            let deadline = Instant::now() + Duration::from_secs(10);
            loop {
                let shown = feed.counts().0;
                feed.image_at(Instant::now(), sensor).expect("frame");
                if feed.counts().0 > shown {
                    break;
                }
                assert!(Instant::now() < deadline, "frame {i} never arrived");
                std::thread::sleep(Duration::from_micros(200));
            }
        }
        streamed.step_image(feed.image_at(Instant::now(), sensor).expect("frame")).expect("step");
    }
    let (a, b) = (box_at(&read), box_at(&streamed));
    let travel = (a - box_at(&Session::new(scene, TechniqueKind::PARTICLE, options).expect("session"))).length();
    (a, b, travel)
}

#[test]
fn infrared_frames_streamed_as_yuyv_move_the_box_exactly_as_read_from_files() {
    let (read, streamed, travel) = both_ways("edge_push", CameraKind::Ir, PixelFormat::Yuyv);
    thresholds::CAMERA_EDGE_PUSH_TRAVEL.check(travel, "the filmed push moved the box");
    assert_eq!(read, streamed, "the same frames through the camera path must give the same physics");
}

#[test]
fn depth_frames_streamed_as_z16_move_the_box_exactly_as_read_from_files() {
    let (read, streamed, travel) = both_ways("flat_hand_sweep", CameraKind::Depth, PixelFormat::Z16);
    thresholds::CAMERA_SWEEP_TRAVEL.check(travel, "the filmed sweep moved the box");
    assert_eq!(read, streamed, "the same frames through the camera path must give the same physics");
}

fn demo(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_surfacelab"))
        .arg("demo")
        .args(args)
        // No window may open: every case here must stop before one would.
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("runs")
}

/// Without the `camera` feature (the default test build) the flag is
/// understood and refused with how to get it; with it, a device that does
/// not exist is named. Either way: exit 2, before any window.
#[test]
fn demo_camera_says_what_it_needs_or_which_device_is_missing() {
    let out = demo(&["--camera", "/no/such/video9"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    if cfg!(feature = "camera") {
        assert!(err.contains("--camera: /no/such/video9: cannot open"), "{err}");
    } else {
        assert!(err.contains("--camera: this surfacelab was built without camera capture"), "{err}");
        assert!(err.contains("--features camera") && err.contains("libclang"), "{err}");
    }
    let out = demo(&["--camera", "/dev/video0", "--calibration", "/no/such/calibration.toml"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--calibration: /no/such/calibration.toml: cannot read"), "{err}");
    let out = demo(&["--calibration", "c.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--calibration is for --images or --camera"));
    let out = demo(&["--camera", "/dev/video0", "--images", "frames"]);
    assert_eq!(out.status.code(), Some(2), "--camera and --images conflict");
}

/// A file that is not a camera is named as such (feature build only: the
/// device is opened).
#[cfg(feature = "camera")]
#[test]
fn a_file_that_is_not_a_camera_is_named() {
    let out = demo(&["--camera", "/dev/null"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--camera: /dev/null: not a V4L2 capture device"), "{err}");
}
