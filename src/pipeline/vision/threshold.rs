//! Thresholding: which pixels count as touching.

use crate::pipeline::surface::ContactImage;
use std::ops::Range;

/// A binary image the size of the contact image: 1 where touching, 0 not.
/// Bytes rather than bits: the run scan in `components` reads eight of them
/// per step as one `u64`, which is faster than unpacking bits and keeps the
/// mask trivially viewable.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Mask {
    pub width: usize,
    pub height: usize,
    pub bits: Vec<u8>,
}

impl Mask {
    /// True when `(x, y)` is inside the image and set.
    pub fn get(&self, x: i32, y: i32) -> bool {
        x >= 0
            && y >= 0
            && (x as usize) < self.width
            && (y as usize) < self.height
            && self.bits[y as usize * self.width + x as usize] != 0
    }

    /// Number of set pixels.
    pub fn count(&self) -> usize {
        self.bits.iter().filter(|&&b| b != 0).count()
    }
}

/// Pixels with grey `>= level` are set. Level 0 sets every pixel.
pub fn threshold(image: &ContactImage, level: u8) -> Mask {
    let mut mask = Mask::default();
    threshold_into(image, level, &mut mask);
    mask
}

/// Like [`threshold`], reusing `mask`'s allocation.
pub fn threshold_into(image: &ContactImage, level: u8, mask: &mut Mask) {
    mask.width = image.width;
    mask.height = image.height;
    mask.bits.clear();
    mask.bits.extend(image.pixels.iter().map(|&p| u8::from(p >= level)));
}

/// Like [`threshold_into`] for a `mask` already made from a frame of the
/// same size that differed from `image` only in `rows`: only those rows
/// are thresholded again. Falls back to the whole image when the sizes
/// differ or `level` is 0 (which sets every pixel).
pub fn threshold_rows(image: &ContactImage, level: u8, mask: &mut Mask, rows: Range<usize>) {
    let w = image.width;
    if level == 0 || mask.width != w || mask.height != image.height || mask.bits.len() != image.pixels.len() {
        threshold_into(image, level, mask);
        return;
    }
    let (r0, r1) = (rows.start.min(image.height), rows.end.min(image.height));
    if r0 >= r1 {
        return;
    }
    for (m, &p) in mask.bits[r0 * w..r1 * w].iter_mut().zip(&image.pixels[r0 * w..r1 * w]) {
        *m = u8::from(p >= level);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn level_is_inclusive() {
        let image = ContactImage::from_pixels(4, 1, vec![0, 9, 10, 255]).expect("4 pixels");
        assert_eq!(threshold(&image, 10).bits, vec![0, 0, 1, 1]);
        assert_eq!(threshold(&image, 0).count(), 4);
        assert!(threshold(&image, 10).get(3, 0) && !threshold(&image, 10).get(4, 0));
    }
}
