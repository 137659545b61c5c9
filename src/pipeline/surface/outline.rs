//! Arbitrary touch outlines: the shape a tracker that sends contours (TUIO
//! 2.0's `ocg`, `icg` and `arg`) or a gesture file with `points` says is on
//! the glass, drawn as it is rather than mapped onto a hand template.
//!
//! An outline is a set of closed rings filled by the **even-odd rule**: a
//! point is inside when a ray from it crosses the rings an odd number of
//! times. TUIO 2.0 does not say which way its contours wind, so a rule that
//! ignores winding is the only one that reads every tracker alike: the
//! outer contour is filled and each inner contour cuts a hole, whichever way
//! either turns; area spans become rectangles side by side. (Rejected:
//! nonzero winding, which would fill a hole whose tracker wound it the same
//! way as the outer contour.)
//!
//! Invariant, checked once by [`Outline::new`]: at least one ring, every
//! ring of at least [`MIN_RING_POINTS`] points, every coordinate finite and
//! within [`bounds::POSITION_M`], at most [`MAX_OUTLINE_POINTS`] points in
//! all. The rasterizer and everything downstream rely on it.

use crate::scene::bounds;

/// Fewest points a ring may have: fewer enclose nothing.
pub const MIN_RING_POINTS: usize = 3;
/// Most points in one outline, all rings together. A hand's contour on a
/// 640 × 480 sensor has a few hundred points; the most TUIO 2.0 area spans
/// one 64 KiB datagram holds (5,461) have 21,844 corners. The cap keeps a
/// hostile packet or file from costing the rasterizer seconds per frame.
pub const MAX_OUTLINE_POINTS: usize = 32_768;

/// Why a set of rings is not an outline. `ring` and `point` count from 0.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OutlineError {
    #[error("no ring: an outline needs at least one closed contour")]
    Empty,
    #[error("ring {ring} has {count} points; a contour needs at least {MIN_RING_POINTS}")]
    TooFewPoints { ring: usize, count: usize },
    #[error("ring {ring}, point {point} is not finite")]
    NotFinite { ring: usize, point: usize },
    #[error("ring {ring}, point {point} is out of range (within ±{} m of the table centre)", bounds::POSITION_M)]
    OutOfRange { ring: usize, point: usize },
    #[error("{count} points in all; at most {MAX_OUTLINE_POINTS}")]
    TooManyPoints { count: usize },
}

/// Closed rings in metres, filled by the even-odd rule (module doc). Cheap
/// to share: hands carry it behind an `Arc`.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    rings: Vec<Vec<[f32; 2]>>,
}

impl Outline {
    /// Checks the rings (see the module doc's invariant). A ring is closed
    /// implicitly: its last point joins its first.
    pub fn new(rings: Vec<Vec<[f32; 2]>>) -> Result<Self, OutlineError> {
        if rings.is_empty() {
            return Err(OutlineError::Empty);
        }
        let count: usize = rings.iter().map(Vec::len).sum();
        if count > MAX_OUTLINE_POINTS {
            return Err(OutlineError::TooManyPoints { count });
        }
        let far = bounds::POSITION_M;
        for (ring, points) in rings.iter().enumerate() {
            if points.len() < MIN_RING_POINTS {
                return Err(OutlineError::TooFewPoints { ring, count: points.len() });
            }
            for (point, p) in points.iter().enumerate() {
                if !(p[0].is_finite() && p[1].is_finite()) {
                    return Err(OutlineError::NotFinite { ring, point });
                }
                if p[0].abs() > far || p[1].abs() > far {
                    return Err(OutlineError::OutOfRange { ring, point });
                }
            }
        }
        Ok(Self { rings })
    }

    pub fn rings(&self) -> &[Vec<[f32; 2]>] {
        &self.rings
    }

    /// Points in all rings.
    pub fn point_count(&self) -> usize {
        self.rings.iter().map(Vec::len).sum()
    }

