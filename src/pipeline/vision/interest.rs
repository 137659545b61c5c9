//! Where the caller needs flow: block matching is most of the vision
//! stage's cost (~0.5 µs per outline point), only the Particle technique
//! reads it, and only near bodies it can move.

use glam::Vec2;

/// Where this frame's caller needs flow.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum FlowInterest {
    /// Every outline point (the paper's way).
    #[default]
    All,
    /// No outline point.
    None,
    /// Points near any of these regions (pixels): a point is measured
    /// when it lies within `flow_scale` times the largest flow it can have
    /// (its predicted flow plus the search radius and a pixel of sub-pixel
    /// refinement) of a region, so that a point that may move into one
    /// within the frame is measured.
    Near { regions: Vec<ConvexRegion>, flow_scale: f32 },
}

impl FlowInterest {
    /// Whether a point at `px` with predicted flow `guess` needs its flow,
    /// given the matcher's search radius.
    pub fn wants(&self, px: [f32; 2], guess: [f32; 2], search_radius: f32) -> bool {
        match self {
            FlowInterest::All => true,
            FlowInterest::None => false,
            FlowInterest::Near { regions, flow_scale } => {
                let reach = flow_scale * (guess[0].hypot(guess[1]) + search_radius + 1.0);
                let p = Vec2::from(px);
                regions.iter().any(|r| r.within(p, reach))
            }
        }
    }
}

/// A convex region of the plane as the half-planes that bound it, with its
/// bounding box for a quick reject. Units are the caller's (pixels here,
/// metres on the glass for the Particle technique's culling).
#[derive(Debug, Clone, PartialEq)]
pub struct ConvexRegion {
    min: Vec2,
    max: Vec2,
    /// Unit outward normal `n` and offset `c` of each edge: `n · p <= c`
    /// inside.
    edges: Vec<(Vec2, f32)>,
}

impl ConvexRegion {
    /// The convex hull of `points` (any order, duplicates and collinear
    /// points allowed); `None` without any finite point. One point or
    /// points on a line give a region of no area, which [`Self::within`]
    /// still measures distance to.
    pub fn hull_of(points: &[Vec2]) -> Option<Self> {
        let mut p: Vec<Vec2> = points.iter().copied().filter(|q| q.is_finite()).collect();
        if p.is_empty() {
            return None;
        }
        p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        p.dedup();
        let (min, max) = p.iter().fold((p[0], p[0]), |(lo, hi), q| (lo.min(*q), hi.max(*q)));
        // Andrew's monotone chain, counter-clockwise (y up).
        let cross = |o: Vec2, a: Vec2, b: Vec2| (a - o).perp_dot(b - o);
        let mut hull: Vec<Vec2> = Vec::with_capacity(2 * p.len());
        for pass in 0..2 {
            let start = hull.len();
            let points: Box<dyn Iterator<Item = &Vec2>> =
                if pass == 0 { Box::new(p.iter()) } else { Box::new(p.iter().rev()) };
            for &q in points {
                while hull.len() >= start + 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0 {
                    hull.pop();
                }
                hull.push(q);
            }
            hull.pop();
        }
        let edges = if hull.len() >= 3 {
            (0..hull.len())
                .map(|i| {
                    let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
                    let n = Vec2::new(b.y - a.y, a.x - b.x).normalize();
                    (n, n.dot(a))
                })
                .collect()
        } else {
            // A point or a segment: its bounding box stands for it.
            Vec::new()
        };
        Some(Self { min, max, edges })
    }

    /// How far `p` lies outside the region along the worst edge normal:
    /// at most 0 inside, and never more than the true distance outside (it
    /// equals it except beyond a corner, where it is less). Growing the
    /// region by `d` this way keeps every point within `d` of it.
    pub fn outside_by(&self, p: Vec2) -> f32 {
        let boxed = (self.min - p).max(p - self.max).max_element();
        self.edges.iter().map(|&(n, c)| n.dot(p) - c).fold(boxed, f32::max)
    }

    /// Whether `p` lies within `d` of the region (or a little further
    /// beyond a corner: see [`Self::outside_by`]).
    pub fn within(&self, p: Vec2, d: f32) -> bool {
        let near_box = p.cmpge(self.min - d).all() && p.cmple(self.max + d).all();
        near_box && self.outside_by(p) <= d
    }

