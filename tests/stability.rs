//! Hard cases that must stay numerically stable, in the shape of rapier's
//! `joint_stability.rs`: each runs ≥ 10,000 steps through the real pipeline
//! and asserts no NaN, no object leaving the world, speeds below a stated
//! limit and penetration below a bound of `common/thresholds.rs`. Every
//! case's scene is a file under `tasks/cases/`, so a failure can be watched
//! in the demo
//! (`surfacelab demo --task tasks/cases/NAME.toml`).

mod common;

use common::thresholds::{self, Threshold};
use glam::{Vec2, Vec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surfacelab::contact::{self, ConvexPolygon};
use surfacelab::pipeline::surface::{Hand, HandKind, PixelPoint};
use surfacelab::pipeline::technique::{TechniqueConfig, TechniqueKind};
use surfacelab::pipeline::world::ObjectId;
use surfacelab::scene;
use surfacelab::session::{Session, SessionOptions};

const STEPS: usize = 10_000;

/// The techniques that hold rigid objects: every one but Direct.
const HOLDING: [TechniqueKind; 3] = [TechniqueKind::PROXY, TechniqueKind::PARTICLE, TechniqueKind::JOINT];

struct Case<'a> {
    task: &'a str,
    kind: TechniqueKind,
    /// Fastest any object may move (m/s).
    speed_limit: Threshold,
    /// Steps before penetration is judged (overlap recovery needs a few).
    settle_steps: usize,
    /// Deepest overlap allowed between scene bodies (m).
    max_penetration: Threshold,
    config: Option<TechniqueConfig>,
    sensor_px: (u32, u32),
}

impl<'a> Case<'a> {
    fn new(task: &'a str, kind: TechniqueKind, speed_limit: Threshold) -> Self {
        Case {
            task,
            kind,
            speed_limit,
            settle_steps: 0,
            max_penetration: thresholds::STABILITY_PENETRATION,
            config: None,
            sensor_px: (640, 480),
        }
    }

    /// One case of `task` under each technique of `kinds`.
    fn each(task: &'a str, kinds: &'a [TechniqueKind], speed_limit: Threshold) -> impl Iterator<Item = Case<'a>> {
        kinds.iter().map(move |&kind| Case::new(task, kind, speed_limit))
    }
}

fn path(task: &str) -> String {
    format!("{}/{task}", env!("CARGO_MANIFEST_DIR"))
}

/// Runs a case for `steps`, feeding `hands(step, session)`; returns the session.
fn run(case: &Case<'_>, steps: usize, mut hands: impl FnMut(usize, &Session) -> Vec<Hand>) -> Session {
    run_with(case, steps, |_| {}, &mut hands)
}

fn run_with(
    case: &Case<'_>,
    steps: usize,
    setup: impl FnOnce(&mut Session),
    hands: &mut dyn FnMut(usize, &Session) -> Vec<Hand>,
) -> Session {
    let scene = scene::load(&path(case.task)).expect("scene loads");
    let options =
        SessionOptions { config: case.config.clone(), sensor_px: case.sensor_px, ..SessionOptions::default() };
    let mut s = Session::new(&scene, case.kind, options).expect("session");
    setup(&mut s);
    let (hw, hd) = (scene.table.width / 2.0 + 0.1, scene.table.depth / 2.0 + 0.1);
    let mut worst_pen = 0.0f32;
    for k in 0..steps {
        let h = hands(k, &s);
        s.step(&h).expect("step");
        let w = s.world_mut();
        let pen = w.measure_penetration();
        if k >= case.settle_steps {
            worst_pen = worst_pen.max(pen);
        }
        for (i, p) in w.object_poses().iter().enumerate() {
            if !p.active {
                continue;
            }
            let q = p.position;
            assert!(q.is_finite(), "{} {}: object {i} non-finite at step {k}", case.task, case.kind);
            assert!(
                q.x.abs() < hw && q.y.abs() < hd && q.z > -0.2 && q.z < 1.0,
                "{} {}: object {i} left the world at step {k}: {q}",
                case.task,
                case.kind
            );
        }
    }
    let st = s.world().stats();
    assert_eq!(st.nan_count, 0, "{} {}: NaN", case.task, case.kind);
    case.speed_limit.check(st.max_speed_seen, &format!("{} {}: max speed", case.task, case.kind));
    case.max_penetration.check(worst_pen, &format!("{} {}: penetration", case.task, case.kind));
    s
}

