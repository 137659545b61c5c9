//! Connected components of the mask: the contacts, with their shape
//! statistics.
//!
//! Run-based two-pass labelling: each row is cut into runs of set pixels,
//! runs that touch runs of the row above (8-connected) are joined in a
//! union-find, and each set of runs becomes a [`Blob`]. Runs are few (one or
//! two per row per hand) where pixels are many, and the statistics are sums
//! over runs, so no label image is needed.

use crate::pipeline::surface::ContactImage;
use std::ops::Range;

use super::contour::trace_contour;
use super::hull::convex_hull;
use super::threshold::Mask;

/// Set pixels `x0..x1` (end exclusive) of row `y`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Run {
    pub y: u32,
    pub x0: u32,
    pub x1: u32,
}

impl Run {
    pub fn len(self) -> u32 {
        self.x1 - self.x0
    }

    pub fn is_empty(self) -> bool {
        self.x1 == self.x0
    }
}

/// Inclusive pixel bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BBox {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

impl BBox {
    pub fn width(self) -> u32 {
        self.x1 - self.x0 + 1
    }

    pub fn height(self) -> u32 {
        self.y1 - self.y0 + 1
    }

    pub fn contains(self, x: i64, y: i64) -> bool {
        x >= i64::from(self.x0) && x <= i64::from(self.x1) && y >= i64::from(self.y0) && y <= i64::from(self.y1)
    }
}

/// The ellipse with the blob's area-normalised second moments: for a solid
/// ellipse these are its true axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    /// Plain centroid, pixels.
    pub centre: [f32; 2],
    /// Semi-major and semi-minor axis, pixels (`2 sqrt(eigenvalue)`).
    pub semi_axes: [f32; 2],
    /// Direction of the major axis, radians in image orientation (from
    /// +column towards +row, i.e. clockwise on screen), in `(-pi/2, pi/2]`.
    /// Negate for the table frame.
    pub angle: f32,
}

impl Ellipse {
    /// Major over minor axis; large for a finger or forearm, about 1 for a
    /// fingertip (whose angle is then meaningless).
    pub fn elongation(&self) -> f32 {
        self.semi_axes[0] / self.semi_axes[1].max(0.5)
    }
}

/// One connected set of touching pixels. Positions are `[column, row]`
/// with integers at pixel centres (see `surface::Sensor`).
#[derive(Debug, Clone, PartialEq)]
pub struct Blob {
    /// Pixel count.
    pub area: u32,
    /// Mean of the pixel centres.
    pub centroid: [f32; 2],
    /// Grey-weighted mean: follows pressure, and moves smoothly when the
    /// thresholded outline gains or loses a pixel.
    pub weighted_centroid: [f32; 2],
    pub bbox: BBox,
    pub ellipse: Ellipse,
    pub mean_grey: f32,
    pub max_grey: u8,
    /// Outer boundary pixels, counter-clockwise on screen.
    pub contour: Vec<[i32; 2]>,
    /// Convex hull of the contour, same orientation, no collinear points.
    pub hull: Vec<[i32; 2]>,
    /// The pixels themselves, sorted by row then column.
    pub runs: Vec<Run>,
}

impl Blob {
    /// True when pixel `(x, y)` belongs to the blob.
    pub fn contains(&self, x: i64, y: i64) -> bool {
        if !self.bbox.contains(x, y) {
            return false;
        }
        let start = self.runs.partition_point(|r| i64::from(r.y) < y);
        self.runs[start..]
            .iter()
            .take_while(|r| i64::from(r.y) == y)
            .any(|r| x >= i64::from(r.x0) && x < i64::from(r.x1))
    }

    /// Chebyshev distance from `(x, y)` to the nearest blob pixel, looking
    /// at most `reach` rows up and down; `None` when none is that close.
    pub fn distance_within(&self, x: i64, y: i64, reach: i64) -> Option<i64> {
        let start = self.runs.partition_point(|r| i64::from(r.y) < y - reach);
        self.runs[start..]
            .iter()
            .take_while(|r| i64::from(r.y) <= y + reach)
            .map(|r| {
                let dx = if x < i64::from(r.x0) {
                    i64::from(r.x0) - x
                } else if x >= i64::from(r.x1) {
                    x - i64::from(r.x1) + 1
                } else {
                    0
                };
                dx.max((i64::from(r.y) - y).abs())
            })
            .min()
    }
}

/// Extracts the runs of one mask row. Skips eight empty (or eight full)
/// pixels at a time: most of a frame is empty glass.
fn row_runs(row: &[u8], y: u32, out: &mut Vec<Run>) {
    const ONES: u64 = 0x0101_0101_0101_0101;
    let n = row.len();
    let word = |x: usize| -> u64 {
        let bytes: [u8; 8] = row[x..x + 8].try_into().unwrap_or([0xff; 8]);
        u64::from_ne_bytes(bytes)
    };
    let mut x = 0;
    while x < n {
        while x + 8 <= n && word(x) == 0 {
            x += 8;
        }
        while x < n && row[x] == 0 {
            x += 1;
        }
        if x >= n {
            break;
        }
        let start = x;
        while x + 8 <= n && word(x) == ONES {
            x += 8;
        }
        while x < n && row[x] != 0 {
            x += 1;
        }
        out.push(Run { y, x0: start as u32, x1: x as u32 });
    }
}