    /// Its bounding box corners `(min, max)`.
    pub fn bounds(&self) -> (Vec2, Vec2) {
        (self.min, self.max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> ConvexRegion {
        let pts = [[100.0, 100.0], [120.0, 100.0], [120.0, 110.0], [100.0, 110.0], [110.0, 105.0], [110.0, 100.0]];
        ConvexRegion::hull_of(&pts.map(Vec2::from)).expect("points")
    }

    #[test]
    fn flow_interest_grows_each_region_by_the_points_largest_flow() {
        let near = FlowInterest::Near { regions: vec![square()], flow_scale: 1.5 };
        // Inside: always.
        assert!(near.wants([110.0, 105.0], [0.0, 0.0], 3.0));
        // 7 px left of it: reach is 1.5 * (0 + 3 + 1) = 6 px, so not...
        assert!(!near.wants([93.0, 105.0], [0.0, 0.0], 3.0));
        // ...unless the point is predicted to move 2 px (1.5 * 6 = 9 px).
        assert!(near.wants([93.0, 105.0], [2.0, 0.0], 3.0));
        assert!(FlowInterest::All.wants([0.0, 0.0], [0.0, 0.0], 3.0));
        assert!(!FlowInterest::None.wants([110.0, 105.0], [0.0, 0.0], 3.0));
        assert!(!FlowInterest::Near { regions: Vec::new(), flow_scale: 1.0 }.wants([1.0, 1.0], [0.0, 0.0], 3.0));
    }

    #[test]
    fn outside_by_is_the_edge_distance_and_a_lower_bound_beyond_corners() {
        let r = square();
        assert_eq!(r.outside_by(Vec2::new(93.0, 105.0)), 7.0);
        assert_eq!(r.outside_by(Vec2::new(110.0, 113.0)), 3.0);
        assert!(r.outside_by(Vec2::new(110.0, 105.0)) <= -5.0 + 1e-4, "5 px inside from the nearest edge");
        // Beyond the corner (120, 110) by (3, 4): true distance 5, edges say 4.
        assert_eq!(r.outside_by(Vec2::new(123.0, 114.0)), 4.0);
        assert!(r.within(Vec2::new(123.0, 114.0), 4.0) && !r.within(Vec2::new(123.0, 114.0), 3.9));
    }

    #[test]
    fn a_turned_square_is_tighter_than_its_box() {
        // A diamond |x| + |y| <= 1: the point (0.8, 0.8) is in its box but
        // 0.6 / sqrt(2) = 0.42 outside it.
        let d =
            ConvexRegion::hull_of(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]].map(Vec2::from)).expect("pts");
        assert!((d.outside_by(Vec2::new(0.8, 0.8)) - 0.6 / 2f32.sqrt()).abs() < 1e-6);
        assert!(!d.within(Vec2::new(0.8, 0.8), 0.4) && d.within(Vec2::new(0.8, 0.8), 0.43));
        // Winding and duplicates do not matter.
        let cw = ConvexRegion::hull_of(&[[0.0, -1.0], [-1.0, 0.0], [0.0, 1.0], [1.0, 0.0], [1.0, 0.0]].map(Vec2::from));
        assert_eq!(cw.as_ref(), Some(&d));
    }

    #[test]
    fn degenerate_inputs_use_their_box() {
        assert!(ConvexRegion::hull_of(&[]).is_none());
        assert!(ConvexRegion::hull_of(&[Vec2::NAN]).is_none());
        let point = ConvexRegion::hull_of(&[Vec2::new(1.0, 2.0)]).expect("one point");
        assert_eq!(point.outside_by(Vec2::new(1.0, 5.0)), 3.0);
        let line = ConvexRegion::hull_of(&[Vec2::ZERO, Vec2::new(4.0, 0.0), Vec2::new(2.0, 0.0)]).expect("a segment");
        assert_eq!(line.outside_by(Vec2::new(2.0, -1.5)), 1.5);
        assert_eq!(line.outside_by(Vec2::new(2.0, 0.0)), 0.0);
    }
}
