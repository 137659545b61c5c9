//! One frame from surface to physics — two flat hands on a
//! 640×480 contact image → vision → ~1400 particles → one step of the
//! sorting scene — with the paper's create/destroy particles against
//! pooled particles, each with and without culling the particles that can
//! touch nothing movable, all with line-of-sight capsules (the default),
//! and the default with ball particles. The pooled rows move a resting
//! hand's particles on what it rests on as one persistent pad (the
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

fn hands(k: usize) -> Vec<Hand> {
    // Two flat hands sliding slowly over the sorting objects.
    let t = k as f32 / 60.0;
    vec![
        Hand::new(1, HandKind::FlatHand, -0.12 + 0.04 * (t * 0.7).sin(), 0.02).with_pressure(1.0),
        Hand::new(2, HandKind::FlatHand, 0.12 - 0.04 * (t * 0.7).sin(), -0.05).with_angle(0.4).with_pressure(1.0),
    ]
}

fn run(pooled: bool, cull: bool, capsules: bool) -> (StageTimes, usize, usize) {
    let scene = scene::load("sorting").expect("scene");
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
        s.step(&hands(k)).expect("step");
    }
    let mut sum = StageTimes::default();
    let (mut particles, mut sensed) = (0, 0);
    for k in WARMUP..WARMUP + FRAMES {
        s.step(&hands(k)).expect("step");
        let t = s.last_times();
        sum.rasterize_us += t.rasterize_us;
        sum.vision_us += t.vision_us;
        sum.technique_us += t.technique_us;
        sum.step_us += t.step_us;
        particles += s.counts().bodies;
        sensed += s.frame().edges.len();
    }
    let n = FRAMES as f64;
    (
        StageTimes {
            rasterize_us: sum.rasterize_us / n,
            vision_us: sum.vision_us / n,
            technique_us: sum.technique_us / n,
            step_us: sum.step_us / n,
        },
        particles / FRAMES,
        sensed / FRAMES,
    )
}

fn main() {
    // `cargo test` runs benches with --bench absent; do nothing then.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    println!("| variant | sensed | simulated | rasterize µs | vision µs | technique µs | step µs | total ms |");
    println!("|---|---|---|---|---|---|---|---|");
    let mut totals = Vec::new();
    for (pooled, cull, capsules, name) in [
        (false, false, true, "create/destroy (paper)"),
        (true, false, true, "pooled"),
        (false, true, true, "create/destroy + cull"),
        (true, true, true, "pooled + cull (default)"),
        (true, true, false, "pooled + cull, ball particles"),
    ] {
        let (t, n, sensed) = run(pooled, cull, capsules);
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
    println!(
        "\npooled vs paper: {:.1}x; pooled + cull vs paper: {:.1}x (target: <= 2 ms and >= 5x); \
         line-of-sight capsules cost {:.2}x ball particles (pooled + cull)",
        totals[0] / totals[1],
        totals[0] / totals[3],
        totals[3] / totals[4]
    );
}
