//! A live camera as input: a vision-based table's infrared camera or a
//! depth camera above the table, captured through V4L2, decoded to grey,
//! and rectified into the contact image like recorded frames
//! ([`crate::input::images`]).
//!
//! ```text
//! /dev/videoN ─▶ V4lCamera ─▶ bytes ─▶ decode (PixelFormat) ─▶ CameraImage ─▶ capture thread ─▶ CameraFeed ─▶ ContactImage
//! ```
//!
//! Only `V4lCamera` touches the device, and it needs the `camera` cargo
//! feature (the `v4l` crate's bindings are generated with libclang at
//! build time). Everything after the bytes is built and tested in every
//! build, with recorded frames standing in for the device
//! ([`FrameGrabber`]).

mod capture;
#[cfg(feature = "camera")]
mod device;
mod error;
mod feed;
mod pixel_format;

pub use capture::{CameraSource, ChannelCamera, Delivery, FrameGrabber, QUEUE_FRAMES};
#[cfg(feature = "camera")]
pub use device::V4lCamera;
pub use error::CameraError;
pub use feed::{CameraFeed, fits, whole_view};
pub use pixel_format::{PixelFormat, RawFormat, decode, describe, encode};
