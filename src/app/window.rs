//! The window: winit's event loop, the wgpu surface, egui, and the frame
//! loop. Each frame runs the physics steps real time asks for (the lab's
//! fixed-step clock), lays out the panel and the view, renders the table
//! into the view's texture, copies that into the window, draws egui on top
//! and presents; frames are paced to the display's refresh rate.

use super::lab::Lab;
use super::panel::{self, Action, HAND_MODES, PanelState};
use super::ui_cache;
use super::view::{self, ViewFrame};
use super::window_surface::{WindowSurface, window_egui};
use super::{DemoOptions, Screenshot};
use crate::input::{Button, Modifiers, MouseEvent, SourceEvent};
use crate::render::{Alpha, GpuContext, Readback, Renderer, RendererOptions, readable, save_png, texture_2d};
use crate::session::RunReport;
use anyhow::{Context, anyhow, bail};
use glam::Vec2;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};
use winit::application::ApplicationHandler;
use winit::dpi::{LogicalSize, PhysicalPosition};
use winit::event::{ElementState, MouseScrollDelta, TouchPhase, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

/// Wheel pixels per notch for touchpads that report pixels.
const PIXELS_PER_NOTCH: f64 = 40.0;

/// Opens the window and runs until it is closed (or `--quit-after`, or the
/// last participant trial).
pub fn run(mut options: DemoOptions) -> anyhow::Result<()> {
    let camera = options.camera.take();
    let mut lab = Lab::new(&options, camera)?;
    if let Some(path) = &options.record {
        lab.start_recording(Some(path.clone()))?;
    }
    let display = super::window_surface::display_name();
    let event_loop = EventLoop::new().map_err(|e| {
        anyhow!("cannot open a window on display {display:?}: {e}; unset DISPLAY and WAYLAND_DISPLAY to run the headless job instead")
    })?;
    // Ctrl-C (SIGINT) closes the window like its close button, so the
    // recording is saved and the summary printed.
    let interrupted = Arc::new(AtomicBool::new(false));
    let proxy = event_loop.create_proxy();
    let flag = Arc::clone(&interrupted);
    if let Err(e) = ctrlc::set_handler(move || {
        flag.store(true, Ordering::SeqCst);
        let _ = proxy.send_event(());
    }) {
        tracing::warn!("Ctrl-C will end the demo without its summary: {e}");
    }
    let mut app = App::new(options, lab, interrupted);
    event_loop.run_app(&mut app).context("the window's event loop failed")?;
    if app.lab.participant.is_some() {
        // A trial cut short has no row; its input is not kept either.
        app.lab.discard_recording();
    } else {
        app.lab.stop_recording();
    }
    eprintln!("surfacelab demo: {}; physics {:.1} s behind real time", app.lab.stats.summary(), app.lab.behind_s());
    if let Some(path) = &app.options.report {
        let report = RunReport::from_session(
            &app.lab.session,
            app.lab.view.feedback,
            "live input",
            app.started.elapsed().as_secs_f64(),
        );
        report.save(path).with_context(|| format!("writing report {}", path.display()))?;
    }
    app.error.map_or(Ok(()), Err)
}

struct App {
    options: DemoOptions,
    lab: Lab,
    panel: PanelState,
    gfx: Option<Gfx>,
    error: Option<anyhow::Error>,
    started: Instant,
    last_frame: Instant,
    /// Time between frames: the monitor's refresh period.
    period: Duration,
    /// The view's rectangle in physical pixels, from the last layout.
    view_px: egui::Rect,
    cursor: Option<PhysicalPosition<f64>>,
    /// A left drag started on the view: the mouse model gets every event until it ends.
    dragging: bool,
    screenshot: Option<Screenshot>,
    /// Set by the Ctrl-C handler.
    interrupted: Arc<AtomicBool>,
}

/// Everything that needs the window.
struct Gfx {
    window: Arc<Window>,
    title: String,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    gpu: GpuContext,
    renderer: Renderer,
    target: ViewTarget,
    /// The view is copied into the window (fast) rather than drawn by egui
    /// as a textured rectangle (on lavapipe that costs a large share of the
    /// frame, `scripts/demo-fps.sh`).
    direct: bool,
    egui: egui::Context,
    egui_state: egui_winit::State,
    egui_renderer: egui_wgpu::Renderer,
    /// Draws the cached panel ([`ui_cache`]); its own renderer because a
    /// renderer holds the buffers of one list of primitives per submission.
    panel_renderer: egui_wgpu::Renderer,
    panel: Option<PanelTexture>,
}

/// The panel as last drawn, in a texture of the window's size and format.
struct PanelTexture {
    texture: wgpu::Texture,
    drawn: Vec<egui::ClippedPrimitive>,
}

/// The texture the table is rendered into. Its format is the window's
/// without the sRGB suffix: the renderer then writes sRGB-encoded values,
/// which both a copy into the window and egui (which treats texture values
/// as encoded numbers) show unchanged.
struct ViewTarget {
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    id: egui::TextureId,
}

impl ViewTarget {
    fn new(
        device: &wgpu::Device,
        egui_renderer: &mut egui_wgpu::Renderer,
        format: wgpu::TextureFormat,
        size: [u32; 2],
    ) -> Self {
        let (texture, view) = view_texture(device, format, size);
        let id = egui_renderer.register_native_texture(device, &view, wgpu::FilterMode::Nearest);
        Self { texture, view, id }
    }

    fn size(&self) -> [u32; 2] {
        [self.texture.width(), self.texture.height()]
    }

    fn resize(&mut self, device: &wgpu::Device, egui_renderer: &mut egui_wgpu::Renderer, size: [u32; 2]) {
        if self.size() != size {
            (self.texture, self.view) = view_texture(device, self.texture.format(), size);
            egui_renderer.update_egui_texture_from_wgpu_texture(device, &self.view, wgpu::FilterMode::Nearest, self.id);
        }
    }
}

fn view_texture(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    size: [u32; 2],
) -> (wgpu::Texture, wgpu::TextureView) {
    let usage =
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC;
    let texture = texture_2d(device, "table view", size, format, usage);
    let view = texture.create_view(&wgpu::TextureViewDescriptor { label: Some("table view"), ..Default::default() });
    (texture, view)
}

impl App {
    fn new(options: DemoOptions, mut lab: Lab, interrupted: Arc<AtomicBool>) -> Self {
        let now = Instant::now();
        // Wall time (`Lab::wall`) counts from here; TUIO packets are timed by the same clock.
        lab.input.set_clock(now);
        let screenshot = options.screenshot_after.clone();
        Self {
            options,
            lab,
            panel: PanelState::new(),
            gfx: None,
            error: None,
            started: now,
            last_frame: now,
            period: Duration::from_secs_f64(1.0 / 60.0),
            view_px: egui::Rect::NOTHING,
            cursor: None,
            dragging: false,
            screenshot,
            interrupted,
        }
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, e: anyhow::Error) {
        self.error = Some(e);
        event_loop.exit();
    }

    /// The table point under a window position, if it is over the view.
    fn table_point(&self, p: PhysicalPosition<f64>) -> Option<[f32; 2]> {
        let gfx = self.gfx.as_ref()?;
        let camera = gfx.renderer.camera()?;
        let local = Vec2::new(p.x as f32 - self.view_px.min.x, p.y as f32 - self.view_px.min.y);
        let hit = camera.pixel_to_plane(gfx.target.size(), local, 0.0)?;
        Some([hit.x, hit.y])
    }

    /// Whether a pointer event at `p` belongs to the table (not to egui).
    fn on_view(&self, p: PhysicalPosition<f64>) -> bool {
        let over = self.view_px.contains(egui::pos2(p.x as f32, p.y as f32));
        over && self.gfx.as_ref().is_some_and(|g| !g.egui.egui_wants_pointer_input())
    }

    fn mouse(&mut self, e: MouseEvent) {
        let at = self.wall_now();
        self.lab.input.push(at, SourceEvent::Mouse(e));
    }

    /// Seconds since the demo opened, to stamp input as it arrives.
    fn wall_now(&self) -> f64 {
        self.started.elapsed().as_secs_f64()
    }

    fn pointer_event(&mut self, event: &WindowEvent) {
        match *event {
            WindowEvent::CursorMoved { position, .. } => {
                self.cursor = Some(position);
                if (self.dragging || self.on_view(position))
                    && let Some(p) = self.table_point(position)
                {
                    self.mouse(MouseEvent::Moved(p));
                }
            }
            WindowEvent::CursorLeft { .. } => {
                self.cursor = None;
                self.dragging = false;
                self.mouse(MouseEvent::Left);
            }
            WindowEvent::MouseInput { state, button, .. } => {
                let button = match button {
                    winit::event::MouseButton::Left => Button::Left,
                    winit::event::MouseButton::Right => Button::Right,
                    winit::event::MouseButton::Middle => Button::Middle,
                    _ => return,
                };
                match state {
                    ElementState::Pressed if self.cursor.is_some_and(|c| self.on_view(c)) => {
                        if button == Button::Left {
                            self.dragging = true;
                        }
                        self.mouse(MouseEvent::Pressed(button));
                    }
                    ElementState::Pressed => {}
                    ElementState::Released => {
                        if button == Button::Left {
                            self.dragging = false;
                        }
                        self.mouse(MouseEvent::Released(button));
                    }
                }
            }
            WindowEvent::MouseWheel { delta, .. } if self.cursor.is_some_and(|c| self.on_view(c)) || self.dragging => {
                let notches = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => (p.y / PIXELS_PER_NOTCH) as f32,
                };
                self.mouse(MouseEvent::Wheel(notches));
            }
            WindowEvent::ModifiersChanged(m) => {
                let s = m.state();
                self.mouse(MouseEvent::Modifiers(Modifiers {
                    shift: s.shift_key(),
                    ctrl: s.control_key(),
                    alt: s.alt_key(),
                }));
            }
            WindowEvent::Touch(t) => {
                let down = self.lab.input.touching(t.id);
                match t.phase {
                    TouchPhase::Started | TouchPhase::Moved
                        if down || (t.phase == TouchPhase::Started && self.on_view(t.location)) =>
                    {
                        if let Some(p) = self.table_point(t.location) {
                            let at = self.wall_now();
                            self.lab.input.push(at, SourceEvent::TouchAt(t.id, p));
                        }
                    }
                    TouchPhase::Ended | TouchPhase::Cancelled => {
                        let at = self.wall_now();
                        self.lab.input.push(at, SourceEvent::TouchUp(t.id));
                    }
                    _ => {}
                }
            }
            _ => {}
        }
    }

    /// Keyboard shortcuts of the researcher's panel.
    fn key(&mut self, key: &Key) {
        if self.lab.participant.is_some() {
            return;
        }
        let action = match key.as_ref() {
            Key::Named(NamedKey::Space) => {
                self.lab.toggle_pause();
                None
            }
            Key::Character(c) => match c.to_ascii_lowercase().as_str() {
                "n" => {
                    self.lab.request_step();
                    None
                }
                "r" => Some(Action::Reset),
                "s" => Some(Action::Screenshot),
                // In participant mode the condition fixes what is shown.
                "f" if self.lab.participant.is_none() => {
                    self.lab.view.feedback = !self.lab.view.feedback;
                    None
                }
                "o" if self.lab.participant.is_none() => {
                    self.lab.view.contact_overlay = !self.lab.view.contact_overlay;
                    None
                }
                digit => {
                    if let Some(i) = digit.parse::<usize>().ok().filter(|d| (1..=HAND_MODES.len()).contains(d)) {
                        self.mouse(MouseEvent::Mode(HAND_MODES[i - 1].0));
                    }
                    None
                }
            },
            _ => None,
        };
        if let Some(a) = action {
            self.apply(a);
        }
    }

    fn apply(&mut self, action: Action) {
        let result = match action {
            Action::LoadTask(t) => self.lab.load_task(&t),
            Action::Technique(k) => self.lab.set_technique(k),
            Action::Restart | Action::Reset => self.lab.reset(),
            Action::DefaultParameters => self.lab.default_parameters(),
            Action::Screenshot => {
                if let Some(g) = &self.gfx {
                    let size = g.target.size();
                    self.lab.screenshot(&g.gpu, size);
                }
                Ok(())
            }
            Action::StartRecording(path) => self.lab.start_recording(path),
            Action::StopRecording => {
                self.lab.stop_recording();
                Ok(())
            }
        };
        if let Err(e) = result {
            self.lab.say(format!("{e:#}"));
        }
    }

    /// One frame: physics, UI, render, present.
    fn frame(&mut self, event_loop: &ActiveEventLoop) -> anyhow::Result<()> {
        let now = Instant::now();
        let elapsed = (now - self.last_frame).as_secs_f64();
        self.last_frame = now;
        self.lab.wall = (now - self.started).as_secs_f64();
        let steps = self.lab.advance(elapsed);
        let render_start = Instant::now();
        let pointer_on_view = self.cursor.is_some_and(|c| self.on_view(c));
        // The table under a still pointer changes when the view does (the
        // first frames, a resize): keep the mouse model's cursor on it.
        if let Some(c) = self.cursor
            && (pointer_on_view || self.dragging)
            && let Some(p) = self.table_point(c)
            && p != self.lab.input.mouse.cursor()
        {
            self.mouse(MouseEvent::Moved(p));
        }
        let Some(gfx) = self.gfx.as_mut() else {
            return Ok(());
        };

        let (full, actions, view_rect) = layout(gfx, &mut self.lab, &mut self.panel, pointer_on_view);
        let ppp = full.pixels_per_point;
        let (min, max) = ((view_rect.min.to_vec2() * ppp).round(), (view_rect.max.to_vec2() * ppp).round());
        self.view_px = egui::Rect::from_min_max(min.to_pos2(), max.to_pos2());
        let size = [(max.x - min.x).max(1.0) as u32, (max.y - min.y).max(1.0) as u32];
        let device = gfx.gpu.device.clone();
        let queue = gfx.gpu.queue.clone();
        gfx.target.resize(&device, &mut gfx.egui_renderer, size);
        gfx.renderer.prepare(&self.lab.draw_list(size), size)?;

        let Some((frame, suboptimal)) = acquire(gfx, &device)? else {
            return Ok(());
        };
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame") });
        gfx.renderer.paint(&mut encoder, &gfx.target.view);
        let primitives = gfx.egui.tessellate(full.shapes, ppp);
        for (id, deltas) in &full.textures_delta.set {
            for delta in deltas {
                gfx.egui_renderer.update_texture(&device, &queue, *id, delta);
                gfx.panel_renderer.update_texture(&device, &queue, *id, delta);
            }
        }
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [gfx.config.width, gfx.config.height],
            pixels_per_point: ppp,
        };
        // The panel is redrawn only when it changed; the rest is drawn live.
        let split = if gfx.direct { ui_cache::cacheable_prefix(&primitives, view_rect) } else { 0 };
        let (cached, live) = primitives.split_at(split);
        let mut commands = Vec::new();
        if gfx.direct {
            let textures_changed = !full.textures_delta.set.is_empty();
            commands.extend(redraw_panel(gfx, &mut encoder, cached, &screen, textures_changed));
        }
        commands.extend(gfx.egui_renderer.update_buffers(&device, &queue, &mut encoder, live, &screen));
        let at = [min.x as u32, min.y as u32];
        compose(gfx, &mut encoder, &frame.texture, at, live, &screen);

        // `--screenshot-after`: this very frame, read back.
        let capture = match &self.screenshot {
            Some(s) if self.lab.wall >= s.after_s => {
                Some(read_back(gfx, &mut encoder, &frame.texture, at, live, &screen))
            }
            _ => None,
        };
        commands.push(encoder.finish());
        queue.submit(commands);
        gfx.window.pre_present_notify();
        queue.present(frame);
        if suboptimal {
            gfx.surface.configure(&device, &gfx.config);
        }
        let title = window_title(&self.lab);
        if gfx.title != title {
            gfx.window.set_title(&title);
            gfx.title = title;
        }
        for id in &full.textures_delta.free {
            gfx.egui_renderer.free_texture(id);
            gfx.panel_renderer.free_texture(id);
        }
        self.lab.stats.push_frame(elapsed * 1000.0, render_start.elapsed().as_secs_f64() * 1000.0, steps);

        if let Some(readback) = capture
            && let Some(shot) = self.screenshot.take()
        {
            save_screenshot(&readback, &device, &shot, self.lab.wall)?;
        }
        for a in actions {
            self.apply(a);
        }
        let quit = self.options.quit_after.is_some_and(|q| self.lab.wall >= q);
        if quit || self.lab.finished() {
            event_loop.exit();
        }
        Ok(())
    }

    fn create_gfx(&mut self, event_loop: &ActiveEventLoop) -> anyhow::Result<Gfx> {
        let [w, h] = self.options.window_size;
        let title = window_title(&self.lab);
        let attributes = Window::default_attributes().with_title(title.clone()).with_inner_size(LogicalSize::new(w, h));
        let window = Arc::new(event_loop.create_window(attributes).context("cannot create the demo window")?);
        let WindowSurface { gpu, surface, caps, format } = WindowSurface::new(event_loop, &window)?;
        let summary = gpu.summary();
        let size = window.inner_size();
        // Copies into the surface put the table view in place without egui;
        // copies out of it let `--screenshot-after` read the real frame.
        let direct = caps.usages.contains(wgpu::TextureUsages::COPY_DST);
        let mut usage = wgpu::TextureUsages::RENDER_ATTACHMENT | (caps.usages & wgpu::TextureUsages::COPY_DST);
        if readable(format) {
            usage |= caps.usages & wgpu::TextureUsages::COPY_SRC;
        }
        let config = WindowSurface::config_for(&caps, format, usage, [size.width, size.height]);
        surface.configure(&gpu.device, &config);
        let scale = window.scale_factor() as f32;
        let options = RendererOptions { feedback_line_px: 3.0 * scale, ..RendererOptions::for_adapter(&summary) };
        let view_format = format.remove_srgb_suffix();
        let renderer = Renderer::new(&gpu.device, &gpu.queue, view_format, options)?;
        let (egui, egui_state) = window_egui(&window, &gpu.device);
        // No dithering: exact colours, so screenshots can be checked pixel by pixel.
        let egui_options = egui_wgpu::RendererOptions { dithering: false, ..egui_wgpu::RendererOptions::default() };
        let mut egui_renderer = egui_wgpu::Renderer::new(&gpu.device, format, egui_options);
        let panel_renderer = egui_wgpu::Renderer::new(&gpu.device, format, egui_options);
        let target =
            ViewTarget::new(&gpu.device, &mut egui_renderer, view_format, [size.width.max(1), size.height.max(1)]);
        if let Some(hz) =
            window.current_monitor().and_then(|m| m.refresh_rate_millihertz()).filter(|&mhz| mhz >= 10_000)
        {
            self.period = Duration::from_secs_f64(1000.0 / f64::from(hz));
        }
        if let Some(fps) = self.options.max_fps {
            self.period = self.period.max(Duration::from_secs_f64(1.0 / fps));
        }
        tracing::info!("demo window on {summary}, surface {format:?} {usage:?}, {:?} per frame", self.period);
        eprintln!("surfacelab demo: {} with {} on {}", self.lab.task, self.lab.technique(), summary);
        Ok(Gfx {
            window,
            title,
            surface,
            config,
            gpu,
            renderer,
            target,
            direct,
            egui,
            egui_state,
            egui_renderer,
            panel_renderer,
            panel: None,
        })
    }
}

