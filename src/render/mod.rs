//! The wgpu renderer: draws a [`DrawList`] into a window or an off-screen image.
//!
//! - [`GpuContext`] / [`probe_adapter`]: the GPU connection (headless by
//!   default, honouring `WGPU_BACKEND`), and what `doctor` reports.
//! - [`Renderer`]: long-lived pipelines; `prepare(&DrawList, size)` uploads a
//!   frame, `paint(encoder, view)` draws it into any view of its format.
//! - [`Capture`] / [`render_to_image`] / [`save_png`]: off-screen frames.
//! - `snapshot`: golden-image checks for tests; [`samples`]: shared scenes.
//!
//! Shaders live in `shaders/<pipeline>.wgsl`, each prefixed with
//! `shaders/frame.wgsl` (uniforms, shadow lookup, lighting).

mod bounds;
mod buffer;
mod camera;
mod capture;
mod contact_texture;
mod draw_list;
mod error;
mod frame;
mod gpu;
mod gpu_record;
mod instances;
mod light;
mod mesh;
mod mesh_library;
mod palette;
mod pipelines;
mod readback;
mod renderer;
pub mod samples;
mod shadow_map;
mod shadow_regions;
mod snapshot;
mod targets;
mod texture;
mod uniforms;

pub use camera::CameraMatrices;
pub use capture::{CAPTURE_FORMAT, Capture, render_to_image, save_png};
pub use draw_list::*;
pub use error::RenderError;
pub use gpu::{
    AdapterSummary, GpuContext, GpuError, INSTALL_HINT, preferred_surface_format, probe_adapter, request_adapter,
    request_device,
};
pub use instances::DOT_PER_LINE_WIDTH;
pub use palette::{FEEDBACK_RED, TARGET_RED, WAYPOINT_BLUE};
pub use readback::{Alpha, Readback, padded_bytes_per_row, readable};
pub use renderer::{Renderer, RendererOptions};
pub use snapshot::{SnapshotDir, Tolerance, compare};
pub use texture::texture_2d;
