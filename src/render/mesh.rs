//! Triangle meshes on the CPU: the unit shapes objects are instanced from, and
//! per-vertex normals for deformables. Pure functions; no GPU here.
//!
//! Winding: counter-clockwise seen from outside (the pipelines cull back faces
//! with `FrontFace::Ccw`).

use bytemuck::{Pod, Zeroable};
use glam::Vec3;

use crate::render::gpu_record::GpuRecord;
use std::f32::consts::{PI, TAU};

/// One mesh vertex as the vertex shaders read it (`@location(0)`, `@location(1)`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
}

impl GpuRecord for Vertex {
    const ATTRIBUTES: &'static [wgpu::VertexAttribute] = &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
    const STEP: wgpu::VertexStepMode = wgpu::VertexStepMode::Vertex;
}

impl Vertex {
    pub fn new(position: Vec3, normal: Vec3) -> Self {
        Self { position: position.to_array(), normal: normal.to_array() }
    }
}

/// An indexed triangle list.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshData {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

/// Segments around the axis of round shapes: smooth silhouettes for objects
/// up to ~150 px across. Small triangles are not free on lavapipe (it shades
/// whole 4x4 blocks), so 32 costs a little more per frame than 16.
const ROUND_SEGMENTS: u32 = 32;
/// Latitude bands of a sphere (and of the two halves of a capsule together).
const SPHERE_RINGS: u32 = 16;

/// A cube of side 1 centred at the origin, flat-shaded (24 vertices).
pub fn unit_box() -> MeshData {
    let mut mesh = MeshData::default();
    // Each face: its normal and two in-plane axes with `u × v = n`, so the
    // quad (−u−v, +u−v, +u+v, −u+v) is counter-clockwise seen from outside.
    for n in [Vec3::X, Vec3::NEG_X, Vec3::Y, Vec3::NEG_Y, Vec3::Z, Vec3::NEG_Z] {
        let u = if n.z.abs() > 0.5 { Vec3::X * n.z.signum() } else { Vec3::Z.cross(n) };
        let v = n.cross(u);
        let base = mesh.vertices.len() as u32;
        for (su, sv) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            mesh.vertices.push(Vertex::new(0.5 * (n + su * u + sv * v), n));
        }
        mesh.indices.extend([base, base + 1, base + 2, base, base + 2, base + 3]);
    }
    mesh
}

/// A sphere of radius 1 (UV sphere, smooth normals).
pub fn unit_sphere() -> MeshData {
    capsule(1.0, 0.0)
}

/// A cylinder of radius 1 and height 1 along z, centred at the origin, with
/// smooth sides and flat caps.
pub fn unit_cylinder() -> MeshData {
    let mut mesh = MeshData::default();
    let n = ROUND_SEGMENTS;
    // Side: two rings sharing radial normals.
    for i in 0..=n {
        let a = TAU * i as f32 / n as f32;
        let radial = Vec3::new(a.cos(), a.sin(), 0.0);
        mesh.vertices.push(Vertex::new(radial - 0.5 * Vec3::Z, radial));
        mesh.vertices.push(Vertex::new(radial + 0.5 * Vec3::Z, radial));
    }
    for i in 0..n {
        let (b0, t0, b1, t1) = (2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3);
        mesh.indices.extend([b0, b1, t1, b0, t1, t0]);
    }
    // Caps: a fan around a centre vertex each.
    for side in [1.0f32, -1.0] {
        let normal = Vec3::Z * side;
        let centre = mesh.vertices.len() as u32;
        mesh.vertices.push(Vertex::new(0.5 * normal, normal));
        for i in 0..n {
            let a = TAU * i as f32 / n as f32;
            mesh.vertices.push(Vertex::new(Vec3::new(a.cos(), a.sin(), 0.5 * side), normal));
        }
        for i in 0..n {
            let (p, q) = (centre + 1 + i, centre + 1 + (i + 1) % n);
            if side > 0.0 {
                mesh.indices.extend([centre, p, q]);
            } else {
                mesh.indices.extend([centre, q, p]);
            }
        }
    }
    mesh
}

/// A capsule along z: a cylinder of the given radius from −`half_height` to
/// +`half_height` closed by two hemispheres. `half_height = 0` is a sphere.
///
/// Built as a UV sphere whose upper half is lifted by `half_height` and lower
/// half lowered by it; the equator is duplicated so the side is a straight band.
pub fn capsule(radius: f32, half_height: f32) -> MeshData {
    let mut mesh = MeshData::default();
    let segments = ROUND_SEGMENTS;
    let half_rings = SPHERE_RINGS / 2;
    // Latitude rows from the north pole (row 0) to the south pole; with a
    // cylinder part the equator row appears twice (once per hemisphere).
    let mut rows: Vec<(f32, f32)> = Vec::new(); // (polar angle, z offset)
    for r in 0..=half_rings {
        rows.push((0.5 * PI * r as f32 / half_rings as f32, half_height));
    }
    // A sphere's two hemispheres share the equator row.
    let first_south = u32::from(half_height <= 0.0);
    for r in first_south..=half_rings {
        rows.push((0.5 * PI + 0.5 * PI * r as f32 / half_rings as f32, -half_height));
    }
    for &(polar, dz) in &rows {
        for i in 0..=segments {
            let a = TAU * i as f32 / segments as f32;
            let n = Vec3::new(polar.sin() * a.cos(), polar.sin() * a.sin(), polar.cos());
            mesh.vertices.push(Vertex::new(n * radius + Vec3::Z * dz, n));
        }
    }
    let stride = segments + 1;
    for row in 0..rows.len() as u32 - 1 {
        for i in 0..segments {
            let a = row * stride + i; // upper-left
            let b = a + stride; // lower-left
            // Rows go north to south and angles counter-clockwise seen from
            // +z, so (a, b, b+1) faces outwards.
            mesh.indices.extend([a, b, b + 1, a, b + 1, a + 1]);
        }
    }
    // The pole rows are degenerate (all vertices coincide); drop the zero-area
    // triangles they produce.
    let positions: Vec<Vec3> = mesh.vertices.iter().map(|v| Vec3::from(v.position)).collect();
    let tris: Vec<[u32; 3]> = mesh
        .indices
        .chunks_exact(3)
        .map(|t| [t[0], t[1], t[2]])
        .filter(|t| {
            let [p, q, r] = t.map(|i| positions[i as usize]);
            (q - p).cross(r - p).length_squared() > 1e-12 * radius.max(1e-3).powi(4)
        })
        .collect();
    mesh.indices = tris.into_iter().flatten().collect();
    mesh
}

