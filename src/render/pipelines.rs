//! Every render pipeline and bind-group layout, created once per renderer.
//!
//! Each pipeline's shader is `shaders/<pipeline>.wgsl` with
//! `shaders/frame.wgsl` (uniforms, shadow lookup, lighting) prepended: WGSL
//! has no includes, and one shared prelude keeps the lighting identical
//! across the table, the objects and the decals.

use crate::render::gpu_record::GpuRecord;
use crate::render::instances::{
    CubeInstance, DecalInstance, LineInstance, ObjectInstance, OverlayRegion, StripInstance,
};
use crate::render::mesh::Vertex;
use crate::render::targets::DEPTH_FORMAT;

macro_rules! shader_source {
    ($name:literal) => {
        concat!(include_str!("../../shaders/frame.wgsl"), "\n", include_str!(concat!("../../shaders/", $name, ".wgsl")))
    };
}

/// Shader sources by pipeline name (this order is relied on in `Pipelines::new`).
pub const SHADERS: [(&str, &str); 7] = [
    ("shadow", shader_source!("shadow")),
    ("flat", shader_source!("flat")),
    ("grid", shader_source!("grid")),
    ("mesh", shader_source!("mesh")),
    ("decal", shader_source!("decal")),
    ("overlay", shader_source!("overlay")),
    ("feedback", shader_source!("feedback")),
];

#[derive(Debug)]
pub struct Pipelines {
    /// Group 0 of the main pass: uniforms, shadow map, comparison sampler.
    pub frame_layout: wgpu::BindGroupLayout,
    /// Group 0 of the shadow pass: uniforms only (the shadow map is the
    /// attachment there, so it cannot also be bound).
    pub shadow_pass_layout: wgpu::BindGroupLayout,
    /// Group 1 of the overlay pipeline: contact image and its sampler.
    pub overlay_layout: wgpu::BindGroupLayout,

    pub shadow_solid: wgpu::RenderPipeline,
    pub shadow_two_sided: wgpu::RenderPipeline,
    /// The table and boxes (flat faces, lit per face).
    pub flat: wgpu::RenderPipeline,
    pub grid: wgpu::RenderPipeline,
    pub mesh_solid: wgpu::RenderPipeline,
    pub mesh_two_sided: wgpu::RenderPipeline,
    pub decal: wgpu::RenderPipeline,
    pub overlay: wgpu::RenderPipeline,
    pub feedback_lines_hidden: wgpu::RenderPipeline,
    pub feedback_lines_visible: wgpu::RenderPipeline,
    pub feedback_cubes_hidden: wgpu::RenderPipeline,
    pub feedback_cubes_visible: wgpu::RenderPipeline,
}

/// What the pipelines are compiled against.
#[derive(Debug, Clone, Copy)]
pub struct PipelineConfig {
    pub color_format: wgpu::TextureFormat,
    pub sample_count: u32,
}

/// Depth state of one pipeline: test, write, bias.
struct Depth {
    compare: wgpu::CompareFunction,
    write: bool,
    bias: wgpu::DepthBiasState,
}

impl Depth {
    fn opaque() -> Self {
        Self { compare: wgpu::CompareFunction::Less, write: true, bias: wgpu::DepthBiasState::default() }
    }

    fn test_only(compare: wgpu::CompareFunction) -> Self {
        Self { compare, write: false, bias: wgpu::DepthBiasState::default() }
    }

    fn state(self) -> wgpu::DepthStencilState {
        wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(self.write),
            depth_compare: Some(self.compare),
            stencil: wgpu::StencilState::default(),
            bias: self.bias,
        }
    }
}

/// One pipeline's description, turned into a `RenderPipelineDescriptor`.
struct Spec<'a> {
    label: &'a str,
    layout: &'a wgpu::PipelineLayout,
    module: &'a wgpu::ShaderModule,
    vs: &'a str,
    /// `None`: depth only.
    fs: Option<&'a str>,
    buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>],
    cull: Option<wgpu::Face>,
    depth: Depth,
    blend: Option<wgpu::BlendState>,
    sample_count: u32,
}

