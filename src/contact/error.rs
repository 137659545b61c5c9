//! Errors of the contact module: one for a polygon's shape, one for a query.

use thiserror::Error;

/// Why a list of points is not a usable polygon. Vertex and edge numbers are
/// the caller's input indices (0-based), whatever winding was given.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum PolygonError {
    #[error("needs at least 3 distinct vertices, got {distinct}")]
    TooFewPoints { distinct: usize },
    #[error("vertex {vertex} is not a finite number")]
    NotFinite { vertex: usize },
    #[error("has zero area (its vertices lie on one line)")]
    ZeroArea,
    #[error("vertex {vertex} makes a reflex angle (the polygon is not convex)")]
    Reflex { vertex: usize },
    #[error("vertex {vertex} folds the boundary back on itself")]
    FoldsBack { vertex: usize },
    #[error("its boundary winds {turns} times around the interior (self-intersecting)")]
    Winding { turns: i64 },
    #[error("edges starting at vertices {first} and {second} cross (not a simple polygon)")]
    SelfIntersecting { first: usize, second: usize },
    #[error("a circle needs a positive finite radius, got {radius}")]
    BadRadius { radius: f64 },
    #[error(
        "is concave with {vertices} vertices after cleaning; convex decomposition accepts at most {limit} \
         (simplify the outline, or split it into convex parts)"
    )]
    TooManyVertices { vertices: usize, limit: usize },
}

/// An error of a contact query, naming the polygon at fault (`a` or `b` in
/// the JSON contract).
#[derive(Clone, Debug, Error, PartialEq)]
pub enum ContactError {
    #[error("invalid JSON input: {0}")]
    Json(String),
    /// The problem is part of the message rather than a `#[source]`, so that
    /// printing the error chain does not say it twice.
    #[error("polygon `{name}`: {problem}")]
    Polygon { name: String, problem: PolygonError },
    #[error("polygon `{name}`: {message}")]
    Malformed { name: String, message: String },
}

impl ContactError {
    /// Attaches a polygon's name to a shape error.
    pub fn polygon(name: &str, problem: PolygonError) -> Self {
        Self::Polygon { name: name.to_owned(), problem }
    }
}
