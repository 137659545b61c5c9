//! What undeclared effects cost: the same scene stepped with its declared
//! effects and with every effect switched on.
//!
//! `cargo bench --bench world`

use criterion::{Criterion, criterion_group, criterion_main};
use surfacelab::scene::{self, EffectSet};
use surfacelab::world::World;

fn settle_and_step(c: &mut Criterion) {
    for task in ["positioning", "sorting", "steering"] {
        let s = scene::load(task).expect("scene");
        let mut g = c.benchmark_group(format!("world_step/{task}"));
        for (label, effects) in [("declared", s.effects), ("all_effects", EffectSet::all())] {
            g.bench_function(label, |b| {
                let mut w = World::with_effects(&s, effects);
                // Keep the objects moving so sleeping and CCD both have work to
                // judge: a gentle stir every step.
                let mut k = 0usize;
                b.iter(|| {
                    k += 1;
                    let i = k % w.object_count();
                    let h = w.object_body(i);
                    if let Some(body) = w.physics_mut().bodies.get_mut(h)
                        && body.is_dynamic()
                        && k.is_multiple_of(120)
                    {
                        body.apply_impulse(glam::Vec3::new(0.02, 0.0, 0.0), true);
                    }
                    w.step();
                });
            });
        }
        g.finish();
    }
}

criterion_group!(benches, settle_and_step);
criterion_main!(benches);