/// This frame's egui pass: the panel (unless a participant sits), then the
/// view in what is left. Returns egui's output (platform output handled),
/// the panel's actions and where the view went, in points.
fn layout(
    gfx: &mut Gfx,
    lab: &mut Lab,
    panel_state: &mut PanelState,
    pointer_on_view: bool,
) -> (egui::FullOutput, Vec<Action>, egui::Rect) {
    let raw = gfx.egui_state.take_egui_input(&gfx.window);
    let participant = lab.participant.is_some();
    let camera = gfx.renderer.camera().copied();
    let frame_info = ViewFrame {
        texture: (!gfx.direct).then_some(gfx.target.id),
        camera: camera.as_ref().map(|c| (c, gfx.target.size())),
        pointer_on_view,
    };
    let mut actions = Vec::new();
    let mut view_rect = egui::Rect::NOTHING;
    let mut full = gfx.egui.run_ui(raw, |ui| {
        if !participant {
            actions = panel::show_side(ui, lab, panel_state);
        }
        let rect = ui.available_rect_before_wrap();
        view_rect = view::show(ui, rect, lab, frame_info);
    });
    gfx.egui_state.handle_platform_output(&gfx.window, std::mem::take(&mut full.platform_output));
    (full, actions, view_rect)
}

fn window_title(lab: &Lab) -> String {
    format!("surfacelab: {} ({})", lab.task, lab.technique())
}

