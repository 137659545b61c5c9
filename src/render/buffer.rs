//! A GPU buffer rewritten every frame that grows (never shrinks) to fit.

/// Holds per-frame data (instances, deformable vertices). Reallocates to the
/// next power of two when the data outgrows it, so steady scenes stop
/// allocating after the first frames.
#[derive(Debug)]
pub struct GrowableBuffer {
    label: &'static str,
    usage: wgpu::BufferUsages,
    buffer: wgpu::Buffer,
    /// Bytes written by the last `write`.
    len: u64,
}

impl GrowableBuffer {
    pub fn new(device: &wgpu::Device, label: &'static str, usage: wgpu::BufferUsages) -> Self {
        let usage = usage | wgpu::BufferUsages::COPY_DST;
        Self { label, usage, buffer: Self::allocate(device, label, usage, 1024), len: 0 }
    }

    fn allocate(device: &wgpu::Device, label: &str, usage: wgpu::BufferUsages, size: u64) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor { label: Some(label), size, usage, mapped_at_creation: false })
    }

    /// Replaces the contents with `data`.
    pub fn write(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, data: &[u8]) {
        let needed = data.len() as u64;
        if needed > self.buffer.size() {
            self.buffer = Self::allocate(device, self.label, self.usage, needed.next_power_of_two());
        }
        // write_buffer needs a multiple of 4 bytes; every record here is.
        debug_assert_eq!(needed % wgpu::COPY_BUFFER_ALIGNMENT, 0);
        if needed > 0 {
            queue.write_buffer(&self.buffer, 0, data);
        }
        self.len = needed;
    }

    /// The bytes written last, for `set_vertex_buffer`/`set_index_buffer`.
    pub fn slice(&self) -> wgpu::BufferSlice<'_> {
        self.buffer.slice(..self.len.max(4))
    }
}
