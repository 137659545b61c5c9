//! Cost of the image path: per 640×480 camera frame, decoding
//! its PNG and rectifying it into the 640×480 contact image, for an 8-bit
//! IR frame (with background subtraction) and a 16-bit depth frame, both
//! from the synthetic cameras filming a flat hand; and the same frames as a
//! live camera delivers them (YUYV for IR, Z16 for depth), decoded from
//! the driver's bytes instead of a PNG. Prints a table of means.
//!
//! `cargo bench --bench images`

use std::time::Instant;
use surfacelab::input::camera::{PixelFormat, RawFormat, decode, encode};
use surfacelab::input::images::{CameraImage, CameraKind, Rectifier, Synthesizer};
use surfacelab::pipeline::surface::{ContactImage, Hand, HandKind, RasterParams, Sensor, rasterize};

const FRAMES: u32 = 200;

fn main() {
    let sensor = Sensor::default();
    let hand = Hand::new(1, HandKind::FlatHand, 0.05, -0.02).with_angle(0.3).with_pressure(1.0);
    let contact = rasterize(&[hand], &sensor, &RasterParams::default());
    let dir = tempfile::tempdir().expect("temp dir");
    println!("{:<10} {:>10} {:>12} {:>14} {:>10}", "frame", "bytes", "decode µs", "rectify µs", "total µs");
    for kind in [CameraKind::Ir, CameraKind::Depth] {
        let synth = Synthesizer::new(kind, &sensor, [640, 480], 3).expect("camera");
        let path = dir.path().join(format!("{}.png", kind.name()));
        synth.frame(&contact, 0).write(&path).expect("write");
        let bytes = std::fs::metadata(&path).expect("size").len();
        let t = Instant::now();
        let rectifier = Rectifier::new(synth.calibration(), &sensor);
        let setup_ms = t.elapsed().as_secs_f64() * 1e3;
        let read = || CameraImage::read(&path).expect("decode");
        measure(&format!("{} PNG", kind.name()), bytes, &rectifier, read, setup_ms);
        // The same frame as a V4L2 camera hands it over.
        let png = CameraImage::read(&path).expect("decode");
        let pixel = if kind == CameraKind::Depth { PixelFormat::Z16 } else { PixelFormat::Yuyv };
        let format = RawFormat::packed(640, 480, pixel);
        let raw = encode(&png, &format).expect("encode");
        let from_raw = || decode(&format, &raw).expect("decode");
        measure(&format!("{} {}", kind.name(), pixel.name()), raw.len() as u64, &rectifier, from_raw, setup_ms);
    }
}

/// Times `FRAMES` decodes (by `get`) and rectifications; prints a row.
fn measure(name: &str, bytes: u64, rectifier: &Rectifier, get: impl Fn() -> CameraImage, setup_ms: f64) {
    let (mut decode, mut rectify) = (0.0, 0.0);
    let mut out = ContactImage::default();
    let mut lit = 0;
    for _ in 0..FRAMES {
        let t0 = Instant::now();
        let frame = get();
        let t1 = Instant::now();
        assert!(rectifier.rectify(&frame, &mut out));
        let t2 = Instant::now();
        decode += (t1 - t0).as_secs_f64();
        rectify += (t2 - t1).as_secs_f64();
        lit = out.pixels.iter().filter(|&&g| g >= 48).count();
    }
    let n = f64::from(FRAMES) / 1e6;
    println!(
        "{name:<10} {bytes:>10} {:>12.0} {:>14.0} {:>10.0}   (rectifier set-up {setup_ms:.1} ms once; {lit} contact pixels lit)",
        decode / n,
        rectify / n,
        (decode + rectify) / n
    );
}
