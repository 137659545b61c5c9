//! Scene files: the shipped tasks load, and every class of bad input names
//! the file, the line and the field.

use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::scene::{self, Color, Effect, Goal, SceneError, Shape};
use surfacelab::session::{Session, SessionOptions};

#[test]
fn positioning_has_four_spheres_and_four_boxes_each_with_a_target() {
    let s = scene::load("positioning").expect("positioning loads");
    let Goal::Positioning { targets, .. } = &s.goal else { panic!("positioning goal, got {:?}", s.goal) };
    assert_eq!(targets.len(), 8);
    let spheres = targets.iter().filter(|t| matches!(s.object(t.object).shape, Shape::Sphere { .. })).count();
    let boxes = targets.iter().filter(|t| matches!(s.object(t.object).shape, Shape::Box { .. })).count();
    assert_eq!((spheres, boxes), (4, 4));
    for t in targets {
        assert!(s.on_table(t.position));
    }
}

#[test]
fn sorting_has_two_colours_and_a_zone_for_each() {
    let s = scene::load("sorting").expect("sorting loads");
    let Goal::Sorting { zones, .. } = &s.goal else { panic!("sorting goal") };
    let red = Color::parse("red").expect("palette");
    let blue = Color::parse("blue").expect("palette");
    assert!(s.objects.iter().all(|o| o.color == red || o.color == blue));
    for c in [red, blue] {
        assert!(s.objects.iter().any(|o| o.color == c), "an object of {c:?}");
        assert!(zones.iter().any(|z| z.color == c), "zone for {c:?}");
    }
    // Different shapes, sizes and masses.
    let masses: Vec<f32> = s.objects.iter().map(|o| o.mass).collect();
    assert!(masses.iter().copied().fold(0.0, f32::max) / masses.iter().copied().fold(f32::MAX, f32::min) > 4.0);
}

#[test]
fn steering_starts_far_top_right_on_a_raised_platform() {
    let s = scene::load("steering").expect("steering loads");
    let Goal::Steering(g) = &s.goal else { panic!("steering goal") };
    let start = s.object(g.object).position;
    assert!(start.x > 0.25 && start.y > 0.15, "start at far top right, got {start}");
    let platform = s.object(g.platform.expect("platform"));
    assert!(start.z > platform.position.z + platform.shape.half_z(), "cylinder starts on the platform");
    assert!(g.waypoints.len() >= 3);
    assert!(!s.effects.contains(Effect::Sleeping));
}

#[test]
fn loading_by_path_works_too() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tasks/sorting.toml");
    assert_eq!(scene::load(path).expect("by path").name, "sorting");
}

/// A positioning scene that loads (shared with `tests/scene_validation.rs`).
const GOOD: &str = include_str!("scenes/box_and_ball.toml");

#[test]
fn the_good_template_loads() {
    let s = scene::parse(GOOD, "good.toml").expect("template is valid");
    assert_eq!(s.objects[0].position.z, 0.05, "an [x, y] position rests on the table");
}

/// Each class of bad input, made by replacing one line of [`GOOD`]: the
/// message starts with the file (and the line, where given) and names every
/// one of the needles.
#[test]
fn bad_input_names_the_file_the_line_and_the_field() {
    let cases: &[(&str, &str, &str, &[&str])] = &[
        ("shape = \"box\"", "shape = \"pyramid\"", "bad.toml:7:", &["pyramid"]),
        ("mass = 1.0", "mass = -2.0", "bad.toml:9:", &["objects[0].mass", "-2"]),
        ("mass = 1.0", "mass = nan", "bad.toml", &["objects[0].mass", "finite"]),
        ("mass = 1.0\n", "", "bad.toml", &["objects[0].mass", "needs"]),
        ("name = \"t\"\n", "", "bad.toml", &["missing field `name`"]),
        ("[\"gravity\"]", "[\"gravity\", \"magnetism\"]", "bad.toml:2:", &["magnetism"]),
        ("position = [0.2, 0.1]", "position = [0.9, 0.1]", "bad.toml", &["goal.targets[0].position", "off the table"]),
        ("mass = 1.0", "mass = 1.0\nmas = 2.0", "bad.toml", &["mas"]),
        ("object = \"a\"", "object = \"b\"", "bad.toml", &["goal.targets[0].object", "`b`"]),
    ];
    for (from, to, prefix, needles) in cases {
        assert!(GOOD.contains(from), "`{from}` is not in the template");
        let text = GOOD.replacen(from, to, 1);
        let e = match scene::parse(&text, "bad.toml") {
            Ok(_) => panic!("should not load:\n{text}"),
            Err(e) => e.to_string(),
        };
        assert!(e.starts_with(prefix), "`{from}` → `{to}`: expected `{prefix}` first: {e}");
        for n in *needles {
            assert!(e.contains(n), "`{from}` → `{to}`: no `{n}` in: {e}");
        }
    }
}

#[test]
fn missing_scene_file_lists_where_it_looked() {
    match scene::load("no_such_scene") {
        Err(SceneError::NotFound { tried, .. }) => assert!(tried.contains("tasks")),
        other => panic!("expected NotFound, got {other:?}"),
    }
}

#[test]
fn sorting_matches_zones_to_objects_by_colour_value_not_spelling() {
    // The object is `#ff0000`, its zone `#FF0000`: the same colour. The
    // green box has no zone, so the goal concerns one object.
    let text = include_str!("scenes/hex_sorting.toml");
    let s = scene::parse(text, "hex_sorting.toml").expect("loads");
    assert_eq!(s.objects[0].color, Color::parse("#FF0000").expect("hex"));
    let mut session = Session::new(&s, TechniqueKind::JOINT, SessionOptions::default()).expect("session");
    assert_eq!(session.tracker().progress().total, 1, "only the red box has a zone");
    while session.time() < 1.0 && !session.progress().complete {
        session.step(&[]).expect("steps");
    }
    let p = session.progress();
    assert!(p.complete && p.placed == 1, "the red box rests in its zone: {p:?}");
}