fn find(parent: &mut [u32], mut i: u32) -> u32 {
    while parent[i as usize] != i {
        let up = parent[parent[i as usize] as usize];
        parent[i as usize] = up;
        i = up;
    }
    i
}

/// The 8-connected components of `mask` with at least `min_area` pixels,
/// ordered by their first pixel in raster order. `image` supplies the grey
/// levels (it must have the mask's size).
pub fn find_blobs(image: &ContactImage, mask: &Mask, min_area: u32) -> Vec<Blob> {
    find_blobs_in_rows(image, mask, min_area, 0..mask.height)
}

/// [`find_blobs`] for a mask that is clear outside `rows`: only those rows
/// are scanned. The result is the same as [`find_blobs`]'s.
pub fn find_blobs_in_rows(image: &ContactImage, mask: &Mask, min_area: u32, rows: Range<usize>) -> Vec<Blob> {
    let (w, h) = (mask.width, mask.height);
    if w == 0 || h == 0 || mask.bits.len() != w * h || image.pixels.len() != w * h {
        return Vec::new();
    }
    // Pass 1: runs, joined to overlapping runs of the previous row.
    let mut runs: Vec<Run> = Vec::new();
    let mut parent: Vec<u32> = Vec::new();
    let mut prev_start = 0usize;
    for y in rows.start.min(h)..rows.end.min(h) {
        let start = runs.len();
        let row = &mask.bits[y * w..(y + 1) * w];
        // Most rows are empty glass: an OR over the row vectorises and
        // skips them at memory speed.
        if row.iter().fold(0u8, |a, &b| a | b) != 0 {
            row_runs(row, y as u32, &mut runs);
        }
        parent.extend(start as u32..runs.len() as u32);
        // Two runs in adjacent rows are 8-connected when their column
        // ranges overlap once widened by one pixel.
        let (mut i, mut j) = (prev_start, start);
        while i < start && j < runs.len() {
            let (a, b) = (runs[i], runs[j]);
            if a.x0 <= b.x1 && b.x0 <= a.x1 {
                let (ra, rb) = (find(&mut parent, i as u32), find(&mut parent, j as u32));
                if ra != rb {
                    // The older run stays the root: roots are then first runs.
                    parent[ra.max(rb) as usize] = ra.min(rb);
                }
            }
            if a.x1 < b.x1 {
                i += 1;
            } else {
                j += 1;
            }
        }
        prev_start = start;
    }
    // Pass 2: group runs by root, in raster order of their first run.
    let mut slot = vec![u32::MAX; runs.len()];
    let mut groups: Vec<Vec<Run>> = Vec::new();
    for (i, &run) in runs.iter().enumerate() {
        let root = find(&mut parent, i as u32) as usize;
        if slot[root] == u32::MAX {
            slot[root] = groups.len() as u32;
            groups.push(Vec::new());
        }
        groups[slot[root] as usize].push(run);
    }
    groups
        .into_iter()
        .filter(|g| g.iter().map(|r| r.len()).sum::<u32>() >= min_area.max(1))
        .map(|g| describe(image, mask, g))
        .collect()
}

/// Sum of the integers `0..n`, and of their squares.
fn sums(n: u64) -> (u64, u64) {
    if n == 0 { (0, 0) } else { (n * (n - 1) / 2, (n - 1) * n * (2 * n - 1) / 6) }
}

