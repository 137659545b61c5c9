//! The paper's other interactions: cloth, tearing, soft volumes,
//! gathering, stopping a ball, cambered cards. Each test replays a gesture
//! through the real pipeline (rasterizer → vision → technique → rapier) and
//! checks a number; the others are printed (`--nocapture`) for docs/performance.md.
//!
//! Budget: the whole file runs in well under two minutes in release on two
//! cores (the 10,000-step cloth run is the longest).

mod common;

use common::{asset, thresholds};
use glam::{Vec2, Vec3};
use surfacelab::input::Gesture;
use surfacelab::pipeline::surface::{Hand, HandKind};
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::pipeline::world::{ObjectId, World, WorldError};
use surfacelab::scene::SoftId;
use surfacelab::scene::{self, Effect, EffectSet, Goal, Scene};
use surfacelab::session::{Session, SessionOptions};

fn task(name: &str) -> Scene {
    scene::load(&asset(&format!("tasks/{name}.toml"))).unwrap_or_else(|e| panic!("{e}"))
}

fn gesture(name: &str) -> Gesture {
    Gesture::load(asset(&format!("assets/gestures/{name}.toml"))).unwrap_or_else(|e| panic!("{e}"))
}

fn session(scene: &Scene, kind: TechniqueKind) -> Session {
    Session::new(scene, kind, SessionOptions::default()).expect("session")
}

/// A flat hand that lands at `x0` (y = -0.02), rests 0.3 s, then slides
/// along x to `x1` in `seconds`.
fn flat_hand_drag(x0: f32, x1: f32, seconds: f32) -> Gesture {
    let text = format!(
        "format = \"surfacelab-gesture\"\nversion = 1\n[[hands]]\nid = 1\nkind = \"flat_hand\"\n\
         keys = [{{ t = 0.0, pos = [{x0}, -0.02] }}, {{ t = 0.3 }}, {{ t = {}, pos = [{x1}, -0.02] }}]\n",
        0.3 + seconds
    );
    Gesture::from_str(&text, "flat_hand_drag").expect("gesture")
}

/// Replays `g` and then `settle` more seconds with no hands.
fn replay(scene: &Scene, kind: TechniqueKind, g: &Gesture, settle: f64) -> Session {
    let mut s = session(scene, kind);
    s.replay_until(g, g.duration() + settle).expect("replay");
    assert_eq!(s.world().stats().nan_count, 0, "{kind}: NaN seen");
    assert!(s.world().soft_all_finite(), "{kind}: a soft particle is not finite");
    s
}

#[test]
fn the_new_tasks_load_with_hints_goals_and_their_effects() {
    for (name, needs) in [
        ("cloth", Some(Effect::Cloth)),
        ("tear", Some(Effect::Tearing)),
        ("soft", Some(Effect::SoftBodies)),
        ("gather", None),
        ("ball", None),
        ("cards", None),
        ("tangibles", None),
    ] {
        let s = task(name);
        assert!(!s.hint.is_empty(), "{name}: no hint");
        assert!(s.time_limit_s > 0.0 && s.goal != Goal::None, "{name}: no timed goal");
        match needs {
            Some(e) => assert!(s.effects.contains(e) && !s.soft_bodies.is_empty(), "{name}: declares {}", s.effects),
            None => assert!(
                !s.effects.any_soft() && s.soft_bodies.is_empty(),
                "{name}: pays for soft bodies it has none of"
            ),
        }
        let w = World::new(&s);
        assert_eq!(w.physics().soft_bodies.len(), s.soft_bodies.len(), "{name}: soft bodies created");
    }
    assert_eq!(task("gather").objects.len(), 40);
}