fn tip(id: u32, p: Vec2) -> Hand {
    Hand::new(id, HandKind::Fingertips(1), p.x, p.y).with_pressure(0.9)
}

/// Linear move from a to b over `frames`, then hold.
fn lerp(a: Vec2, b: Vec2, k: usize, frames: usize) -> Vec2 {
    a.lerp(b, (k as f32 / frames as f32).min(1.0))
}

#[test]
fn two_joints_pulling_one_box_apart() {
    let case = Case::new("tasks/cases/one_box.toml", TechniqueKind::JOINT, thresholds::SPEED_PULLED_APART);
    run(&case, STEPS, |k, _| {
        vec![
            tip(1, lerp(Vec2::new(-0.04, 0.0), Vec2::new(-0.35, 0.05), k, 60)),
            tip(2, lerp(Vec2::new(0.04, 0.0), Vec2::new(0.35, -0.05), k, 60)),
        ]
    });
}

#[test]
fn four_joints_pulling_one_box_apart() {
    // When one of four stretched joints breaks, the other three yank the box:
    // the paper's own "breaking joints fling objects". Bounded, not exploding.
    // The last joint slings the box, spinning at 5 rad/s, into the rim wall:
    // its corner arrives at 0.5 m/s (8 mm a step) and rapier's soft contact
    // lets it in for a step or two, then out (`thresholds::FLUNG_BOX_PENETRATION`).
    let case = Case {
        max_penetration: thresholds::FLUNG_BOX_PENETRATION,
        ..Case::new("tasks/cases/one_box.toml", TechniqueKind::JOINT, thresholds::SPEED_FLUNG_BOX)
    };
    let dirs = [Vec2::X, Vec2::NEG_X, Vec2::Y, Vec2::NEG_Y];
    run(&case, STEPS, |k, _| {
        dirs.iter().enumerate().map(|(i, d)| tip(i as u32 + 1, lerp(*d * 0.045, *d * 0.3, k, 90))).collect()
    });
}

#[test]
fn a_joint_on_a_box_that_a_flat_hand_pins_down() {
    let case = Case::new("tasks/cases/one_box.toml", TechniqueKind::JOINT, thresholds::SPEED_HELD);
    run(&case, STEPS, |k, _| {
        let palm = Hand::new(1, HandKind::FlatHand, -0.02, 0.0).with_pressure(1.0);
        vec![palm, tip(2, lerp(Vec2::new(0.055, 0.0), Vec2::new(0.3, 0.0), k, 120))]
    });
}

#[test]
fn a_stack_of_five_boxes_under_a_pressing_flat_hand() {
    for kind in [TechniqueKind::PROXY, TechniqueKind::PARTICLE] {
        let case = Case {
            max_penetration: thresholds::STACK_PENETRATION,
            ..Case::new("tasks/cases/stack5.toml", kind, thresholds::SPEED_HELD)
        };
        let s = run(&case, STEPS, |_, _| vec![Hand::new(1, HandKind::FlatHand, 0.0, 0.0).with_pressure(1.0)]);
        // Still a stack: every box within 2 cm of the axis.
        for id in s.world().object_ids() {
            let p = s.world().object_pose(id).position;
            assert!(p.truncate().length() < 0.02, "{kind}: box {id:?} slid off the stack to {p}");
        }
    }
}

