//! The physics world: determinism, ray casts, and effect gating.

mod common;

use common::scenes;
use glam::{Vec2, Vec3};
use surfacelab::pipeline::world::{ObjectId, World};
use surfacelab::scene::{self, EffectSet, Scene};

fn push_pattern(world: &mut World, step: usize) {
    // A fixed, input-like sequence of forces on a few objects.
    let n = world.object_count();
    let i = step % n;
    let f = Vec3::new(((step * 7) % 5) as f32 - 2.0, ((step * 3) % 7) as f32 - 3.0, 0.0) * 0.5;
    if let Some(mut b) = world.push_object(ObjectId::new(i))
        && b.is_dynamic()
    {
        b.add_force(f);
    }
}

#[test]
fn same_scene_and_inputs_give_bit_identical_state() {
    let s = scene::load("sorting").expect("scene");
    let mut a = World::new(&s);
    let mut b = World::new(&s);
    for k in 0..600 {
        push_pattern(&mut a, k);
        push_pattern(&mut b, k);
        a.step();
        b.step();
    }
    assert_eq!(a.state_bits(), b.state_bits());
    // And the inputs mattered: a world without them differs.
    let mut c = World::new(&s);
    for _ in 0..600 {
        c.step();
    }
    assert_ne!(a.state_bits(), c.state_bits());
}

#[test]
fn objects_rest_on_the_table_without_drifting() {
    let s = scene::load("positioning").expect("scene");
    let mut w = World::new(&s);
    for _ in 0..180 {
        w.step();
    }
    for (id, o) in s.object_ids().zip(&s.objects) {
        let p = w.object_pose(id).position;
        assert!((p - o.position).length() < 0.005, "{} moved from {} to {p}", o.name, o.position);
    }
    assert_eq!(w.stats().nan_count, 0);
    assert!(w.measure_penetration() < 0.005);
}

#[test]
fn contact_ray_hits_the_object_under_the_point() {
    let s = scene::load("positioning").expect("scene");
    let mut w = World::new(&s);
    w.step();
    for (id, o) in s.object_ids().zip(&s.objects) {
        let hit = w.cast_contact_ray(o.position.truncate()).expect("hits something");
        assert_eq!(hit.object, Some(id), "ray at {} should hit {}", o.position, o.name);
        let top = o.position.z + o.shape.half_z();
        assert!((hit.point.z - top).abs() < 0.01, "{}: hit z {} vs top {top}", o.name, hit.point.z);
        assert!(hit.normal.z > 0.5, "the top faces up");
    }
    let empty = w.cast_contact_ray(Vec2::new(0.0, -0.3)).expect("hits the table");
    assert_eq!(empty.object, None);
    assert!(empty.point.z.abs() < 1e-4);
}

#[test]
fn undeclared_effects_are_switched_off() {
    let pos = scene::load("positioning").expect("scene"); // gravity friction sleeping joints
    let w = World::new(&pos);
    let c = w.config();
    assert_eq!(c.ccd_substeps, 0);
    assert_eq!(w.physics().integration_parameters.max_ccd_substeps, 0);
    assert!(c.sleeping && c.joints && c.friction && !c.soft_bodies);
    assert!(w.physics().bodies.iter().all(|(_, b)| !b.is_ccd_enabled()));

    let steer = scene::load("steering").expect("scene"); // no sleeping
    let w = World::new(&steer);
    assert!(!w.config().sleeping);

    let all = World::with_effects(&pos, EffectSet::all());
    assert!(all.config().ccd_substeps > 0);
    assert!(all.physics().bodies.iter().filter(|(_, b)| b.is_dynamic()).all(|(_, b)| b.is_ccd_enabled()));
}

#[test]
fn sleeping_happens_only_when_declared() {
    let s = scene::load("positioning").expect("scene");
    let mut on = World::new(&s);
    let mut off = World::with_effects(&s, s.effects.iter().filter(|e| *e != scene::Effect::Sleeping).collect());
    for _ in 0..300 {
        on.step();
        off.step();
    }
    let asleep = |w: &World| w.object_ids().filter(|&id| w.physics().bodies[w.object_body(id)].is_sleeping()).count();
    assert_eq!(asleep(&on), s.objects.len(), "resting objects sleep when declared");
    assert_eq!(asleep(&off), 0, "and never when not");
}

