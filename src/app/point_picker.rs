//! `calibrate`'s window: a camera frame shown whole, and four clicks where
//! the table's four points appear in it, in order. Backspace (or a right
//! click) takes the last point back, Enter accepts the four, Escape or
//! closing the window gives up.
//!
//! A click means the camera pixel under the pointer: the pointer's
//! physical pixel centre carried into the frame's pixel coordinates
//! (integers at pixel centres, as the calibration file has them), so at one
//! screen pixel per camera pixel a click on pixel (x, y) gives exactly
//! (x, y).

use super::window_surface::{WindowSurface, window_egui};
use crate::input::images::{CameraImage, Pixels};
use crate::render::GpuContext;
use anyhow::{Context, anyhow};
use std::sync::Arc;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

/// The window is the frame's size, or smaller to fit this on screen.
const MAX_WINDOW: [u32; 2] = [1280, 800];

/// Shows `frame` in a window titled `title` and returns the four image
/// points clicked, in the order of `names` (what each point is, for the
/// prompt), or `None` if the user gave up.
pub fn pick_points(frame: &CameraImage, names: [&str; 4], title: &str) -> anyhow::Result<Option<[[f64; 2]; 4]>> {
    let display = super::window_surface::display_name();
    let event_loop = EventLoop::new().map_err(|e| {
        anyhow!("cannot open a window on display {display:?}: {e}; give the points with --points instead")
    })?;
    let mut picker = Picker {
        frame: [frame.width, frame.height],
        grey: display_grey(frame),
        names: names.map(str::to_owned),
        title: title.to_owned(),
        points: Vec::new(),
        outcome: None,
        gfx: None,
        error: None,
    };
    event_loop.run_app(&mut picker).context("the calibration window's event loop failed")?;
    if let Some(e) = picker.error {
        return Err(e);
    }
    Ok(match picker.outcome {
        Some(Outcome::Accepted) => picker.points.try_into().ok(),
        _ => None,
    })
}

/// A frame's levels as 8-bit grey to look at: 8-bit frames as they are;
/// 16-bit depth stretched so the nearest reading is white and the farthest
/// black (no reading stays black), which shows the table's edges.
pub fn display_grey(frame: &CameraImage) -> Vec<u8> {
    match &frame.pixels {
        Pixels::Grey8(p) => p.clone(),
        Pixels::Grey16(p) => {
            let valid = p.iter().copied().filter(|&d| d > 0);
            let (lo, hi) = valid.fold((u16::MAX, 0), |(lo, hi), d| (lo.min(d), hi.max(d)));
            let span = f32::from(hi.saturating_sub(lo)).max(1.0);
            p.iter().map(|&d| if d == 0 { 0 } else { (255.0 * f32::from(hi - d) / span).round() as u8 }).collect()
        }
    }
}

/// Where a frame of `frame` pixels is drawn in an area of `area` points:
/// as large as fits, its aspect kept, centred.
pub fn fitted(area: egui::Rect, frame: [u32; 2]) -> egui::Rect {
    let (fw, fh) = (frame[0] as f32, frame[1] as f32);
    let scale = (area.width() / fw).min(area.height() / fh);
    egui::Rect::from_center_size(area.center(), egui::vec2(fw * scale, fh * scale))
}

/// The frame pixel under a pointer at `pointer` points, with the frame
/// drawn in `shown` and `pixels_per_point` screen pixels a point: the
/// pointer's pixel centre (half a screen pixel in), in frame pixels whose
/// integers are pixel centres.
pub fn frame_point(pointer: egui::Pos2, pixels_per_point: f32, shown: egui::Rect, frame: [u32; 2]) -> [f64; 2] {
    let half = 0.5 / pixels_per_point;
    let to = |p: f32, min: f32, size: f32, n: u32| -0.5 + f64::from(p + half - min) * f64::from(n) / f64::from(size);
    [to(pointer.x, shown.min.x, shown.width(), frame[0]), to(pointer.y, shown.min.y, shown.height(), frame[1])]
}