fn build(device: &wgpu::Device, color_format: wgpu::TextureFormat, spec: Spec<'_>) -> wgpu::RenderPipeline {
    let targets =
        [Some(wgpu::ColorTargetState { format: color_format, blend: spec.blend, write_mask: wgpu::ColorWrites::ALL })];
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(spec.label),
        layout: Some(spec.layout),
        vertex: wgpu::VertexState {
            module: spec.module,
            entry_point: Some(spec.vs),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            buffers: spec.buffers,
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            front_face: wgpu::FrontFace::Ccw,
            cull_mode: spec.cull,
            ..Default::default()
        },
        depth_stencil: Some(spec.depth.state()),
        multisample: wgpu::MultisampleState { count: spec.sample_count, ..Default::default() },
        fragment: spec.fs.map(|entry| wgpu::FragmentState {
            module: spec.module,
            entry_point: Some(entry),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            targets: &targets,
        }),
        multiview_mask: None,
        cache: None,
    })
}

fn shader(device: &wgpu::Device, (name, source): (&str, &'static str)) -> wgpu::ShaderModule {
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(&format!("{name}.wgsl")),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    })
}

fn layout_entry(binding: u32, visibility: wgpu::ShaderStages, ty: wgpu::BindingType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry { binding, visibility, ty, count: None }
}

fn uniform_entry() -> wgpu::BindGroupLayoutEntry {
    layout_entry(
        0,
        wgpu::ShaderStages::VERTEX_FRAGMENT,
        wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
    )
}

/// The frame's bind groups: the main pass's (uniforms, shadow map and its
/// comparison sampler), the shadow pass's (uniforms) and the contact
/// image overlay's (texture and sampler).
fn bind_group_layouts(device: &wgpu::Device) -> [wgpu::BindGroupLayout; 3] {
    let frame_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("frame bind group layout"),
        entries: &[
            uniform_entry(),
            layout_entry(
                1,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Depth,
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
            ),
            layout_entry(
                2,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
            ),
        ],
    });
    let shadow_pass_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("shadow pass bind group layout"),
        entries: &[uniform_entry()],
    });
    let overlay_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("contact image bind group layout"),
        entries: &[
            layout_entry(
                0,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: true },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
            ),
            layout_entry(
                1,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            ),
        ],
    });
    [frame_layout, shadow_pass_layout, overlay_layout]
}

