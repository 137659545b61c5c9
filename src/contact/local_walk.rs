//! Walking the entrance block from any state, not only from its lowest
//! point as the full walk does: the steps of [`super::separated`]'s
//! downhill walk and of [`super::overlapping`]'s local search. Edges are
//! ordered by angle from the current edge's normal rather than from the x
//! axis, and a state is found by its support direction in O(log n).

use super::entrance_block::{Cover, Step, parallel};
use super::polygon::ConvexPolygon;
use super::vec2::{Vec2, at_or_after_in_half};

/// The state `(i, j)` of the block's support vertex in direction `n`: B's
/// vertex farthest along `n` and A's farthest against it, each found by
/// binary search on the polygon's normals.
#[inline]
pub(crate) fn support(a: &ConvexPolygon, b: &ConvexPolygon, n: Vec2) -> (usize, usize) {
    (a.first_edge_at_or_after(-n), b.first_edge_at_or_after(n))
}

/// A state found by angle may have taken one of two parallel edges and not
/// the other (their angles a rounding apart, either side of `n`); the full
/// walk takes such a pair together, so the taken one is given back.
pub(crate) fn unsplit(a: &ConvexPolygon, b: &ConvexPolygon, i: usize, j: usize) -> (usize, usize) {
    let (na, nb) = (a.normals(), b.normals());
    let (n, m) = (na.len(), nb.len());
    let (ip, jp) = (if i == 0 { n - 1 } else { i - 1 }, if j == 0 { m - 1 } else { j - 1 });
    if parallel(nb[jp], -na[i]) {
        (i, jp)
    } else if parallel(-na[ip], nb[j]) {
        (ip, j)
    } else {
        (i, j)
    }
}

/// 0 when `v` is at an angle in `[0, π)` counter-clockwise from `c`.
#[inline]
fn half_from(c: Vec2, v: Vec2) -> u8 {
    let x = c.cross(v);
    u8::from(!(x > 0.0 || (x == 0.0 && c.dot(v) > 0.0)))
}

/// The full walk's `order`, with angles measured from the current edge's
/// normal `c` instead of from the x axis: which of B's next edge (normal
/// `nb`) and −A's next edge (normal `na`) comes first counter-clockwise.
#[inline]
pub(crate) fn order_from(c: Vec2, nb: Vec2, na: Vec2) -> Step {
    if parallel(nb, na) {
        return Step::Both;
    }
    let (hb, ha) = (half_from(c, nb), half_from(c, na));
    if hb != ha {
        return if hb < ha { Step::B } else { Step::A };
    }
    // na after nb in their half from `c` (robust there, see the helper).
    if at_or_after_in_half(nb, na, c, hb) { Step::B } else { Step::A }
}

/// The mirror image of [`order_from`] going clockwise: which of B's
/// previous edge and −A's previous edge comes last before `c`.
#[inline]
pub(crate) fn order_back(c: Vec2, nb: Vec2, na: Vec2) -> Step {
    if parallel(nb, na) {
        return Step::Both;
    }
    let (hb, ha) = (half_from(nb, c), half_from(na, c));
    if hb != ha {
        return if hb < ha { Step::B } else { Step::A };
    }
    // Both lie within the same half-turn behind `c` (clockwise). More than
    // three eighths of a turn apart, `nb × na` is noise (as in
    // `at_or_after_in_half`), and the one nearer `c` is the one on the same
    // side of `c`'s perpendicular as the half's start.
    let (x, y) = (nb.cross(na), nb.dot(na));
    if y < 0.0 && x.abs() < -y {
        let nearer_b = if hb == 0 { c.dot(nb) > 0.0 } else { c.dot(nb) < 0.0 };
        return if nearer_b { Step::B } else { Step::A };
    }
    if x > 0.0 { Step::A } else { Step::B }
}

#[inline]
pub(crate) fn cover_direction(av: &[Vec2], bv: &[Vec2], c: Cover) -> Vec2 {
    let i1 = if c.i + 1 == av.len() { 0 } else { c.i + 1 };
    let j1 = if c.j + 1 == bv.len() { 0 } else { c.j + 1 };
    match c.step {
        Step::B => bv[j1] - bv[c.j],
        Step::A => av[c.i] - av[i1],
        Step::Both => (bv[j1] - bv[c.j]) + (av[c.i] - av[i1]),
    }
}