#[test]
fn soft_bodies_exist_only_when_their_effect_is_declared() {
    let cloth = task("cloth");
    // The same scene with the effect off: no soft body, and asking for one
    // is refused with the scene and the effect named.
    let off: EffectSet = cloth.effects.iter().filter(|e| *e != Effect::Cloth).collect();
    let mut w = World::with_effects(&cloth, off);
    assert!(w.physics().soft_bodies.is_empty());
    assert!(!w.soft_exists(SoftId::new(0)));
    let err = w.add_soft_body(&cloth.soft_bodies[0]).expect_err("effect is off");
    assert!(matches!(err, WorldError::EffectNotDeclared { effect: Effect::Cloth, .. }), "{err}");
    let msg = err.to_string();
    assert!(msg.contains("`cloth`") && msg.contains("scene `cloth`"), "{msg}");

    // A scene file that uses a soft body without declaring it fails to load, naming the field.
    let text = std::fs::read_to_string(asset("tasks/tear.toml")).expect("read");
    let e = scene::parse(&text.replace(", \"tearing\"]", "]"), "tear.toml").expect_err("tearing undeclared");
    let e = e.to_string();
    assert!(e.contains("soft_bodies[0].tear_strain") && e.contains("`tearing`") && e.starts_with("tear.toml:"), "{e}");
    let e = scene::parse(&text.replace("kind = \"cloth\"", "kind = \"jelly\""), "tear.toml")
        .expect_err("bad kind")
        .to_string();
    assert!(e.contains("jelly"), "{e}");
    let e = scene::parse(&text.replace("mass = 0.03", "mass = -1"), "tear.toml").expect_err("bad mass").to_string();
    assert!(e.contains("soft_bodies[0].mass") && e.contains("-1"), "{e}");
    let e = scene::parse(&text.replace("mass = 0.03", "mass = 0.03\ncrease = 2.0"), "tear.toml")
        .expect_err("crease out of range")
        .to_string();
    assert!(e.contains("soft_bodies[0].crease"), "{e}");
    let soft = std::fs::read_to_string(asset("tasks/soft.toml")).expect("read");
    let e = scene::parse(&soft.replace("mass = 0.08", "mass = 0.08\ncrease = 0.03"), "soft.toml")
        .expect_err("a volume does not crease")
        .to_string();
    assert!(e.contains("soft_bodies[0].crease") && e.contains("only a cloth"), "{e}");
}

/// A light box on the cloth rests on it (rigid–soft contacts happen), and
/// the contact ray lands on the cloth, naming the particle under it.
#[test]
fn rigid_bodies_rest_on_cloth_and_rays_land_on_it() {
    let s = scene::parse(include_str!("scenes/box_on_cloth.toml"), "box_on_cloth").expect("scene");
    let mut w = World::new(&s);
    let hit = w.cast_contact_ray(Vec2::new(0.06, 0.05)).expect("hit");
    let (h, particle) = hit.soft.expect("the ray lands on the cloth");
    assert!(hit.object.is_none() && hit.normal.z > 0.9);
    let p = w.physics().soft_bodies[h].particle_position(particle as usize);
    thresholds::CLOTH_RAY_PARTICLE.check(
        (p.truncate() - hit.point.truncate()).length(),
        &format!("nearest particle {p} to the hit {}", hit.point),
    );
    for _ in 0..120 {
        w.step();
    }
    let z = w.object_pose(ObjectId::new(0)).position.z;
    println!("box on cloth: centre z = {z:.4} m (on the bare table it would be 0.0100)");
    thresholds::BOX_ON_CLOTH_HEIGHT.check(z, "the box's centre on the cloth");
}

/// Pulling the two halves apart with two flat hands tears the paper; one
/// hand dragging it moves it without tearing it.
#[test]
fn two_opposing_hands_tear_the_sheet_one_hand_drags_it_whole() {
    let scene = task("tear");
    let two = gesture("tear_two_hands");
    let one = flat_hand_drag(0.05, 0.25, 1.2);
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY, TechniqueKind::JOINT] {
        let torn = replay(&scene, kind, &two, 0.5);
        let pieces = torn.world().soft_piece_masses(SoftId::new(0));
        let dragged = replay(&scene, kind, &one, 0.5);
        let moved = dragged.world().soft_center(SoftId::new(0)).expect("sheet").x;
        println!(
            "{kind}: two hands -> pieces {pieces:.4?} (goal complete {}); one hand -> {} piece(s), sheet moved {moved:.3} m",
            torn.progress().complete,
            dragged.world().soft_piece_masses(SoftId::new(0)).len()
        );
        if kind == TechniqueKind::JOINT {
            // A contact holds one particle: pulling two particles apart tears
            // the sheet, but where it rips depends on which particles were grabbed.
            assert!(pieces.len() >= 2, "{kind}: did not tear: {pieces:?}");
        } else {
            assert!(torn.progress().complete, "{kind}: not torn in two: {pieces:?}");
        }
        assert_eq!(dragged.world().soft_piece_masses(SoftId::new(0)).len(), 1, "{kind}: one hand tore the sheet");
        thresholds::SHEET_DRAGGED.check(moved, &format!("{kind}: one hand moved the sheet"));
    }
}