#[test]
fn joints_need_the_joints_effect() {
    let mut s = scene::load("positioning").expect("scene");
    assert!(World::new(&s).require_joints("the Joint technique").is_ok());
    s.effects = s.effects.iter().filter(|e| *e != scene::Effect::Joints).collect();
    let e = World::new(&s).require_joints("the Joint technique").expect_err("joints off");
    assert!(e.to_string().contains("joints"));
}

#[test]
fn no_gravity_no_friction_when_undeclared() {
    let mut s = scene::load("positioning").expect("scene");
    s.effects = EffectSet::empty();
    let w = World::new(&s);
    assert_eq!(w.physics().gravity, Vec3::ZERO);
    assert!(w.physics().colliders.iter().all(|(_, c)| c.friction() == 0.0));
}

#[test]
fn touching_where_an_object_appears_hits_its_top() {
    // The steering cylinder sits far from the table centre, so its contact
    // ray is oblique: a touch where its cap *appears* lands on the cap.
    let s = scene::load("steering").expect("scene");
    let w = World::new(&s);
    let cyl = s.object_id("cylinder").expect("cylinder");
    let c = s.object(cyl).position;
    let top = c.z + 0.025;
    for (dx, dy) in [(0.0, 0.0), (-0.01, 0.0), (0.0, 0.015), (0.012, -0.012)] {
        // Where the user sees that point of the cap, they touch.
        let seen = w.screen_point(Vec3::new(c.x + dx, c.y + dy, top));
        assert!(seen.length() > c.truncate().length(), "perspective pushes it outward");
        let hit = w.cast_contact_ray(seen).expect("hit");
        assert_eq!(hit.object, Some(cyl), "offset ({dx}, {dy})");
        // Exact, although parry's own cylinder normals tilt near the rim.
        assert!((hit.point.z - top).abs() < 1e-4 && hit.normal.z > 0.9999, "{hit:?}");
        assert!((hit.point.truncate() - Vec2::new(c.x + dx, c.y + dy)).length() < 1e-3);
    }
}

/// Two of the `gather` task's 2.2 cm blue discs, `a` at `a_at` and `b` at
/// `b_at` (table metres).
fn two_discs(a_at: [f32; 2], b_at: [f32; 2]) -> Scene {
    let disc = scenes::disc(0.011, 0.01);
    scenes::build(
        &scenes::table("two_discs").object("a", disc, a_at, 0.01, "blue").object("b", disc, b_at, 0.01, "blue"),
    )
}

/// Two of the `gather` task's 2.2 cm discs, one driven into the other at
/// 0.2 m/s (a hand's sweep) for half a second: they push, not pass
/// through each other. parry's GJK/EPA gives up at this size (absolute
/// tolerances; `pipeline/world/magnified.rs`) and, unmagnified, lets them
/// sink millimetres into each other in `surfacelab behaviours --case gather`.
#[test]
fn small_discs_pushed_together_do_not_interpenetrate() {
    let s = two_discs([-0.03, 0.0], [0.0, 0.003]);
    let mut w = World::new(&s);
    let (a, b) = (ObjectId::new(0), ObjectId::new(1));
    let mut deepest = 0.0f32;
    for _ in 0..30 {
        w.push_object(a).expect("a").set_linvel(Vec3::new(0.2, 0.0, 0.0));
        w.step();
        deepest = deepest.max(w.max_object_overlap());
    }
    let moved = w.object_pose(b).position.x;
    assert!(moved > 0.01, "the pushed disc moved only {moved} m");
    assert!(deepest < 0.002, "discs sank {:.1} mm into each other", deepest * 1000.0);
}

