//! How hard a particle presses, measured in rapier: the behaviour behind the
//! comment in `src/pipeline/technique/particle.rs` (where it places particles).
//!
//! Sixteen particles (0.2 kg, pressing 0.08 N each) rest on a
//! 10 cm box; the normal impulse they get from the box in each step,
//! divided by what their weight calls for (16 × 0.08 N × dt), is their
//! *press fraction*.

mod common;

use common::scenes;
use glam::Vec3;
use surfacelab::pipeline::world::prelude::*;
use surfacelab::pipeline::world::{Layer, TechniqueBody, World};
use surfacelab::scene;
use surfacelab::scene::ObjectId;

/// A box for particles to press on.
fn press_scene() -> scene::Scene {
    scenes::build(&scenes::table("press").table_friction(0.3).object(
        "box",
        scenes::cuboid(0.06, 0.06, 0.03),
        [0.0, 0.0],
        0.1,
        "orange",
    ))
}

const N: usize = 16;
const MASS: f32 = 0.2;
const WEIGHT: f32 = 0.08;
const R: f32 = 0.003;

fn ring(box_top: f32, k: usize) -> Vec3 {
    let a = std::f32::consts::TAU * k as f32 / N as f32;
    // 0.1 mm into the top, as `ParticleTechnique` places them.
    Vec3::new(0.008 * a.cos(), 0.008 * a.sin(), box_top + R - 0.0001)
}

/// Press fraction in each of `steps` steps. `fresh`: new bodies every step
/// (the paper's create/destroy); else the same bodies re-placed each step
/// (the pooled variant).
fn press(fresh: bool, steps: usize) -> Vec<f32> {
    let scene = press_scene();
    let mut world = World::new(&scene);
    for _ in 0..30 {
        world.step();
    }
    let dt = world.dt();
    let boxc = world.object_collider(ObjectId::new(0));
    let mut bodies: Vec<TechniqueBody> = Vec::new();
    let mut out = Vec::new();
    for step in 0..steps {
        let top = world.object_pose(ObjectId::new(0)).position.z + 0.015;
        if fresh || step == 0 {
            for b in bodies.drain(..) {
                world.remove_body(b);
            }
            for k in 0..N {
                let body = RigidBodyBuilder::dynamic()
                    .translation(ring(top, k))
                    .gravity_scale(WEIGHT / (MASS * 9.81))
                    .lock_rotations()
                    .build();
                let col = ColliderBuilder::ball(R)
                    .mass(MASS)
                    .friction(1.5)
                    .collision_groups(Layer::Particle.groups())
                    .build();
                bodies.push(world.spawn_body(body, col));
            }
        } else {
            for (k, &h) in bodies.iter().enumerate() {
                let b = world.technique_body_mut(h).expect("particle");
                b.set_position(Pose::from_translation(ring(top, k)), true);
                b.set_linvel(Vec3::ZERO, true);
            }
        }
        world.step();
        let physics = world.physics();
        let impulse: f32 = bodies
            .iter()
            .filter_map(|&h| physics.narrow_phase.contact_pair(physics.bodies[h.handle()].colliders()[0], boxc))
            .flat_map(|pair| pair.manifolds().iter().flat_map(|m| m.points.iter().map(|p| p.data.impulse)))
            .sum();
        out.push(impulse / (N as f32 * WEIGHT * dt));
    }
    out
}

#[test]
fn a_new_particle_presses_with_a_fraction_of_its_weight_and_a_kept_one_with_all_of_it() {
    let pooled = press(false, 8);
    println!("pooled press fractions: {pooled:.2?}");
    // rapier's soft contact (30 Hz) gives a contact that is one step old
    // well under half the normal impulse its weight calls for...
    assert!(pooled[0] < 0.5, "first step: {:.2}", pooled[0]);
    // ...and a contact kept from step to step (warm-started) all of it
    // within a few steps, to 10%.
    assert!(pooled[4..].iter().all(|f| (0.9..=1.1).contains(f)), "kept: {pooled:.2?}");
    let fresh = press(true, 8);
    println!("fresh press fractions: {fresh:.2?}");
    assert!(fresh[0] < 0.5, "first step: {:.2}", fresh[0]);
}