/// The paper declares `sleeping`: at rest it sleeps (and costs next to
/// nothing), and a hand landing on it later wakes it and drags it.
#[test]
fn a_sleeping_sheet_wakes_under_a_hand() {
    let scene = task("tear");
    assert!(scene.effects.contains(Effect::Sleeping));
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY, TechniqueKind::JOINT] {
        let mut s = session(&scene, kind);
        while s.time() < 1.0 {
            s.step(&[]).expect("step");
        }
        assert!(
            s.world().soft_pieces(SoftId::new(0)).all(|(_, b)| b.is_sleeping()),
            "{kind}: the resting sheet does not sleep"
        );
        let start = s.world().soft_center(SoftId::new(0)).expect("sheet").x;
        while s.time() < 2.5 {
            let t = (s.time() - 1.0) as f32;
            let hand = Hand::new(1, HandKind::FlatHand, 0.05 + 0.1 * t.min(1.0), -0.02);
            s.step(std::slice::from_ref(&hand)).expect("step");
        }
        let moved = s.world().soft_center(SoftId::new(0)).expect("sheet").x - start;
        println!("{kind}: hand landing on the sleeping sheet dragged it {moved:.3} m");
        thresholds::SLEEPING_SHEET_DRAGGED.check(moved, &format!("{kind}: the sleeping sheet followed the hand"));
    }
}

/// A flat hand (Proxy) resting on the cloth and moving slowly in circles
/// for 10,000 steps: every particle stays finite, on the table and slow,
/// and the hand's proxy stays on the table (a light proxy on a soft body
/// presses with a large gravity scale: it must never fall through).
#[test]
fn cloth_under_a_flat_hand_stays_finite_for_ten_thousand_steps() {
    // The task's cloth at 12 x 12 particles (the file's time budget).
    let mut scene = task("cloth");
    scene.soft_bodies[0].resolution = [12, 12, 1];
    let mut s = session(&scene, TechniqueKind::PROXY);
    let mut top_speed = 0.0f32;
    let mut lowest = f32::MAX;
    for k in 0..10_000 {
        let t = k as f32 / 60.0;
        let hand = Hand::new(1, HandKind::FlatHand, 0.04 * (t * 0.7).cos(), 0.04 * (t * 0.7).sin());
        s.step(std::slice::from_ref(&hand)).expect("step");
        if k % 10 == 0 {
            top_speed = top_speed.max(s.world().soft_max_speed(SoftId::new(0)));
            for (_, b) in s.world().soft_pieces(SoftId::new(0)) {
                lowest = lowest.min(b.particle_positions().map(|p| p.z).fold(f32::MAX, f32::min));
            }
        }
    }
    println!(
        "cloth under a flat hand, 10000 steps: top particle speed {top_speed:.3} m/s, lowest particle z {lowest:.4} m"
    );
    assert!(s.world().soft_all_finite(), "a particle is not finite");
    assert_eq!(s.world().stats().nan_count, 0);
    thresholds::CLOTH_TOP_SPEED.check(top_speed, "the fastest cloth particle under a hand moving at 0.03 m/s");
    thresholds::CLOTH_LOWEST.check(lowest, "the lowest cloth particle's centre under the hand");
    assert_eq!(s.world().soft_piece_masses(SoftId::new(0)).len(), 1);
    let fell = s.world().physics().bodies.iter().any(|(_, b)| b.is_dynamic() && b.translation().z < -0.01);
    assert!(!fell, "a body fell through the table");
}