/// Camera rays over the steering cylinder (on its platform, off the
/// table's centre, so its near wall is in view), upright and tilted a
/// little as it is while dragged: each hit lies on the surface its normal
/// says, top or wall. parry casts rays at cylinders by GJK, whose hits
/// from the eye can land a millimetre off the surface with normals
/// between the two; a hit under the top near the rim is then taken for the
/// wall, and a particle placed there slides down "the wall" into the top
/// and tips the cylinder over under a dragging fingertip. The world
/// solves the ray and the cylinder exactly (`ray::cylinder_hit`).
#[test]
fn cap_and_wall_hits_get_their_own_normals() {
    let s = scene::load("steering").expect("scene");
    let mut w = World::new(&s);
    let id = s.object_ids().zip(&s.objects).find(|(_, o)| o.name == "cylinder").map(|(id, _)| id).expect("cylinder");
    let start = s.objects[id.index()].position;
    let (r, hh) = (0.025f32, 0.025f32);
    let (mut tops, mut walls) = (0, 0);
    // Poses along a drag towards the table's centre, leaning up to 3°.
    for k in 0..24 {
        let (tilt_deg, towards) = (k as f32 * 0.125, k as f32 * 1.3);
        let lean = glam::Quat::from_axis_angle(Vec3::new(-towards.sin(), towards.cos(), 0.0), tilt_deg.to_radians());
        let at = start - Vec3::new(0.007, 0.0, 0.0) * k as f32;
        w.place_object(id, at, lean);
        w.step();
        let pose = w.object_pose(id);
        let (axis, centre) = (pose.rotation * Vec3::Z, pose.position);
        let apparent = w.screen_point(centre + axis * hh);
        // A 6 x 6 cm patch around where the top appears, every millimetre.
        for i in 0..60 {
            for j in 0..60 {
                let p = apparent + Vec2::new(i as f32 - 30.0, j as f32 - 30.0) * 0.001;
                let Some(hit) = w.cast_contact_ray(p) else { continue };
                if hit.object != Some(id) {
                    continue;
                }
                let rel = hit.point - centre;
                let along = rel.dot(axis);
                let radial = (rel - axis * along).length();
                let at = format!("pose {k}: hit {along} m along the axis, {radial} m from it");
                if hit.normal.dot(axis) > 0.999 {
                    tops += 1;
                    assert!((along - hh).abs() < 1e-5, "{at}: a top hit off the top");
                    assert!(radial <= r + 1e-5, "{at}: a top hit outside the rim");
                } else {
                    walls += 1;
                    assert!(hit.normal.dot(axis).abs() < 1e-3, "{at}: neither top nor wall, normal {}", hit.normal);
                    assert!((radial - r).abs() < 1e-5, "{at}: a wall hit off the wall");
                    // A point nearer the top than the wall is on the top.
                    assert!(r - radial <= hh - along + 1e-5, "{at}: a wall hit nearer the top");
                    let outwards = (rel - axis * along).normalize();
                    assert!(hit.normal.dot(outwards) > 0.999, "{at}: a wall normal {} not radial", hit.normal);
                }
            }
        }
    }
    // The patches cover the top and the part of the near wall in view.
    assert!(tops > 24 * 1500 && walls > 24 * 50, "{tops} top hits, {walls} wall hits");
}

/// A row of five 2.2 cm discs and walls on a technique layer, driven like
/// a hand's bodies (whatever impulse it takes) at a sweep's 0.2 m/s.
/// Returns the deepest overlap of two discs, how far the first disc moved
/// and the world after 0.5 s.
fn squeeze_row(walls: &[f32], give_way: bool) -> (f32, f32, World) {
    use std::fmt::Write;
    use surfacelab::pipeline::world::Layer;
    use surfacelab::pipeline::world::prelude::{ColliderBuilder, RigidBodyBuilder};
    let mut text = format!(
        "name = \"row\"\neffects = [\"gravity\", \"friction\"]\n[physics]\ngive_way = {give_way}\n[table]\nsize = [1.0, 0.75]\n"
    );
    for i in 0..5 {
        let x = -0.046 + 0.023 * i as f32;
        let _ = write!(
            text,
            "[[objects]]\nname = \"d{i}\"\nshape = \"cylinder\"\nradius = 0.011\nheight = 0.01\nmass = 0.01\nposition = [{x}, 0.0]\ncolor = \"blue\"\n"
        );
    }
    let s = scene::parse(&text, "row.toml").expect("scene");
    let mut w = World::new(&s);
    for &x in walls {
        let body = RigidBodyBuilder::kinematic_velocity_based().translation(Vec3::new(x, 0.0, 0.01)).linvel(Vec3::new(
            -0.2 * x.signum(),
            0.0,
            0.0,
        ));
        let wall = ColliderBuilder::cuboid(0.005, 0.04, 0.01).collision_groups(Layer::Proxy.groups());
        w.for_technique().spawn_body(body, wall);
    }
    let start = w.object_pose(ObjectId::new(0)).position.x;
    let mut deepest = 0.0f32;
    for _ in 0..30 {
        w.step();
        deepest = deepest.max(w.max_object_overlap());
    }
    let moved = w.object_pose(ObjectId::new(0)).position.x - start;
    (deepest, moved, w)
}