#[test]
fn a_ball_flicked_at_40_m_per_s_at_a_thin_wall_does_not_tunnel() {
    let case = Case::new("tasks/cases/ball_wall.toml", TechniqueKind::PROXY, thresholds::SPEED_FLICKED_BALL);
    // CCD stops it at the wall, though the contact may sink a few mm in the
    // step it arrives; tunnelling would put its centre past the near face.
    let wall_face = 0.2 - 0.005;
    let mut s = run_with(
        &case,
        STEPS,
        |s| {
            s.world_mut().push_object(ObjectId::new(0)).expect("the ball").set_linvel(Vec3::new(40.0, 0.0, 0.0));
        },
        &mut |_, s: &Session| {
            let x = s.world().object_pose(ObjectId::new(0)).position.x;
            assert!(x <= wall_face, "the ball passed into the wall: x = {x}");
            Vec::new()
        },
    );
    assert!(s.world_mut().object_pose(ObjectId::new(0)).position.x < 0.2);
}

#[test]
fn deeply_overlapping_objects_recover_calmly() {
    let mut case = Case::new("tasks/cases/overlap.toml", TechniqueKind::PROXY, thresholds::SPEED_HELD);
    case.settle_steps = 120;
    run(&case, STEPS, |_, _| Vec::new());
}

#[test]
fn a_100_to_1_mass_ratio_stack_pushed_on_top() {
    for case in Case::each("tasks/cases/mass_ratio.toml", &HOLDING, thresholds::SPEED_HELD) {
        let s = run(&case, STEPS, |k, s| {
            // A fingertip drags the light box around on the heavy block for 3 s.
            let top = s.world().screen_point(Vec3::new(0.0, 0.0, 0.07));
            if k < 180 { vec![tip(1, top + lerp(Vec2::ZERO, Vec2::new(0.03, 0.02), k, 180))] } else { Vec::new() }
        });
        let light = s.world().object_pose(ObjectId::new(0)).position;
        assert!(light.z > 0.05, "{}: the light box fell off or sank: {light}", case.kind);
    }
}

#[test]
#[ignore = "fails on rapier 0.36: soft-contact stiffness scales with the light pair's mass, so a 10 kg block crushes a 0.1 kg box (1.5 cm in 6 steps at 4-30 iterations, 30-240 Hz contacts); kept to re-check on rapier upgrades"]
fn a_100_to_1_mass_ratio_stack_heavy_on_light() {
    let case = Case::new("tasks/cases/mass_ratio_inverted.toml", TechniqueKind::PROXY, thresholds::SPEED_HELD);
    run(&case, STEPS, |_, _| Vec::new());
}

#[test]
fn proxies_losing_and_regaining_tracking_every_frame() {
    let case = Case::new("tasks/cases/one_box.toml", TechniqueKind::PROXY, thresholds::SPEED_AT_REST);
    run(&case, STEPS, |k, _| {
        let x = -0.05 + 0.1 * ((k % 600) as f32 / 600.0);
        if k % 2 == 0 { vec![tip(1, Vec2::new(x, 0.0))] } else { Vec::new() }
    });
}

#[test]
fn a_tracked_contact_teleporting_across_the_table() {
    // The contact jumps 60 cm every half second between two spots beside
    // the 14 cm box: whatever the technique makes of the jump, the box
    // is never touched and stays at rest.
    for case in Case::each("tasks/cases/one_box.toml", &HOLDING, thresholds::SPEED_AT_REST) {
        run(&case, STEPS, |k, _| {
            let side = if (k / 30) % 2 == 0 { -0.3 } else { 0.3 };
            vec![tip(1, Vec2::new(side, 0.0))]
        });
    }
}

#[test]
fn a_capsule_particle_wedged_under_an_object() {
    let mut case = Case::new("tasks/cases/one_box.toml", TechniqueKind::PARTICLE, thresholds::SPEED_HELD);
    case.config = Some(TechniqueConfig { particle_capsules: true, ..TechniqueConfig::default() });
    // A fingertip half on the box's rim, half on the table, pressing in.
    run(&case, STEPS, |k, _| vec![tip(1, lerp(Vec2::new(-0.085, 0.0), Vec2::new(-0.065, 0.0), k, 300))]);
}

