//! Convex hull of pixel points (Andrew's monotone chain).

/// The convex hull of `points`, counter-clockwise on the table (y up) and
/// on screen, which in raw pixel coordinates (rows growing downwards) is a
/// negative signed area. Collinear points are dropped, so downstream
/// geometry (the contact-theory walk) gets no straight angles. One point
/// gives one point, two distinct points a two-point "hull".
pub fn convex_hull(points: &[[i32; 2]]) -> Vec<[i32; 2]> {
    let mut p: Vec<[i32; 2]> = points.to_vec();
    p.sort_unstable();
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    // Cross product of (a - o) x (b - o) in pixel coordinates.
    let cross = |o: [i32; 2], a: [i32; 2], b: [i32; 2]| {
        i64::from(a[0] - o[0]) * i64::from(b[1] - o[1]) - i64::from(a[1] - o[1]) * i64::from(b[0] - o[0])
    };
    // Keep right turns in pixel coordinates (= left turns with y up): the
    // first pass builds the chain along the larger rows, the second comes
    // back along the smaller ones without popping into the first.
    let mut hull: Vec<[i32; 2]> = Vec::with_capacity(p.len() + 1);
    for &q in &p {
        while hull.len() >= 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) >= 0 {
            hull.pop();
        }
        hull.push(q);
    }
    let first = hull.len() + 1;
    for &q in p.iter().rev().skip(1) {
        while hull.len() >= first && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) >= 0 {
            hull.pop();
        }
        hull.push(q);
    }
    hull.pop();
    if hull.len() == 2 && hull[0] == hull[1] {
        hull.pop();
    }
    hull
}

/// Signed area in pixel coordinates (shoelace); negative for the
/// orientation [`convex_hull`] produces.
pub fn signed_area(polygon: &[[i32; 2]]) -> f64 {
    let n = polygon.len();
    let mut twice = 0i64;
    for i in 0..n {
        let a = polygon[i];
        let b = polygon[(i + 1) % n];
        twice += i64::from(a[0]) * i64::from(b[1]) - i64::from(b[0]) * i64::from(a[1]);
    }
    twice as f64 * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_with_inner_and_collinear_points() {
        let pts = [[0, 0], [2, 0], [4, 0], [4, 4], [0, 4], [2, 2], [1, 3], [0, 2]];
        let hull = convex_hull(&pts);
        assert_eq!(hull.len(), 4);
        assert_eq!(signed_area(&hull), -16.0);
        // Counter-clockwise on screen: from the top-left corner go down first.
        assert_eq!(hull[0], [0, 0]);
        assert_eq!(hull[1], [0, 4]);
    }

    #[test]
    fn degenerate_inputs() {
        assert!(convex_hull(&[]).is_empty());
        assert_eq!(convex_hull(&[[1, 1], [1, 1]]), vec![[1, 1]]);
        assert_eq!(convex_hull(&[[0, 0], [1, 1], [2, 2]]).len(), 2);
    }
}
