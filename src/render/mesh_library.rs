//! The unit meshes on the GPU, plus capsules cached by size.

use std::collections::HashMap;

use wgpu::util::DeviceExt;

use crate::render::draw_list::MeshKind;
use crate::render::mesh::{self, MeshData};

/// A mesh uploaded once.
#[derive(Debug)]
pub struct GpuMesh {
    pub vertices: wgpu::Buffer,
    pub indices: wgpu::Buffer,
    pub index_count: u32,
}

impl GpuMesh {
    pub fn upload(device: &wgpu::Device, name: &str, data: &MeshData) -> Self {
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(&format!("{name} vertices")),
            contents: bytemuck::cast_slice(&data.vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(&format!("{name} indices")),
            contents: bytemuck::cast_slice(&data.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self { vertices, indices, index_count: data.indices.len() as u32 }
    }
}

/// Capsules are not uniformly scalable, so each size is its own mesh. The
/// key is the exact bit pattern of (radius, half height): a scene has a few
/// sizes, all stable from frame to frame.
pub type CapsuleKey = (u32, u32);

/// Which mesh a batch of instances uses (resolved by [`MeshLibrary::get`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshRef {
    Box,
    Sphere,
    Cylinder,
    Capsule(CapsuleKey),
}

/// Capsule sizes unused for this many frames are dropped.
const CAPSULE_IDLE_FRAMES: u64 = 600;

#[derive(Debug)]
pub struct MeshLibrary {
    cube: GpuMesh,
    sphere: GpuMesh,
    cylinder: GpuMesh,
    capsules: HashMap<CapsuleKey, (GpuMesh, u64)>,
    frame: u64,
}

impl MeshLibrary {
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            cube: GpuMesh::upload(device, "unit box", &mesh::unit_box()),
            sphere: GpuMesh::upload(device, "unit sphere", &mesh::unit_sphere()),
            cylinder: GpuMesh::upload(device, "unit cylinder", &mesh::unit_cylinder()),
            capsules: HashMap::new(),
            frame: 0,
        }
    }

    /// Starts a frame: forgets capsule sizes idle for a long time.
    pub fn begin_frame(&mut self) {
        self.frame += 1;
        let now = self.frame;
        self.capsules.retain(|_, (_, last_used)| now - *last_used <= CAPSULE_IDLE_FRAMES);
    }

    /// The mesh for `kind`, uploading a capsule of a new size on first use.
    pub fn resolve(&mut self, device: &wgpu::Device, kind: MeshKind) -> MeshRef {
        match kind {
            MeshKind::Box => MeshRef::Box,
            MeshKind::Sphere => MeshRef::Sphere,
            MeshKind::Cylinder => MeshRef::Cylinder,
            MeshKind::Capsule { radius, half_height } => {
                let radius = if radius.is_finite() { radius.abs() } else { 0.0 };
                let half_height = if half_height.is_finite() { half_height.max(0.0) } else { 0.0 };
                let key = (radius.to_bits(), half_height.to_bits());
                let frame = self.frame;
                self.capsules.entry(key).and_modify(|(_, last_used)| *last_used = frame).or_insert_with(|| {
                    let name = format!("capsule r={radius} h={half_height}");
                    (GpuMesh::upload(device, &name, &mesh::capsule(radius, half_height)), frame)
                });
                MeshRef::Capsule(key)
            }
        }
    }

    /// A mesh resolved this frame (an unknown capsule falls back to the box).
    pub fn get(&self, mesh: MeshRef) -> &GpuMesh {
        match mesh {
            MeshRef::Box => &self.cube,
            MeshRef::Sphere => &self.sphere,
            MeshRef::Cylinder => &self.cylinder,
            MeshRef::Capsule(key) => self.capsules.get(&key).map_or(&self.cube, |(m, _)| m),
        }
    }

    pub fn cached_capsules(&self) -> usize {
        self.capsules.len()
    }
}
