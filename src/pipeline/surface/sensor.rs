//! The camera under the table: which table point each pixel of the contact
//! image sees.

use glam::Vec2;
use serde::{Deserialize, Serialize};

/// A newtype over `Vec2` for one kind of coordinate, so that the compiler
/// refuses one kind where another is meant.
macro_rules! coordinates {
    ($(#[$doc:meta])* $name:ident($a:ident, $b:ident)) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Default)]
        pub struct $name(pub Vec2);

        impl $name {
            pub const fn new($a: f32, $b: f32) -> $name {
                $name(Vec2::new($a, $b))
            }

            pub fn to_array(self) -> [f32; 2] {
                self.0.to_array()
            }
        }

        impl From<[f32; 2]> for $name {
            fn from(p: [f32; 2]) -> $name {
                $name(Vec2::from(p))
            }
        }

        impl From<Vec2> for $name {
            fn from(p: Vec2) -> $name {
                $name(p)
            }
        }

        impl From<$name> for Vec2 {
            fn from(p: $name) -> Vec2 {
                p.0
            }
        }
    };
}

coordinates!(
    /// A position in the contact image: `[column, row]`, integers at pixel
    /// centres (see [`Sensor`]).
    PixelPoint(column, row)
);

coordinates!(
    /// A point on the table, metres from its centre, x to the right and y
    /// away from the viewer (see [`Sensor`]).
    TablePoint(x, y)
);

coordinates!(
    /// A displacement or velocity in the contact image, pixels (per frame):
    /// columns grow to the right, rows downwards.
    PixelVector(columns, rows)
);

coordinates!(
    /// A displacement or velocity on the table, metres (per frame): x to the
    /// right, y away from the viewer.
    TableVector(x, y)
);

/// The mapping between contact-image pixels and table coordinates.
///
/// Table coordinates are metres with the table centred at the origin, x to
/// the right, y away from the viewer (the top of the screen). The contact
/// image covers the whole table: row 0 is the far edge (+y), column 0 the
/// left edge (-x).
///
/// Pixel positions are `[column, row]` with *integer values at pixel
/// centres*, the convention of every centroid, contour point and edge sample
/// that `vision` reports. Pixel `(c, r)` therefore maps to
/// `x = (c + 0.5) / W * width - width / 2`, `y = depth / 2 - (r + 0.5) / H * depth`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Sensor {
    /// Image width in pixels (columns).
    pub width_px: u32,
    /// Image height in pixels (rows).
    pub height_px: u32,
    /// Table extent along x, metres.
    pub table_width_m: f32,
    /// Table extent along y, metres.
    pub table_depth_m: f32,
}

impl Default for Sensor {
    /// 640 x 480 over a 1.0 x 0.75 m table: square pixels of 1.5625 mm.
    fn default() -> Self {
        Self::new(640, 480, 1.0, 0.75)
    }
}

impl Sensor {
    pub const fn new(width_px: u32, height_px: u32, table_width_m: f32, table_depth_m: f32) -> Self {
        Self { width_px, height_px, table_width_m, table_depth_m }
    }

    /// Pixel position (`[column, row]`, integers at pixel centres) to table
    /// metres. A table point where a pixel is meant does not compile:
    ///
    /// ```compile_fail
    /// use surfacelab::pipeline::surface::{Sensor, TablePoint};
    /// Sensor::default().to_table(TablePoint::new(0.1, 0.2));
    /// ```
    pub fn to_table(&self, px: PixelPoint) -> TablePoint {
        let [sx, sy] = self.pixel_size();
        let PixelPoint(Vec2 { x: c, y: r }) = px;
        TablePoint::new((c + 0.5) * sx - self.table_width_m * 0.5, self.table_depth_m * 0.5 - (r + 0.5) * sy)
    }

    /// Table metres to a (fractional) pixel position; the inverse of
    /// [`Sensor::to_table`]. Points off the table give positions outside the
    /// image: callers decide whether to clamp.
    pub fn to_pixel(&self, p: TablePoint) -> PixelPoint {
        let [sx, sy] = self.pixel_size();
        let TablePoint(Vec2 { x, y }) = p;
        PixelPoint::new((x + self.table_width_m * 0.5) / sx - 0.5, (self.table_depth_m * 0.5 - y) / sy - 0.5)
    }

    /// A displacement or velocity in pixels (rows grow downwards) to metres
    /// on the table (y grows away from the viewer). Angles measured in the
    /// image (from +column towards +row) change sign the same way.
    pub fn vector_to_table(&self, v: PixelVector) -> TableVector {
        let [sx, sy] = self.pixel_size();
        TableVector::new(v.0.x * sx, -v.0.y * sy)
    }

    /// A table displacement in metres to pixels; inverse of
    /// [`Sensor::vector_to_table`].
    pub fn vector_to_pixel(&self, v: TableVector) -> PixelVector {
        let [sx, sy] = self.pixel_size();
        PixelVector::new(v.0.x / sx, -v.0.y / sy)
    }

    /// Size of one pixel on the table along x and y, metres.
    pub fn pixel_size(&self) -> [f32; 2] {
        [self.table_width_m / self.width_px.max(1) as f32, self.table_depth_m / self.height_px.max(1) as f32]
    }

    /// Size of one pixel in metres, the mean of the x and y sizes (they are
    /// equal when the image and the table have the same aspect ratio, as in
    /// the default 4:3 set-up). Use it for lengths and radii.
    pub fn metres_per_pixel(&self) -> f32 {
        let [sx, sy] = self.pixel_size();
        0.5 * (sx + sy)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_and_centre_map_as_documented() {
        let s = Sensor::default();
        let first = s.to_table(PixelPoint::new(0.0, 0.0)).to_array();
        assert!((first[0] - (-0.5 + 0.000_781_25)).abs() < 1e-6);
        assert!((first[1] - (0.375 - 0.000_781_25)).abs() < 1e-6);
        // The table centre lies between the four middle pixels.
        let c = s.to_pixel(TablePoint::new(0.0, 0.0)).to_array();
        assert!((c[0] - 319.5).abs() < 1e-4 && (c[1] - 239.5).abs() < 1e-4);
        assert!((s.metres_per_pixel() - 0.001_562_5).abs() < 1e-9);
    }

    #[test]
    fn round_trip() {
        let s = Sensor::new(100, 50, 2.0, 0.5);
        for p in [[0.0, 0.0], [12.25, 3.5], [99.0, 49.0]] {
            let q = s.to_pixel(s.to_table(PixelPoint::from(p))).to_array();
            assert!((q[0] - p[0]).abs() < 1e-4 && (q[1] - p[1]).abs() < 1e-4);
        }
        // 2 cm by 1 cm pixels; rows grow downwards, table y away from the viewer.
        assert_eq!(s.vector_to_table(PixelVector::new(1.0, 1.0)), TableVector::new(0.02, -0.01));
        let v = s.vector_to_pixel(s.vector_to_table(PixelVector::new(3.0, -2.0))).to_array();
        assert!((v[0] - 3.0).abs() < 1e-5 && (v[1] + 2.0).abs() < 1e-5);
    }
}
