//! Synthetic touch input: hands and tangibles on the table, drawn into the contact image a vision-based surface sees.

mod gesture;
mod hand;
mod image;
mod mouse;
mod raster;
mod sensor;
mod shape;
pub mod tuio;

pub use gesture::{FORMAT, Gesture, GestureError, GestureRecorder, Key, Track, VERSION};
pub use hand::{Hand, HandKind, Pose};
pub use image::ContactImage;
pub use mouse::{Button, DEGREES_PER_NOTCH, MAX_SPREAD, Modifiers, Mouse, MouseEvent, SPREAD_PER_NOTCH};
pub use raster::{Noise, RasterParams, rasterize, rasterize_into, rasterize_patches, rasterize_rows};
pub use sensor::Sensor;
pub use shape::{Patch, Prepared, Shape};
