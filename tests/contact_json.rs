//! The JSON contract of `surfacelab contact`: one line out for good input,
//! an error naming the polygon for bad input.

use serde_json::{Value, json};
use surfacelab::contact::{ContactError, answer_json};

fn parse(line: &str) -> Value {
    assert!(!line.contains('\n'), "one line: {line}");
    serde_json::from_str(line).expect("the answer is JSON")
}

fn err(input: &str, allow_concave: bool) -> String {
    answer_json(input, allow_concave).expect_err("must be rejected").to_string()
}

#[test]
fn a_separated_pair_gives_distance_exit_witness_and_features() {
    let out =
        answer_json(r#"{"a": [[0,0],[1,0],[1,1],[0,1]], "b": [[3,0.25],[4,0.25],[4,0.5]]}"#, false).expect("answer");
    let v = parse(&out);
    assert_eq!(v["relation"], "separated");
    assert_eq!(v["distance"], 2.0);
    assert_eq!(v["exit"], json!([2.0, 0.0]));
    // A's right edge [1, 2] faces B's vertex 0 at (3, 0.25).
    assert_eq!(v["witness"], json!([[1.0, 0.25], [3.0, 0.25]]));
    assert_eq!(v["features"], json!([{"kind": "edge_angle", "a_edge": [1, 2], "b_vertex": 0}]));
}

#[test]
fn feature_indices_are_the_callers_even_for_clockwise_input() {
    // Both clockwise. A's vertex 1 (1, 1) lies on B's bottom edge, the
    // input edge 3 → 0 ((2, 1) → (0, 1)); edges are reported counter-
    // clockwise, so it is [0, 3]: (0, 1) → (2, 1).
    let out = answer_json(r#"{"a": [[0,0],[1,1],[2,0]], "b": [[0,1],[0,3],[2,3],[2,1]]}"#, false).expect("answer");
    let v = parse(&out);
    assert_eq!(v["relation"], "touching");
    assert_eq!(v["distance"], 0.0);
    assert_eq!(v["features"], json!([{"kind": "angle_edge", "a_vertex": 1, "b_edge": [0, 3]}]));
}

#[test]
fn intersecting_and_vertex_on_vertex() {
    let v = parse(
        &answer_json(r#"{"a": [[0,0],[2,0],[2,2],[0,2]], "b": [[1.5,0.5],[3,0.5],[3,1],[1.5,1]]}"#, false)
            .expect("answer"),
    );
    assert_eq!(v["relation"], "intersecting");
    assert_eq!(v["distance"], -0.5);
    assert_eq!(v["exit"], json!([-0.5, 0.0]));

    let v = parse(
        &answer_json(r#"{"a": [[0,0],[1,0],[1,1],[0,1]], "b": [[1,1],[2,1],[2,2],[1,2]]}"#, false).expect("answer"),
    );
    assert_eq!(v["relation"], "touching");
    assert_eq!(v["features"], json!([{"kind": "angle_angle", "a_vertex": 2, "b_vertex": 0}]));
}

#[test]
fn concave_input_needs_the_flag() {
    let input = r#"{"a": [[0,0],[3,0],[3,1],[1,1],[1,3],[0,3]], "b": [[2,2],[3,2],[3,3],[2,3]]}"#;
    assert_eq!(err(input, false), "polygon `a`: vertex 3 makes a reflex angle (the polygon is not convex)");
    let v = parse(&answer_json(input, true).expect("answer"));
    assert_eq!(v["relation"], "separated");
    assert_eq!(v["distance"], 1.0);
}

#[test]
fn bad_input_names_the_polygon_and_the_problem() {
    assert!(err("{not json", false).starts_with("invalid JSON input:"));
    assert!(err("[1, 2]", false).starts_with("invalid JSON input: expected an object"));
    assert_eq!(
        err(r#"{"a": [[0,0],[1,0],[0,1]]}"#, false),
        "polygon `b`: is missing (expected an array of [x, y] pairs)"
    );
    assert_eq!(err(r#"{"a": 3, "b": []}"#, false), "polygon `a`: must be an array of [x, y] pairs");
    // A query of polygons `a` and `b`, and the unit triangle.
    let q = |a: &str, b: &str| format!(r#"{{"a": {a}, "b": {b}}}"#);
    let tri = "[[0,0],[1,0],[0,1]]";
    // (input, concave allowed, the message)
    for (input, concave, want) in [
        (q("[[0,0],[1,0],[0,1,2]]", tri), false, "polygon `a`: vertex 2 is not an [x, y] pair of numbers"),
        (q(tri, "[[0,0],[1,1],[2,2]]"), false, "polygon `b`: has zero area (its vertices lie on one line)"),
        (q("[[0,0],[1,0],[0,0]]", tri), true, "polygon `a`: needs at least 3 distinct vertices, got 2"),
        (
            q("[[0,0],[2,2],[2,0],[0,2]]", tri),
            true,
            "polygon `a`: edges starting at vertices 0 and 2 cross (not a simple polygon)",
        ),
    ] {
        assert_eq!(err(&input, concave), want, "{input}");
    }
    // Numbers beyond f64 are a JSON error, reported as such.
    assert!(
        err(r#"{"a": [[0,0],[1e999,0],[0,1]], "b": [[0,0],[1,0],[0,1]]}"#, false).starts_with("invalid JSON input")
    );
    assert!(matches!(answer_json("{}", false), Err(ContactError::Malformed { .. })));
}