/// The inverse of [`frame_point`] without the half pixel: where a frame
/// point is drawn, in points.
fn shown_at(p: [f64; 2], shown: egui::Rect, frame: [u32; 2]) -> egui::Pos2 {
    let to = |v: f64, min: f32, size: f32, n: u32| min + ((v + 0.5) * f64::from(size) / f64::from(n)) as f32;
    egui::pos2(to(p[0], shown.min.x, shown.width(), frame[0]), to(p[1], shown.min.y, shown.height(), frame[1]))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Outcome {
    Accepted,
    GaveUp,
}

struct Picker {
    frame: [u32; 2],
    grey: Vec<u8>,
    names: [String; 4],
    title: String,
    points: Vec<[f64; 2]>,
    outcome: Option<Outcome>,
    gfx: Option<Gfx>,
    error: Option<anyhow::Error>,
}

struct Gfx {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    device: wgpu::Device,
    queue: wgpu::Queue,
    egui: egui::Context,
    state: egui_winit::State,
    renderer: egui_wgpu::Renderer,
    texture: Option<egui::TextureHandle>,
}

impl Picker {
    fn create_gfx(&self, event_loop: &ActiveEventLoop) -> anyhow::Result<Gfx> {
        let [fw, fh] = self.frame;
        let scale = (f64::from(MAX_WINDOW[0]) / f64::from(fw)).min(f64::from(MAX_WINDOW[1]) / f64::from(fh)).min(1.0);
        let size = PhysicalSize::new((f64::from(fw) * scale).round() as u32, (f64::from(fh) * scale).round() as u32);
        let attributes = Window::default_attributes().with_title(self.title.clone()).with_inner_size(size);
        let window = Arc::new(event_loop.create_window(attributes).context("cannot create the calibration window")?);
        let WindowSurface { gpu, surface, caps, format } = WindowSurface::new(event_loop, &window)?;
        let inner = window.inner_size();
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let config = WindowSurface::config_for(&caps, format, usage, [inner.width, inner.height]);
        let GpuContext { device, queue, .. } = gpu;
        surface.configure(&device, &config);
        let (egui, state) = window_egui(&window, &device);
        let renderer = egui_wgpu::Renderer::new(&device, format, egui_wgpu::RendererOptions::default());
        Ok(Gfx { window, surface, config, device, queue, egui, state, renderer, texture: None })
    }

    /// The prompt over the frame.
    fn prompt(&self) -> String {
        match self.points.len() {
            n @ 0..4 => format!(
                "Click the {} ({} of 4). Backspace or right click: take the last back. Esc: give up.",
                self.names[n],
                n + 1
            ),
            _ => "Enter: write the calibration. Backspace or right click: take the last back. Esc: give up.".into(),
        }
    }

    fn key(&mut self, key: &Key) {
        match key {
            Key::Named(NamedKey::Enter) if self.points.len() == 4 => self.outcome = Some(Outcome::Accepted),
            Key::Named(NamedKey::Backspace) => {
                self.points.pop();
            }
            Key::Named(NamedKey::Escape) => self.outcome = Some(Outcome::GaveUp),
            _ => {}
        }
    }

    fn frame(&mut self) -> anyhow::Result<()> {
        let prompt = self.prompt();
        let Some(gfx) = self.gfx.as_mut() else {
            return Ok(());
        };
        let raw = gfx.state.take_egui_input(&gfx.window);
        let (frame, grey, names) = (self.frame, &self.grey, &self.names);
        let points = &mut self.points;
        let texture = &mut gfx.texture;
        let output = gfx.egui.run_ui(raw, |ui| {
            let ctx = ui.ctx().clone();
            let handle = texture.get_or_insert_with(|| {
                let size = [frame[0] as usize, frame[1] as usize];
                let image = egui::ColorImage::from_gray(size, grey);
                ctx.load_texture("frame", image, egui::TextureOptions::NEAREST)
            });
            egui::CentralPanel::default().frame(egui::Frame::NONE.fill(egui::Color32::BLACK)).show(ui, |ui| {
                let shown = fitted(ui.max_rect(), frame);
                let response = ui.allocate_rect(shown, egui::Sense::click());
                let painter = ui.painter();
                let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
                painter.image(handle.id(), shown, uv, egui::Color32::WHITE);
                let ppp = ctx.pixels_per_point();
                if response.clicked()
                    && points.len() < 4
                    && let Some(p) = response.interact_pointer_pos()
                {
                    points.push(frame_point(p, ppp, shown, frame));
                }
                if response.secondary_clicked() {
                    points.pop();
                }
                draw_markers(painter, points, names, shown, frame);
                let banner = egui::Rect::from_min_size(ui.max_rect().min, egui::vec2(ui.max_rect().width(), 24.0));
                painter.rect_filled(banner, 0.0, egui::Color32::from_black_alpha(190));
                painter.text(
                    banner.left_center() + egui::vec2(8.0, 0.0),
                    egui::Align2::LEFT_CENTER,
                    &prompt,
                    egui::FontId::proportional(14.0),
                    egui::Color32::WHITE,
                );
            });
        });
        gfx.state.handle_platform_output(&gfx.window, output.platform_output);
        let ppp = output.pixels_per_point;
        let primitives = gfx.egui.tessellate(output.shapes, ppp);
        for (id, deltas) in &output.textures_delta.set {
            for delta in deltas {
                gfx.renderer.update_texture(&gfx.device, &gfx.queue, *id, delta);
            }
        }
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [gfx.config.width, gfx.config.height],
            pixels_per_point: ppp,
        };
        let surface_texture = match gfx.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f) | wgpu::CurrentSurfaceTexture::Suboptimal(f) => f,
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => return Ok(()),
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                gfx.surface.configure(&gfx.device, &gfx.config);
                return Ok(());
            }
            wgpu::CurrentSurfaceTexture::Validation => anyhow::bail!("the window surface reported a validation error"),
        };
        let mut encoder =
            gfx.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("calibrate") });
        let commands = gfx.renderer.update_buffers(&gfx.device, &gfx.queue, &mut encoder, &primitives, &screen);
        let view = surface_texture.texture.create_view(&wgpu::TextureViewDescriptor::default());
        {
            let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("calibrate"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            gfx.renderer.render(&mut pass.forget_lifetime(), &primitives, &screen);
        }
        gfx.queue.submit(commands.into_iter().chain(std::iter::once(encoder.finish())));
        gfx.window.pre_present_notify();
        gfx.queue.present(surface_texture);
        for id in &output.textures_delta.free {
            gfx.renderer.free_texture(id);
        }
        Ok(())
    }
}

