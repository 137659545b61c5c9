//! A window's GPU surface, as both of the app's windows (the demo and
//! `calibrate`'s point picker) set it up: an adapter that can present to
//! the window, its device, the surface format egui draws into, and egui
//! for the window.

use crate::render::{GpuContext, preferred_surface_format, request_adapter, request_device};
use anyhow::{Context, anyhow};
use std::sync::Arc;
use winit::event_loop::ActiveEventLoop;
use winit::window::Window;

/// The display a window opens on, for error messages: `WAYLAND_DISPLAY`,
/// else `DISPLAY`, an empty variable counting as unset (as winit treats
/// it), else "".
pub fn display_name() -> String {
    let set = |name: &str| std::env::var(name).ok().filter(|v| !v.is_empty());
    set("WAYLAND_DISPLAY").or_else(|| set("DISPLAY")).unwrap_or_default()
}

/// The GPU, the window's surface and what it can do.
pub struct WindowSurface {
    pub gpu: GpuContext,
    pub surface: wgpu::Surface<'static>,
    pub caps: wgpu::SurfaceCapabilities,
    /// A plain 8-bit format where offered: egui draws sRGB-encoded values,
    /// so such a surface shows them as they are (on lavapipe the per-pixel
    /// conversion of an sRGB surface costs a large share of the frame,
    /// `scripts/demo-fps.sh`).
    pub format: wgpu::TextureFormat,
}

impl WindowSurface {
    pub fn new(event_loop: &ActiveEventLoop, window: &Arc<Window>) -> anyhow::Result<WindowSurface> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_with_display_handle_from_env(Box::new(
            event_loop.owned_display_handle(),
        )));
        let surface =
            instance.create_surface(Arc::clone(window)).context("cannot create a GPU surface for the window")?;
        let adapter = pollster::block_on(request_adapter(&instance, Some(&surface)))?;
        let (device, queue) = pollster::block_on(request_device(&adapter))?;
        let gpu = GpuContext::from_parts(instance, adapter, device, queue);
        let caps = surface.get_capabilities(&gpu.adapter);
        let format = caps
            .formats
            .iter()
            .copied()
            .find(|f| matches!(f, wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Rgba8Unorm))
            .or_else(|| preferred_surface_format(&caps.formats))
            .ok_or_else(|| anyhow!("the adapter {} cannot present to this window", gpu.summary()))?;
        Ok(WindowSurface { gpu, surface, caps, format })
    }

    /// A configuration of a surface with `caps` in `format` for `size`
    /// pixels with `usage`, paced by vsync.
    pub fn config_for(
        caps: &wgpu::SurfaceCapabilities,
        format: wgpu::TextureFormat,
        usage: wgpu::TextureUsages,
        size: [u32; 2],
    ) -> wgpu::SurfaceConfiguration {
        wgpu::SurfaceConfiguration {
            usage,
            format,
            color_space: wgpu::SurfaceColorSpace::Auto,
            width: size[0].max(1),
            height: size[1].max(1),
            present_mode: wgpu::PresentMode::AutoVsync,
            desired_maximum_frame_latency: 2,
            alpha_mode: caps.alpha_modes.first().copied().unwrap_or(wgpu::CompositeAlphaMode::Auto),
            view_formats: vec![],
        }
    }
}

/// egui for `window` on `device`: a dark context and its winit state at
/// the window's scale, no texture larger than the device takes.
pub fn window_egui(window: &Window, device: &wgpu::Device) -> (egui::Context, egui_winit::State) {
    let egui = egui::Context::default();
    egui.set_theme(egui::Theme::Dark);
    let max_side = device.limits().max_texture_dimension_2d as usize;
    let scale = window.scale_factor() as f32;
    let state = egui_winit::State::new(egui.clone(), egui::ViewportId::ROOT, window, Some(scale), None, Some(max_side));
    (egui, state)
}