/// A flat hand pressing a jelly block squashes it and the block bulges
/// instead of shrinking: its volume stays within 6% (Particle) and 2%
/// (Proxy) of its rest volume (`thresholds::SQUISHED_VOLUME_*`).
#[test]
fn a_squished_soft_block_keeps_its_volume() {
    let (scene, g) = (task("soft"), gesture("squish"));
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY] {
        let mut s = session(&scene, kind);
        let rest_z = centre_z(&s);
        let (_, rest) = s.world().soft_volume(SoftId::new(0));
        let (mut min_ratio, mut max_ratio, mut lowest) = (f32::MAX, 0.0f32, f32::MAX);
        while s.time() < g.duration() {
            let hands = g.sample(s.time());
            s.step(&hands).expect("step");
            if s.time() > 0.5 {
                let (v, _) = s.world().soft_volume(SoftId::new(0));
                min_ratio = min_ratio.min(v / rest);
                max_ratio = max_ratio.max(v / rest);
                lowest = lowest.min(centre_z(&s));
            }
        }
        println!(
            "{kind}: squished jelly centre {rest_z:.4} -> {lowest:.4} m high, volume {min_ratio:.3}..{max_ratio:.3} of rest"
        );
        thresholds::SQUISH_PRESS.check(rest_z - lowest, &format!("{kind}: the hand pressed the block's centre down"));
        let bound = if kind == TechniqueKind::PARTICLE {
            thresholds::SQUISHED_VOLUME_PARTICLE
        } else {
            thresholds::SQUISHED_VOLUME_PROXY
        };
        bound.check(
            (1.0 - min_ratio).max(max_ratio - 1.0),
            &format!("{kind}: volume went to {min_ratio}..{max_ratio} of rest"),
        );
    }
}

fn centre_z(s: &Session) -> f32 {
    s.world().soft_center(SoftId::new(0)).expect("block").z
}

/// Two forearms sweeping together gather the forty pieces: Particle gets at
/// least 80% into the goal circle; Proxy (one cube per arm) and Joint
/// (kinematic prisms for contacts that grab nothing) are reported.
#[test]
fn a_two_arm_sweep_gathers_the_pieces() {
    let scene = task("gather");
    let Goal::Gather { center, radius, .. } = scene.goal else { panic!("gather goal") };
    let g = gesture("sweep_gather");
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY, TechniqueKind::JOINT] {
        let s = replay(&scene, kind, &g, 1.0);
        let w = s.world();
        let inside =
            w.object_ids().filter(|&id| (w.object_pose(id).position.truncate() - center).length() <= radius).count();
        println!(
            "{kind}: {inside} of {} pieces inside the circle; goal complete: {}",
            w.object_count(),
            s.progress().complete
        );
        if kind == TechniqueKind::PARTICLE {
            let fraction = inside as f32 / w.object_count() as f32;
            thresholds::GATHERED.check(fraction, "particle: the pieces gathered into the circle");
        }
    }
}

/// A ball rolling at 0.5 m/s meets a flat hand laid on its path: it stops
/// within 5 cm of where the hand landed.
#[test]
fn a_flat_hand_stops_a_rolling_ball() {
    let scene = task("ball");
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY] {
        let mut s = session(&scene, kind);
        let r = 0.03;
        {
            let mut b = s.world_mut().push_object(ObjectId::new(0)).expect("the ball is a dynamic object");
            b.set_linvel(Vec3::new(0.5, 0.0, 0.0));
            b.set_angvel(Vec3::new(0.0, 0.5 / r, 0.0));
        }
        // Roll for 0.4 s, then lay the palm where the ball's top appears.
        while s.time() < 0.4 {
            s.step(&[]).expect("step");
        }
        let landed = s.world().object_pose(ObjectId::new(0)).position;
        let screen = s.world().screen_point(landed + Vec3::Z * r);
        let hand = Hand::new(1, HandKind::FlatHand, screen.x, screen.y - 0.01);
        while s.time() < 2.0 {
            s.step(std::slice::from_ref(&hand)).expect("step");
        }
        let end = s.world().object_pose(ObjectId::new(0));
        let travel = (end.position - landed).truncate().length();
        println!(
            "{kind}: ball at {:.3} m/s met the hand at x = {:.3}; it travelled {travel:.3} m more, now at {:.3} m/s",
            0.5,
            landed.x,
            end.linvel.length()
        );
        thresholds::BALL_STOPPED_TRAVEL.check(travel, &format!("{kind}: the ball rolled on under the hand"));
        if kind == TechniqueKind::PARTICLE {
            // Many particles on the ball hold it still; the single proxy
            // cube on its top lets it rock in place.
            thresholds::BALL_STOPPED_SPEED
                .check(end.linvel.length(), &format!("{kind}: the ball's speed under the hand"));
        }
    }
}