/// Draws a frame into `target` (the window's texture or its twin): when
/// copies are possible the cached panel and the view copied to their
/// places (the view at `at`), then the live part of egui (`primitives`).
fn compose(
    gfx: &Gfx,
    encoder: &mut wgpu::CommandEncoder,
    target: &wgpu::Texture,
    at: [u32; 2],
    primitives: &[egui::ClippedPrimitive],
    screen: &egui_wgpu::ScreenDescriptor,
) {
    let view = target.create_view(&wgpu::TextureViewDescriptor::default());
    let clear = wgpu::LoadOp::Clear(wgpu::Color::BLACK);
    if gfx.direct {
        // Cleared first so no pixel is ever undefined, whatever the layout.
        drop(pass(encoder, &view, clear));
        let [w, h] = gfx.target.size();
        let width = w.min(target.width().saturating_sub(at[0]));
        let height = h.min(target.height().saturating_sub(at[1]));
        if let Some(panel) = &gfx.panel
            && panel.texture.size() == target.size()
        {
            for [x, y, width, height] in
                ui_cache::outside([target.width(), target.height()], [at[0], at[1], width, height])
            {
                let origin = wgpu::Origin3d { x, y, z: 0 };
                encoder.copy_texture_to_texture(
                    wgpu::TexelCopyTextureInfo { origin, ..panel.texture.as_image_copy() },
                    wgpu::TexelCopyTextureInfo { origin, ..target.as_image_copy() },
                    wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                );
            }
        }
        if width > 0 && height > 0 {
            encoder.copy_texture_to_texture(
                gfx.target.texture.as_image_copy(),
                wgpu::TexelCopyTextureInfo {
                    texture: target,
                    mip_level: 0,
                    origin: wgpu::Origin3d { x: at[0], y: at[1], z: 0 },
                    aspect: wgpu::TextureAspect::All,
                },
                wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
            );
        }
        gfx.egui_renderer.render(&mut pass(encoder, &view, wgpu::LoadOp::Load).forget_lifetime(), primitives, screen);
    } else {
        gfx.egui_renderer.render(&mut pass(encoder, &view, clear).forget_lifetime(), primitives, screen);
    }
}