/// Area-weighted vertex normals of a triangle soup. Vertices touched by no
/// (non-degenerate) triangle get +z, the table's normal.
///
/// Triangles with an index out of range are skipped; callers validate first.
pub fn vertex_normals(positions: &[Vec3], triangles: &[[u32; 3]]) -> Vec<Vec3> {
    let mut normals = vec![Vec3::ZERO; positions.len()];
    for t in triangles {
        let [i, j, k] = t.map(|i| i as usize);
        let (Some(&p), Some(&q), Some(&r)) = (positions.get(i), positions.get(j), positions.get(k)) else {
            continue;
        };
        // The cross product's length is twice the area: larger faces weigh more.
        let face = (q - p).cross(r - p);
        for &i in t {
            normals[i as usize] += face;
        }
    }
    normals.into_iter().map(|n| n.try_normalize().unwrap_or(Vec3::Z)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every triangle's geometric normal points away from the shape's centre.
    fn assert_outward(mesh: &MeshData, name: &str) {
        assert!(!mesh.indices.is_empty(), "{name} has no triangles");
        for t in mesh.indices.chunks_exact(3) {
            let [p, q, r] = [t[0], t[1], t[2]].map(|i| Vec3::from(mesh.vertices[i as usize].position));
            let face = (q - p).cross(r - p);
            let centroid = (p + q + r) / 3.0;
            assert!(face.dot(centroid) > 0.0, "{name}: inward triangle at {centroid}");
            let shading = Vec3::from(mesh.vertices[t[0] as usize].normal);
            assert!(shading.dot(face) > 0.0, "{name}: vertex normal disagrees with winding");
        }
    }

    #[test]
    fn unit_shapes_face_outwards() {
        assert_outward(&unit_box(), "box");
        assert_outward(&unit_sphere(), "sphere");
        assert_outward(&unit_cylinder(), "cylinder");
        assert_outward(&capsule(0.3, 0.5), "capsule");
    }

    #[test]
    fn unit_shapes_have_the_documented_extents() {
        let extent = |m: &MeshData| {
            m.vertices.iter().fold((Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)), |(lo, hi), v| {
                (lo.min(v.position.into()), hi.max(v.position.into()))
            })
        };
        let (lo, hi) = extent(&unit_box());
        assert!(lo.abs_diff_eq(Vec3::splat(-0.5), 1e-6) && hi.abs_diff_eq(Vec3::splat(0.5), 1e-6));
        let (lo, hi) = extent(&unit_sphere());
        assert!(lo.abs_diff_eq(Vec3::splat(-1.0), 1e-5) && hi.abs_diff_eq(Vec3::splat(1.0), 1e-5));
        let (lo, hi) = extent(&unit_cylinder());
        assert!(lo.abs_diff_eq(Vec3::new(-1.0, -1.0, -0.5), 1e-5));
        assert!(hi.abs_diff_eq(Vec3::new(1.0, 1.0, 0.5), 1e-5));
        let (lo, hi) = extent(&capsule(0.2, 0.3));
        assert!(lo.abs_diff_eq(Vec3::new(-0.2, -0.2, -0.5), 1e-5));
        assert!(hi.abs_diff_eq(Vec3::new(0.2, 0.2, 0.5), 1e-5));
    }

    #[test]
    fn normals_of_a_flat_sheet_point_along_its_winding() {
        let positions = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(1.0, 1.0, 0.0), Vec3::splat(9.0)];
        let normals = vertex_normals(&positions, &[[0, 1, 3], [0, 3, 2]]);
        for n in &normals[..4] {
            assert!(n.abs_diff_eq(Vec3::Z, 1e-6));
        }
        assert_eq!(normals[4], Vec3::Z, "unused vertex falls back to +z");
        let flipped = vertex_normals(&positions, &[[0, 3, 1]]);
        assert!(flipped[0].abs_diff_eq(Vec3::NEG_Z, 1e-6));
    }

    #[test]
    fn normals_skip_out_of_range_and_degenerate_triangles() {
        let positions = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let normals = vertex_normals(&positions, &[[0, 1, 7], [0, 0, 1]]);
        assert_eq!(normals, vec![Vec3::Z; 3]);
    }
}
