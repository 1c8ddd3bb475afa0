//! One view's copy of the terrain's triangles on the GPU
//! ([`crate::render::scene::TerrainMesh`]): uploaded once per mesh (its id),
//! not per frame.

use egui_wgpu::wgpu;
use egui_wgpu::wgpu::util::DeviceExt as _;

use crate::render::scene::TerrainMesh;

/// The vertex and index buffers of the terrain a view draws.
#[derive(Default)]
pub(super) struct TerrainBuffers {
    buffers: Option<(wgpu::Buffer, wgpu::Buffer)>,
    /// Indices to draw (0: nothing, the floor).
    pub(super) count: u32,
    /// The mesh uploaded ([`TerrainMesh::id`]; 0 none).
    id: u64,
}

impl TerrainBuffers {
    /// Holds `mesh` on the GPU (uploading it when it is not the one held);
    /// `None` draws no terrain.
    pub(super) fn show(&mut self, device: &wgpu::Device, mesh: Option<&TerrainMesh>) {
        let Some(mesh) = mesh.filter(|m| !m.indices.is_empty()) else {
            self.buffers = None;
            self.count = 0;
            self.id = 0;
            return;
        };
        if mesh.id == self.id {
            return;
        }
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("gaitlab terrain vertices"),
            contents: bytemuck::cast_slice(&mesh.positions),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("gaitlab terrain indices"),
            contents: bytemuck::cast_slice(&mesh.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        self.buffers = Some((vertices, indices));
        self.count = u32::try_from(mesh.indices.len()).unwrap_or(0);
        self.id = mesh.id;
    }

    /// Draws the terrain held (call with the terrain pipeline set).
    pub(super) fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        if let Some((vertices, indices)) = &self.buffers
            && self.count > 0
        {
            pass.set_vertex_buffer(0, vertices.slice(..));
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..self.count, 0, 0..1);
        }
    }
}
