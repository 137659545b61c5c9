//! The input layer: every source of [`Hand`](crate::pipeline::surface::Hand)s
//! for the surface. Sources only describe where hands are; the surface turns
//! them into a contact image.
//!
//! - [`Mouse`]: a mouse (and its wheel and modifier keys) as one hand.
//! - [`tuio`]: TUIO 1.1 and 2.0 packets decoded into hands, and the UDP listener.
//! - [`Gesture`]: gesture files (recorded or written by hand) replayed frame by frame;
//!   [`GestureRecorder`] writes them.
//! - [`Input`]: the demo's sources merged into one list per physics step.
//! - [`images`]: recorded camera frames and their calibration, rectified into
//!   contact images (not hands: a camera sees the contact image itself).
//! - [`camera`]: a live V4L2 camera's frames, decoded and rectified the same way.
//! - [`CameraInput`]: either of the two, as a session's input.

pub mod camera;
mod camera_input;
mod gesture;
pub mod images;
mod mouse;
mod sources;
pub mod tuio;

pub use camera_input::CameraInput;
pub use gesture::{FORMAT, Gesture, GestureError, GestureRecorder, Key, Track, VERSION, quantized};
pub use mouse::{Button, DEGREES_PER_NOTCH, MAX_SPREAD, Modifiers, Mouse, MouseEvent, SPREAD_PER_NOTCH};
pub use sources::{Input, SCRIPT_ID_BASE, SourceEvent, TOUCH_ID_BASE};