/// The length of the row between its end discs' centres (m).
fn row_length(w: &World) -> f32 {
    w.object_pose(ObjectId::new(4)).position.x - w.object_pose(ObjectId::new(0)).position.x
}

/// Hands give way where they close on a pile (`pipeline/world/give_way.rs`,
/// scene `physics.give_way`): two walls closing on a row of five discs
/// (11 cm of them) from 18 cm apart to 6 cm in 0.5 s cannot fit them.
/// Pressing with whatever impulse it takes (`give_way = false`), they
/// press the discs millimetres into each other and crush the row; giving
/// way, they stop pressing once they close on the row, which keeps its
/// length. One wall alone still pushes the row along: a push from one side
/// is no squeeze.
#[test]
fn a_row_squeezed_between_two_hands_gives_way_instead_of_interpenetrating() {
    let (deepest, _, w) = squeeze_row(&[-0.09, 0.09], false);
    assert!(deepest > 0.005, "without giving way the discs sank only {:.1} mm", deepest * 1000.0);
    assert!(row_length(&w) < 0.07, "without giving way the row kept {:.1} cm", row_length(&w) * 100.0);

    let (deepest, _, w) = squeeze_row(&[-0.09, 0.09], true);
    assert!(deepest < 0.001, "discs sank {:.1} mm into each other", deepest * 1000.0);
    assert!(row_length(&w) > 0.08, "the row was squeezed to {:.1} cm between centres", row_length(&w) * 100.0);

    let (deepest, moved, _) = squeeze_row(&[-0.09], true);
    assert!(moved > 0.05, "one wall pushed the row only {:.1} cm", moved * 100.0);
    assert!(deepest < 0.002, "discs pushed along sank {:.1} mm into each other", deepest * 1000.0);
}

/// Two 2.2 cm discs placed 4 mm inside each other (what two swept fronts
/// closing 6.7 mm a step leave before rapier's 2 mm contact prediction sees
/// them), stepped once with or without a hand's wall resting against the
/// first. Returns the overlap after the step (m).
fn overlap_after_one_step(hand: bool) -> f32 {
    use surfacelab::pipeline::world::Layer;
    use surfacelab::pipeline::world::prelude::{ColliderBuilder, RigidBodyBuilder};
    let s = two_discs([0.0, 0.0], [0.018, 0.0]);
    let mut w = World::new(&s);
    if hand {
        // Resting against the first disc's far side, still.
        let body = RigidBodyBuilder::kinematic_velocity_based().translation(Vec3::new(-0.016, 0.0, 0.01));
        let wall = ColliderBuilder::cuboid(0.005, 0.04, 0.01).collision_groups(Layer::Proxy.groups());
        w.for_technique().spawn_body(body, wall);
        w.step();
        w.place_object(ObjectId::new(0), Vec3::new(0.0, 0.0, 0.005), glam::Quat::IDENTITY);
        w.place_object(ObjectId::new(1), Vec3::new(0.018, 0.0, 0.005), glam::Quat::IDENTITY);
    }
    w.step();
    w.max_object_overlap()
}

/// Objects a step leaves inside each other while a hand touches one are
/// moved apart by position (`pipeline/world/pile_projection.rs`): the
/// solver alone takes a 4 mm overlap out over several steps, at speeds its
/// soft contacts bound, while a sweep goes on pressing: left to the
/// solver, most of the overlap remains after the step; with a hand's wall
/// touching the first disc, only the projection's slop (0.5 mm) does.
#[test]
fn objects_a_hand_pushes_into_each_other_are_moved_apart_within_the_step() {
    let alone = overlap_after_one_step(false);
    let touched = overlap_after_one_step(true);
    assert!(alone > 0.002, "the solver alone took the overlap down to {:.1} mm", alone * 1000.0);
    assert!(touched < 0.0006, "with a hand touching, {:.2} mm left", touched * 1000.0);
}
