//! The desktop demo: a window with the live table and a side panel, for a
//! researcher trying the techniques and for a participant doing trials. It
//! only wires library pieces together: [`crate::session`] runs the
//! pipeline, [`crate::render`] draws it, [`crate::input::Mouse`] and
//! [`crate::input::tuio`] turn input into hands, the gesture recorder and
//! the study's row types write files.
//!
//! - `window`: winit, wgpu and egui; the frame loop.
//! - `lab`: the state the window shows and the panel changes.
//! - `clock`: the fixed physics timestep, independent of the frame rate.
//! - `panel` / `view`: the side panel; the table view and its overlays.
//! - `input`: mouse, touch, TUIO and scripted hands merged; `tuio`: the UDP listener.
//! - `record`: gesture recording; `participant`: study trials and their rows.
//! - `point_picker`: `calibrate`'s window, four clicks on a camera frame.

mod clock;
mod lab;
mod options;
mod panel;
mod participant_mode;
mod point_picker;
mod record;
mod scene_view;
mod stats;
mod ui_cache;
mod view;
mod window;
mod window_surface;

pub use options::{DEFAULT_WINDOW, DemoOptions, Screenshot};
pub use participant_mode::ParticipantOptions;
pub use point_picker::pick_points;
pub use record::Recording;
pub use scene_view::{ViewOptions, draw_list, fitted_draw_list, scene_camera};
pub use window::run;
