//! The plane-to-plane projective map between a camera image and the table:
//! four point pairs fix it (the direct linear transform with `h33 = 1`).

use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

/// A 3×3 homography mapping `[x, y]` to `[x', y']` in homogeneous
/// coordinates. Invariant: invertible, and finite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Homography(Matrix3<f64>);

impl Homography {
    /// The map that sends each `from[i]` to `to[i]`. `None` when the
    /// points do not fix one (three on a line, two the same): the 8×8
    /// system is then singular. Callers that read user points check the
    /// quadrilaterals first (see [`convex_in_order`]) so that the error can
    /// say which.
    ///
    /// Why nalgebra's LU: the system is tiny but its pivots vary by orders
    /// of magnitude (pixels against metres); partial pivoting in `f64`
    /// keeps the result within 1e-9 of exact for camera-sized inputs
    /// (tested below), which a hand-rolled elimination would have to prove.
    pub fn from_points(from: &[[f64; 2]; 4], to: &[[f64; 2]; 4]) -> Option<Homography> {
        let mut a = SMatrix::<f64, 8, 8>::zeros();
        let mut b = SVector::<f64, 8>::zeros();
        for (i, ([x, y], [u, v])) in from.iter().zip(to).enumerate() {
            let (r0, r1) = (2 * i, 2 * i + 1);
            // u = (h0 x + h1 y + h2) / (h6 x + h7 y + 1), v likewise with h3..h5.
            a.row_mut(r0).copy_from_slice(&[*x, *y, 1.0, 0.0, 0.0, 0.0, -u * x, -u * y]);
            a.row_mut(r1).copy_from_slice(&[0.0, 0.0, 0.0, *x, *y, 1.0, -v * x, -v * y]);
            b[r0] = *u;
            b[r1] = *v;
        }
        let h = a.lu().solve(&b)?;
        let m = Matrix3::new(h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7], 1.0);
        let finite = m.iter().all(|v| v.is_finite());
        (finite && m.determinant().abs() > 1e-12 * m.norm().powi(3)).then_some(Homography(m))
    }

    /// Where `p` maps to; `None` for a point on the line the map sends to
    /// infinity (never a point between calibration points of a valid
    /// calibration).
    pub fn apply(&self, p: [f64; 2]) -> Option<[f64; 2]> {
        let q = self.0 * Vector3::new(p[0], p[1], 1.0);
        (q.z.abs() > 1e-12).then(|| [q.x / q.z, q.y / q.z])
    }

    /// The map the other way.
    pub fn inverse(&self) -> Homography {
        // An invertible matrix (the constructor's invariant) has an inverse.
        Homography(self.0.try_inverse().unwrap_or_else(Matrix3::identity))
    }

    /// The denominator `h6 x + h7 y + 1` at `p`: its sign says which side
    /// of the vanishing line `p` lies on.
    pub fn depth_sign(&self, p: [f64; 2]) -> f64 {
        self.0[(2, 0)] * p[0] + self.0[(2, 1)] * p[1] + self.0[(2, 2)]
    }
}

/// Whether four points are the corners of a convex quadrilateral, in order
/// round it (either way round), with no three on a line: the shape four
/// reference marks have in any camera's view of the table, and the
/// condition under which the homography maps the inside of one to the
/// inside of the other. A crossed order (a "bow tie") or a point inside the
/// triangle of the other three is the usual mistake and fails here.
/// `min_area` is the least area each corner's triangle may have.
pub fn convex_in_order(p: &[[f64; 2]; 4], min_area: f64) -> bool {
    let cross = |i: usize| {
        let (a, b, c) = (p[i], p[(i + 1) % 4], p[(i + 2) % 4]);
        (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
    };
    let c: Vec<f64> = (0..4).map(cross).collect();
    let all_pos = c.iter().all(|&v| v > 2.0 * min_area);
    let all_neg = c.iter().all(|&v| v < -2.0 * min_area);
    all_pos || all_neg
}

#[cfg(test)]
mod tests {
    use super::*;

    const IMAGE: [[f64; 2]; 4] = [[70.0, 40.0], [590.0, 60.0], [620.0, 450.0], [30.0, 430.0]];
    const TABLE: [[f64; 2]; 4] = [[-0.5, 0.375], [0.5, 0.375], [0.5, -0.375], [-0.5, -0.375]];

    #[test]
    fn maps_the_four_points_and_back() {
        let h = Homography::from_points(&IMAGE, &TABLE).expect("valid");
        for (p, q) in IMAGE.iter().zip(&TABLE) {
            let m = h.apply(*p).expect("finite");
            assert!((m[0] - q[0]).abs() < 1e-9 && (m[1] - q[1]).abs() < 1e-9, "{p:?} -> {m:?}, want {q:?}");
        }
        let inv = h.inverse();
        let back = inv.apply(h.apply([300.0, 200.0]).expect("finite")).expect("finite");
        assert!((back[0] - 300.0).abs() < 1e-7 && (back[1] - 200.0).abs() < 1e-7, "{back:?}");
    }

    /// A pure scale and shift is a homography too: the centre of the image
    /// rectangle goes to the centre of the table.
    #[test]
    fn an_axis_aligned_rectangle_maps_affinely() {
        let image = [[0.0, 0.0], [640.0, 0.0], [640.0, 480.0], [0.0, 480.0]];
        let h = Homography::from_points(&image, &TABLE).expect("valid");
        let c = h.apply([320.0, 240.0]).expect("finite");
        assert!(c[0].abs() < 1e-12 && c[1].abs() < 1e-12, "{c:?}");
        let q = h.apply([160.0, 120.0]).expect("finite");
        assert!((q[0] + 0.25).abs() < 1e-12 && (q[1] - 0.1875).abs() < 1e-12, "{q:?}");
    }

    /// Lines stay lines (the defining property): the midpoint of the image
    /// points' diagonal crossing maps onto the table diagonals' crossing.
    #[test]
    fn diagonals_cross_where_the_table_diagonals_cross() {
        let h = Homography::from_points(&IMAGE, &TABLE).expect("valid");
        // Crossing of the image diagonals 0-2 and 1-3.
        let ([x1, y1], [x2, y2]) = (IMAGE[0], IMAGE[2]);
        let ([x3, y3], [x4, y4]) = (IMAGE[1], IMAGE[3]);
        let d = (x1 - x2) * (y3 - y4) - (y1 - y2) * (x3 - x4);
        let t = ((x1 - x3) * (y3 - y4) - (y1 - y3) * (x3 - x4)) / d;
        let cross = [x1 + t * (x2 - x1), y1 + t * (y2 - y1)];
        let m = h.apply(cross).expect("finite");
        assert!(m[0].abs() < 1e-9 && m[1].abs() < 1e-9, "{m:?}");
    }

    #[test]
    fn degenerate_points_fix_no_map() {
        let line = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 0.0]];
        assert!(Homography::from_points(&line, &TABLE).is_none());
        assert!(!convex_in_order(&line, 1e-6));
        let bow_tie = [IMAGE[0], IMAGE[2], IMAGE[1], IMAGE[3]];
        assert!(!convex_in_order(&bow_tie, 1e-6));
        assert!(convex_in_order(&IMAGE, 1.0) && convex_in_order(&TABLE, 1e-6));
        let reversed = [IMAGE[3], IMAGE[2], IMAGE[1], IMAGE[0]];
        assert!(convex_in_order(&reversed, 1.0));
    }
}
