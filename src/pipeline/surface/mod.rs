//! The sensing surface: hands and tangibles on the table ([`Hand`], [`Footprint`],
//! [`Outline`]) drawn into the contact image a vision-based surface sees ([`ContactImage`],
//! [`rasterize_rows`]) through its camera ([`Sensor`]). Where hands come from
//! (mouse, TUIO, gesture files) is the input layer's business.

mod footprint;
mod hand;
mod image;
mod outline;
mod raster;
mod sensor;

pub use footprint::{Footprint, Patch, Prepared};
pub use hand::{Hand, HandKind, Pose};
pub use image::ContactImage;
pub use outline::{MAX_OUTLINE_POINTS, MIN_RING_POINTS, Outline, OutlineError};
pub use raster::{Noise, RasterParams, rasterize, rasterize_into, rasterize_patches, rasterize_rows};
pub use sensor::{PixelPoint, PixelVector, Sensor, TablePoint, TableVector};
