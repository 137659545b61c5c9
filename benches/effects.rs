//! What each effect costs on the scene that declares it: one world step of
//! the scene as declared against the same scene with that effect switched
//! off (for soft bodies: the body is then not created at all; for tearing:
//! the same sheet without a tear threshold). Also the fixed cost of a step
//! of an empty rapier world, which bounds what rapier's per-step soft-body
//! passes cost when there are no soft bodies.
//!
//! `cargo bench --bench effects` (about a minute); results in target/criterion.

use criterion::{Criterion, criterion_group, criterion_main};
use std::time::Duration;
use surfacelab::pipeline::surface::{Hand, HandKind};
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::pipeline::world::prelude::PhysicsWorld;
use surfacelab::pipeline::world::{ObjectId, World};
use surfacelab::scene::{self, Effect, EffectSet, Scene};
use surfacelab::session::{Session, SessionOptions};

fn without(effects: EffectSet, e: Effect) -> EffectSet {
    effects.iter().filter(|x| *x != e).collect()
}

/// The scene's world, stepped for `warm` seconds first so it is in its
/// usual state (a dropped cloth settled, objects resting or asleep).
fn warmed(s: &Scene, effects: EffectSet, warm: f32) -> World {
    let mut w = World::with_effects(s, effects);
    for _ in 0..(warm / w.dt()) as usize {
        w.step();
    }
    w
}

fn bench_pair(c: &mut Criterion, group: &str, runs: Vec<(&str, Scene, EffectSet)>) {
    let mut g = c.benchmark_group(group);
    g.sample_size(30).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(2));
    for (label, s, effects) in runs {
        let mut w = warmed(&s, effects, 0.5);
        // Keep something happening: a nudge to the first object (if any)
        // every two seconds, so sleeping and CCD have work to judge.
        let mut k = 0usize;
        g.bench_function(label, |b| {
            b.iter(|| {
                k += 1;
                if w.object_count() > 0
                    && k.is_multiple_of(120)
                    && let Some(mut body) = w.push_object(ObjectId::new(0))
                    && body.is_dynamic()
                {
                    body.apply_impulse(glam::Vec3::new(0.01, 0.005, 0.0));
                }
                w.step();
            });
        });
    }
    g.finish();
}

/// A whole frame (rasterize, vision, Proxy technique, step) with a flat
/// hand circling slowly on the scene's first soft body: what the effect
/// costs while someone is using it.
fn bench_under_hand(c: &mut Criterion, group: &str, runs: Vec<(&str, Scene)>) {
    let mut g = c.benchmark_group(group);
    g.sample_size(20).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    for (label, s) in runs {
        let at = s.soft_bodies.first().map_or(glam::Vec2::ZERO, |b| b.position.truncate());
        let mut session = Session::new(&s, TechniqueKind::PROXY, SessionOptions::default()).expect("session");
        let mut k = 0u32;
        g.bench_function(label, |b| {
            b.iter(|| {
                k += 1;
                let t = k as f32 / 60.0;
                let hand =
                    Hand::new(1, HandKind::FlatHand, at.x + 0.03 * (t * 0.7).cos(), at.y + 0.03 * (t * 0.7).sin());
                session.step(std::slice::from_ref(&hand)).expect("step");
            });
        });
    }
    g.finish();
}

fn effects(c: &mut Criterion) {
    // Soft bodies: the scene with its soft bodies, and without them.
    for (task, effect) in [("cloth", Effect::Cloth), ("soft", Effect::SoftBodies)] {
        let s = scene::load(task).expect("scene");
        let off = without(s.effects, effect);
        bench_pair(c, &format!("effect/{effect}"), vec![("declared", s.clone(), s.effects), ("off", s, off)]);
    }
    for (task, effect) in [("cloth", Effect::Cloth), ("soft", Effect::SoftBodies)] {
        let s = scene::load(task).expect("scene");
        let mut off = s.clone();
        off.effects = without(s.effects, effect);
        off.soft_bodies.clear();
        bench_under_hand(c, &format!("effect/{effect}/under_hand"), vec![("declared", s), ("off", off)]);
    }
    // Tearing: the paper sheet, tearable or not, and no sheet at all.
    let tear = scene::load("tear").expect("scene");
    let mut plain = tear.clone();
    plain.soft_bodies[0].tear_strain = None;
    let no_tearing = without(tear.effects, Effect::Tearing);
    let no_sheet = without(no_tearing, Effect::Cloth);
    bench_pair(
        c,
        "effect/tearing",
        vec![
            ("declared", tear.clone(), tear.effects),
            ("off_same_sheet", plain, no_tearing),
            ("no_sheet", tear, no_sheet),
        ],
    );
    // The rigid effects on the scenes that declare them.
    for (task, effect) in [("ball", Effect::Ccd), ("gather", Effect::Sleeping)] {
        let s = scene::load(task).expect("scene");
        let off = without(s.effects, effect);
        bench_pair(c, &format!("effect/{effect}"), vec![("declared", s.clone(), s.effects), ("off", s, off)]);
    }
    // The floor: an empty rapier world (no body, no collider, no soft body).
    let mut g = c.benchmark_group("effect/empty_world");
    g.sample_size(30).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1));
    let mut empty = PhysicsWorld::new();
    g.bench_function("step", |b| b.iter(|| empty.step()));
    g.finish();
}

criterion_group!(benches, effects);
criterion_main!(benches);
