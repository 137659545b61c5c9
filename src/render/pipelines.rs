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
    /// `flat` without the shadow lookup, for the table where no shadow can
    /// fall (`shadow_regions`).
    pub flat_unshadowed: wgpu::RenderPipeline,
    pub grid: wgpu::RenderPipeline,
    pub mesh_solid: wgpu::RenderPipeline,
    pub mesh_two_sided: wgpu::RenderPipeline,
    pub decal: wgpu::RenderPipeline,
    /// `decal` without the shadow lookups (`shadow_regions`).
    pub decal_unshadowed: wgpu::RenderPipeline,
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
#[derive(Clone, Copy)]
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

/// One pipeline's description, turned into a `RenderPipelineDescriptor`
/// by [`Pass::build`].
#[derive(Clone, Copy)]
struct Spec<'a> {
    label: &'a str,
    module: &'a wgpu::ShaderModule,
    vs: &'a str,
    /// `None`: depth only.
    fs: Option<&'a str>,
    buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>],
    cull: Option<wgpu::Face>,
    depth: Depth,
    blend: Option<wgpu::BlendState>,
}

impl<'a> Spec<'a> {
    /// `module`'s `vs_main` and `fs_main` drawing `buffers`: both faces,
    /// opaque depth, no blending.
    fn new(
        label: &'a str,
        module: &'a wgpu::ShaderModule,
        buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>],
    ) -> Self {
        Spec {
            label,
            module,
            vs: "vs_main",
            fs: Some("fs_main"),
            buffers,
            cull: None,
            depth: Depth::opaque(),
            blend: None,
        }
    }

    fn entry_points(self, vs: &'a str, fs: Option<&'a str>) -> Self {
        Spec { vs, fs, ..self }
    }

    fn cull(self, cull: Option<wgpu::Face>) -> Self {
        Spec { cull, ..self }
    }

    fn depth(self, depth: Depth) -> Self {
        Spec { depth, ..self }
    }

    fn blend(self, blend: Option<wgpu::BlendState>) -> Self {
        Spec { blend, ..self }
    }
}

/// What every pipeline of one render pass shares.
struct Pass<'a> {
    device: &'a wgpu::Device,
    format: wgpu::TextureFormat,
    samples: u32,
    layout: &'a wgpu::PipelineLayout,
}

