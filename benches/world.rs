//! What undeclared effects cost: the same scene stepped with only its
//! declared effects and with every effect switched on, while every object
//! is kept moving (a slow circular stir, as hands would) so that sleeping
//! cannot hide the difference.
//!
//! `cargo bench --bench world`

use criterion::{Criterion, criterion_group, criterion_main};
use glam::Vec3;
use surfacelab::pipeline::world::{ObjectId, World};
use surfacelab::scene::{self, EffectSet};

fn stir(w: &mut World, k: usize) {
    let t = k as f32 / 60.0;
    for i in 0..w.object_count() {
        if let Some(mut b) = w.push_object(ObjectId::new(i))
            && b.is_dynamic()
        {
            let phase = t * 1.5 + i as f32;
            let f = Vec3::new(phase.cos(), phase.sin(), 0.0) * (b.mass() * 4.0);
            b.reset_forces();
            b.add_force(f);
        }
    }
}

fn effects(c: &mut Criterion) {
    for task in ["positioning", "sorting", "steering"] {
        let s = scene::load(task).expect("scene");
        let mut g = c.benchmark_group(format!("world_step/{task}"));
        for (label, effects) in [("declared", s.effects), ("all_effects", EffectSet::all())] {
            g.bench_function(label, |b| {
                let mut w = World::with_effects(&s, effects);
                let mut k = 0usize;
                b.iter(|| {
                    k += 1;
                    stir(&mut w, k);
                    w.step();
                    if k.is_multiple_of(600) {
                        // Keep the scene on the table: start over every 10 s.
                        w.reset_objects();
                    }
                });
            });
        }
        g.finish();
    }
}

criterion_group!(benches, effects);
criterion_main!(benches);
