//! The long-lived renderer: pipelines and static meshes made once;
//! `prepare` uploads a frame's [`DrawList`], `paint` records its passes into
//! any texture view of the format given at construction — a window's surface
//! texture or an off-screen capture texture, with the same code.
//!
//! In a window, per frame:
//!
//! ```text
//! renderer.prepare(&draw_list, [config.width, config.height])?;   // after a resize too
//! let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame") });
//! renderer.paint(&mut encoder, &surface_view);                    // clears, draws the table
//! // egui afterwards, in its own pass with LoadOp::Load on the same view
//! queue.submit([encoder.finish()]);
//! ```
//!
//! Frame passes: a depth-only shadow pass (the objects seen from the light),
//! then one main pass: table, table markings, objects, deformables, decals,
//! the contact image, and the feedback last (hidden parts faint, visible
//! parts solid).
//! The table and the decals are drawn cell by cell
//! ([`shadow_regions`](crate::render::shadow_regions)): with the shadow
//! lookup only where a caster's shadow can reach.

use crate::render::bounds::shadow_bounds;
use crate::render::camera::CameraMatrices;
use crate::render::contact_texture::ContactTexture;
use crate::render::draw_list::{Decal, DrawList, Rgba};
use crate::render::error::RenderError;
use crate::render::frame::{FrameData, TABLE_INSTANCE, validate};
use crate::render::gpu::AdapterSummary;
use crate::render::instances::TABLE_THICKNESS;
use crate::render::light::{ShadowProjection, light_direction};
use crate::render::mesh_library::{MeshLibrary, MeshRef};
use crate::render::pipelines::{PipelineConfig, Pipelines};
use crate::render::shadow_map::ShadowMap;
use crate::render::shadow_regions::{self, PixelRect};
use crate::render::targets::RenderTargets;
use crate::render::uniforms::FrameUniforms;

/// Vertices per decal instance: four quads (`VERTICES` in `shaders/decal.wgsl`).
const DECAL_VERTICES: u32 = 24;

/// Choices fixed for a renderer's lifetime.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RendererOptions {
    /// 1 (no MSAA) or 4. On lavapipe at 1024x768, 4x MSAA almost triples
    /// the frame time (`cargo bench --bench render`), so [`Default`] is 1 and
    /// [`RendererOptions::for_adapter`] enables it on real GPUs only.
    pub sample_count: u32,
    /// Side of the square shadow map in texels. 1024 over a 0.6 m table is
    /// ~0.7 mm per texel; 2048 looks the same with PCF and costs noticeably
    /// more per frame on lavapipe.
    pub shadow_map_size: u32,
    /// Width of feedback lines in pixels (scale with the window's DPI).
    pub feedback_line_px: f32,
}

impl Default for RendererOptions {
    fn default() -> Self {
        Self { sample_count: 1, shadow_map_size: 1024, feedback_line_px: 3.0 }
    }
}

impl RendererOptions {
    /// The defaults on software rasterisers; 4x MSAA and a 2048² shadow map
    /// on real GPUs, where both are cheap.
    pub fn for_adapter(adapter: &AdapterSummary) -> Self {
        if adapter.is_software() {
            Self::default()
        } else {
            Self { sample_count: 4, shadow_map_size: 2048, ..Self::default() }
        }
    }
}

/// Draws [`DrawList`]s into views of one colour format. Create once (it
/// compiles the pipelines); reuse every frame.
#[derive(Debug)]
pub struct Renderer {
    device: wgpu::Device,
    queue: wgpu::Queue,
    target_format: wgpu::TextureFormat,
    options: RendererOptions,
    pipelines: Pipelines,
    meshes: MeshLibrary,
    shadow_map: ShadowMap,
    uniforms: wgpu::Buffer,
    frame_bind_group: wgpu::BindGroup,
    shadow_bind_group: wgpu::BindGroup,
    contact_sampler: wgpu::Sampler,
    contact: Option<ContactTexture>,
    /// Sized by the last `prepare`.
    targets: Option<RenderTargets>,
    frame: FrameData,
    /// The view cut into rectangles, each with whether a shadow can fall
    /// in it: the table and decals are drawn per rectangle, with the shadow
    /// lookup only where it can matter ([`shadow_regions`]).
    shadow_cells: Vec<(PixelRect, bool)>,
    clear: wgpu::Color,
    camera: Option<CameraMatrices>,
}

