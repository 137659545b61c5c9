//! The JSON contract behind `surfacelab contact [FILE|-]`.
//!
//! Input: `{"a": [[x, y], ...], "b": [[x, y], ...]}` — A moves, B is fixed,
//! world coordinates, either winding, other keys ignored.
//!
//! Output, one line:
//! `{"relation": "separated"|"touching"|"intersecting", "distance": d,
//!   "exit": [dx, dy], "witness": [[ax, ay], [bx, by]], "features": [...]}`
//! with the meanings of [`ContactReport`]. `features` lists the contacts
//! that hold once A is moved by `exit` (one for a point contact, two for the
//! ends of an edge-on-edge overlap), each one of
//! * `{"kind": "angle_edge", "a_vertex": i, "b_edge": [j, k]}` — vertex i of
//!   A on edge j→k of B,
//! * `{"kind": "edge_angle", "a_edge": [i, k], "b_vertex": j}` — vertex j of
//!   B on edge i→k of A,
//! * `{"kind": "angle_angle", "a_vertex": i, "b_vertex": j}` — vertex on
//!   vertex,
//!
//! indexing the caller's input arrays. An edge `[j, k]` is given
//! counter-clockwise: for clockwise input it is the input edge k→j; it spans
//! any straight-angle vertices dropped in cleaning, and for a concave
//! polygon it is an edge of one of its convex pieces.
//!
//! Errors name the polygon and the problem ("polygon `a`: vertex 3 makes a
//! reflex angle (the polygon is not convex)"); the CLI maps every error to
//! exit code 2.

use serde::Serialize;
use serde_json::{Map, Value};

use super::concave::{SimplePolygon, UnionBlock};
use super::entrance_block::EntranceBlock;
use super::error::ContactError;
use super::polygon::ConvexPolygon;
use super::report::{ContactReport, Feature};
use super::vec2::Vec2;

/// Answers one query. With `allow_concave`, simple non-convex polygons are
/// decomposed (see [`UnionBlock`]); without it they are an error.
pub fn answer_json(input: &str, allow_concave: bool) -> Result<String, ContactError> {
    let value: Value = serde_json::from_str(input).map_err(|e| ContactError::Json(e.to_string()))?;
    let object = value.as_object().ok_or_else(|| {
        ContactError::Json(r#"expected an object {"a": [[x, y], ...], "b": [[x, y], ...]}"#.to_owned())
    })?;
    let a = read_points(object, "a")?;
    let b = read_points(object, "b")?;
    let report = if allow_concave {
        let a = SimplePolygon::named("a", &a)?;
        let b = SimplePolygon::named("b", &b)?;
        match (a.is_convex(), b.is_convex(), a.pieces().first(), b.pieces().first()) {
            (true, true, Some(pa), Some(pb)) => EntranceBlock::new(pa, pb).report(),
            _ => UnionBlock::new(&a, &b).report(),
        }
    } else {
        let a = ConvexPolygon::named("a", &a)?;
        let b = ConvexPolygon::named("b", &b)?;
        EntranceBlock::new(&a, &b).report()
    };
    serde_json::to_string(&Answer::from(&report)).map_err(|e| ContactError::Json(e.to_string()))
}

fn read_points(object: &Map<String, Value>, name: &str) -> Result<Vec<Vec2>, ContactError> {
    let malformed = |message: String| ContactError::Malformed { name: name.to_owned(), message };
    let list = object
        .get(name)
        .ok_or_else(|| malformed("is missing (expected an array of [x, y] pairs)".to_owned()))?
        .as_array()
        .ok_or_else(|| malformed("must be an array of [x, y] pairs".to_owned()))?;
    list.iter()
        .enumerate()
        .map(|(i, pair)| match pair.as_array().map(Vec::as_slice) {
            Some([x, y]) => match (x.as_f64(), y.as_f64()) {
                (Some(x), Some(y)) => Ok(Vec2::new(x, y)),
                _ => Err(malformed(format!("vertex {i} is not an [x, y] pair of numbers"))),
            },
            _ => Err(malformed(format!("vertex {i} is not an [x, y] pair of numbers"))),
        })
        .collect()
}

/// The output line. Kept apart from [`ContactReport`] so the contract does
/// not move when the Rust types do.
#[derive(Serialize)]
struct Answer {
    relation: &'static str,
    distance: f64,
    exit: [f64; 2],
    witness: [[f64; 2]; 2],
    features: Vec<FeatureJson>,
}

#[derive(Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
enum FeatureJson {
    AngleEdge { a_vertex: usize, b_edge: [usize; 2] },
    EdgeAngle { a_edge: [usize; 2], b_vertex: usize },
    AngleAngle { a_vertex: usize, b_vertex: usize },
}

impl From<&ContactReport> for Answer {
    fn from(r: &ContactReport) -> Self {
        // `+ 0.0` turns a -0.0 (an exact touch approached from inside) into 0.
        let plain = |v: Vec2| [v.x + 0.0, v.y + 0.0];
        Self {
            relation: r.relation.as_str(),
            distance: r.distance + 0.0,
            exit: plain(r.exit),
            witness: [plain(r.witness[0]), plain(r.witness[1])],
            features: r
                .features
                .iter()
                .map(|&f| match f {
                    Feature::AngleEdge { a_vertex, b_edge } => FeatureJson::AngleEdge { a_vertex, b_edge },
                    Feature::EdgeAngle { a_edge, b_vertex } => FeatureJson::EdgeAngle { a_edge, b_vertex },
                    Feature::AngleAngle { a_vertex, b_vertex } => FeatureJson::AngleAngle { a_vertex, b_vertex },
                })
                .collect(),
        }
    }
}