    /// Axis-aligned bounds `[min, max]`.
    pub fn bounds(&self) -> [[f32; 2]; 2] {
        let mut lo = [f32::MAX; 2];
        let mut hi = [f32::MIN; 2];
        for p in self.rings.iter().flatten() {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        [lo, hi]
    }

    /// The outline moved so that the middle of its bounds is the origin,
    /// and that middle: how a hand carries an outline in its own frame,
    /// placed by its pose, so that moving a hand between two tracker
    /// reports moves its outline too.
    pub fn centred(&self) -> (Self, [f32; 2]) {
        let [lo, hi] = self.bounds();
        let c = [(lo[0] + hi[0]) * 0.5, (lo[1] + hi[1]) * 0.5];
        let rings = self.rings.iter().map(|r| r.iter().map(|p| [p[0] - c[0], p[1] - c[1]]).collect()).collect();
        (Self { rings }, c)
    }

    /// The rings scaled by `scale`, turned by `angle` (radians,
    /// counter-clockwise) about the origin, then moved by `offset`: placed
    /// on the table by a hand's pose.
    pub fn placed(&self, offset: [f32; 2], angle: f32, scale: f32) -> Vec<Vec<[f32; 2]>> {
        let (sin, cos) = angle.sin_cos();
        self.rings
            .iter()
            .map(|r| {
                r.iter()
                    .map(|p| {
                        let (x, y) = (p[0] * scale, p[1] * scale);
                        [x * cos - y * sin + offset[0], x * sin + y * cos + offset[1]]
                    })
                    .collect()
            })
            .collect()
    }

    /// Whether `p` is inside (even-odd).
    pub fn contains(&self, p: [f32; 2]) -> bool {
        contains(&self.rings, p)
    }

    /// Filled area in square metres, for rings that do not cross (the outer
    /// contour with its holes inside it, spans side by side): each ring's
    /// area counts positive at even nesting depth and negative at odd.
    pub fn area(&self) -> f32 {
        self.rings
            .iter()
            .enumerate()
            .map(|(i, ring)| {
                let a = shoelace(ring).abs();
                let depth =
                    self.rings.iter().enumerate().filter(|&(j, other)| j != i && contains_ring(other, ring[0])).count();
                if depth % 2 == 0 { a } else { -a }
            })
            .sum()
    }
}

/// Even-odd containment of `p` in `rings`.
pub fn contains(rings: &[Vec<[f32; 2]>], p: [f32; 2]) -> bool {
    rings.iter().filter(|r| contains_ring(r, p)).count() % 2 == 1
}

fn contains_ring(ring: &[[f32; 2]], p: [f32; 2]) -> bool {
    let mut inside = false;
    let mut j = ring.len() - 1;
    for i in 0..ring.len() {
        let (a, b) = (ring[j], ring[i]);
        if (a[1] <= p[1]) != (b[1] <= p[1]) {
            let x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if p[0] < x {
                inside = !inside;
            }
        }
        j = i;
    }
    inside
}

fn shoelace(ring: &[[f32; 2]]) -> f32 {
    let mut sum = 0.0;
    let mut j = ring.len() - 1;
    for i in 0..ring.len() {
        sum += ring[j][0] * ring[i][1] - ring[i][0] * ring[j][1];
        j = i;
    }
    0.5 * sum
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(c: [f32; 2], half: f32) -> Vec<[f32; 2]> {
        vec![
            [c[0] - half, c[1] - half],
            [c[0] + half, c[1] - half],
            [c[0] + half, c[1] + half],
            [c[0] - half, c[1] + half],
        ]
    }

    #[test]
    fn holes_are_cut_whichever_way_they_wind() {
        let outer = square([0.0, 0.0], 0.1);
        let mut hole = square([0.0, 0.0], 0.05);
        for h in [hole.clone(), {
            hole.reverse();
            hole
        }] {
            let o = Outline::new(vec![outer.clone(), h]).expect("valid");
            assert!(o.contains([0.08, 0.0]), "in the ring between the contours");
            assert!(!o.contains([0.0, 0.0]), "in the hole");
            assert!(!o.contains([0.2, 0.0]), "outside");
            // 0.2² − 0.1² m².
            assert!((o.area() - 0.03).abs() < 1e-6, "{}", o.area());
        }
    }

    #[test]
    fn bad_rings_are_refused_with_where() {
        assert_eq!(Outline::new(vec![]), Err(OutlineError::Empty));
        assert_eq!(
            Outline::new(vec![square([0.0, 0.0], 0.1), vec![[0.0, 0.0], [1.0, 0.0]]]),
            Err(OutlineError::TooFewPoints { ring: 1, count: 2 })
        );
        let mut nan = square([0.0, 0.0], 0.1);
        nan[2][1] = f32::NAN;
        assert_eq!(Outline::new(vec![nan]), Err(OutlineError::NotFinite { ring: 0, point: 2 }));
        let mut far = square([0.0, 0.0], 0.1);
        far[3][0] = 101.0;
        assert_eq!(Outline::new(vec![far]), Err(OutlineError::OutOfRange { ring: 0, point: 3 }));
        let many = vec![[0.0, 0.0]; MAX_OUTLINE_POINTS + 1];
        assert_eq!(Outline::new(vec![many]), Err(OutlineError::TooManyPoints { count: MAX_OUTLINE_POINTS + 1 }));
    }

    #[test]
    fn centred_and_placed_put_it_back() {
        let o = Outline::new(vec![square([0.3, -0.1], 0.05)]).expect("valid");
        let (local, c) = o.centred();
        assert!((c[0] - 0.3).abs() < 1e-6 && (c[1] + 0.1).abs() < 1e-6);
        let back = local.placed(c, 0.0, 1.0);
        for (a, b) in back[0].iter().zip(&o.rings()[0]) {
            assert!((a[0] - b[0]).abs() < 1e-6 && (a[1] - b[1]).abs() < 1e-6);
        }
        // A quarter turn counter-clockwise takes local +x to +y.
        let turned = Outline::new(vec![vec![[0.1, 0.0], [0.1, 0.01], [0.09, 0.0]]]).expect("valid");
        let p = turned.placed([1.0, 0.0], std::f32::consts::FRAC_PI_2, 2.0)[0][0];
        assert!((p[0] - 1.0).abs() < 1e-6 && (p[1] - 0.2).abs() < 1e-6, "{p:?}");
    }
}
