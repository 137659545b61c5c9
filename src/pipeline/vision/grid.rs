//! A uniform grid over bounding boxes: which boxes may meet a given area.
//!
//! Tracking and Sobel compare every contact with every other only through
//! this index, so a frame of speckle with thousands of blobs (a sensor whose
//! noise crosses the threshold) costs time proportional to the blobs, not
//! to their square.

/// Boxes `[x0, y0, x1, y1]` (inclusive pixels) filed by the grid cells they
/// cover.
#[derive(Debug, Clone, Default)]
pub struct BoxGrid {
    cell: i64,
    cols: i64,
    rows: i64,
    cells: Vec<Vec<u32>>,
}

/// Side of a grid cell, pixels: about a fingertip, so a cell holds few
/// contacts and a hand covers few cells.
const CELL: i64 = 32;

impl BoxGrid {
    /// Files `boxes` (index = position in the slice). Negative coordinates
    /// are clamped to cell 0 and everything beyond the largest box to the
    /// last cell, so any query area is valid.
    pub fn new(boxes: &[[i64; 4]]) -> Self {
        let max_x = boxes.iter().map(|b| b[2]).max().unwrap_or(0).max(0);
        let max_y = boxes.iter().map(|b| b[3]).max().unwrap_or(0).max(0);
        let (cols, rows) = (max_x / CELL + 1, max_y / CELL + 1);
        let mut grid = Self { cell: CELL, cols, rows, cells: vec![Vec::new(); (cols * rows) as usize] };
        for (i, b) in boxes.iter().enumerate() {
            let [c0, r0, c1, r1] = grid.span(*b);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    grid.cells[(r * cols + c) as usize].push(i as u32);
                }
            }
        }
        grid
    }

    /// Cell range `[c0, r0, c1, r1]` covered by `area`.
    fn span(&self, area: [i64; 4]) -> [i64; 4] {
        let col = |x: i64| (x.max(0) / self.cell).min(self.cols - 1);
        let row = |y: i64| (y.max(0) / self.cell).min(self.rows - 1);
        [col(area[0]), row(area[1]), col(area[2].max(area[0])), row(area[3].max(area[1]))]
    }

    /// Indices of the boxes filed in the cells `area` covers, each once, in
    /// increasing order: a superset of the boxes that meet `area`.
    pub fn query(&self, area: [i64; 4], out: &mut Vec<u32>) {
        out.clear();
        if self.cells.is_empty() {
            return;
        }
        let [c0, r0, c1, r1] = self.span(area);
        for r in r0..=r1 {
            for c in c0..=c1 {
                out.extend_from_slice(&self.cells[(r * self.cols + c) as usize]);
            }
        }
        out.sort_unstable();
        out.dedup();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_boxes_near_an_area_once() {
        let boxes = [[0, 0, 10, 10], [100, 100, 300, 120], [40, 0, 41, 1]];
        let grid = BoxGrid::new(&boxes);
        let mut out = Vec::new();
        grid.query([5, 5, 6, 6], &mut out);
        assert_eq!(out, vec![0]);
        grid.query([0, 0, 1000, 1000], &mut out);
        assert_eq!(out, vec![0, 1, 2]);
        grid.query([-50, -50, -1, -1], &mut out);
        assert_eq!(out, vec![0]);
        BoxGrid::new(&[]).query([0, 0, 1, 1], &mut out);
        assert!(out.is_empty());
    }
}
