//! The unit capsule mesh ([`crate::render::mesh::capsule_mesh`]) on the GPU:
//! the vertex and index buffers every solid is instanced from.

use egui_wgpu::wgpu;
use wgpu::util::DeviceExt as _;

use crate::render::mesh;

/// Vertex and index buffers of the unit capsule.
pub(super) struct CapsuleMesh {
    /// `vec4` positions of the unit capsule.
    pub(super) vertices: wgpu::Buffer,
    /// `u16` triangle indices (padded to a multiple of 4 bytes).
    pub(super) indices: wgpu::Buffer,
    /// Indices to draw (the padding excluded).
    pub(super) index_count: u32,
}

impl CapsuleMesh {
    /// Builds the mesh at [`mesh::SEGMENTS`] × [`mesh::HEMISPHERE_RINGS`] and uploads it.
    pub(super) fn new(device: &wgpu::Device) -> Self {
        let (vertices, indices) = mesh::capsule_mesh(mesh::SEGMENTS, mesh::HEMISPHERE_RINGS);
        let mesh_vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("gaitlab capsule mesh"),
            contents: bytemuck::cast_slice(&vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        // Pad the index data to a multiple of 4 bytes (wgpu's copy alignment).
        let mut index_data: Vec<u16> = indices.clone();
        if index_data.len() % 2 == 1 {
            index_data.push(0);
        }
        let mesh_indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("gaitlab capsule mesh indices"),
            contents: bytemuck::cast_slice(&index_data),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self {
            vertices: mesh_vertices,
            indices: mesh_indices,
            index_count: u32::try_from(indices.len()).unwrap_or(0),
        }
    }
}