/// Statistics of one component from its runs.
fn describe(image: &ContactImage, mask: &Mask, runs: Vec<Run>) -> Blob {
    let w = image.width;
    let (mut area, mut sx, mut sy, mut sxx, mut syy, mut sxy) = (0u64, 0u64, 0u64, 0u64, 0u64, 0u64);
    let (mut g_sum, mut g_x, mut g_y, mut g_max) = (0u64, 0u64, 0u64, 0u8);
    let mut bbox = BBox { x0: u32::MAX, y0: runs[0].y, x1: 0, y1: runs[runs.len() - 1].y };
    for r in &runs {
        let (n, y) = (u64::from(r.len()), u64::from(r.y));
        let (s1a, s2a) = sums(u64::from(r.x0));
        let (s1b, s2b) = sums(u64::from(r.x1));
        let (s1, s2) = (s1b - s1a, s2b - s2a);
        area += n;
        sx += s1;
        sy += y * n;
        sxx += s2;
        syy += y * y * n;
        sxy += y * s1;
        bbox.x0 = bbox.x0.min(r.x0);
        bbox.x1 = bbox.x1.max(r.x1 - 1);
        let row = &image.pixels[r.y as usize * w..][r.x0 as usize..r.x1 as usize];
        let mut row_sum = 0u64;
        for (x, &g) in (u64::from(r.x0)..).zip(row) {
            row_sum += u64::from(g);
            g_x += u64::from(g) * x;
            g_max = g_max.max(g);
        }
        g_sum += row_sum;
        g_y += row_sum * y;
    }
    let a = area as f64;
    let (cx, cy) = (sx as f64 / a, sy as f64 / a);
    // Central second moments; + 1/12 treats each pixel as a unit square,
    // which makes a rasterized ellipse report its true axes.
    let mu20 = sxx as f64 / a - cx * cx + 1.0 / 12.0;
    let mu02 = syy as f64 / a - cy * cy + 1.0 / 12.0;
    let mu11 = sxy as f64 / a - cx * cy;
    let half_sum = 0.5 * (mu20 + mu02);
    let root = (0.25 * (mu20 - mu02).powi(2) + mu11 * mu11).sqrt();
    let major = 2.0 * (half_sum + root).max(0.0).sqrt();
    let minor = 2.0 * (half_sum - root).max(0.0).sqrt();
    let mut angle = 0.5 * (2.0 * mu11).atan2(mu20 - mu02);
    if angle <= -std::f64::consts::FRAC_PI_2 {
        angle += std::f64::consts::PI;
    }
    let weighted_centroid = if g_sum > 0 {
        [(g_x as f64 / g_sum as f64) as f32, (g_y as f64 / g_sum as f64) as f32]
    } else {
        [cx as f32, cy as f32]
    };
    let contour = trace_contour(mask, [runs[0].x0 as i32, runs[0].y as i32]);
    // The hull of a blob is the hull of each row's two extreme pixels:
    // fewer points than the contour, so less to sort.
    let mut extremes: Vec<[i32; 2]> = Vec::with_capacity(2 * (bbox.y1 - bbox.y0 + 1) as usize);
    for row in runs.chunk_by(|a, b| a.y == b.y) {
        let y = row[0].y as i32;
        extremes.push([row[0].x0 as i32, y]);
        extremes.push([row[row.len() - 1].x1 as i32 - 1, y]);
    }
    let hull = convex_hull(&extremes);
    Blob {
        area: area as u32,
        centroid: [cx as f32, cy as f32],
        weighted_centroid,
        bbox,
        ellipse: Ellipse {
            centre: [cx as f32, cy as f32],
            semi_axes: [major as f32, minor as f32],
            angle: angle as f32,
        },
        mean_grey: (g_sum as f64 / a) as f32,
        max_grey: g_max,
        contour,
        hull,
        runs,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::vision::threshold::threshold;

    fn image(rows: &[&str]) -> ContactImage {
        let pixels = rows.iter().flat_map(|r| r.bytes().map(|b| if b == b'#' { 200 } else { 0 })).collect();
        ContactImage::from_pixels(rows[0].len(), rows.len(), pixels).expect("rectangular")
    }

    #[test]
    fn eight_connectivity_and_order() {
        let img = image(&["#....##", ".#...#.", "..#....", ".......", "##...#."]);
        let blobs = find_blobs(&img, &threshold(&img, 1), 1);
        let areas: Vec<u32> = blobs.iter().map(|b| b.area).collect();
        assert_eq!(areas, vec![3, 3, 2, 1]);
        assert_eq!(blobs[0].bbox, BBox { x0: 0, y0: 0, x1: 2, y1: 2 });
        assert!(blobs[0].contains(1, 1) && !blobs[0].contains(1, 0));
        assert_eq!(blobs[0].distance_within(4, 2, 2), Some(2));
        assert_eq!(find_blobs(&img, &threshold(&img, 1), 2).len(), 3);
    }

    #[test]
    fn u_shape_joins_late() {
        // The two arms only meet on the last row: union-find must join them.
        let img = image(&["#...#", "#...#", "#####"]);
        let blobs = find_blobs(&img, &threshold(&img, 1), 1);
        assert_eq!(blobs.len(), 1);
        assert_eq!(blobs[0].area, 9);
        assert_eq!(blobs[0].runs.len(), 5);
    }

    #[test]
    fn moments_of_a_bar() {
        let img = image(&[".........", ".#######.", "........."]);
        let b = &find_blobs(&img, &threshold(&img, 1), 1)[0];
        assert_eq!(b.centroid, [4.0, 1.0]);
        assert_eq!(b.weighted_centroid, [4.0, 1.0]);
        assert!(b.ellipse.angle.abs() < 1e-6);
        // A 7 x 1 bar: variance (49 - 1) / 12 + 1 / 12 = 49 / 12 along x.
        assert!((b.ellipse.semi_axes[0] - 2.0 * (49.0f32 / 12.0).sqrt()).abs() < 1e-4);
        assert_eq!(b.hull.len(), 2);
        assert_eq!((b.mean_grey, b.max_grey), (200.0, 200));
    }
}