/// A render pass drawing into `view`.
fn pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    view: &wgpu::TextureView,
    load: wgpu::LoadOp<wgpu::Color>,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("egui"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: None,
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}

/// An off-screen texture like the window's, for captures when the surface
/// itself cannot be copied.
/// Records a read-back of this frame as the window shows it: the frame
/// itself where the surface allows copies, else the same picture composed
/// again on a twin texture.
fn read_back(
    gfx: &mut Gfx,
    encoder: &mut wgpu::CommandEncoder,
    frame: &wgpu::Texture,
    at: [u32; 2],
    live: &[egui::ClippedPrimitive],
    screen: &egui_wgpu::ScreenDescriptor,
) -> Readback {
    let device = gfx.gpu.device.clone();
    let readback = Readback::new(&device, [frame.width(), frame.height()], frame.format(), "window capture readback");
    if gfx.config.usage.contains(wgpu::TextureUsages::COPY_SRC) {
        readback.record(encoder, frame);
    } else {
        let twin = twin_texture(&device, &gfx.config);
        compose(gfx, encoder, &twin, at, live, screen);
        readback.record(encoder, &twin);
    }
    readback
}

/// Waits for a read-back and writes it where `--screenshot-after` asked.
fn save_screenshot(readback: &Readback, device: &wgpu::Device, shot: &Screenshot, wall: f64) -> anyhow::Result<()> {
    let image = readback.read(device, Alpha::Opaque)?;
    save_png(&image, &shot.path)?;
    eprintln!(
        "surfacelab demo: window screenshot {}x{} at {wall:.1} s -> {}",
        image.width(),
        image.height(),
        shot.path.display()
    );
    Ok(())
}