#[test]
fn the_steering_cylinder_pinned_between_two_hands() {
    for case in Case::each("tasks/steering.toml", &HOLDING, thresholds::SPEED_HELD) {
        let s = run(&case, STEPS, |k, s| {
            // Two hand edges close in on the cylinder from both sides and hold.
            let c = s.world().screen_point(Vec3::new(0.34, 0.22, 0.07));
            let gap = 0.06 - 0.035 * (k as f32 / 120.0).min(1.0);
            vec![
                Hand::new(1, HandKind::Edge, c.x - gap, c.y).with_pressure(1.0),
                Hand::new(2, HandKind::Edge, c.x + gap, c.y).with_pressure(1.0),
            ]
        });
        assert!(s.world().object_pose(ObjectId::new(1)).position.is_finite());
    }
}

#[test]
fn a_thin_card_pressed_on_one_side_tilts_and_stays_calm() {
    for kind in [TechniqueKind::PROXY, TechniqueKind::PARTICLE] {
        let case = Case::new("tasks/cases/cambered_card.toml", kind, thresholds::SPEED_HELD);
        let mut tilted = false;
        let s = run(&case, STEPS, |k, s| {
            if k == 60 {
                // By now the pressed end is down and the other end up.
                let q = s.world().object_pose(ObjectId::new(0)).rotation;
                let tilt = (q * Vec3::X).z.abs();
                tilted = tilt > 0.05;
            }
            vec![tip(1, Vec2::new(0.05, 0.0))]
        });
        let q = s.world().object_pose(ObjectId::new(0)).rotation;
        let end = s.world().object_pose(ObjectId::new(0)).position + q * Vec3::new(-0.06, 0.0, 0.0);
        assert!(tilted, "{kind}: the card did not tilt");
        assert!(end.z > 0.025, "{kind}: the far end should stay raised, at z = {}", end.z);
    }
}

#[test]
fn contact_module_fed_degenerate_pairs_by_the_real_pipeline() {
    // Random hands of every kind, some tiny and light, against the footprints
    // of the positioning scene's objects: the vision stage's hulls (often a
    // few pixels, collinear or single-point) must either be rejected with an
    // error or give finite answers that agree with the brute force.
    let scene = scene::load("positioning").expect("scene");
    let mut s = Session::new(&scene, TechniqueKind::PROXY, SessionOptions::default()).expect("session");
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    let footprints: Vec<ConvexPolygon> = scene
        .objects
        .iter()
        .map(|o| {
            let r = f64::from(o.shape.footprint_radius());
            let pts: Vec<[f64; 2]> = (0..8)
                .map(|k| {
                    let a = std::f64::consts::TAU * f64::from(k) / 8.0;
                    [f64::from(o.position.x) + r * a.cos(), f64::from(o.position.y) + r * a.sin()]
                })
                .collect();
            ConvexPolygon::from_xy(&pts).expect("footprint")
        })
        .collect();
    let (mut answered, mut rejected) = (0, 0);
    for k in 0..STEPS {
        let kind = HandKind::ALL[rng.random_range(0..HandKind::ALL.len())];
        let hand = Hand::new(1, kind, rng.random_range(-0.45..0.45), rng.random_range(-0.33..0.33))
            .with_scale(rng.random_range(0.05..1.2))
            .with_pressure(rng.random_range(0.2..1.0))
            .with_angle(rng.random_range(0.0..std::f32::consts::TAU));
        s.step(std::slice::from_ref(&hand)).expect("step");
        if k % 10 != 0 {
            continue;
        }
        for c in &s.frame().contacts {
            let pts: Vec<[f64; 2]> = c
                .blob
                .hull
                .iter()
                .map(|p| s.sensor().to_table(PixelPoint::new(p[0] as f32, p[1] as f32)).to_array())
                .map(|q| [f64::from(q[0]), f64::from(q[1])])
                .collect();
            let Ok(a) = ConvexPolygon::from_xy(&pts) else {
                rejected += 1;
                continue;
            };
            for b in &footprints {
                let r = contact::contact_report(&a, b);
                let brute = contact::brute_force_report(&a, b);
                assert!(r.distance.is_finite() && r.exit.x.is_finite() && r.exit.y.is_finite());
                assert!(
                    (r.distance - brute.distance).abs() < 1e-6,
                    "entrance block {} vs brute force {}",
                    r.distance,
                    brute.distance
                );
                answered += 1;
            }
        }
    }
    // A contact hull too thin to be a convex polygon (a blob a pixel wide)
    // is skipped, not tested: this seeded run skips 1 hull and answers
    // 7848 pairs; more than three skips, or under 5000 answers (two thirds
    // of those measured), fail the test.
    println!("contact pairs answered {answered}, hulls rejected {rejected}");
    assert!(answered > 5000, "answered {answered}, rejected {rejected}");
    assert!(rejected <= 3, "{rejected} hulls rejected, {answered} pairs answered");
}