/// The clicked points on the shown frame: a cross and a circle each, a
/// label pointing into the frame, and the ring through them.
fn draw_markers(painter: &egui::Painter, points: &[[f64; 2]], names: &[String; 4], shown: egui::Rect, frame: [u32; 2]) {
    let marker = egui::Color32::from_rgb(255, 64, 160);
    let corners: Vec<egui::Pos2> = points.iter().map(|p| shown_at(*p, shown, frame)).collect();
    if corners.len() > 1 {
        let mut ring = corners.clone();
        if corners.len() == 4 {
            ring.push(corners[0]);
        }
        painter.add(egui::Shape::line(ring, egui::Stroke::new(1.5, marker)));
    }
    for (i, (c, name)) in corners.iter().zip(names).enumerate() {
        painter.circle_stroke(*c, 6.0, egui::Stroke::new(2.0, marker));
        painter.line_segment([*c - egui::vec2(10.0, 0.0), *c + egui::vec2(10.0, 0.0)], (1.0, marker));
        painter.line_segment([*c - egui::vec2(0.0, 10.0), *c + egui::vec2(0.0, 10.0)], (1.0, marker));
        // Labels point into the frame, so none runs off its edge.
        let (offset, align) = match (c.x > shown.center().x, c.y > shown.center().y) {
            (false, false) => (egui::vec2(9.0, 9.0), egui::Align2::LEFT_TOP),
            (true, false) => (egui::vec2(-9.0, 9.0), egui::Align2::RIGHT_TOP),
            (true, true) => (egui::vec2(-9.0, -9.0), egui::Align2::RIGHT_BOTTOM),
            (false, true) => (egui::vec2(9.0, -9.0), egui::Align2::LEFT_BOTTOM),
        };
        let text = format!("{} {name}", i + 1);
        painter.text(*c + offset, align, text, egui::FontId::proportional(14.0), marker);
    }
}