/// A fingertip sweeping right over the ball (the start of `ball_stop`)
/// never sends it left: particles landing on its far side, a face the
/// camera sees edge-on, could slide down into the wedge under it and shoot
/// the ball backwards (see `MAX_SURFACE_SPEEDUP` in
/// src/pipeline/technique/particle.rs).
#[test]
fn a_fingertip_sweeping_over_a_ball_never_launches_it_backwards() {
    let (scene, g) = (task("ball"), gesture("ball_stop"));
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY] {
        let mut s = session(&scene, kind);
        let start = s.world().object_pose(ObjectId::new(0)).position.x;
        let mut slowest = 0.0f32;
        while s.time() < 0.9 {
            let hands = g.sample(s.time());
            s.step(&hands).expect("step");
            slowest = slowest.min(s.world().object_pose(ObjectId::new(0)).linvel.x);
        }
        let moved = s.world().object_pose(ObjectId::new(0)).position.x - start;
        println!("{kind}: the sweep moved the ball {moved:+.3} m along x; lowest x velocity {slowest:+.2} m/s");
        assert!(slowest > -0.15, "{kind}: the ball was launched backwards at {slowest} m/s");
        assert!(moved > -0.01, "{kind}: the ball went {moved} m the wrong way");
    }
}

/// A fingertip pressing one end of a card resting across a ridge tips the
/// card: that end goes down, the other lifts (Particle and Proxy press;
/// Joint only grabs, so its tilt is reported).
#[test]
fn a_card_pressed_on_one_side_tilts() {
    let (scene, g) = (task("cards"), gesture("card_tilt"));
    let white = scene.object_id("card_white").expect("card");
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY, TechniqueKind::JOINT] {
        let mut s = session(&scene, kind);
        let mut tilt = 0.0f32;
        while s.time() < g.duration() {
            let hands = g.sample(s.time());
            s.step(&hands).expect("step");
            let q = s.world().object_pose(white).rotation;
            // Positive when the right end (+x) is up.
            let end = q * Vec3::X;
            tilt = tilt.max(end.z.asin().to_degrees());
        }
        println!("{kind}: pressing the card's left end tipped it {tilt:.1} degrees");
        if kind == TechniqueKind::JOINT {
            // A joint grabs and drags; it cannot press (the paper's point).
            continue;
        }
        thresholds::CARD_TILT.check(tilt, &format!("{kind}: pressing one end tipped the card"));
    }
}

/// The ruler tangible pushed up the table lines the blocks up in the blue
/// strip (reported for every technique; Particle must manage it).
#[test]
fn a_ruler_pushes_the_blocks_into_line() {
    let scene = task("tangibles");
    let Goal::Sorting { zones, .. } = &scene.goal else { panic!("sorting goal") };
    let g = gesture("ruler_push");
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY, TechniqueKind::JOINT] {
        let s = replay(&scene, kind, &g, 1.0);
        let w = s.world();
        let ys: Vec<f32> = w.object_ids().map(|id| w.object_pose(id).position.y).collect();
        let lined = w.object_ids().filter(|&id| zones[0].contains(w.object_pose(id).position.truncate())).count();
        let spread = ys.iter().copied().fold(f32::MIN, f32::max) - ys.iter().copied().fold(f32::MAX, f32::min);
        println!(
            "{kind}: {lined} of {} blocks in the strip, y spread {spread:.3} m, goal complete: {}",
            w.object_count(),
            s.progress().complete
        );
        if kind == TechniqueKind::PARTICLE {
            assert_eq!(lined, w.object_count(), "particle: blocks at y = {ys:?}");
        }
    }
}