impl Pipelines {
    pub fn new(device: &wgpu::Device, config: PipelineConfig) -> Self {
        use wgpu::CompareFunction::Always;
        let [frame_layout, shadow_pass_layout, overlay_layout] = bind_group_layouts(device);
        let pipeline_layout = |label: &str, groups: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(label),
                bind_group_layouts: groups,
                immediate_size: 0,
            })
        };
        let shadow_layout = pipeline_layout("shadow pipeline layout", &[Some(&shadow_pass_layout)]);
        let main_layout = pipeline_layout("main pass pipeline layout", &[Some(&frame_layout)]);
        let overlay_pipeline_layout =
            pipeline_layout("overlay pipeline layout", &[Some(&frame_layout), Some(&overlay_layout)]);

        let [shadow_module, flat_module, grid_module, mesh_module, decal_module, overlay_module, feedback_module] =
            SHADERS.map(|named| shader(device, named));

        let mesh_buffers = [Some(Vertex::layout()), Some(ObjectInstance::layout())];
        let samples = config.sample_count;
        let format = config.color_format;
        let alpha = Some(wgpu::BlendState::ALPHA_BLENDING);

        let shadow = |label, cull| {
            build(
                device,
                format,
                Spec {
                    label,
                    layout: &shadow_layout,
                    module: &shadow_module,
                    vs: "vs_main",
                    fs: None,
                    buffers: &mesh_buffers,
                    cull,
                    // Slope-scaled bias against acne on surfaces grazing the
                    // light; the shader's normal offset does the rest.
                    depth: Depth {
                        bias: wgpu::DepthBiasState { constant: 2, slope_scale: 2.0, clamp: 0.0 },
                        ..Depth::opaque()
                    },
                    blend: None,
                    sample_count: 1,
                },
            )
        };
        let main = MainPass { device, format, samples, layout: &main_layout };
        let mesh = |label, cull| main.mesh(&mesh_module, &mesh_buffers, label, cull);
        let [flat, grid, decal] = main.surfaces(&flat_module, &grid_module, &decal_module, &mesh_buffers);
        let [feedback_lines_hidden, feedback_lines_visible, feedback_cubes_hidden, feedback_cubes_visible] =
            main.feedback(&feedback_module);
        Self {
            shadow_solid: shadow("shadow pipeline (solid)", Some(wgpu::Face::Back)),
            shadow_two_sided: shadow("shadow pipeline (two-sided)", None),
            mesh_solid: mesh("mesh pipeline (solid)", Some(wgpu::Face::Back)),
            mesh_two_sided: mesh("mesh pipeline (two-sided)", None),
            flat,
            grid,
            decal,
            overlay: build(
                device,
                format,
                Spec {
                    label: "overlay pipeline",
                    layout: &overlay_pipeline_layout,
                    module: &overlay_module,
                    vs: "vs_main",
                    fs: Some("fs_main"),
                    buffers: &[Some(OverlayRegion::layout())],
                    cull: None,
                    // The hands are on the glass, above everything the table shows:
                    // drawn over objects (no depth test), never hidden by them.
                    depth: Depth::test_only(Always),
                    blend: alpha,
                    sample_count: samples,
                },
            ),
            feedback_lines_hidden,
            feedback_lines_visible,
            feedback_cubes_hidden,
            feedback_cubes_visible,
            frame_layout,
            shadow_pass_layout,
            overlay_layout,
        }
    }
}

/// What every pipeline of the main pass shares.
struct MainPass<'a> {
    device: &'a wgpu::Device,
    format: wgpu::TextureFormat,
    samples: u32,
    layout: &'a wgpu::PipelineLayout,
}