impl ApplicationHandler for Picker {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.gfx.is_some() {
            return;
        }
        match self.create_gfx(event_loop) {
            Ok(gfx) => {
                eprintln!("surfacelab calibrate: click the four points in the window ({})", self.names.join(", "));
                gfx.window.request_redraw();
                self.gfx = Some(gfx);
            }
            Err(e) => {
                self.error = Some(e);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        if let Some(gfx) = self.gfx.as_mut() {
            let response = gfx.state.on_window_event(&gfx.window, &event);
            if response.repaint {
                gfx.window.request_redraw();
            }
        }
        match event {
            WindowEvent::CloseRequested => self.outcome = Some(Outcome::GaveUp),
            WindowEvent::KeyboardInput { event, .. } if event.state.is_pressed() => {
                self.key(&event.logical_key);
                if let Some(gfx) = &self.gfx {
                    gfx.window.request_redraw();
                }
            }
            WindowEvent::Resized(size) => {
                if let Some(gfx) = self.gfx.as_mut() {
                    gfx.config.width = size.width.max(1);
                    gfx.config.height = size.height.max(1);
                    gfx.surface.configure(&gfx.device, &gfx.config);
                    gfx.window.request_redraw();
                }
            }
            WindowEvent::RedrawRequested => {
                if let Err(e) = self.frame() {
                    self.error = Some(e);
                    event_loop.exit();
                }
            }
            _ => {}
        }
        if self.outcome.is_some() {
            event_loop.exit();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_click_at_one_screen_pixel_a_camera_pixel_is_that_pixel() {
        let shown = egui::Rect::from_min_size(egui::pos2(0.0, 0.0), egui::vec2(640.0, 480.0));
        assert_eq!(frame_point(egui::pos2(100.0, 37.0), 1.0, shown, [640, 480]), [100.0, 37.0]);
        assert_eq!(frame_point(egui::pos2(0.0, 0.0), 1.0, shown, [640, 480]), [0.0, 0.0]);
        // At half size, screen pixel 50 covers camera pixels 100 and 101: its centre is between them.
        let half = egui::Rect::from_min_size(egui::pos2(20.0, 0.0), egui::vec2(320.0, 240.0));
        assert_eq!(frame_point(egui::pos2(70.0, 10.0), 1.0, half, [640, 480]), [100.5, 20.5]);
        // HiDPI: 2 screen pixels a point; the pointer at 10.0 points is screen pixel 20, camera pixel 20.
        assert_eq!(
            frame_point(
                egui::pos2(10.0, 5.0),
                2.0,
                egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(320.0, 240.0)),
                [640, 480]
            ),
            [20.0, 10.0]
        );
        // Drawing a point puts it where a click on it lands (up to the half pixel).
        let p = [123.0, 45.0];
        let at = shown_at(p, half, [640, 480]);
        let back = frame_point(at - egui::vec2(0.5, 0.5), 1.0, half, [640, 480]);
        assert!((back[0] - p[0]).abs() < 1e-4 && (back[1] - p[1]).abs() < 1e-4, "{back:?}");
    }

    #[test]
    fn frames_are_fitted_whole_and_centred() {
        let area = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(800.0, 800.0));
        let shown = fitted(area, [640, 480]);
        assert_eq!((shown.min, shown.size()), (egui::pos2(0.0, 100.0), egui::vec2(800.0, 600.0)));
    }

    #[test]
    fn depth_frames_show_near_as_white_and_no_reading_as_black() {
        let frame = CameraImage { width: 4, height: 1, pixels: Pixels::Grey16(vec![1000, 1200, 0, 1100]) };
        assert_eq!(display_grey(&frame), vec![255, 0, 0, 128]);
        let ir = CameraImage { width: 2, height: 1, pixels: Pixels::Grey8(vec![7, 9]) };
        assert_eq!(display_grey(&ir), vec![7, 9]);
    }
}
