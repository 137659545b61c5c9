//! Per-frame data: what `Renderer::prepare` uploads from a [`DrawList`] and
//! `Renderer::paint` draws. Its buffers are reused from frame to frame.

use std::ops::Range;

use crate::render::buffer::GrowableBuffer;
use crate::render::draw_list::DrawList;
use crate::render::error::RenderError;
use crate::render::instances::{DecalInstance, ObjectInstance, OverlayRegion, feedback_instances, table_markings};
use crate::render::mesh::{Vertex, vertex_normals};
use crate::render::mesh_library::{MeshLibrary, MeshRef};

/// Instances sharing one mesh, drawn with one call.
#[derive(Debug, Clone, PartialEq)]
pub struct Batch {
    pub mesh: MeshRef,
    pub instances: Range<u32>,
}

/// Where the table's instance is in the object buffer (it is drawn with the
/// unit box and its own pipeline, and casts no shadow worth a pass).
pub const TABLE_INSTANCE: u32 = 0;

/// One deformable inside the shared deformable buffers.
#[derive(Debug, Clone, PartialEq)]
pub struct DeformableRange {
    pub indices: Range<u32>,
    pub base_vertex: i32,
    /// Its instance (identity transform, its colour) in the object buffer.
    pub instance: u32,
}

#[derive(Debug)]
pub struct FrameData {
    pub objects: GrowableBuffer,
    pub batches: Vec<Batch>,
    pub deformable_vertices: GrowableBuffer,
    pub deformable_indices: GrowableBuffer,
    pub deformables: Vec<DeformableRange>,
    pub decals: GrowableBuffer,
    pub decal_count: u32,
    pub lines: GrowableBuffer,
    pub line_count: u32,
    pub cubes: GrowableBuffer,
    pub cube_count: u32,
    pub strips: GrowableBuffer,
    pub strip_count: u32,
    /// One [`OverlayRegion`] when the contact image has contact.
    pub overlay_region: GrowableBuffer,
    pub show_overlay: bool,
}

impl FrameData {
    pub fn new(device: &wgpu::Device) -> Self {
        let vertex = wgpu::BufferUsages::VERTEX;
        Self {
            objects: GrowableBuffer::new(device, "object instances", vertex),
            batches: Vec::new(),
            deformable_vertices: GrowableBuffer::new(device, "deformable vertices", vertex),
            deformable_indices: GrowableBuffer::new(device, "deformable indices", wgpu::BufferUsages::INDEX),
            deformables: Vec::new(),
            decals: GrowableBuffer::new(device, "decal instances", vertex),
            decal_count: 0,
            lines: GrowableBuffer::new(device, "feedback line instances", vertex),
            line_count: 0,
            cubes: GrowableBuffer::new(device, "feedback cube instances", vertex),
            cube_count: 0,
            strips: GrowableBuffer::new(device, "table marking instances", vertex),
            strip_count: 0,
            overlay_region: GrowableBuffer::new(device, "contact region instance", vertex),
            show_overlay: false,
        }
    }

    /// Uploads everything `list` draws except the uniforms and the contact image.
    pub fn upload(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        meshes: &mut MeshLibrary,
        list: &DrawList,
        line_px: f32,
    ) {
        // The table, then the objects grouped by mesh (first-seen order, so
        // the output does not depend on hashing).
        let mut groups: Vec<(MeshRef, Vec<ObjectInstance>)> = Vec::new();
        for object in &list.objects {
            if !object.transform.is_finite() {
                continue;
            }
            let mesh = meshes.resolve(device, object.mesh);
            let instance = ObjectInstance::object(object);
            match groups.iter_mut().find(|(m, _)| *m == mesh) {
                Some((_, list)) => list.push(instance),
                None => groups.push((mesh, vec![instance])),
            }
        }
        let mut instances = vec![ObjectInstance::table(&list.table)];
        debug_assert_eq!(instances.len() as u32, TABLE_INSTANCE + 1);
        self.batches.clear();
        for (mesh, group) in groups {
            let start = instances.len() as u32;
            instances.extend(group);
            self.batches.push(Batch { mesh, instances: start..instances.len() as u32 });
        }

        // Deformables: one vertex and one index buffer for all, normals
        // recomputed from this frame's positions.
        let mut vertices: Vec<Vertex> = Vec::new();
        let mut indices: Vec<u32> = Vec::new();
        self.deformables.clear();
        for d in &list.deformables {
            let normals = vertex_normals(&d.positions, &d.triangles);
            let base_vertex = vertices.len() as i32;
            vertices.extend(d.positions.iter().zip(&normals).map(|(&p, &n)| Vertex::new(p, n)));
            let start = indices.len() as u32;
            indices.extend(d.triangles.iter().flatten());
            let instance = instances.len() as u32;
            instances.push(ObjectInstance::deformable(d.color));
            self.deformables.push(DeformableRange { indices: start..indices.len() as u32, base_vertex, instance });
        }
        self.objects.write(device, queue, bytemuck::cast_slice(&instances));
        self.deformable_vertices.write(device, queue, bytemuck::cast_slice(&vertices));
        self.deformable_indices.write(device, queue, bytemuck::cast_slice(&indices));

        let decals: Vec<DecalInstance> = list.decals.iter().map(DecalInstance::new).collect();
        self.decals.write(device, queue, bytemuck::cast_slice(&decals));
        self.decal_count = decals.len() as u32;

        let (lines, cubes) = feedback_instances(&list.feedback, line_px);
        self.lines.write(device, queue, bytemuck::cast_slice(&lines));
        self.line_count = lines.len() as u32;
        self.cubes.write(device, queue, bytemuck::cast_slice(&cubes));
        self.cube_count = cubes.len() as u32;

        let strips = table_markings(&list.table);
        self.strips.write(device, queue, bytemuck::cast_slice(&strips));
        self.strip_count = strips.len() as u32;

        let region = list.contact_overlay.as_ref().and_then(OverlayRegion::of);
        self.show_overlay = region.is_some();
        if let Some(region) = region {
            self.overlay_region.write(device, queue, bytemuck::bytes_of(&region));
        }
    }
}

/// Rejects draw lists the GPU code cannot draw meaningfully.
pub fn validate(list: &DrawList) -> Result<(), RenderError> {
    let bad = |msg: String| Err(RenderError::InvalidDrawList(msg));
    if !(list.table.width > 0.0 && list.table.depth > 0.0) {
        return bad(format!("table size {} x {} must be positive", list.table.width, list.table.depth));
    }
    if !list.camera.eye.is_finite() || !list.camera.target.is_finite() || list.camera.eye == list.camera.target {
        return bad(format!(
            "camera eye {} and target {} must be finite and distinct",
            list.camera.eye, list.camera.target
        ));
    }
    for (i, d) in list.deformables.iter().enumerate() {
        let n = d.positions.len();
        if let Some(t) = d.triangles.iter().find(|t| t.iter().any(|&v| v as usize >= n)) {
            return bad(format!("deformable {i}: triangle {t:?} indexes past its {n} vertices"));
        }
        if d.positions.iter().any(|p| !p.is_finite()) {
            return bad(format!("deformable {i} has a non-finite vertex"));
        }
    }
    if let Some(o) = &list.contact_overlay
        && (o.width == 0 || o.height == 0 || o.pixels.len() != o.width as usize * o.height as usize)
    {
        return bad(format!(
            "contact overlay is {}x{} but has {} pixels (one byte per pixel expected)",
            o.width,
            o.height,
            o.pixels.len()
        ));
    }
    Ok(())
}