impl Pass<'_> {
    fn build(&self, spec: Spec<'_>) -> wgpu::RenderPipeline {
        let targets = [Some(wgpu::ColorTargetState {
            format: self.format,
            blend: spec.blend,
            write_mask: wgpu::ColorWrites::ALL,
        })];
        self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(spec.label),
            layout: Some(self.layout),
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
            multisample: wgpu::MultisampleState { count: self.samples, ..Default::default() },
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

        // Slope-scaled bias against acne on surfaces grazing the light; the
        // shader's normal offset does the rest.
        let shadow_depth =
            || Depth { bias: wgpu::DepthBiasState { constant: 2, slope_scale: 2.0, clamp: 0.0 }, ..Depth::opaque() };
        let shadow_pass = Pass { device, format, samples: 1, layout: &shadow_layout };
        let shadow = |label, cull| {
            let spec = Spec::new(label, &shadow_module, &mesh_buffers).entry_points("vs_main", None);
            shadow_pass.build(spec.cull(cull).depth(shadow_depth()))
        };
        let main = Pass { device, format, samples, layout: &main_layout };
        let mesh = |label, cull| main.mesh(&mesh_module, &mesh_buffers, label, cull);
        let [flat, flat_unshadowed, grid, decal, decal_unshadowed] =
            main.surfaces(&flat_module, &grid_module, &decal_module, &mesh_buffers);
        let [feedback_lines_hidden, feedback_lines_visible, feedback_cubes_hidden, feedback_cubes_visible] =
            main.feedback(&feedback_module);
        let overlay_pass = Pass { device, format, samples, layout: &overlay_pipeline_layout };
        let overlay_buffers = [Some(OverlayRegion::layout())];
        Self {
            shadow_solid: shadow("shadow pipeline (solid)", Some(wgpu::Face::Back)),
            shadow_two_sided: shadow("shadow pipeline (two-sided)", None),
            mesh_solid: mesh("mesh pipeline (solid)", Some(wgpu::Face::Back)),
            mesh_two_sided: mesh("mesh pipeline (two-sided)", None),
            flat,
            flat_unshadowed,
            grid,
            decal,
            decal_unshadowed,
            // The hands are on the glass, above everything the table shows:
            // drawn over objects (no depth test), never hidden by them.
            overlay: overlay_pass.build(
                Spec::new("overlay pipeline", &overlay_module, &overlay_buffers)
                    .depth(Depth::test_only(Always))
                    .blend(alpha),
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

/// The main pass's pipelines.
impl Pass<'_> {
    /// Meshes (spheres, cylinders, soft bodies), culled or two-sided.
    fn mesh(
        &self,
        module: &wgpu::ShaderModule,
        buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
        label: &str,
        cull: Option<wgpu::Face>,
    ) -> wgpu::RenderPipeline {
        self.build(Spec::new(label, module, buffers).cull(cull))
    }

    /// The table's flat faces, its grid strips and the zone decals.
    fn surfaces(
        &self,
        flat_module: &wgpu::ShaderModule,
        grid_module: &wgpu::ShaderModule,
        decal_module: &wgpu::ShaderModule,
        mesh_buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
    ) -> [wgpu::RenderPipeline; 5] {
        use wgpu::CompareFunction::LessEqual;
        let flat = Spec::new("flat pipeline", flat_module, mesh_buffers).cull(Some(wgpu::Face::Back));
        let flat_unshadowed = self
            .build(Spec { label: "flat pipeline (unshadowed)", ..flat }.entry_points("vs_main", Some("fs_unshadowed")));
        let flat = self.build(flat);
        // Multiplicative: the strip darkens what the table shows.
        let darken = wgpu::BlendState {
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
        };
        let strip_buffers = [Some(StripInstance::layout())];
        let grid = Spec::new("grid pipeline", grid_module, &strip_buffers);
        let grid = self.build(grid.depth(Depth::test_only(LessEqual)).blend(Some(darken)));
        let decal_buffers = [Some(DecalInstance::layout())];
        let decal = Spec::new("decal pipeline", decal_module, &decal_buffers)
            .depth(Depth::test_only(LessEqual))
            .blend(Some(wgpu::BlendState::ALPHA_BLENDING));
        let decal_unshadowed = self.build(
            Spec { label: "decal pipeline (unshadowed)", ..decal }.entry_points("vs_main", Some("fs_unshadowed")),
        );
        let decal = self.build(decal);
        [flat, flat_unshadowed, grid, decal, decal_unshadowed]
    }

    /// The technique's feedback: lines and cubes, each in a pass for the
    /// parts hidden behind objects and one for the visible parts.
    fn feedback(&self, feedback_module: &wgpu::ShaderModule) -> [wgpu::RenderPipeline; 4] {
        use wgpu::CompareFunction::{Greater, LessEqual};
        let line_buffers = [Some(LineInstance::layout())];
        let cube_buffers = [Some(Vertex::layout()), Some(CubeInstance::layout())];
        // Hidden parts pass where something nearer is drawn and leave the
        // depth as it is; visible parts pass the usual test and write it.
        let feedback = |label, vs, buffers: &[Option<wgpu::VertexBufferLayout<'_>>], cull, hidden: bool| {
            let (fs, depth) = if hidden {
                ("fs_hidden", Depth::test_only(Greater))
            } else {
                ("fs_visible", Depth { write: true, ..Depth::test_only(LessEqual) })
            };
            let spec = Spec::new(label, feedback_module, buffers).entry_points(vs, Some(fs)).cull(cull);
            self.build(spec.depth(depth).blend(Some(wgpu::BlendState::ALPHA_BLENDING)))
        };
        // Lines are quads whose winding depends on the screen direction, so
        // they are not culled; cubes are.
        let back = Some(wgpu::Face::Back);
        [
            feedback("feedback lines pipeline (hidden parts)", "vs_line", &line_buffers, None, true),
            feedback("feedback lines pipeline (visible parts)", "vs_line", &line_buffers, None, false),
            feedback("feedback cubes pipeline (hidden parts)", "vs_cube", &cube_buffers, back, true),
            feedback("feedback cubes pipeline (visible parts)", "vs_cube", &cube_buffers, back, false),
        ]
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
