//! One negative test per class of scene-validator error: each breaks one
//! field of a scene that loads, and checks that the message names the file,
//! the line of the bad value (of its table when the key is missing), the
//! field, and what was wrong.

use std::fmt::Write as _;
use surfacelab::scene;

/// A positioning scene that loads; every test breaks one thing in it.
const OBJECTS: &str = include_str!("scenes/box_and_ball.toml");

/// A cloth that may tear, with a goal on it.
const SOFT: &str = include_str!("scenes/tearing_cloth.toml");

/// A steering scene: an object, a platform, waypoints and a finish.
const STEER: &str = include_str!("scenes/steering_puck.toml");

/// The positioning goal's one target in [`OBJECTS`].
const TARGETS: &str = "[[goal.targets]]\nobject = \"a\"\nposition = [0.2, 0.1]\n";

/// `text` with `from` replaced by `to`; `from` must occur, so a test cannot
/// silently stop breaking anything.
fn with(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "`{from}` is not in the template");
    text.replacen(from, to, 1)
}

/// [`OBJECTS`] with its positioning goal turned into a sorting goal of one
/// zone, `zone` being the zone's lines after its header.
fn sorting(zone: &str) -> String {
    with(
        &with(OBJECTS, TARGETS, ""),
        "kind = \"positioning\"\n",
        &format!("kind = \"sorting\"\n[[goal.zones]]\n{zone}"),
    )
}

