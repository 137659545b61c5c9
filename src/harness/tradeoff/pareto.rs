//! The Pareto front of (time, error) points: the settings no other setting
//! beats on both counts.

/// One measured setting of a knob.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    pub label: String,
    /// Cost, e.g. µs per frame or ns per query.
    pub time: f64,
    /// Error against the reference, in the knob's unit.
    pub error: f64,
}

/// Indices of the points on the front (lower time and lower error are
/// better), sorted by time. A point is dominated when another is no worse
/// on both and strictly better on one.
pub fn pareto_front(points: &[Point]) -> Vec<usize> {
    let mut front: Vec<usize> = (0..points.len())
        .filter(|&i| {
            let p = &points[i];
            !points.iter().enumerate().any(|(j, q)| {
                j != i && q.time <= p.time && q.error <= p.error && (q.time < p.time || q.error < p.error)
            })
        })
        .collect();
    front.sort_by(|&a, &b| points[a].time.total_cmp(&points[b].time));
    front
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(time: f64, error: f64) -> Point {
        Point { label: String::new(), time, error }
    }

    #[test]
    fn dominated_points_leave_the_front() {
        let pts = [p(1.0, 10.0), p(2.0, 5.0), p(3.0, 6.0), p(4.0, 1.0), p(2.0, 5.0)];
        // (3, 6) is beaten by (2, 5); the duplicate (2, 5) points keep each other.
        assert_eq!(pareto_front(&pts), vec![0, 1, 4, 3]);
    }

    #[test]
    fn a_single_point_is_its_own_front() {
        assert_eq!(pareto_front(&[p(1.0, 1.0)]), vec![0]);
    }
}