/// The window's next surface texture, and whether it is suboptimal; `None`
/// when there is nothing to draw on this frame (occluded, timed out, or the
/// surface was just reconfigured).
fn acquire(gfx: &mut Gfx, device: &wgpu::Device) -> anyhow::Result<Option<(wgpu::SurfaceTexture, bool)>> {
    Ok(match gfx.surface.get_current_texture() {
        wgpu::CurrentSurfaceTexture::Success(f) => Some((f, false)),
        wgpu::CurrentSurfaceTexture::Suboptimal(f) => Some((f, true)),
        wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => None,
        wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
            gfx.surface.configure(device, &gfx.config);
            None
        }
        wgpu::CurrentSurfaceTexture::Validation => bail!("the window surface reported a validation error"),
    })
}

/// Redraws the cached panel texture if the panel changed (its primitives,
/// its textures or the window size); returns the command buffers egui needs.
fn redraw_panel(
    gfx: &mut Gfx,
    encoder: &mut wgpu::CommandEncoder,
    cached: &[egui::ClippedPrimitive],
    screen: &egui_wgpu::ScreenDescriptor,
    textures_changed: bool,
) -> Vec<wgpu::CommandBuffer> {
    let size = [gfx.config.width, gfx.config.height];
    let stale = textures_changed
        || gfx.panel.as_ref().is_none_or(|p| {
            [p.texture.width(), p.texture.height()] != size || !ui_cache::same_primitives(&p.drawn, cached)
        });
    if !stale {
        return Vec::new();
    }
    let (device, queue) = (gfx.gpu.device.clone(), gfx.gpu.queue.clone());
    let texture = match gfx.panel.take() {
        Some(p) if [p.texture.width(), p.texture.height()] == size => p.texture,
        _ => twin_texture(&device, &gfx.config),
    };
    let commands = gfx.panel_renderer.update_buffers(&device, &queue, encoder, cached, screen);
    let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
    let clear = wgpu::LoadOp::Clear(wgpu::Color::BLACK);
    gfx.panel_renderer.render(&mut pass(encoder, &view, clear).forget_lifetime(), cached, screen);
    gfx.panel = Some(PanelTexture { texture, drawn: cached.to_vec() });
    commands
}