impl Renderer {
    /// Builds the pipelines for targets of `target_format` (an sRGB format
    /// is best; for a non-sRGB window surface the shaders encode sRGB
    /// themselves). Holds clones of `device` and `queue`.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        target_format: wgpu::TextureFormat,
        options: RendererOptions,
    ) -> Result<Self, RenderError> {
        if ![1, 4].contains(&options.sample_count) {
            return Err(RenderError::InvalidOptions(format!(
                "sample_count {} (WebGPU guarantees 1 and 4)",
                options.sample_count
            )));
        }
        let max = device.limits().max_texture_dimension_2d;
        if !(1..=max).contains(&options.shadow_map_size) {
            return Err(RenderError::InvalidOptions(format!(
                "shadow_map_size {} not in 1..={max}",
                options.shadow_map_size
            )));
        }
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let pipelines =
            Pipelines::new(device, PipelineConfig { color_format: target_format, sample_count: options.sample_count });
        let shadow_map = ShadowMap::new(device, options.shadow_map_size);
        let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("frame uniforms"),
            size: std::mem::size_of::<FrameUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let frame_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("frame bind group"),
            layout: &pipelines.frame_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&shadow_map.view) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&shadow_map.sampler) },
            ],
        });
        let shadow_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shadow pass bind group"),
            layout: &pipelines.shadow_pass_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() }],
        });
        let contact_sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("contact image sampler"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let meshes = MeshLibrary::new(device);
        let frame = FrameData::new(device);
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(RenderError::Validation { during: "creating the renderer", message: error.to_string() });
        }
        Ok(Self {
            device: device.clone(),
            queue: queue.clone(),
            target_format,
            options,
            pipelines,
            meshes,
            shadow_map,
            uniforms,
            frame_bind_group,
            shadow_bind_group,
            contact_sampler,
            contact: None,
            targets: None,
            frame,
            shadow_cells: Vec::new(),
            clear: wgpu::Color::BLACK,
            camera: None,
        })
    }

    pub fn target_format(&self) -> wgpu::TextureFormat {
        self.target_format
    }

    pub fn options(&self) -> RendererOptions {
        self.options
    }

    /// The camera of the last prepared frame (picking, overlays drawn by the
    /// caller); `None` before the first `prepare`.
    pub fn camera(&self) -> Option<&CameraMatrices> {
        self.camera.as_ref()
    }

    /// Number of capsule sizes currently cached.
    pub fn cached_capsules(&self) -> usize {
        self.meshes.cached_capsules()
    }

    /// Uploads `list` for a target of `size` pixels (width, height); call
    /// again whenever the list or the size changes (a window resize just
    /// passes the new size: the depth and MSAA buffers follow).
    pub fn prepare(&mut self, list: &DrawList, size: [u32; 2]) -> Result<(), RenderError> {
        let max = self.device.limits().max_texture_dimension_2d;
        if !(1..=max).contains(&size[0]) || !(1..=max).contains(&size[1]) {
            return Err(RenderError::TargetSize { width: size[0], height: size[1], max });
        }
        validate(list)?;
        if self.targets.as_ref().is_none_or(|t| t.size != size) {
            self.targets = Some(RenderTargets::new(&self.device, size, self.target_format, self.options.sample_count));
        }
        self.meshes.begin_frame();

        let camera = CameraMatrices::for_draw_list(list, size);
        let shadow = ShadowProjection::fit(&shadow_bounds(list), light_direction());
        let encode_srgb = !self.target_format.is_srgb();
        let uniforms = FrameUniforms::new(list, size, &camera, &shadow, self.options.shadow_map_size, encode_srgb);
        self.queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        // Receivers drawn per cell: the table (its sides too) and the decals.
        let floor = list
            .decals
            .iter()
            .map(|d| match *d {
                Decal::Disc { z, .. } | Decal::Rect { z, .. } => z,
            })
            .fold(-TABLE_THICKNESS, f32::min);
        let margin = shadow_regions::reach(uniforms.shadow[0], uniforms.shadow[3]);
        let regions = shadow_regions::shadow_rects(list, camera.view_proj, size, light_direction(), floor, margin);
        self.shadow_cells = shadow_regions::cells(size, &regions);
        self.camera = Some(camera);
        self.clear = clear_color(list.clear_color, encode_srgb);

        // Lines keep their look at any size: the width is for a 768-pixel-high
        // view and grows with it (never below the option's width).
        let line_px = self.options.feedback_line_px * (size[1] as f32 / 768.0).max(1.0);
        self.frame.upload(&self.device, &self.queue, &mut self.meshes, list, line_px);

        if let Some(overlay) = &list.contact_overlay {
            let size = [overlay.width, overlay.height];
            if self.contact.as_ref().is_none_or(|c| c.size() != size) {
                self.contact = Some(ContactTexture::new(
                    &self.device,
                    &self.pipelines.overlay_layout,
                    &self.contact_sampler,
                    size,
                ));
            }
            if let Some(contact) = &self.contact {
                contact.upload(&self.queue, overlay);
            }
        }
        Ok(())
    }

    /// Records the shadow pass and the main pass of the prepared frame,
    /// drawing into `target` (format `target_format()`, size as prepared;
    /// cleared first). Draw UI on top afterwards with a pass that loads.
    /// Does nothing before the first `prepare`.
    pub fn paint(&self, encoder: &mut wgpu::CommandEncoder, target: &wgpu::TextureView) {
        let Some(targets) = &self.targets else {
            return;
        };
        self.paint_shadow_map(encoder);

        let (view, resolve_target, store) = match &targets.msaa_color {
            // The multisampled buffer is only needed until it is resolved.
            Some(msaa) => (msaa, Some(target), wgpu::StoreOp::Discard),
            None => (target, None, wgpu::StoreOp::Store),
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("main pass"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(self.clear), store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &targets.depth,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        let f = &self.frame;
        let p = &self.pipelines;
        pass.set_bind_group(0, &self.frame_bind_group, &[]);

        // Opaque: the table, its markings, the objects (boxes lit per face,
        // round meshes per pixel), then the two-sided deformables.
        let cube = self.meshes.get(MeshRef::Box);
        pass.set_vertex_buffer(0, cube.vertices.slice(..));
        pass.set_vertex_buffer(1, f.objects.slice());
        pass.set_index_buffer(cube.indices.slice(..), wgpu::IndexFormat::Uint32);
        self.per_cell(&mut pass, [&p.flat_unshadowed, &p.flat], |pass| {
            pass.draw_indexed(0..cube.index_count, 0, TABLE_INSTANCE..TABLE_INSTANCE + 1);
        });
        pass.set_pipeline(&p.grid);
        pass.set_vertex_buffer(0, f.strips.slice());
        pass.draw(0..6, 0..f.strip_count);
        pass.set_vertex_buffer(1, f.objects.slice());
        for batch in &f.batches {
            pass.set_pipeline(if batch.mesh == MeshRef::Box { &p.flat } else { &p.mesh_solid });
            let mesh = self.meshes.get(batch.mesh);
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..mesh.index_count, 0, batch.instances.clone());
        }
        if !f.deformables.is_empty() {
            pass.set_pipeline(&p.mesh_two_sided);
            pass.set_vertex_buffer(0, f.deformable_vertices.slice());
            pass.set_index_buffer(f.deformable_indices.slice(), wgpu::IndexFormat::Uint32);
            for d in &f.deformables {
                pass.draw_indexed(d.indices.clone(), d.base_vertex, d.instance..d.instance + 1);
            }
        }

        // Painted on surfaces: decals, then the hand shadow over them.
        if f.decal_count > 0 {
            pass.set_vertex_buffer(0, f.decals.slice());
            self.per_cell(&mut pass, [&p.decal_unshadowed, &p.decal], |pass| {
                pass.draw(0..DECAL_VERTICES, 0..f.decal_count);
            });
        }
        if let (true, Some(contact)) = (f.show_overlay, &self.contact) {
            pass.set_pipeline(&p.overlay);
            pass.set_bind_group(1, &contact.bind_group, &[]);
            pass.set_vertex_buffer(0, f.overlay_region.slice());
            pass.draw(0..6, 0..1);
        }

        // Feedback last: hidden parts faintly (tested against the scene's
        // depth only), then visible parts solid.
        if f.line_count > 0 {
            pass.set_pipeline(&p.feedback_lines_hidden);
            pass.set_vertex_buffer(0, f.lines.slice());
            pass.draw(0..6, 0..f.line_count);
        }
        if f.cube_count > 0 {
            pass.set_pipeline(&p.feedback_cubes_hidden);
            pass.set_vertex_buffer(0, cube.vertices.slice(..));
            pass.set_vertex_buffer(1, f.cubes.slice());
            pass.set_index_buffer(cube.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..cube.index_count, 0, 0..f.cube_count);
            pass.set_pipeline(&p.feedback_cubes_visible);
            pass.draw_indexed(0..cube.index_count, 0, 0..f.cube_count);
        }
        if f.line_count > 0 {
            pass.set_pipeline(&p.feedback_lines_visible);
            pass.set_vertex_buffer(0, f.lines.slice());
            pass.draw(0..6, 0..f.line_count);
        }
    }

    /// Runs `draw` once per shadow cell, scissored to it, with
    /// `[unshadowed, shadowed]` pipeline as the cell asks; leaves the
    /// scissor on the whole target.
    fn per_cell(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        [unshadowed, shadowed]: [&wgpu::RenderPipeline; 2],
        mut draw: impl FnMut(&mut wgpu::RenderPass<'_>),
    ) {
        let mut current = None;
        for &(cell, shadow) in &self.shadow_cells {
            if current != Some(shadow) {
                pass.set_pipeline(if shadow { shadowed } else { unshadowed });
                current = Some(shadow);
            }
            pass.set_scissor_rect(cell.min[0], cell.min[1], cell.width(), cell.height());
            draw(pass);
        }
        if let Some(t) = &self.targets {
            pass.set_scissor_rect(0, 0, t.size[0], t.size[1]);
        }
    }

    fn paint_shadow_map(&self, encoder: &mut wgpu::CommandEncoder) {
        let f = &self.frame;
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shadow pass"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.shadow_map.view,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_bind_group(0, &self.shadow_bind_group, &[]);
        pass.set_pipeline(&self.pipelines.shadow_solid);
        pass.set_vertex_buffer(1, f.objects.slice());
        for batch in &f.batches {
            let mesh = self.meshes.get(batch.mesh);
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..mesh.index_count, 0, batch.instances.clone());
        }
        if !f.deformables.is_empty() {
            pass.set_pipeline(&self.pipelines.shadow_two_sided);
            pass.set_vertex_buffer(0, f.deformable_vertices.slice());
            pass.set_index_buffer(f.deformable_indices.slice(), wgpu::IndexFormat::Uint32);
            for d in &f.deformables {
                pass.draw_indexed(d.indices.clone(), d.base_vertex, d.instance..d.instance + 1);
            }
        }
    }

    /// `prepare` + `paint` + submit, for callers with nothing else to draw.
    pub fn render(
        &mut self,
        list: &DrawList,
        target: &wgpu::TextureView,
        size: [u32; 2],
    ) -> Result<wgpu::SubmissionIndex, RenderError> {
        self.prepare(list, size)?;
        let mut encoder =
            self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame encoder") });
        self.paint(&mut encoder, target);
        Ok(self.queue.submit([encoder.finish()]))
    }
}

/// The clear colour as the target stores it: sRGB targets take linear
/// values; others need them encoded like the shaders' output.
fn clear_color(c: Rgba, encode_srgb: bool) -> wgpu::Color {
    let encode = |v: f32| {
        let v = v.clamp(0.0, 1.0);
        if !encode_srgb {
            v
        } else if v <= 0.003_130_8 {
            v * 12.92
        } else {
            1.055 * v.powf(1.0 / 2.4) - 0.055
        }
    };
    wgpu::Color {
        r: encode(c[0]) as f64,
        g: encode(c[1]) as f64,
        b: encode(c[2]) as f64,
        a: c[3].clamp(0.0, 1.0) as f64,
    }
}
