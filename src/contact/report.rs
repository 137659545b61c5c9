//! What a contact query answers: relation, signed distance, exit, witness
//! points and the features in contact.

use super::vec2::Vec2;

/// The paper's three relations of two polygons.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Relation {
    /// The signed distance is above the touching tolerance.
    Separated,
    /// The signed distance is within the touching tolerance of zero.
    Touching,
    /// The signed distance is below minus the touching tolerance.
    Intersecting,
}

impl Relation {
    /// Classifies a signed distance against a tolerance.
    pub fn from_signed_distance(distance: f64, tolerance: f64) -> Self {
        if distance > tolerance {
            Self::Separated
        } else if distance < -tolerance {
            Self::Intersecting
        } else {
            Self::Touching
        }
    }

    /// The lower-case name used by the JSON contract.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Separated => "separated",
            Self::Touching => "touching",
            Self::Intersecting => "intersecting",
        }
    }
}

/// One contact between a feature of A and a feature of B, once A has been
/// moved by the exit translation.
///
/// Indices are the caller's *input* indices (see
/// [`ConvexPolygon::source_index`](super::polygon::ConvexPolygon::source_index)).
/// An edge is the pair `[start, end]` of its end vertices in
/// counter-clockwise order; when the input was clockwise this is the input
/// edge `end → start`, and when straight-angle vertices were dropped the
/// edge spans them (`[2, 5]` is the straight chain 2-3-4-5).
///
/// Two parallel edges lying on each other are reported as the two ends of
/// their common segment, each of which is a vertex of A on an edge of B, a
/// vertex of B on an edge of A, or a vertex on a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Feature {
    /// A vertex of A lies on (the inside of) an edge of B.
    AngleEdge { a_vertex: usize, b_edge: [usize; 2] },
    /// A vertex of B lies on (the inside of) an edge of A.
    EdgeAngle { a_edge: [usize; 2], b_vertex: usize },
    /// A vertex of A lies on a vertex of B.
    AngleAngle { a_vertex: usize, b_vertex: usize },
}

/// At most two features (a point contact, or the two ends of an edge–edge
/// overlap), kept inline so a query allocates nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Features {
    items: [Feature; 2],
    len: usize,
}

impl Features {
    pub const fn new() -> Self {
        let filler = Feature::AngleAngle { a_vertex: 0, b_vertex: 0 };
        Self { items: [filler; 2], len: 0 }
    }

    /// Adds `feature` unless it is already present; a third distinct feature
    /// is dropped (it cannot occur for convex pieces, see [`Feature`]).
    #[inline]
    pub fn push(&mut self, feature: Feature) {
        if self.as_slice().contains(&feature) || self.len == self.items.len() {
            return;
        }
        self.items[self.len] = feature;
        self.len += 1;
    }

    #[inline]
    pub fn as_slice(&self) -> &[Feature] {
        &self.items[..self.len]
    }
}

impl Default for Features {
    fn default() -> Self {
        Self::new()
    }
}

impl std::ops::Deref for Features {
    type Target = [Feature];
    fn deref(&self) -> &[Feature] {
        self.as_slice()
    }
}

/// The full answer of a contact query between A (moving) and B (fixed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactReport {
    pub relation: Relation,
    /// Gap when separated (> 0), about zero when touching, minus the
    /// penetration depth when intersecting.
    pub distance: f64,
    /// The shortest translation of A that makes it just touch B (brings it
    /// into contact when separated, pushes it out when intersecting), so
    /// `|exit| = |distance|`.
    pub exit: Vec2,
    /// `[point on A, point on B]`, A at its current position: the closest
    /// points when separated, otherwise the points that meet once A is moved
    /// by `exit`. Always `witness[1] ≈ witness[0] + exit`.
    pub witness: [Vec2; 2],
    /// The features that touch once A is moved by `exit`.
    pub features: Features,
    /// The tolerance `relation` was judged with.
    pub tolerance: f64,
}
