//! A vertex buffer of per-instance primitives (capsules, segments, ground
//! marks) that grows to the next power of two and never shrinks, so a steady
//! scene uploads without allocating.

use bytemuck::Pod;
use egui_wgpu::wgpu;

/// Smallest instance buffer, bytes.
const MIN_INSTANCE_BYTES: u64 = 4096;

/// A vertex/instance buffer that grows (to the next power of two) but never shrinks.
pub(super) struct InstanceBuffer {
    buffer: wgpu::Buffer,
    label: &'static str,
    /// Instances written by the last upload.
    pub(super) count: u32,
}

impl InstanceBuffer {
    pub(super) fn new(device: &wgpu::Device, label: &'static str) -> Self {
        Self {
            buffer: Self::create(device, label, MIN_INSTANCE_BYTES),
            label,
            count: 0,
        }
    }

    fn create(device: &wgpu::Device, label: &'static str, size: u64) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    pub(super) fn upload<T: Pod>(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        items: &[T],
    ) {
        let bytes: &[u8] = bytemuck::cast_slice(items);
        let needed = bytes.len() as u64;
        if needed > self.buffer.size() {
            let size = needed.next_power_of_two().max(MIN_INSTANCE_BYTES);
            self.buffer = Self::create(device, self.label, size);
        }
        if !bytes.is_empty() {
            queue.write_buffer(&self.buffer, 0, bytes);
        }
        self.count = u32::try_from(items.len()).unwrap_or(u32::MAX);
    }

    /// The uploaded part (call only when `count > 0`: empty slices are invalid).
    pub(super) fn slice<T>(&self) -> wgpu::BufferSlice<'_> {
        self.buffer
            .slice(..u64::from(self.count) * size_of::<T>() as u64)
    }
}
