//! How a record in a vertex buffer is laid out for the vertex shaders.

use bytemuck::Pod;

/// A `#[repr(C)]` record the vertex shaders read from a buffer. Its
/// attributes give each field's `@location` and format; the buffer layout
/// follows from them, the record's size and whether it advances per vertex or
/// per instance, so no record spells its layout out by hand.
pub trait GpuRecord: Pod {
    /// The fields' `@location`s and formats, in field order.
    const ATTRIBUTES: &'static [wgpu::VertexAttribute];
    /// Per instance unless the record is a mesh vertex.
    const STEP: wgpu::VertexStepMode = wgpu::VertexStepMode::Instance;

    fn layout() -> wgpu::VertexBufferLayout<'static> {
        wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<Self>() as wgpu::BufferAddress,
            step_mode: Self::STEP,
            attributes: Self::ATTRIBUTES,
        }
    }
}
