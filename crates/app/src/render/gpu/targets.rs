//! One view's GPU state: its offscreen targets (multisampled colour, resolved
//! colour, depth) at the view's size, its uniform buffer and its instance
//! buffers. Each side-by-side view keeps its own, so views never overwrite
//! each other's data within a frame.

use egui_wgpu::wgpu;

use super::formats::{SCENE_COLOR_FORMAT, SCENE_DEPTH_FORMAT};
use super::globals::Globals;
use super::instance_buffer::InstanceBuffer;
use super::pipelines::Pipelines;
use super::terrain_buffers::TerrainBuffers;

/// Views not drawn for this many egui frames give their GPU targets back.
pub(super) const STALE_FRAMES: u64 = 120;

/// One view's offscreen targets, uniforms and instance buffers.
pub(super) struct ViewTargets {
    pub(super) size: [u32; 2],
    /// Multisampled colour target (`None` without MSAA: draw straight into `color`).
    pub(super) msaa: Option<wgpu::TextureView>,
    /// Resolved colour, sampled by the compositing pass.
    pub(super) color: wgpu::TextureView,
    pub(super) depth: wgpu::TextureView,
    pub(super) composite: wgpu::BindGroup,
    pub(super) globals: wgpu::Buffer,
    pub(super) globals_group: wgpu::BindGroup,
    /// Capsules, then the spheres as zero-length capsules.
    pub(super) solids: InstanceBuffer,
    pub(super) segments: InstanceBuffer,
    pub(super) marks: InstanceBuffer,
    /// The terrain's triangles (none on the floor).
    pub(super) terrain: TerrainBuffers,
    /// egui frame number of the last prepare.
    pub(super) last_frame: u64,
}

/// The size-dependent part of [`ViewTargets`], made anew on a resize.
struct Textures {
    msaa: Option<wgpu::TextureView>,
    color: wgpu::TextureView,
    depth: wgpu::TextureView,
    composite: wgpu::BindGroup,
}

impl ViewTargets {
    /// Targets of `size` pixels with `samples` per pixel, bound with `pipelines`' layouts.
    pub(super) fn new(
        device: &wgpu::Device,
        pipelines: &Pipelines,
        samples: u32,
        size: [u32; 2],
    ) -> Self {
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("gaitlab globals"),
            size: size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let globals_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaitlab globals"),
            layout: &pipelines.globals_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals.as_entire_binding(),
            }],
        });
        let Textures {
            msaa,
            color,
            depth,
            composite,
        } = Textures::new(device, pipelines, samples, size);
        Self {
            size,
            msaa,
            color,
            depth,
            composite,
            globals,
            globals_group,
            solids: InstanceBuffer::new(device, "gaitlab solids"),
            segments: InstanceBuffer::new(device, "gaitlab segments"),
            marks: InstanceBuffer::new(device, "gaitlab ground marks"),
            terrain: TerrainBuffers::default(),
            last_frame: 0,
        }
    }

    /// Replaces the textures with new ones of `size` pixels.
    pub(super) fn resize(
        &mut self,
        device: &wgpu::Device,
        pipelines: &Pipelines,
        samples: u32,
        size: [u32; 2],
    ) {
        let textures = Textures::new(device, pipelines, samples, size);
        self.msaa = textures.msaa;
        self.color = textures.color;
        self.depth = textures.depth;
        self.composite = textures.composite;
        self.size = size;
    }
}

impl Textures {
    fn new(device: &wgpu::Device, pipelines: &Pipelines, samples: u32, size: [u32; 2]) -> Self {
        let extent = wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: 1,
        };
        let texture = |label: &str, format, samples, usage| {
            device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size: extent,
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage,
                    view_formats: &[],
                })
                .create_view(&wgpu::TextureViewDescriptor::default())
        };
        let msaa = (samples > 1).then(|| {
            texture(
                "gaitlab scene msaa",
                SCENE_COLOR_FORMAT,
                samples,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            )
        });
        let color = texture(
            "gaitlab scene color",
            SCENE_COLOR_FORMAT,
            1,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
        );
        let depth = texture(
            "gaitlab scene depth",
            SCENE_DEPTH_FORMAT,
            samples,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let composite = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaitlab composite"),
            layout: &pipelines.composite_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&color),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&pipelines.sampler),
                },
            ],
        });
        Self {
            msaa,
            color,
            depth,
            composite,
        }
    }
}
