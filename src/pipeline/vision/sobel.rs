//! Sobel gradient: where the contact image changes fast, i.e. the outlines
//! of contacts, which the particle technique turns into particles.
//!
//! Outlines exist only next to contacts, so [`find_edges`] evaluates the
//! gradient only inside each blob's bounding box grown by [`EDGE_PAD`]
//! pixels (the soft edge reaches about half the falloff outside the
//! thresholded blob). For two hands that is about a tenth of the frame;
//! [`gradient_magnitude`] does the whole frame for display and comparison.

use crate::pipeline::surface::ContactImage;

use super::components::Blob;
use super::grid::BoxGrid;

/// Pixels added around each blob's bounding box before looking for edges.
pub const EDGE_PAD: u32 = 2;

/// The two Sobel kernels summed over a 3 x 3 neighbourhood span two pixels
/// with weights 1-2-1: dividing by 8 turns the response into grey levels
/// per pixel, the slope of the image.
const NORMALISE: f32 = 1.0 / 8.0;

/// A point of a contact's outline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgePixel {
    pub x: u32,
    pub y: u32,
    /// Gradient length, grey levels per pixel.
    pub magnitude: f32,
    /// Gradient `[d/dcolumn, d/drow]`, grey levels per pixel; points into
    /// the contact (towards brighter pixels).
    pub gradient: [f32; 2],
    /// Index in the `blobs` slice of the contact this outline belongs to.
    pub blob: usize,
}

/// Raw Sobel response `[gx, gy]` at `(x, y)` (row gradient positive
/// downwards). The image is extended by repeating its border, so a contact
/// running off the table shows no edge along the table's rim: what lies
/// beyond is unknown, not empty.
#[inline]
pub fn sobel_at(image: &ContactImage, x: usize, y: usize) -> [i32; 2] {
    let (w, h) = (image.width, image.height);
    let p = &image.pixels;
    if x >= 1 && y >= 1 && x + 1 < w && y + 1 < h {
        let (u, m, d) = ((y - 1) * w + x, y * w + x, (y + 1) * w + x);
        let g = |i: usize| i32::from(p[i]);
        let gx = g(u + 1) + 2 * g(m + 1) + g(d + 1) - g(u - 1) - 2 * g(m - 1) - g(d - 1);
        let gy = g(d - 1) + 2 * g(d) + g(d + 1) - g(u - 1) - 2 * g(u) - g(u + 1);
        return [gx, gy];
    }
    let at = |dx: isize, dy: isize| {
        let cx = (x as isize + dx).clamp(0, w as isize - 1) as usize;
        let cy = (y as isize + dy).clamp(0, h as isize - 1) as usize;
        i32::from(p[cy * w + cx])
    };
    let gx = at(1, -1) + 2 * at(1, 0) + at(1, 1) - at(-1, -1) - 2 * at(-1, 0) - at(-1, 1);
    let gy = at(-1, 1) + 2 * at(0, 1) + at(1, 1) - at(-1, -1) - 2 * at(0, -1) - at(1, -1);
    [gx, gy]
}

/// Gradient magnitude (grey levels per pixel) of every pixel, row-major.
/// The whole-frame reference for display and for the benchmark that
/// justifies [`find_edges`]'s bounding boxes.
pub fn gradient_magnitude(image: &ContactImage) -> Vec<f32> {
    let (w, h) = (image.width, image.height);
    let mut out = vec![0.0f32; w * h];
    for y in 0..h {
        let row = &mut out[y * w..(y + 1) * w];
        if y == 0 || y + 1 == h || w < 3 {
            for (x, o) in row.iter_mut().enumerate() {
                let [gx, gy] = sobel_at(image, x, y);
                *o = ((gx * gx + gy * gy) as f32).sqrt() * NORMALISE;
            }
            continue;
        }
        let u = &image.pixels[(y - 1) * w..y * w];
        let m = &image.pixels[y * w..(y + 1) * w];
        let d = &image.pixels[(y + 1) * w..(y + 2) * w];
        // Interior columns as three-wide windows over the three rows, a
        // loop the compiler vectorises.
        for (((o, u), m), d) in row[1..w - 1].iter_mut().zip(u.windows(3)).zip(m.windows(3)).zip(d.windows(3)) {
            let g = |v: u8| i32::from(v);
            let gx = g(u[2]) + 2 * g(m[2]) + g(d[2]) - g(u[0]) - 2 * g(m[0]) - g(d[0]);
            let gy = g(d[0]) + 2 * g(d[1]) + g(d[2]) - g(u[0]) - 2 * g(u[1]) - g(u[2]);
            *o = ((gx * gx + gy * gy) as f32).sqrt() * NORMALISE;
        }
        for x in [0, w - 1] {
            let [gx, gy] = sobel_at(image, x, y);
            row[x] = ((gx * gx + gy * gy) as f32).sqrt() * NORMALISE;
        }
    }
    out
}

