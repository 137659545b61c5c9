//! Golden-image checks for tests, in egui's style: the reference is
//! `DIR/NAME.png`; a failing run writes `NAME.new.png` (what was rendered) and
//! `NAME.diff.png` (where it differs) beside it, both git-ignored; running
//! with `UPDATE_SNAPSHOTS=1` accepts the new images as references.
//!
//! Needs no GPU: it compares images, so any test producing an image (the
//! renderer, plots, vision debug output) can use it.

use std::path::{Path, PathBuf};

use image::{Rgba, RgbaImage};

/// How different an image may be and still match.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// A pixel differs when any channel differs by more than this (0..=255).
    pub per_pixel: u8,
    /// The image differs when more than this share of its pixels (0..=1) do.
    pub max_differing_share: f64,
}

/// The outcome of comparing two images of equal size.
#[derive(Debug, Clone)]
pub struct Comparison {
    pub differing_pixels: usize,
    pub total_pixels: usize,
    /// Largest channel difference anywhere.
    pub max_channel_delta: u8,
    /// Differing pixels in red (brighter = larger difference), the rest a
    /// faded grey copy of the reference.
    pub diff_image: RgbaImage,
}

impl Comparison {
    pub fn differing_share(&self) -> f64 {
        self.differing_pixels as f64 / self.total_pixels.max(1) as f64
    }
}

/// Compares images of the same size (see [`Tolerance::per_pixel`]).
pub fn compare(reference: &RgbaImage, actual: &RgbaImage, per_pixel: u8) -> Comparison {
    assert_eq!(reference.dimensions(), actual.dimensions(), "compare needs images of one size");
    let mut diff_image = RgbaImage::new(reference.width(), reference.height());
    let mut differing_pixels = 0;
    let mut max_channel_delta = 0;
    for ((r, a), d) in reference.pixels().zip(actual.pixels()).zip(diff_image.pixels_mut()) {
        let delta = r.0.iter().zip(a.0).map(|(x, y)| x.abs_diff(y)).max().unwrap_or(0);
        max_channel_delta = max_channel_delta.max(delta);
        if delta > per_pixel {
            differing_pixels += 1;
            *d = Rgba([128 + delta / 2, 0, 0, 255]);
        } else {
            let grey = ((u16::from(r[0]) + u16::from(r[1]) + u16::from(r[2])) / 3) as u8;
            let faded = 160 + grey / 4;
            *d = Rgba([faded, faded, faded, 255]);
        }
    }
    Comparison { differing_pixels, total_pixels: reference.pixels().len(), max_channel_delta, diff_image }
}

/// A folder of reference images.
#[derive(Debug, Clone)]
pub struct SnapshotDir {
    dir: PathBuf,
}

/// Why a snapshot did not match; the message says which files to look at.
#[derive(Debug, thiserror::Error)]
pub enum SnapshotError {
    #[error("snapshot {name}: no reference image {}; wrote {}; run with UPDATE_SNAPSHOTS=1 to accept it", reference.display(), new.display())]
    Missing { name: String, reference: PathBuf, new: PathBuf },
    #[error("snapshot {name}: size {actual:?} differs from the reference's {expected:?}; wrote {}", new.display())]
    Size { name: String, expected: (u32, u32), actual: (u32, u32), new: PathBuf },
    #[error(
        "snapshot {name}: {differing} of {total} pixels ({share:.3}%) differ by more than {per_pixel} \
         (max {max_delta}); allowed {allowed:.3}%; see {} and {}; run with UPDATE_SNAPSHOTS=1 to accept",
        new.display(), diff.display(), share = 100.0 * *differing as f64 / *total as f64,
        allowed = 100.0 * allowed_share
    )]
    Differs {
        name: String,
        differing: usize,
        total: usize,
        per_pixel: u8,
        max_delta: u8,
        allowed_share: f64,
        new: PathBuf,
        diff: PathBuf,
    },
    #[error("snapshot {name}: {what} {}", path.display())]
    Io {
        name: String,
        what: &'static str,
        path: PathBuf,
        #[source]
        source: Box<image::ImageError>,
    },
}

/// True when `UPDATE_SNAPSHOTS` is set to anything but empty, `0` or `false`.
pub fn update_requested() -> bool {
    std::env::var("UPDATE_SNAPSHOTS").is_ok_and(|v| !matches!(v.as_str(), "" | "0" | "false"))
}

