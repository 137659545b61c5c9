//! The contact image: what the camera under the table sees.

/// An 8-bit grey image, row-major, row 0 at the far edge of the table (see
/// [`super::Sensor`]). Bright means touching; the grey level of a touch
/// grows with its pressure; 0 is empty glass.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ContactImage {
    pub width: usize,
    pub height: usize,
    /// `width * height` grey levels, row after row.
    pub pixels: Vec<u8>,
}

impl ContactImage {
    /// An all-black (untouched) image.
    pub fn new(width: usize, height: usize) -> Self {
        Self { width, height, pixels: vec![0; width * height] }
    }

    /// Wraps existing pixels; `None` when their count is not `width * height`.
    pub fn from_pixels(width: usize, height: usize, pixels: Vec<u8>) -> Option<Self> {
        (pixels.len() == width * height).then_some(Self { width, height, pixels })
    }

    /// The grey level at column `x`, row `y`; 0 outside the image, so
    /// neighbourhood code needs no special case at the border.
    pub fn get(&self, x: i32, y: i32) -> u8 {
        if x < 0 || y < 0 || x as usize >= self.width || y as usize >= self.height {
            0
        } else {
            self.pixels[y as usize * self.width + x as usize]
        }
    }

    /// Row `y` as a slice.
    pub fn row(&self, y: usize) -> &[u8] {
        &self.pixels[y * self.width..(y + 1) * self.width]
    }

    /// Sets every pixel back to 0, keeping the allocation.
    pub fn clear(&mut self) {
        self.pixels.fill(0);
    }

    /// True when no pixel is lit.
    pub fn is_blank(&self) -> bool {
        self.pixels.iter().all(|&p| p == 0)
    }
}