fn twin_texture(device: &wgpu::Device, config: &wgpu::SurfaceConfiguration) -> wgpu::Texture {
    let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST;
    texture_2d(device, "window capture", [config.width, config.height], config.format, usage)
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.gfx.is_some() {
            return;
        }
        match self.create_gfx(event_loop) {
            Ok(gfx) => {
                gfx.window.request_redraw();
                self.gfx = Some(gfx);
                self.last_frame = Instant::now();
            }
            Err(e) => self.fail(event_loop, e.context("the demo window could not start")),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(gfx) = self.gfx.as_mut() else { return };
        let response = gfx.egui_state.on_window_event(&gfx.window, &event);
        match &event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => {
                if size.width > 0 && size.height > 0 {
                    gfx.config.width = size.width;
                    gfx.config.height = size.height;
                    gfx.surface.configure(&gfx.gpu.device, &gfx.config);
                    gfx.window.request_redraw();
                }
            }
            WindowEvent::RedrawRequested => {
                if let Err(e) = self.frame(event_loop) {
                    self.fail(event_loop, e);
                }
            }
            WindowEvent::KeyboardInput { event: key, .. } => {
                let typing = response.consumed || gfx.egui.egui_wants_keyboard_input();
                if key.state == ElementState::Pressed && !key.repeat && !typing {
                    let k = key.logical_key.clone();
                    self.key(&k);
                }
            }
            other => self.pointer_event(other),
        }
    }

    fn user_event(&mut self, event_loop: &ActiveEventLoop, (): ()) {
        if self.interrupted.load(Ordering::SeqCst) {
            event_loop.exit();
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.interrupted.load(Ordering::SeqCst) {
            event_loop.exit();
            return;
        }
        let Some(gfx) = &self.gfx else { return };
        let next = self.last_frame + self.period;
        if Instant::now() >= next {
            gfx.window.request_redraw();
            event_loop.set_control_flow(ControlFlow::Wait);
        } else {
            event_loop.set_control_flow(ControlFlow::WaitUntil(next));
        }
    }
}
