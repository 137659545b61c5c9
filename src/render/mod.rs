//! The wgpu renderer: draws a [`DrawList`] into a window or an off-screen image.
//!
//! - [`GpuContext`] / [`probe_adapter`]: the GPU connection (headless by
//!   default, honouring `WGPU_BACKEND`), and what `doctor` reports.
//! - [`Renderer`]: long-lived pipelines; `prepare(&DrawList, size)` uploads a
//!   frame, `paint(encoder, view)` draws it into any view of its format.
//! - [`Capture`] / [`render_to_image`] / [`save_png`]: off-screen frames.
//! - [`snapshot`]: golden-image checks for tests; [`samples`]: shared scenes.
//!
//! Shaders live in `shaders/<pipeline>.wgsl`, each prefixed with
//! `shaders/frame.wgsl` (uniforms, shadow lookup, lighting).

pub mod bounds;
mod buffer;
pub mod camera;
pub mod capture;
mod contact_texture;
pub mod draw_list;
pub mod error;
mod frame;
pub mod gpu;
mod instances;
pub mod light;
pub mod mesh;
mod mesh_library;
pub mod palette;
mod pipelines;
mod readback;
pub mod renderer;
pub mod samples;
mod shadow_map;
pub mod snapshot;
mod targets;
mod uniforms;

pub use camera::CameraMatrices;
pub use capture::{CAPTURE_FORMAT, Capture, render_to_image, save_png};
pub use readback::{Alpha, Readback, padded_bytes_per_row, readable};
pub use draw_list::*;
pub use error::RenderError;
pub use gpu::{
    AdapterSummary, GpuContext, GpuError, INSTALL_HINT, preferred_surface_format, probe_adapter, request_adapter,
    request_device,
};
pub use instances::DOT_PER_LINE_WIDTH;
pub use renderer::{Renderer, RendererOptions};