/// The paper's particles at their most numerous: a forearm and two flat
/// hands at stride 1 on a 1280 × 960 sensor, about 20,000 particles a frame.
#[test]
#[ignore = "20,000 particles for 10,000 steps takes ~25 min on 2 cores; run with `cargo test --release -- --ignored`"]
fn a_20000_particle_flood() {
    flood(STEPS);
}

/// The same flood for 300 steps, so CI checks its stability every run.
#[test]
fn a_20000_particle_flood_short() {
    flood(300);
}

fn flood(steps: usize) {
    let mut case = Case::new("tasks/sorting.toml", TechniqueKind::PARTICLE, thresholds::SPEED_FLOOD);
    case.sensor_px = (1280, 960);
    // Every sensed particle a body (no culling): this is rapier under load.
    case.config = Some(TechniqueConfig {
        particle_stride: 1,
        particle_cap: 25_000,
        particle_cull: false,
        ..TechniqueConfig::default()
    });
    let mut most = 0;
    let s = run(&case, steps, |k, s| {
        most = most.max(s.counts().bodies);
        let t = k as f32 / 60.0;
        vec![
            Hand::new(1, HandKind::Forearm, -0.25 + 0.05 * t.sin(), 0.0).with_pressure(1.0).with_scale(1.3),
            Hand::new(2, HandKind::FlatHand, 0.1, 0.1 + 0.03 * t.cos()).with_pressure(1.0).with_scale(1.3),
            Hand::new(3, HandKind::FlatHand, 0.2, -0.15).with_pressure(1.0).with_angle(0.5).with_scale(1.3),
        ]
    });
    let bodies = most.max(s.counts().bodies);
    assert!(bodies > 15_000, "flood reached only {bodies} particles");
}

// ---------------------------------------------------------------------------
// Scenes at the documented bounds (`scene::bounds`, docs/scenes.md "Bounds"): the
// largest objects, the smallest masses, the most objects. Each is written
// from the bound constants, so a bound that moves is tested where it moves
// to; each runs 10,000 steps with hands pushing and must stay finite.

use surfacelab::scene::bounds;

/// Runs `text` for [`STEPS`] with `hands`; every active pose stays finite
/// and the world counts no NaN. Returns the session.
fn run_at_bound(text: &str, kind: TechniqueKind, hands: impl Fn(usize) -> Vec<Hand>) -> Session {
    let scene = scene::parse(text, "bound.toml").unwrap_or_else(|e| panic!("a scene at the bounds loads: {e}"));
    let mut s = Session::new(&scene, kind, SessionOptions::default()).expect("session");
    for k in 0..STEPS {
        s.step(&hands(k)).expect("step");
        if k % 100 == 99 {
            for (i, p) in s.world().object_poses().iter().enumerate() {
                assert!(p.position.is_finite() && p.rotation.is_finite(), "{kind}: object {i} non-finite at step {k}");
            }
        }
    }
    assert_eq!(s.world().stats().nan_count, 0, "{kind}: NaN");
    s
}