/// Outline points of `blobs`: pixels on the grid of every `stride`-th
/// column and row whose gradient magnitude is at least `threshold` (grey
/// levels per pixel), searched only in the padded bounding boxes.
///
/// The grid is anchored at pixel (0, 0), not at each blob, so a contact
/// that does not move yields the same points frame after frame (pooled
/// particles can stay on them). Overlapping boxes are merged per row, so no
/// pixel is reported twice; where boxes overlap, a pixel goes to the blob
/// with a pixel nearest to it.
pub fn find_edges(image: &ContactImage, blobs: &[Blob], threshold: f32, stride: usize) -> Vec<EdgePixel> {
    let (w, h) = (image.width, image.height);
    let mut edges = Vec::new();
    if w == 0 || h == 0 || blobs.is_empty() {
        return edges;
    }
    let stride = stride.max(1);
    let pad = EDGE_PAD as usize;
    let boxes: Vec<[usize; 4]> = blobs
        .iter()
        .map(|b| {
            [
                (b.bbox.x0 as usize).saturating_sub(pad),
                (b.bbox.y0 as usize).saturating_sub(pad),
                (b.bbox.x1 as usize + pad).min(w - 1),
                (b.bbox.y1 as usize + pad).min(h - 1),
            ]
        })
        .collect();
    let y_first = boxes.iter().map(|b| b[1]).min().unwrap_or(0).div_ceil(stride) * stride;
    let y_last = boxes.iter().map(|b| b[3]).max().unwrap_or(0);
    let limit = threshold.max(0.0) / NORMALISE;
    let limit2 = limit * limit;
    // Column intervals of the boxes covering the current row, with the
    // boxes that cover them.
    let grid = BoxGrid::new(&boxes.iter().map(|b| b.map(|v| v as i64)).collect::<Vec<_>>());
    let mut near: Vec<u32> = Vec::new();
    let mut spans: Vec<(usize, usize, usize)> = Vec::new();
    let mut owners: Vec<usize> = Vec::new();
    for y in (y_first..=y_last).step_by(stride) {
        spans.clear();
        grid.query([0, y as i64, w as i64 - 1, y as i64], &mut near);
        spans.extend(
            near.iter()
                .map(|&i| (i as usize, boxes[i as usize]))
                .filter(|(_, b)| b[1] <= y && y <= b[3])
                .map(|(i, b)| (b[0], b[2], i)),
        );
        if spans.is_empty() {
            continue;
        }
        spans.sort_unstable();
        let mut k = 0;
        while k < spans.len() {
            // Merge overlapping intervals so every pixel is visited once.
            let (x0, mut x1) = (spans[k].0, spans[k].1);
            let mut end = k + 1;
            while end < spans.len() && spans[end].0 <= x1 {
                x1 = x1.max(spans[end].1);
                end += 1;
            }
            for x in (x0.div_ceil(stride) * stride..=x1).step_by(stride) {
                let [gx, gy] = sobel_at(image, x, y);
                let m2 = (gx * gx + gy * gy) as f32;
                if m2 < limit2 || m2 == 0.0 {
                    continue;
                }
                owners.clear();
                if end - k == 1 {
                    owners.push(spans[k].2);
                } else {
                    grid.query([x as i64, y as i64, x as i64, y as i64], &mut near);
                    owners.extend(
                        near.iter()
                            .map(|&i| i as usize)
                            .filter(|&i| boxes[i][0] <= x && x <= boxes[i][2] && boxes[i][1] <= y && y <= boxes[i][3]),
                    );
                }
                let blob = if owners.len() == 1 { owners[0] } else { nearest(blobs, &owners, x, y) };
                edges.push(EdgePixel {
                    x: x as u32,
                    y: y as u32,
                    magnitude: m2.sqrt() * NORMALISE,
                    gradient: [gx as f32 * NORMALISE, gy as f32 * NORMALISE],
                    blob,
                });
            }
            k = end;
        }
    }
    edges
}

/// Of the candidate blobs, the one with a pixel nearest `(x, y)`.
fn nearest(blobs: &[Blob], candidates: &[usize], x: usize, y: usize) -> usize {
    let reach = i64::from(EDGE_PAD) + 2;
    candidates
        .iter()
        .min_by_key(|&&i| blobs[i].distance_within(x as i64, y as i64, reach).unwrap_or(i64::MAX))
        .copied()
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::vision::{find_blobs, threshold};

    #[test]
    fn a_step_has_an_edge_where_it_steps() {
        let mut img = ContactImage::new(20, 10);
        for y in 0..10 {
            for x in 10..20 {
                img.pixels[y * 20 + x] = 160;
            }
        }
        assert_eq!(sobel_at(&img, 10, 5), [4 * 160, 0]);
        // Border replication: no edge at the right rim.
        assert_eq!(sobel_at(&img, 19, 5), [0, 0]);
        let blobs = find_blobs(&img, &threshold(&img, 1), 1);
        let edges = find_edges(&img, &blobs, 10.0, 1);
        assert!(edges.iter().all(|e| e.x == 9 || e.x == 10));
        assert_eq!(edges.len(), 20);
        assert!(edges.iter().all(|e| e.gradient[0] > 0.0 && e.magnitude == 80.0));
        let full = gradient_magnitude(&img);
        assert_eq!(full[5 * 20 + 10], 80.0);
        assert_eq!(find_edges(&img, &blobs, 10.0, 2).len(), 5);
    }

    #[test]
    fn overlapping_boxes_report_each_pixel_once() {
        // An L and a dot inside its bounding box.
        let mut img = ContactImage::new(30, 30);
        for i in 5..25 {
            img.pixels[5 * 30 + i] = 200;
            img.pixels[i * 30 + 5] = 200;
        }
        img.pixels[20 * 30 + 20] = 200;
        let blobs = find_blobs(&img, &threshold(&img, 1), 1);
        assert_eq!(blobs.len(), 2);
        let edges = find_edges(&img, &blobs, 1.0, 1);
        let mut seen: Vec<(u32, u32)> = edges.iter().map(|e| (e.x, e.y)).collect();
        let n = seen.len();
        seen.sort_unstable();
        seen.dedup();
        assert_eq!(seen.len(), n);
        assert!(edges.iter().filter(|e| e.x >= 18 && e.y >= 18).all(|e| e.blob == 1));
    }
}
