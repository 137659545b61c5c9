//! Off-screen frame time at 1024x768: prepare + render + readback, what a
//! study run recording video pays per frame. Goal: <= 15 ms on lavapipe with
//! the default options (no MSAA); 4x MSAA is measured for comparison.
//!
//! `cargo bench --bench render`; results land in target/criterion. Without a
//! GPU adapter this panics with the Mesa install hint.

use criterion::{Criterion, criterion_group, criterion_main};
use surfacelab::render::{Capture, GpuContext, RendererOptions, samples};

const WIDTH: u32 = 1024;
const HEIGHT: u32 = 768;

fn capture_frames(c: &mut Criterion) {
    let gpu = GpuContext::new_headless().unwrap_or_else(|e| panic!("{}", surfacelab::error::chain(&e)));
    eprintln!("adapter: {}", gpu.summary());
    let runs = [
        ("positioning", samples::positioning(), 1),
        ("positioning+feedback+contact", samples::positioning_with_overlays(), 1),
        ("steering", samples::steering(), 1),
        ("shapes", samples::shapes(), 1),
        ("positioning+feedback+contact/msaa4", samples::positioning_with_overlays(), 4),
    ];
    let mut group = c.benchmark_group("capture_1024x768");
    group.sample_size(30);
    for (name, list, sample_count) in &runs {
        let options = RendererOptions { sample_count: *sample_count, ..RendererOptions::default() };
        let mut capture = Capture::with_options(&gpu, WIDTH, HEIGHT, options).unwrap_or_else(|e| panic!("{e}"));
        // The first frame compiles the driver's shader variants (slow on
        // lavapipe): keep it out of the measurement.
        capture.render(list).unwrap_or_else(|e| panic!("{e}"));
        group.bench_function(*name, |b| b.iter(|| capture.render(list).unwrap_or_else(|e| panic!("{e}"))));
    }
    group.finish();
}

criterion_group!(benches, capture_frames);
criterion_main!(benches);