fn error(text: &str) -> String {
    match scene::parse(text, "bad.toml") {
        Ok(_) => panic!("should not load:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// `template` with `from` replaced by `to` does not load, and the error
/// names the file, the line (when given), the field and `what`.
fn breaks(template: &str, from: &str, to: &str, line: Option<usize>, field: &str, what: &str) {
    assert_names(&error(&with(template, from, to)), line, field, what);
}

/// The error names the file, the line (when given), the field and `what`.
fn assert_names(e: &str, line: Option<usize>, field: &str, what: &str) {
    let prefix = line.map_or_else(|| "bad.toml: ".to_owned(), |l| format!("bad.toml:{l}: "));
    assert!(e.starts_with(&prefix), "expected `{prefix}` first: {e}");
    assert!(e.contains(&format!("`{field}`")), "expected field `{field}`: {e}");
    assert!(e.contains(what), "expected `{what}`: {e}");
}

#[test]
fn the_templates_load() {
    for t in [OBJECTS, SOFT, STEER] {
        scene::parse(t, "good.toml").unwrap_or_else(|e| panic!("{e}\n{t}"));
    }
}

#[test]
fn an_unknown_key_is_named_with_its_line() {
    let e = error(&with(OBJECTS, "mass = 1.0\n", "mass = 1.0\nmas = 2.0\n"));
    assert_names(&e, Some(10), "mas", "unknown field");
    assert!(e.ends_with("(at `mas = 2.0`)"), "{e}");
}

#[test]
fn a_wrong_type_is_named_with_its_line() {
    let e = error(&with(OBJECTS, "radius = 0.03", "radius = \"big\""));
    assert!(e.starts_with("bad.toml:15: field `objects[1].radius`: invalid type: string \"big\", expected f32"), "{e}");
}

#[test]
fn an_unknown_name_in_a_closed_list_is_named() {
    breaks(OBJECTS, "shape = \"box\"", "shape = \"pyramid\"", Some(7), "pyramid", "unknown variant");
    breaks(OBJECTS, "[\"gravity\"]", "[\"gravity\", \"magnetism\"]", Some(2), "magnetism", "unknown variant");
    breaks(OBJECTS, "kind = \"positioning\"", "kind = \"juggling\"", Some(20), "juggling", "unknown variant");
}

#[test]
fn a_missing_required_field_is_named() {
    let e = error(&with(OBJECTS, "name = \"t\"\n", ""));
    assert!(e.starts_with("bad.toml") && e.contains("missing field `name`"), "{e}");
}

#[test]
fn a_missing_field_a_shape_or_body_needs_is_named() {
    breaks(OBJECTS, "size = [0.1, 0.1, 0.1]\n", "", Some(5), "objects[0].size", "a box needs `size = [x, y, z]`");
    breaks(OBJECTS, "radius = 0.03\n", "", Some(12), "objects[1].radius", "a sphere needs `radius`");
    breaks(OBJECTS, "mass = 0.1\n", "", Some(12), "objects[1].mass", "a dynamic object needs `mass`");
    breaks(SOFT, "mass = 0.03\n", "", Some(5), "soft_bodies[0].mass", "needs `mass` (kg) or `density`");
}

#[test]
fn a_missing_field_a_goal_needs_is_named() {
    breaks(STEER, "finish = [-0.3, -0.2]\n", "", Some(13), "goal.finish", "a steering goal needs `finish`");
    breaks(STEER, "object = \"puck\"\n", "", Some(13), "goal.object", "this goal needs `goal.object`");
    breaks(OBJECTS, TARGETS, "", Some(19), "goal.targets", "at least one [[goal.targets]]");
    let no_targets = with(OBJECTS, TARGETS, "");
    let positioning = "kind = \"positioning\"";
    breaks(&no_targets, positioning, "kind = \"sorting\"", Some(19), "goal.zones", "at least one [[goal.zones]]");
    breaks(&no_targets, positioning, "kind = \"gather\"", Some(19), "goal.center", "a gather goal needs `center`");
    breaks(&no_targets, positioning, "kind = \"region\"", Some(19), "goal.min", "a region goal needs `min`");
    // The positioning goal's targets under another kind are not dropped.
    breaks(OBJECTS, positioning, "kind = \"sorting\"", Some(19), "goal.targets", "a sorting goal has no `targets`");
    breaks(SOFT, "body = \"paper\"\n", "", Some(14), "goal.body", "this goal needs `body`");
}

#[test]
fn a_value_out_of_range_is_named_with_its_range() {
    breaks(OBJECTS, "mass = 1.0", "mass = -2.0", Some(9), "objects[0].mass", "-2 is out of range (0.001..=1000)");
    breaks(
        OBJECTS,
        "size = [1.0, 0.75]",
        "size = [1.0, 0.75]\nrestitution = 1.5",
        Some(5),
        "table.restitution",
        "1.5 is out of range (0..=1)",
    );
    breaks(
        OBJECTS,
        "position = [0.0, 0.0]",
        "position = [0.0, 0.0]\nrotation_deg = [0.0, 0.0, 400.0]",
        Some(12),
        "objects[0].rotation_deg[2]",
        "400 is out of range (-360..=360)",
    );
    breaks(
        OBJECTS,
        "kind = \"positioning\"",
        "kind = \"positioning\"\ndwell_s = 100.0",
        Some(21),
        "goal.dwell_s",
        "100 is out of range (0..=60)",
    );
    assert_names(
        &error(&format!("{OBJECTS}[physics]\ntimestep_hz = 5.0\n")),
        Some(25),
        "physics.timestep_hz",
        "5 is out of range (10..=10000)",
    );
    breaks(
        SOFT,
        "mass = 0.03",
        "mass = 0.03\ncrumple = 0.9",
        Some(12),
        "soft_bodies[0].crumple",
        "0.9 is out of range (0..=0.6)",
    );
    breaks(
        SOFT,
        "mass = 0.03",
        "mass = 0.03\nthickness = 0.1",
        Some(12),
        "soft_bodies[0].thickness",
        "out of range (up to 0.05 m)",
    );
}

#[test]
fn a_size_that_must_be_positive_is_named() {
    breaks(
        OBJECTS,
        "size = [1.0, 0.75]",
        "size = [0.0, 0.75]",
        Some(4),
        "table.size[0]",
        "0 is out of range (0.05..=10)",
    );
    breaks(OBJECTS, "radius = 0.03", "radius = 0.0", Some(15), "objects[1].radius", "0 is out of range (0.001..=10)");
    let e = error(&with(OBJECTS, "effects = [\"gravity\"]", "effects = [\"gravity\"]\ntime_limit_s = 0"));
    assert!(e.starts_with("bad.toml"), "{e}");
    assert!(e.contains("time_limit_s"), "{e}");
}

#[test]
fn a_count_out_of_range_is_named() {
    assert_names(
        &error(&format!("{OBJECTS}[physics]\nsolver_iterations = 0\n")),
        Some(25),
        "physics.solver_iterations",
        "0 is out of range (1..=100)",
    );
    breaks(
        OBJECTS,
        "position = [0.2, 0.0]",
        "position = [0.2, 0.0]\ncount = 0",
        Some(19),
        "objects[1].count",
        "0 is out of range (1..=1000)",
    );
    breaks(
        SOFT,
        "resolution = [16, 11]",
        "resolution = [16, 1]",
        Some(9),
        "soft_bodies[0].resolution[1]",
        "1 is out of range (2..=128)",
    );
    assert_names(&error(&format!("{SOFT}pieces = 1\n")), Some(17), "goal.pieces", "1 is out of range (2..=100)");
    breaks(
        SOFT,
        "resolution = [16, 11]",
        "resolution = [128, 128]",
        Some(9),
        "soft_bodies[0].resolution",
        "16384 particles is too many",
    );
}

#[test]
fn a_number_that_is_not_finite_is_named() {
    breaks(OBJECTS, "mass = 1.0", "mass = nan", Some(9), "objects[0].mass", "must be a finite number, got NaN");
    breaks(
        OBJECTS,
        "position = [0.0, 0.0]",
        "position = [inf, 0.0]",
        Some(11),
        "objects[0].position[0]",
        "must be a finite number, got inf",
    );
    breaks(
        OBJECTS,
        "position = [0.2, 0.1]",
        "position = [nan, 0.1]",
        Some(23),
        "goal.targets[0].position",
        "must be finite",
    );
}

#[test]
fn an_array_of_the_wrong_length_is_named() {
    breaks(
        OBJECTS,
        "position = [0.0, 0.0]",
        "position = [0.0, 0.0, 0.0, 0.0]",
        Some(11),
        "objects[0].position",
        "must be [x, y] or [x, y, z]",
    );
    breaks(
        SOFT,
        "size = [0.3, 0.2]",
        "size = [0.3, 0.2, 0.1]",
        Some(8),
        "soft_bodies[0].size",
        "a cloth needs `size = [x, y]`",
    );
    breaks(
        SOFT,
        "resolution = [16, 11]",
        "resolution = [16]",
        Some(9),
        "soft_bodies[0].resolution",
        "needs 2 entries, one per side, got 1",
    );
}

#[test]
fn a_place_off_the_table_is_named() {
    breaks(
        OBJECTS,
        "position = [0.2, 0.0]",
        "position = [0.9, 0.0]",
        Some(18),
        "objects[1].position",
        "(0.900, 0.000) lies off the table (±0.500 × ±0.375)",
    );
    breaks(
        OBJECTS,
        "position = [0.2, 0.1]",
        "position = [0.9, 0.1]",
        Some(23),
        "goal.targets[0].position",
        "lies off the table",
    );
    breaks(
        SOFT,
        "position = [0.0, 0.0]",
        "position = [0.0, 0.5]",
        Some(10),
        "soft_bodies[0].position",
        "lies off the table",
    );
    breaks(
        STEER,
        "waypoints = [[0.1, 0.18]]",
        "waypoints = [[0.1, 0.18], [0.1, 0.5]]",
        Some(16),
        "goal.waypoints[1]",
        "lies off the table",
    );
}

#[test]
fn an_unknown_colour_is_named() {
    breaks(
        OBJECTS,
        "color = \"red\"",
        "color = \"reddish\"",
        Some(10),
        "objects[0].color",
        "unknown colour `reddish` (use #rrggbb or one of red, blue",
    );
    breaks(
        OBJECTS,
        "size = [1.0, 0.75]",
        "size = [1.0, 0.75]\ncolor = \"plaid\"",
        Some(5),
        "table.color",
        "unknown colour `plaid`",
    );
    breaks(
        SOFT,
        "color = \"white\"",
        "color = \"#12345\"",
        Some(13),
        "soft_bodies[0].color",
        "unknown colour `#12345`",
    );
    let e = error(&sorting("color = \"mauvish\"\nmin = [0.1, 0.1]\nmax = [0.3, 0.3]\n"));
    assert_names(&e, Some(22), "goal.zones[0].color", "unknown colour `mauvish`");
}

#[test]
fn an_inverted_zone_is_named() {
    let e = error(&sorting("color = \"red\"\nmin = [0.3, 0.1]\nmax = [0.1, 0.3]\n"));
    assert_names(&e, Some(21), "goal.zones[0]", "min must be below max on both axes");
}

#[test]
fn a_duplicate_name_is_named() {
    breaks(OBJECTS, "name = \"ball\"", "name = \"a\"", Some(13), "objects[1].name", "`a` is the name of two objects");
    let e = error(&with(
        &with(
            SOFT,
            "[goal]",
            "[[objects]]\nname = \"paper\"\nshape = \"sphere\"\nradius = 0.02\nmass = 0.1\ncolor = \"red\"\nposition = [0.3, 0.2]\n[goal]",
        ),
        "[[soft_bodies]]",
        "[[soft_bodies]]",
    ));
    assert_names(&e, Some(6), "soft_bodies[0].name", "`paper` is already the name of an object or soft body");
}

#[test]
fn a_reference_to_nothing_is_named() {
    breaks(OBJECTS, "object = \"a\"", "object = \"b\"", Some(22), "goal.targets[0].object", "no object named `b`");
    breaks(STEER, "object = \"puck\"", "object = \"disc\"", Some(15), "goal.object", "no object named `disc`");
    breaks(
        STEER,
        "object = \"puck\"",
        "object = \"puck\"\nplatform = \"stage\"",
        Some(16),
        "goal.platform",
        "no object named `stage`",
    );
    breaks(SOFT, "body = \"paper\"", "body = \"napkin\"", Some(16), "goal.body", "no soft body named `napkin`");
    breaks(SOFT, "tear_strain = 0.25\n", "", Some(15), "goal.body", "`paper` cannot tear: give it a `tear_strain`");
    let e = error(
        &with(SOFT, "kind = \"torn\"", "kind = \"cloth_flat\"")
            .replace("kind = \"cloth\"", "kind = \"volume\"")
            .replace("size = [0.3, 0.2]", "size = [0.3, 0.2, 0.05]")
            .replace("resolution = [16, 11]\n", "")
            .replace("tear_strain = 0.25\n", "")
            .replace("\"cloth\", \"tearing\"", "\"soft_bodies\""),
    );
    assert_names(&e, Some(14), "goal.body", "`paper` is not a cloth");
}

#[test]
fn fields_that_do_not_go_together_are_named() {
    breaks(
        SOFT,
        "mass = 0.03",
        "mass = 0.03\ndensity = 0.5",
        Some(12),
        "soft_bodies[0].density",
        "give `mass` or `density`, not both",
    );
    let volume = with(
        &with(&with(SOFT, "kind = \"cloth\"", "kind = \"volume\""), "size = [0.3, 0.2]", "size = [0.3, 0.2, 0.05]"),
        "resolution = [16, 11]",
        "resolution = [16, 11, 4]",
    )
    .replace("\"cloth\", \"tearing\"", "\"soft_bodies\", \"tearing\"");
    scene::parse(&volume, "volume.toml").unwrap_or_else(|e| panic!("the volume loads: {e}"));
    breaks(
        &volume,
        "mass = 0.03",
        "mass = 0.03\nbending = 2.0",
        Some(12),
        "soft_bodies[0].bending",
        "only a cloth has bending springs",
    );
    breaks(
        &volume,
        "mass = 0.03",
        "mass = 0.03\ncrumple = 0.2",
        Some(12),
        "soft_bodies[0].crumple",
        "only a cloth can start crumpled",
    );
    breaks(
        &volume,
        "mass = 0.03",
        "mass = 0.03\ncrease = 0.2",
        Some(12),
        "soft_bodies[0].crease",
        "only a cloth creases",
    );
}

#[test]
fn an_effect_a_body_needs_but_the_scene_lacks_is_named() {
    breaks(
        SOFT,
        "\"cloth\", \"tearing\"",
        "\"cloth\"",
        Some(12),
        "soft_bodies[0].tear_strain",
        "tearing needs the `tearing` effect: add it to `effects`",
    );
    breaks(
        SOFT,
        "\"cloth\", \"tearing\"",
        "\"tearing\"",
        Some(7),
        "soft_bodies[0].kind",
        "a cloth needs the `cloth` effect",
    );
}

/// A scene that loads must hold nothing a solver cannot take: every number
/// is checked against its bound in `scene::bounds`, and the error names the
/// file, line, field and the bound.
#[test]
fn a_number_past_its_documented_bound_is_named_with_the_bound() {
    // Copies of a fixed body stepped by NaN, inf or 1e30: each copy's position.
    let fixed = |step: &str| {
        with(
            &with(OBJECTS, "mass = 1.0\n", "body = \"fixed\"\ncount = 3\n"),
            "position = [0.0, 0.0]\n",
            &format!("position = [0.0, 0.0]\nstep = {step}\n"),
        )
    };
    let e = error(&fixed("[nan, 0.0]"));
    assert_names(&e, Some(13), "objects[0].step[0]", "must be a finite number, got NaN");
    let e = error(&fixed("[0.0, inf]"));
    assert_names(&e, Some(13), "objects[0].step[1]", "must be a finite number, got inf");
    let e = error(&fixed("[1e30, 0.0]"));
    assert_names(&e, Some(13), "objects[0].step[0]", "1e30 is out of range (-100..=100)");
    let e = error(&fixed("[60.0, 0.0]"));
    assert_names(&e, Some(12), "objects[0].position", "copy 3 lies at (120, 0), farther than 100 m");

    breaks(OBJECTS, "mass = 1.0", "mass = 1e-30", Some(9), "objects[0].mass", "1e-30 is out of range (0.001..=1000)");
    breaks(
        OBJECTS,
        "size = [0.1, 0.1, 0.1]",
        "size = [0.1, 1e30, 0.1]",
        Some(8),
        "objects[0].size[1]",
        "1e30 is out of range (0.001..=10)",
    );
    breaks(
        OBJECTS,
        "size = [1.0, 0.75]",
        "size = [1e30, 0.75]",
        Some(4),
        "table.size[0]",
        "1e30 is out of range (0.05..=10)",
    );
    breaks(
        OBJECTS,
        "effects = [\"gravity\"]",
        "effects = [\"gravity\"]\ntime_limit_s = 1e9",
        Some(3),
        "time_limit_s",
        "1e9 is out of range (at most 600)",
    );
    assert_names(
        &error(&format!("{OBJECTS}[physics]\nccd_substeps = 1000000\n")),
        Some(25),
        "physics.ccd_substeps",
        "1000000 is out of range (0..=16)",
    );

    // Cylinders and capsules of 1e30 would reach parry and panic in its EPA.
    breaks(STEER, "height = 0.02", "height = 1e30", Some(9), "objects[0].height", "1e30 is out of range (0.001..=10)");
    breaks(STEER, "radius = 0.025", "radius = 1e30", Some(8), "objects[0].radius", "1e30 is out of range (0.001..=10)");
    let capsule = with(&with(STEER, "shape = \"cylinder\"", "shape = \"capsule\""), "height = 0.02", "height = 1e30");
    assert_names(&error(&capsule), Some(9), "objects[0].height", "1e30 is out of range (0..=10)");

    breaks(
        SOFT,
        "size = [0.3, 0.2]",
        "size = [0.3, 1e30]",
        Some(8),
        "soft_bodies[0].size[1]",
        "1e30 is out of range (0.001..=10)",
    );
    breaks(
        SOFT,
        "mass = 0.03",
        "mass = 1e-30",
        Some(11),
        "soft_bodies[0].mass",
        "1e-30 is out of range (0.001..=1000)",
    );
    breaks(
        SOFT,
        "mass = 0.03",
        "density = 19000.0",
        Some(11),
        "soft_bodies[0].density",
        "gives a mass of 1140 kg, out of range (0.001..=1000 kg)",
    );
    breaks(
        STEER,
        "finish = [-0.3, -0.2]",
        "finish = [-0.3, -0.2]\nfinish_radius = 1e30",
        Some(18),
        "goal.finish_radius",
        "1e30 is out of range (at most 10)",
    );
}

#[test]
fn too_many_objects_or_copies_at_one_spot_are_refused_before_anything_is_built() {
    let no_goal = with(OBJECTS, &format!("[goal]\nkind = \"positioning\"\n{TARGETS}"), "");
    let many = |count: u32, step: &str| {
        with(
            &with(&no_goal, "mass = 1.0\n", &format!("mass = 1.0\ncount = {count}\n")),
            "position = [0.0, 0.0]\n",
            &format!("position = [-0.45, -0.3]\nstep = {step}\nper_row = 30\nrow_step = [0.0, 0.02]\n"),
        )
    };
    // 1000 is the bound for the whole scene; the ball after them makes 1001.
    let e = error(&many(1000, "[0.03, 0.0]"));
    assert_names(&e, Some(16), "objects[1].count", "1 would make 1001 objects; a scene may have at most 1000");
    let e = error(&many(10_000, "[0.03, 0.0]"));
    assert_names(&e, Some(10), "objects[0].count", "10000 is out of range (1..=1000)");
    let e = error(&many(40, "[0.0, 0.0]"));
    assert_names(&e, Some(13), "objects[0].step", "40 copies need a `step` that is not [0, 0]");
    assert!(scene::parse(&many(999, "[0.03, 0.0]"), "ok.toml").is_ok_and(|s| s.objects.len() == 1000));
}

#[test]
fn a_duplicate_among_the_most_objects_a_scene_may_have_is_named_at_its_line() {
    // The largest legal scene (1000 entries, the bound) with one repeated name.
    let mut text = String::from("name = \"many\"\neffects = [\"gravity\"]\n[table]\nsize = [10.0, 10.0]\n");
    for k in 0..1000 {
        let name = if k == 999 { 500 } else { k };
        let (x, y) = (f64::from(k % 40) * 0.2 - 4.0, f64::from(k / 40) * 0.2 - 4.0);
        writeln!(
            text,
            "[[objects]]\nname = \"o{name}\"\nshape = \"sphere\"\nradius = 0.05\nmass = 0.1\ncolor = \"red\"\nposition = [{x}, {y}]"
        )
        .expect("write to a String");
    }
    let e = error(&text);
    // The 1000th `[[objects]]` header is line 5 + 999 * 7; its `name` the next.
    let line = 5 + 999 * 7 + 1;
    assert_names(&e, Some(line), "objects[999].name", "`o500` is the name of two objects");
}

/// A bad value inside a table is named at its own line, not the table's
/// header: the goal's `finish` (line 17, the `[goal]` header is line 13),
/// a target's `object` inside `[[goal.targets]]` (line 22), and an
/// object's `mass` (line 9, its `[[objects]]` header is line 5).
#[test]
fn a_bad_value_in_a_table_is_named_at_its_own_line() {
    breaks(STEER, "finish = [-0.3, -0.2]", "finish = [-3.0, -0.2]", Some(17), "goal.finish", "lies off the table");
    breaks(
        OBJECTS,
        "object = \"a\"",
        "object = \"nobody\"",
        Some(22),
        "goal.targets[0].object",
        "no object named `nobody`",
    );
    breaks(OBJECTS, "mass = 1.0", "mass = -1.0", Some(9), "objects[0].mass", "");
}

/// The region goal the silent-acceptance checks break: a 10 cm cube `a`
/// kept in a 20 cm square, centre at most 6 cm up (lines 19–24).
fn region(extra: &str) -> String {
    with(
        OBJECTS,
        &format!("kind = \"positioning\"\n{TARGETS}"),
        &format!("kind = \"region\"\nobject = \"a\"\nmin = [0.1, 0.1]\nmax = [0.3, 0.3]\nmax_height = 0.06\n{extra}"),
    )
}

/// What a reader would take and quietly drop or clamp, and goals that can
/// never be met, are errors naming file, line and field.
#[test]
fn nothing_is_accepted_silently() {
    scene::parse(&region(""), "good.toml").unwrap_or_else(|e| panic!("the region scene loads: {e}"));
    // A fixed-length array with extra or missing numbers.
    let e = error(&with(OBJECTS, "size = [1.0, 0.75]", "size = [1.0, 0.75, 0.3]"));
    assert_names(&e, Some(4), "table.size", "expected an array of 2 values, found 3");
    let e = error(&with(OBJECTS, "size = [0.1, 0.1, 0.1]", "size = [0.1, 0.1]"));
    assert_names(&e, Some(8), "objects[0].size", "expected an array of 3 values, found 2");
    let e = error(&with(OBJECTS, "position = [0.2, 0.1]", "position = [0.2, 0.1, 0.0]"));
    assert_names(&e, Some(23), "goal.targets[0].position", "found 3");
    // Empty names, and rows of no objects.
    let e = error(&with(OBJECTS, "name = \"a\"", "name = \"\""));
    assert_names(&e, Some(6), "objects[0].name", "must not be empty");
    let e = error(&with(OBJECTS, "name = \"t\"", "name = \"  \""));
    assert_names(&e, Some(1), "name", "must not be empty");
    let e = error(&with(
        OBJECTS,
        "position = [0.2, 0.0]",
        "position = [0.2, 0.0]\ncount = 3\nstep = [0.05, 0.0]\nper_row = 0",
    ));
    assert_names(&e, Some(21), "objects[1].per_row", "0 is out of range (1..=3)");
    // Goals that can never be met.
    let e = error(&region("").replace("max_height = 0.06", "max_height = 0"));
    assert_names(&e, Some(24), "goal.max_height", "0 must be greater than 0");
    let e = error(&region("").replace("max_height = 0.06", "max_height = 0.04"));
    assert_names(&e, Some(24), "goal.max_height", "below the lowest the centre of `a` can rest (0.050 m)");
    let e = error(&region("").replace("max = [0.3, 0.3]", "max = [0.18, 0.3]"));
    assert_names(&e, Some(23), "goal.max", "the region is 0.080 m across at its narrowest");
    let e = error(&region("").replace("max = [0.3, 0.3]", "max = [0.05, 0.3]"));
    assert_names(&e, Some(23), "goal.max", "must be above `min` on both axes");
    let e = error(&format!("time_limit_s = 5\n{}", region("dwell_s = 5\n")));
    assert_names(&e, Some(26), "goal.dwell_s", "5 s of holding still is not less than the 5 s time limit");
    // A key of another kind of goal.
    let e = error(&region("waypoints = [[0.0, 0.0]]\n"));
    assert_names(&e, Some(25), "goal.waypoints", "a region goal has no `waypoints`");
    let e = error(&with(STEER, "finish = [-0.3, -0.2]", "finish = [-0.3, -0.2]\ndwell_s = 1"));
    assert_names(&e, Some(18), "goal.dwell_s", "a steering goal has no `dwell_s`");
}

/// A scene whose numbers each lie within their bounds, but whose product is
/// hours of simulation, is refused naming the product and its bound.
#[test]
fn work_beyond_reasonable_time_is_refused_with_its_product() {
    let fast = |hz: u32| format!("{SOFT}[physics]\ntimestep_hz = {hz}\n");
    // 176 particles × 60 Hz × 120 s (the default limit) loads.
    scene::parse(&fast(60), "ok.toml").unwrap_or_else(|e| panic!("{e}"));
    let e = error(&fast(10_000));
    assert_names(&e, Some(18), "physics.timestep_hz", "176 particles × 10000 Hz × 120 s = 211,200,000 particle-steps");
    assert!(e.contains("above the bound of 10,000,000 (about 20 minutes of work)"), "{e}");
}
