//! Outer contour of a connected component by Moore-neighbour border
//! following.

use super::threshold::Mask;

/// The eight neighbours, clockwise on screen (rows grow downwards) starting
/// at west: W, NW, N, NE, E, SE, S, SW.
const RING: [[i32; 2]; 8] = [[-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0], [1, 1], [0, 1], [-1, 1]];

fn ring_index(d: [i32; 2]) -> usize {
    RING.iter().position(|&r| r == d).unwrap_or(0)
}

/// The outer boundary pixels of the 8-connected component of `mask` that
/// contains `start`, which must be its first pixel in raster order (topmost
/// row, leftmost in it: the first pixel of a blob's first run), so that its
/// west and northern neighbours are known to be empty.
///
/// The result is a closed polygon through pixel centres (last point not
/// repeated), counter-clockwise on screen and on the table like
/// [`super::convex_hull`]. Pixels on one-pixel-wide necks appear twice, once
/// per side, as border following gives them. Holes are not traced: the
/// physics needs the outside of a hand, and a cup's ring gives its outer rim.
///
/// Moore tracing with the stop rule "back at the start about to make the
/// first move again" (Jacob's criterion is weaker: it stops early on some
/// one-pixel necks through the start).
pub fn trace_contour(mask: &Mask, start: [i32; 2]) -> Vec<[i32; 2]> {
    if !mask.get(start[0], start[1]) {
        return Vec::new();
    }
    let mut contour = vec![start];
    // Direction (index in RING) from the current pixel to its backtrack,
    // an empty neighbour; west of the start is empty by precondition.
    let mut back = 0usize;
    let mut p = start;
    let mut first_move: Option<[i32; 2]> = None;
    // A boundary pixel is visited at most four times (once per side).
    let limit = 4 * mask.width.max(1) * mask.height.max(1) + 8;
    let (w, h) = (mask.width as i32, mask.height as i32);
    let set =
        |q: [i32; 2]| q[0] >= 0 && q[1] >= 0 && q[0] < w && q[1] < h && mask.bits[(q[1] * w + q[0]) as usize] != 0;
    for _ in 0..limit {
        let mut next = None;
        for k in 1..=8 {
            let d = (back + k) % 8;
            let q = [p[0] + RING[d][0], p[1] + RING[d][1]];
            if set(q) {
                // The neighbour scanned just before q is empty: it becomes
                // q's backtrack.
                let b = RING[(d + 7) % 8];
                let b = [p[0] + b[0], p[1] + b[1]];
                next = Some((q, ring_index([b[0] - q[0], b[1] - q[1]])));
                break;
            }
        }
        let Some((q, q_back)) = next else {
            break; // an isolated pixel
        };
        if p == start {
            match first_move {
                None => first_move = Some(q),
                Some(m) if m == q => break,
                Some(_) => {}
            }
        }
        contour.push(q);
        p = q;
        back = q_back;
    }
    // The walk pushed the start again when it came back; drop that copy.
    if contour.len() > 1 && contour[contour.len() - 1] == start {
        contour.pop();
    }
    contour.reverse();
    // Reversing keeps the start last; rotate it to the front.
    contour.rotate_right(1);
    contour
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::vision::hull::signed_area;

    fn mask(rows: &[&str]) -> Mask {
        Mask {
            width: rows[0].len(),
            height: rows.len(),
            bits: rows.iter().flat_map(|r| r.bytes().map(|b| u8::from(b == b'#'))).collect(),
        }
    }

    #[test]
    fn square_outline_in_order() {
        let m = mask(&["....", ".##.", ".##.", "...."]);
        let c = trace_contour(&m, [1, 1]);
        assert_eq!(c, vec![[1, 1], [1, 2], [2, 2], [2, 1]]);
        assert!(signed_area(&c) < 0.0);
    }

    #[test]
    fn single_pixel_and_line() {
        let m = mask(&["...", ".#.", "..."]);
        assert_eq!(trace_contour(&m, [1, 1]), vec![[1, 1]]);
        let m = mask(&["###"]);
        assert_eq!(trace_contour(&m, [0, 0]), vec![[0, 0], [1, 0], [2, 0], [1, 0]]);
    }

    #[test]
    fn neck_through_the_start_is_followed() {
        // Two lobes joined only diagonally through the start pixel.
        let m = mask(&["#...", ".##.", ".##.", "#..."]);
        let c = trace_contour(&m, [0, 0]);
        assert!(c.len() >= 5, "{c:?}");
        // (0, 3) touches (1, 2) diagonally: same 8-connected component.
        assert!(c.contains(&[0, 3]));
        let m = mask(&["#..#", ".##.", "#..#"]);
        let c = trace_contour(&m, [0, 0]);
        for corner in [[0, 0], [3, 0], [0, 2], [3, 2]] {
            assert!(c.contains(&corner), "{corner:?} missing from {c:?}");
        }
    }
}