impl SnapshotDir {
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        Self { dir: dir.into() }
    }

    pub fn reference_path(&self, name: &str) -> PathBuf {
        self.dir.join(format!("{name}.png"))
    }

    pub fn new_path(&self, name: &str) -> PathBuf {
        self.dir.join(format!("{name}.new.png"))
    }

    pub fn diff_path(&self, name: &str) -> PathBuf {
        self.dir.join(format!("{name}.diff.png"))
    }

    /// Checks `image` against the reference `name` (or records it when
    /// `UPDATE_SNAPSHOTS` is set). On success stale `.new`/`.diff` files go.
    pub fn check(&self, name: &str, image: &RgbaImage, tolerance: Tolerance) -> Result<(), SnapshotError> {
        let reference_path = self.reference_path(name);
        let (new, diff) = (self.new_path(name), self.diff_path(name));
        let save = |img: &RgbaImage, path: &Path, what| {
            if let Some(parent) = path.parent() {
                // Reported by the save below if it failed.
                let _ = std::fs::create_dir_all(parent);
            }
            img.save_with_format(path, image::ImageFormat::Png).map_err(|source| SnapshotError::Io {
                name: name.to_owned(),
                what,
                path: path.to_path_buf(),
                source: Box::new(source),
            })
        };
        let clean = || {
            // Absent files are the normal case.
            let _ = std::fs::remove_file(&new);
            let _ = std::fs::remove_file(&diff);
        };
        if update_requested() {
            save(image, &reference_path, "writing reference")?;
            clean();
            return Ok(());
        }
        if !reference_path.exists() {
            save(image, &new, "writing")?;
            return Err(SnapshotError::Missing { name: name.to_owned(), reference: reference_path, new });
        }
        let reference = image::open(&reference_path)
            .map_err(|source| SnapshotError::Io {
                name: name.to_owned(),
                what: "reading reference",
                path: reference_path.clone(),
                source: Box::new(source),
            })?
            .to_rgba8();
        if reference.dimensions() != image.dimensions() {
            save(image, &new, "writing")?;
            return Err(SnapshotError::Size {
                name: name.to_owned(),
                expected: reference.dimensions(),
                actual: image.dimensions(),
                new,
            });
        }
        let comparison = compare(&reference, image, tolerance.per_pixel);
        if comparison.differing_share() > tolerance.max_differing_share {
            save(image, &new, "writing")?;
            save(&comparison.diff_image, &diff, "writing")?;
            return Err(SnapshotError::Differs {
                name: name.to_owned(),
                differing: comparison.differing_pixels,
                total: comparison.total_pixels,
                per_pixel: tolerance.per_pixel,
                max_delta: comparison.max_channel_delta,
                allowed_share: tolerance.max_differing_share,
                new,
                diff,
            });
        }
        clean();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compare_counts_pixels_beyond_the_threshold() {
        let a = RgbaImage::from_pixel(4, 2, Rgba([100, 100, 100, 255]));
        let mut b = a.clone();
        b.put_pixel(0, 0, Rgba([103, 100, 100, 255]));
        b.put_pixel(1, 0, Rgba([100, 120, 100, 255]));
        let c = compare(&a, &b, 3);
        assert_eq!(c.differing_pixels, 1);
        assert_eq!(c.max_channel_delta, 20);
        assert_eq!(c.diff_image.get_pixel(1, 0)[0], 138);
        assert!((c.differing_share() - 0.125).abs() < 1e-12);
    }

    #[test]
    fn check_writes_new_and_diff_on_mismatch() {
        let dir = std::env::temp_dir().join(format!("surfacelab-snapshot-{}", std::process::id()));
        let snapshots = SnapshotDir::new(&dir);
        let a = RgbaImage::from_pixel(8, 8, Rgba([10, 20, 30, 255]));
        let tolerance = Tolerance { per_pixel: 2, max_differing_share: 0.0 };
        if update_requested() {
            return; // The environment would turn every check into an update.
        }
        assert!(matches!(snapshots.check("a", &a, tolerance), Err(SnapshotError::Missing { .. })));
        assert!(snapshots.new_path("a").exists());
        std::fs::rename(snapshots.new_path("a"), snapshots.reference_path("a")).expect("rename");
        snapshots.check("a", &a, tolerance).expect("identical image matches");
        let mut b = a.clone();
        b.put_pixel(3, 3, Rgba([200, 20, 30, 255]));
        assert!(matches!(snapshots.check("a", &b, tolerance), Err(SnapshotError::Differs { .. })));
        assert!(snapshots.new_path("a").exists() && snapshots.diff_path("a").exists());
        snapshots
            .check("a", &b, Tolerance { per_pixel: 2, max_differing_share: 0.02 })
            .expect("one pixel in 64 is within 2%");
        assert!(!snapshots.new_path("a").exists(), "a passing check removes stale outputs");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