#[test]
fn the_largest_objects_on_the_largest_table_stay_finite() {
    let (side, size) = (bounds::TABLE_SIDE_M.1, bounds::OBJECT_SIZE_M.1);
    let mass = bounds::MASS_KG.1;
    let text = format!(
        "name = \"largest\"\neffects = [\"gravity\", \"friction\", \"joints\"]\n[table]\nsize = [{side}, {side}]\n\
         [[objects]]\nname = \"box\"\nshape = \"box\"\nsize = [{size}, {size}, {size}]\nmass = {mass}\ncolor = \"red\"\nposition = [0.0, 0.0]\n\
         [[objects]]\nname = \"cyl\"\nshape = \"cylinder\"\nradius = {size}\nheight = {size}\nmass = {mass}\ncolor = \"blue\"\nposition = [0.0, 0.0, {}]\n\
         [[objects]]\nname = \"cap\"\nshape = \"capsule\"\nradius = {size}\nheight = {size}\nmass = {mass}\ncolor = \"green\"\nposition = [0.0, 0.0, {}]\n",
        size * 1.5,
        size * 4.0
    );
    for kind in [TechniqueKind::JOINT, TechniqueKind::PROXY] {
        run_at_bound(&text, kind, |k| vec![tip(1, lerp(Vec2::new(-1.0, 0.0), Vec2::new(3.0, 2.0), k, 600))]);
    }
}

#[test]
fn the_smallest_and_lightest_objects_under_a_pressing_hand_stay_finite() {
    let (size, mass) = (bounds::OBJECT_SIZE_M.0, bounds::MASS_KG.0);
    let text = format!(
        "name = \"lightest\"\neffects = [\"gravity\", \"friction\"]\n[table]\nsize = [1.0, 0.75]\n\
         [[objects]]\nname = \"crumb\"\nshape = \"box\"\nsize = [{size}, {size}, {size}]\nmass = {mass}\ncolor = \"red\"\n\
         position = [-0.02, -0.02]\ncount = 25\nstep = [0.01, 0.0]\nper_row = 5\nrow_step = [0.0, 0.01]\n\
         [[objects]]\nname = \"bead\"\nshape = \"sphere\"\nradius = 0.01\nmass = {mass}\ncolor = \"blue\"\nposition = [0.05, 0.0]\n"
    );
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY] {
        run_at_bound(&text, kind, |k| {
            let x = lerp(Vec2::new(-0.05, 0.0), Vec2::new(0.1, 0.02), k, 900);
            vec![Hand::new(1, HandKind::FlatHand, x.x, x.y).with_pressure(1.0)]
        });
    }
}

#[test]
fn the_most_objects_a_scene_may_have_stay_finite() {
    let n = bounds::MAX_OBJECTS;
    let per_row = 40;
    let text = format!(
        "name = \"most\"\neffects = [\"gravity\", \"friction\"]\n[table]\nsize = [2.0, 2.0]\n\
         [[objects]]\nname = \"piece\"\nshape = \"box\"\nsize = [0.03, 0.03, 0.02]\nmass = 0.01\ncolor = \"red\"\n\
         position = [-0.9, -0.9]\ncount = {n}\nstep = [0.045, 0.0]\nper_row = {per_row}\nrow_step = [0.0, 0.06]\n"
    );
    let s = run_at_bound(&text, TechniqueKind::PROXY, |k| {
        let p = lerp(Vec2::new(-0.9, -0.9), Vec2::new(0.9, 0.6), k, 3000);
        vec![Hand::new(1, HandKind::Edge, p.x, p.y).with_pressure(1.0)]
    });
    assert_eq!(s.world().object_poses().len(), n);
}
