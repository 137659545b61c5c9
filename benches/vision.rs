//! Time per vision stage at 640 x 480 for three scenes (one fingertip, two
//! flat hands, a forearm), plus rasterization and a whole-frame Sobel for
//! comparison with the bounding-box one.
//!
//! `cargo bench --bench vision`; quick look:
//! `cargo bench --bench vision -- --warm-up-time 1 --measurement-time 2`.

use std::hint::black_box;

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use surfacelab::pipeline::surface::{ContactImage, Hand, HandKind, RasterParams, Sensor, rasterize, rasterize_into};
use surfacelab::pipeline::vision::{
    BlobTracker, BlobTrackerParams, BlockMatcher, Mask, Pipeline, VisionParams, find_blobs, find_edges,
    gradient_magnitude, rigid_guess, threshold_into,
};

/// A scene at frame `k` of a 60 Hz motion: each hand moves ~1 cm/frame and
/// turns a little, so flow and tracking have real work to do.
fn scene(name: &str, k: f32) -> Vec<Hand> {
    match name {
        "one_fingertip" => vec![Hand::new(1, HandKind::Fingertips(1), 0.02 + 0.01 * k, 0.01)],
        "two_flat_hands" => vec![
            Hand::new(1, HandKind::FlatHand, -0.2 + 0.008 * k, -0.05).with_angle(0.3 + 0.02 * k),
            Hand::new(2, HandKind::FlatHand, 0.2 - 0.008 * k, -0.04).with_angle(-0.3 - 0.02 * k),
        ],
        _ => {
            vec![Hand::new(1, HandKind::Forearm, 0.0, -0.1 + 0.006 * k).with_angle(1.2 + 0.01 * k)]
        }
    }
}

fn bench_scene(c: &mut Criterion, name: &str) {
    let sensor = Sensor::default();
    let raster = RasterParams::default();
    let params = VisionParams::default();
    let prev = rasterize(&scene(name, 0.0), &sensor, &raster);
    let cur = rasterize(&scene(name, 1.0), &sensor, &raster);
    let mut group = c.benchmark_group(format!("vision/{name}"));

    let mut image = ContactImage::default();
    group.bench_function("rasterize", |b| {
        let hands = scene(name, 1.0);
        b.iter(|| rasterize_into(black_box(&hands), &sensor, &raster, &mut image));
    });

    let mut mask = Mask::default();
    group.bench_function("threshold", |b| {
        b.iter(|| threshold_into(black_box(&cur), params.threshold, &mut mask));
    });
    threshold_into(&cur, params.threshold, &mut mask);
    let mut prev_mask = Mask::default();
    threshold_into(&prev, params.threshold, &mut prev_mask);

    group.bench_function("components", |b| {
        b.iter(|| find_blobs(black_box(&cur), &mask, params.min_area));
    });
    let blobs = find_blobs(&cur, &mask, params.min_area);
    let prev_blobs = find_blobs(&prev, &prev_mask, params.min_area);

    let mut primed = BlobTracker::new(BlobTrackerParams::default());
    primed.update(&prev_blobs);
    group.bench_function("tracking", |b| {
        b.iter_batched(|| primed.clone(), |mut t| t.update(black_box(&blobs)), BatchSize::SmallInput);
    });
    let tracked = primed.clone().update(&blobs);

    group.bench_function("sobel", |b| {
        b.iter(|| find_edges(black_box(&cur), &blobs, params.edge_threshold, params.stride));
    });
    group.bench_function("sobel_whole_frame", |b| {
        b.iter(|| gradient_magnitude(black_box(&cur)));
    });
    let edges = find_edges(&cur, &blobs, params.edge_threshold, params.stride);

    let matcher = BlockMatcher::new(params.block_size, params.search_radius);
    group.bench_function("flow", |b| {
        b.iter(|| {
            edges
                .iter()
                .map(|e| {
                    let t = &tracked[e.blob];
                    let guess =
                        rigid_guess([e.x as f32, e.y as f32], blobs[e.blob].weighted_centroid, t.velocity, t.rotation);
                    matcher.flow_at(&prev, black_box(&cur), [e.x, e.y], guess)
                })
                .collect::<Vec<_>>()
        });
    });

    let mut pipeline = Pipeline::new(params);
    pipeline.process(&prev);
    group.bench_function("pipeline", |b| {
        b.iter_batched(|| pipeline.clone(), |mut p| p.process(black_box(&cur)), BatchSize::SmallInput);
    });
    group.finish();

    // The pipeline's own stage clock, for the report (median of 200 runs).
    let mut runs: Vec<[f64; 6]> = (0..200)
        .map(|_| {
            let t = pipeline.clone().process(&cur).timings;
            [t.threshold_us, t.components_us, t.tracking_us, t.sobel_us, t.flow_us, t.total_us]
        })
        .collect();
    let mut median = [0.0; 6];
    for (k, m) in median.iter_mut().enumerate() {
        runs.sort_by(|a, b| a[k].total_cmp(&b[k]));
        *m = runs[runs.len() / 2][k];
    }
    let f = pipeline.clone().process(&cur);
    println!(
        "{name}: {} contacts, {} edge samples; StageTimings medians (us): threshold {:.1}, components {:.1}, \
         tracking {:.1}, sobel {:.1}, flow {:.1}, total {:.1}",
        f.contacts.len(),
        f.edges.len(),
        median[0],
        median[1],
        median[2],
        median[3],
        median[4],
        median[5]
    );
}

fn benches(c: &mut Criterion) {
    for name in ["one_fingertip", "two_flat_hands", "forearm"] {
        bench_scene(c, name);
    }
}

criterion_group!(vision, benches);
criterion_main!(vision);