/// Soft bodies keep the world deterministic: the same scene and gesture give
/// bit-identical particles, tear included.
#[test]
fn tearing_is_deterministic() {
    let (scene, g) = (task("tear"), gesture("tear_two_hands"));
    let run = || {
        let s = replay(&scene, TechniqueKind::PROXY, &g, 0.0);
        assert!(s.world().soft_piece_masses(SoftId::new(0)).len() >= 2);
        s.world().state_bits()
    };
    assert_eq!(run(), run());
}

fn highest_particle(s: &Session) -> f32 {
    s.world()
        .soft_pieces(SoftId::new(0))
        .flat_map(|(_, b)| b.particle_positions().map(|p| p.z))
        .fold(f32::MIN, f32::max)
}

/// The task's cloth starts rumpled and stays so (its creases are its rest
/// shape): it covers about 0.64 of its flat area and its ridges stand
/// centimetres high. Two flat hands smoothing it outwards (the paper's
/// "straightened by pushing down with the flat hand") lay it flat past the
/// 90% goal with Particle; every technique smooths it some, and the others
/// are reported. Smoothing may stretch the sheet a little, because warp and
/// weft share the creases' plasticity: stated bound, 15% more area.
#[test]
fn a_crumpled_cloth_stands_until_flat_hands_smooth_it_out() {
    let scene = task("cloth");
    let mut s = session(&scene, TechniqueKind::PARTICLE);
    while s.time() < 2.0 {
        s.step(&[]).expect("step");
    }
    let (start, ridge) = (s.world().soft_coverage(SoftId::new(0)), highest_particle(&s));
    println!("crumpled cloth at rest: covers {start:.3} of its area, ridges {ridge:.3} m high");
    thresholds::RUMPLED_COVER_LEAST.check(start, "the rumpled cloth's cover at rest");
    thresholds::RUMPLED_COVER_MOST.check(start, "the rumpled cloth's cover at rest");
    thresholds::RUMPLED_RIDGE.check(ridge, "the rumpled cloth's highest particle");

    let g = gesture("flatten");
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY, TechniqueKind::JOINT, TechniqueKind::DIRECT] {
        let s = replay(&scene, kind, &g, 1.0);
        let covered = s.world().soft_coverage(SoftId::new(0));
        println!(
            "{kind}: flatten -> covers {covered:.3} of its area, ridges {:.3} m; goal complete: {}",
            highest_particle(&s),
            s.progress().complete
        );
        thresholds::SMOOTHED_GAIN
            .check(covered - start, &format!("{kind}: smoothing took the cloth from {start:.3} to {covered:.3}"));
        thresholds::SMOOTHED_STRETCH.check(covered, &format!("{kind}: the smoothed cloth's cover"));
        if kind == TechniqueKind::PARTICLE {
            assert!(s.progress().complete && covered >= 0.9, "particle: flattened only to {covered:.3}");
        }
    }
}

/// Five fingertips closing on a flat cloth bunch it up (the paper's
/// grasping crumple) and the creases hold after the hand lifts: the cloth
/// covers less of the table a second later. Proxy and Joint keep hold of
/// what they touch; per-frame particles land on top of the cloth each frame
/// and slip (the paper's own remark on grasping with particles), and Direct
/// Force only drags: those two are reported.
#[test]
fn fingertips_closing_on_a_flat_cloth_crumple_it() {
    let mut scene = task("cloth");
    scene.soft_bodies[0].crumple = 0.0;
    let g = gesture("crumple");
    for kind in [TechniqueKind::PARTICLE, TechniqueKind::PROXY, TechniqueKind::JOINT, TechniqueKind::DIRECT] {
        let s = replay(&scene, kind, &g, 1.0);
        let covered = s.world().soft_coverage(SoftId::new(0));
        println!("{kind}: crumple -> the cloth covers {covered:.3} of its area a second after the hand lifted");
        if matches!(kind, TechniqueKind::PROXY | TechniqueKind::JOINT) {
            thresholds::CRUMPLED_COVER.check(covered, &format!("{kind}: the crumpled cloth's cover"));
        }
    }
}

