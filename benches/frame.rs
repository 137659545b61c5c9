//! One frame from surface to physics — two flat hands on a 640×480 contact
//! image → vision → ~1400 particles → one step of the sorting scene — with
//! the paper's create/destroy particles against pooled particles, each with
//! and without culling the particles that can touch nothing movable, all
//! with line-of-sight capsules (the default), and the default with ball
//! particles; then the stretch frame, four flat hands and a forearm at
//! 240 Hz, create/destroy against the default. The pooled rows move a
//! resting hand's particles on what it rests on as one persistent pad (the
//! default, `particle_pad`); the create/destroy rows keep the paper's
//! independent particles. Prints a table of per-stage means.
//!
//! `cargo bench --bench frame`

use surfacelab::pipeline::surface::{Hand, HandKind};
use surfacelab::pipeline::technique::{TechniqueConfig, TechniqueKind};
use surfacelab::scene;
use surfacelab::session::{Session, SessionOptions, StageTimes};

const WARMUP: usize = 60;
const FRAMES: usize = 600;

/// Two flat hands sliding slowly over the sorting objects: the paper's
/// two-hand frame.
fn two_hands(k: usize) -> Vec<Hand> {
    let t = k as f32 / 60.0;
    vec![
        Hand::new(1, HandKind::FlatHand, -0.12 + 0.04 * (t * 0.7).sin(), 0.02).with_pressure(1.0),
        Hand::new(2, HandKind::FlatHand, 0.12 - 0.04 * (t * 0.7).sin(), -0.05).with_angle(0.4).with_pressure(1.0),
    ]
}

/// The stretch frame: four flat hands and a forearm sweeping the sorting
/// objects together (two people at the table).
fn four_hands_and_forearm(k: usize) -> Vec<Hand> {
    let t = k as f32 / 60.0;
    let slide = 0.04 * (t * 0.7).sin();
    vec![
        Hand::new(1, HandKind::FlatHand, -0.3 + slide, 0.12).with_pressure(1.0),
        Hand::new(2, HandKind::FlatHand, -0.1 - slide, 0.12).with_angle(0.3).with_pressure(1.0),
        Hand::new(3, HandKind::FlatHand, 0.1 + slide, -0.1).with_angle(-0.3).with_pressure(1.0),
        Hand::new(4, HandKind::FlatHand, 0.3 - slide, -0.1).with_pressure(1.0),
        Hand::new(5, HandKind::Forearm, slide, -0.25).with_angle(1.5).with_pressure(1.0),
    ]
}

/// What a row of the table runs: its hands and the physics rate.
#[derive(Clone, Copy)]
struct Load {
    hands: fn(usize) -> Vec<Hand>,
    hz: f32,
}

fn run(load: Load, pooled: bool, cull: bool, capsules: bool) -> (StageTimes, usize, usize) {
    let mut scene = scene::load("sorting").expect("scene");
    scene.physics.dt = 1.0 / load.hz;
    let config = TechniqueConfig {
        particle_pooled: pooled,
        particle_cull: cull,
        particle_capsules: capsules,
        particle_stride: 2,
        // The paper's particles are independent bodies: no resting hand's pad.
        particle_pad: pooled,
        ..TechniqueConfig::default()
    };
    let mut s = Session::new(
        &scene,
        TechniqueKind::PARTICLE,
        SessionOptions { config: Some(config), ..SessionOptions::default() },
    )
    .expect("session");
    for k in 0..WARMUP {
        s.step(&(load.hands)(k)).expect("step");
    }
    let mut sum = StageTimes::default();
    let (mut particles, mut sensed) = (0, 0);
    for k in WARMUP..WARMUP + FRAMES {
        s.step(&(load.hands)(k)).expect("step");
        sum.add(&s.last_times());
        particles += s.counts().bodies;
        sensed += s.frame().edges.len();
    }
    (sum.per_frame(FRAMES as u64), particles / FRAMES, sensed / FRAMES)
}

fn main() {
    // `cargo test` runs benches with --bench absent; do nothing then.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let two = Load { hands: two_hands, hz: 60.0 };
    println!("Two flat hands, 60 Hz:\n");
    let totals = table(two, &VARIANTS);
    println!(
        "\npooled vs paper: {:.1}x; pooled + cull vs paper: {:.1}x (target: <= 2 ms and >= 5x); \
         line-of-sight capsules cost {:.2}x ball particles (pooled + cull)",
        totals[0] / totals[1],
        totals[0] / totals[3],
        totals[3] / totals[4]
    );
    let stretch = Load { hands: four_hands_and_forearm, hz: 240.0 };
    println!("\nFour flat hands and a forearm, 240 Hz:\n");
    let totals = table(stretch, &[VARIANTS[0], VARIANTS[3]]);
    println!("\npooled + cull vs paper: {:.1}x (target: >= 10x)", totals[0] / totals[1]);
}

/// (pooled, cull, capsules, name) of each row.
type Variant = (bool, bool, bool, &'static str);

const VARIANTS: [Variant; 5] = [
    (false, false, true, "create/destroy (paper)"),
    (true, false, true, "pooled"),
    (false, true, true, "create/destroy + cull"),
    (true, true, true, "pooled + cull (default)"),
    (true, true, false, "pooled + cull, ball particles"),
];

/// Prints one row per variant under `load`; returns each total (µs).
fn table(load: Load, variants: &[Variant]) -> Vec<f64> {
    println!("| variant | sensed | simulated | rasterize µs | vision µs | technique µs | step µs | total ms |");
    println!("|---|---|---|---|---|---|---|---|");
    let mut totals = Vec::new();
    for &(pooled, cull, capsules, name) in variants {
        let (t, n, sensed) = run(load, pooled, cull, capsules);
        println!(
            "| {name} | {sensed} | {n} | {:.0} | {:.0} | {:.0} | {:.0} | {:.2} |",
            t.rasterize_us,
            t.vision_us,
            t.technique_us,
            t.step_us,
            t.total_us() / 1000.0
        );
        totals.push(t.total_us());
    }
    totals
}