impl MainPass<'_> {
    /// Meshes (spheres, cylinders, soft bodies), culled or two-sided.
    fn mesh(
        &self,
        module: &wgpu::ShaderModule,
        buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
        label: &str,
        cull: Option<wgpu::Face>,
    ) -> wgpu::RenderPipeline {
        build(
            self.device,
            self.format,
            Spec {
                label,
                layout: self.layout,
                module,
                vs: "vs_main",
                fs: Some("fs_main"),
                buffers,
                cull,
                depth: Depth::opaque(),
                blend: None,
                sample_count: self.samples,
            },
        )
    }

    /// The table's flat faces, its grid strips and the zone decals.
    fn surfaces(
        &self,
        flat_module: &wgpu::ShaderModule,
        grid_module: &wgpu::ShaderModule,
        decal_module: &wgpu::ShaderModule,
        mesh_buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
    ) -> [wgpu::RenderPipeline; 3] {
        use wgpu::CompareFunction::LessEqual;
        let alpha = Some(wgpu::BlendState::ALPHA_BLENDING);
        let flat = build(
            self.device,
            self.format,
            Spec {
                label: "flat pipeline",
                layout: self.layout,
                module: flat_module,
                vs: "vs_main",
                fs: Some("fs_main"),
                buffers: mesh_buffers,
                cull: Some(wgpu::Face::Back),
                depth: Depth::opaque(),
                blend: None,
                sample_count: self.samples,
            },
        );
        let grid = build(
            self.device,
            self.format,
            Spec {
                label: "grid pipeline",
                layout: self.layout,
                module: grid_module,
                vs: "vs_main",
                fs: Some("fs_main"),
                buffers: &[Some(StripInstance::layout())],
                cull: None,
                depth: Depth::test_only(LessEqual),
                // Multiplicative: the strip darkens what the table shows.
                blend: Some(wgpu::BlendState {
                    color: wgpu::BlendComponent {
                        src_factor: wgpu::BlendFactor::Dst,
                        dst_factor: wgpu::BlendFactor::Zero,
                        operation: wgpu::BlendOperation::Add,
                    },
                    alpha: wgpu::BlendComponent {
                        src_factor: wgpu::BlendFactor::Zero,
                        dst_factor: wgpu::BlendFactor::One,
                        operation: wgpu::BlendOperation::Add,
                    },
                }),
                sample_count: self.samples,
            },
        );
        let decal = build(
            self.device,
            self.format,
            Spec {
                label: "decal pipeline",
                layout: self.layout,
                module: decal_module,
                vs: "vs_main",
                fs: Some("fs_main"),
                buffers: &[Some(DecalInstance::layout())],
                cull: None,
                depth: Depth::test_only(LessEqual),
                blend: alpha,
                sample_count: self.samples,
            },
        );
        [flat, grid, decal]
    }

    /// The technique's feedback: lines and cubes, each in a pass for the
    /// parts hidden behind objects and one for the visible parts.
    fn feedback(&self, feedback_module: &wgpu::ShaderModule) -> [wgpu::RenderPipeline; 4] {
        use wgpu::CompareFunction::{Greater, LessEqual};
        let alpha = Some(wgpu::BlendState::ALPHA_BLENDING);
        let line_buffers = [Some(LineInstance::layout())];
        let cube_buffers = [Some(Vertex::layout()), Some(CubeInstance::layout())];
        // Lines are quads whose winding depends on the screen direction, so
        // they are not culled; cubes are.
        let feedback = |label, vs, fs, buffers, cull, compare, write| {
            build(
                self.device,
                self.format,
                Spec {
                    label,
                    layout: self.layout,
                    module: feedback_module,
                    vs,
                    fs: Some(fs),
                    buffers,
                    cull,
                    depth: Depth { write, ..Depth::test_only(compare) },
                    blend: alpha,
                    sample_count: self.samples,
                },
            )
        };
        let back = Some(wgpu::Face::Back);
        let lines_hidden = feedback(
            "feedback lines pipeline (hidden parts)",
            "vs_line",
            "fs_hidden",
            &line_buffers,
            None,
            Greater,
            false,
        );
        let lines_visible = feedback(
            "feedback lines pipeline (visible parts)",
            "vs_line",
            "fs_visible",
            &line_buffers,
            None,
            LessEqual,
            true,
        );
        let cubes_hidden = feedback(
            "feedback cubes pipeline (hidden parts)",
            "vs_cube",
            "fs_hidden",
            &cube_buffers,
            back,
            Greater,
            false,
        );
        let cubes_visible = feedback(
            "feedback cubes pipeline (visible parts)",
            "vs_cube",
            "fs_visible",
            &cube_buffers,
            back,
            LessEqual,
            true,
        );
        [lines_hidden, lines_visible, cubes_hidden, cubes_visible]
    }
}

#[cfg(test)]
mod tests {
    use super::SHADERS;
    use wgpu::naga;

    /// Every shader parses and validates without a GPU, so a broken shader
    /// fails here with a readable message, not at pipeline creation.
    #[test]
    fn shaders_validate() {
        for (name, source) in SHADERS {
            let module = naga::front::wgsl::parse_str(source)
                .unwrap_or_else(|e| panic!("{name}.wgsl: {}", e.emit_to_string(source)));
            naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
                .validate(&module)
                .unwrap_or_else(|e| panic!("{name}.wgsl: {}", e.emit_to_string(source)));
        }
    }
}