/// Direct Force acts on soft bodies through the same contract: a flat hand
/// sliding fast over the paper drags it (kinetic friction only, so a slow
/// hand that cannot beat the sheet's friction on the table leaves it).
#[test]
fn direct_force_drags_a_sheet_under_a_fast_hand() {
    let scene = task("tear");
    let g = flat_hand_drag(0.0, 0.2, 0.5);
    let s = replay(&scene, TechniqueKind::DIRECT, &g, 0.5);
    let moved = s.world().soft_center(SoftId::new(0)).expect("sheet").x;
    println!("direct: a hand sliding 0.2 m at 0.4 m/s dragged the paper {moved:.3} m");
    thresholds::DIRECT_SHEET_DRAGGED.check(moved, "direct force dragged the sheet");
    assert_eq!(s.world().soft_piece_masses(SoftId::new(0)).len(), 1, "direct force tore the sheet");
}

/// The slot's goal counts the jelly inside the slot, not perched on its
/// walls: with the walls moved in to a 4 cm slot and the jelly resting
/// across their tops, right over the goal rectangle, it never completes;
/// without the height bound it would.
#[test]
fn a_block_perched_on_the_slot_walls_is_not_in_the_slot() {
    let text = std::fs::read_to_string(asset("tasks/soft.toml")).expect("read");
    let perched = text
        .replace("position = [-0.05, -0.10]", "position = [0.0, 0.17, 0.097]")
        .replace("position = [-0.0520, 0.16]", "position = [-0.045, 0.16]")
        .replace("position = [0.0520, 0.16]", "position = [0.045, 0.16]");
    assert_eq!(perched.matches("0.045, 0.16]").count(), 2, "the walls moved in");
    for (label, text, want) in
        [("with max_height", perched.clone(), false), ("without", perched.replace("max_height = 0.04 ", "# "), true)]
    {
        let scene = scene::parse(&text, "soft.toml").expect("scene");
        let mut s = session(&scene, TechniqueKind::PARTICLE);
        while s.time() < 2.0 {
            s.step(&[]).expect("step");
        }
        let c = s.world().soft_center(SoftId::new(0)).expect("jelly");
        println!("jelly perched on the slot walls ({label}): centre {c:.3}, goal complete: {}", s.progress().complete);
        thresholds::PERCHED_JELLY_HEIGHT.check(c.z, &format!("{label}: the perched jelly's centre"));
        assert_eq!(s.progress().complete, want, "{label}");
    }
}

/// Squeezing the jelly into the slot (`squeeze_into_slot`): Joint pulls the
/// grabbed block through the funnel into the 5.4 cm slot and the goal is
/// met, the block keeping its volume within 1.5% (`thresholds::SQUEEZED_VOLUME`); Particle and Proxy, which
/// hold it only by friction under the hand, slide over it at the mouth
/// (reported).
#[test]
fn a_joint_squeezes_the_jelly_into_the_slot() {
    let (scene, g) = (task("soft"), gesture("squeeze_into_slot"));
    for kind in [TechniqueKind::JOINT, TechniqueKind::PARTICLE, TechniqueKind::PROXY] {
        let mut s = session(&scene, kind);
        let (_, rest) = s.world().soft_volume(SoftId::new(0));
        let (mut lo, mut hi) = (f32::MAX, 0.0f32);
        while s.time() < g.duration() + 2.0 {
            let hands = g.sample(s.time());
            s.step(&hands).expect("step");
            let (v, _) = s.world().soft_volume(SoftId::new(0));
            lo = lo.min(v / rest);
            hi = hi.max(v / rest);
        }
        let c = s.world().soft_center(SoftId::new(0)).expect("jelly");
        println!(
            "{kind}: jelly at ({:.3}, {:.3}, {:.3}), volume {lo:.3}..{hi:.3} of rest, goal complete: {}",
            c.x,
            c.y,
            c.z,
            s.progress().complete
        );
        assert!(s.world().soft_all_finite());
        if kind == TechniqueKind::JOINT {
            assert!(s.progress().complete, "joint: the jelly stopped at {c}");
            thresholds::SQUEEZED_VOLUME
                .check((1.0 - lo).max(hi - 1.0), &format!("joint: volume went to {lo}..{hi} of rest"));
        }
    }
}
