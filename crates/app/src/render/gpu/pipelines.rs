//! The GPU programs of the 3-D view: `scene.wgsl` (lit capsules and spheres,
//! the ground with its fading grid, the terrain's triangles, blob shadows and
//! contact marks, lines) and
//! `composite.wgsl` (the resolved scene onto egui's pass), with their bind
//! group layouts, vertex layouts, blend and depth states and render pipelines.
//!
//! WebGL2 limits shape them: vertex + instance buffers and one uniform buffer
//! at offset 0, no storage buffers, no flat varyings.

use egui_wgpu::wgpu;

use super::formats::{PassFormat, SCENE_COLOR_FORMAT, SCENE_DEPTH_FORMAT};
use super::globals::Globals;
use crate::render::scene::{Capsule, GroundMark, Segment};

/// Bind group layouts, the compositing sampler and the pipelines shared by every view.
pub(super) struct Pipelines {
    /// Group 0 of the scene pipelines: the view's [`Globals`].
    pub(super) globals_layout: wgpu::BindGroupLayout,
    /// Group 0 of the compositing pipeline: the resolved scene and its sampler.
    pub(super) composite_layout: wgpu::BindGroupLayout,
    /// Linear, clamped sampler of the resolved scene.
    pub(super) sampler: wgpu::Sampler,
    /// Every solid (capsules, and spheres as zero-length capsules), depth-writing.
    pub(super) capsule: wgpu::RenderPipeline,
    /// The ground plane with its fading grid (depth test only).
    pub(super) ground: wgpu::RenderPipeline,
    /// Ground that is not flat: the terrain's triangles (depth-writing).
    pub(super) terrain: wgpu::RenderPipeline,
    /// Blob shadows and contact marks (depth test, Min blend).
    pub(super) mark: wgpu::RenderPipeline,
    /// Screen-width lines (depth test, alpha blend).
    pub(super) line: wgpu::RenderPipeline,
    /// The scene's texture onto egui's pass (matches [`PassFormat`]).
    pub(super) composite: wgpu::RenderPipeline,
}

const fn vertex_layout(
    stride: usize,
    step_mode: wgpu::VertexStepMode,
    attributes: &[wgpu::VertexAttribute],
) -> wgpu::VertexBufferLayout<'_> {
    wgpu::VertexBufferLayout {
        array_stride: stride as wgpu::BufferAddress,
        step_mode,
        attributes,
    }
}

impl Pipelines {
    /// Compiles the shaders and builds the pipelines: the scene's for
    /// `samples` per pixel, the compositing one for egui's pass `pass`.
    pub(super) fn new(device: &wgpu::Device, pass: PassFormat, samples: u32) -> Self {
        let scene_shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("gaitlab scene"),
            source: wgpu::ShaderSource::Wgsl(include_str!("scene.wgsl").into()),
        });
        let composite_shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("gaitlab composite"),
            source: wgpu::ShaderSource::Wgsl(include_str!("composite.wgsl").into()),
        });

        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("gaitlab globals"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(size_of::<Globals>() as u64),
                },
                count: None,
            }],
        });
        let composite_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("gaitlab composite"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: true },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("gaitlab composite"),
            address_mode_u: wgpu::AddressMode::ClampToEdge,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            address_mode_w: wgpu::AddressMode::ClampToEdge,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..wgpu::SamplerDescriptor::default()
        });

        let scene_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("gaitlab scene"),
            bind_group_layouts: &[Some(&globals_layout)],
            immediate_size: 0,
        });
        let composite_pipeline_layout =
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("gaitlab composite"),
                bind_group_layouts: &[Some(&composite_layout)],
                immediate_size: 0,
            });

        let mesh_layout = vertex_layout(
            size_of::<[f32; 4]>(),
            wgpu::VertexStepMode::Vertex,
            &wgpu::vertex_attr_array![0 => Float32x4],
        );
        let capsule_attributes =
            wgpu::vertex_attr_array![1 => Float32x4, 2 => Float32x4, 3 => Float32x4];
        let pair_attributes = wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4];
        let line_attributes =
            wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4, 2 => Float32x4];
        let capsule_layout = vertex_layout(
            size_of::<Capsule>(),
            wgpu::VertexStepMode::Instance,
            &capsule_attributes,
        );
        let mark_layout = vertex_layout(
            size_of::<GroundMark>(),
            wgpu::VertexStepMode::Instance,
            &pair_attributes,
        );
        let line_layout = vertex_layout(
            size_of::<Segment>(),
            wgpu::VertexStepMode::Instance,
            &line_attributes,
        );

        let depth = |write: bool| {
            Some(wgpu::DepthStencilState {
                format: SCENE_DEPTH_FORMAT,
                depth_write_enabled: Some(write),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState::default(),
            })
        };
        let alpha_blend = Some(wgpu::BlendState::ALPHA_BLENDING);
        let min_blend = Some(wgpu::BlendState {
            color: wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::One,
                dst_factor: wgpu::BlendFactor::One,
                operation: wgpu::BlendOperation::Min,
            },
            alpha: wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::One,
                dst_factor: wgpu::BlendFactor::One,
                operation: wgpu::BlendOperation::Max,
            },
        });
        let scene_pipeline = |label: &str,
                              vertex_entry: &str,
                              fragment_entry: &str,
                              buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
                              depth_write: bool,
                              blend: Option<wgpu::BlendState>| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&scene_layout),
                vertex: wgpu::VertexState {
                    module: &scene_shader,
                    entry_point: Some(vertex_entry),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    buffers,
                },
                // No culling: spheres and capsules are closed, and the ground and
                // quads are seen from both sides; depth testing does the rest.
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
                    cull_mode: None,
                    ..wgpu::PrimitiveState::default()
                },
                depth_stencil: depth(depth_write),
                multisample: wgpu::MultisampleState {
                    count: samples,
                    mask: !0,
                    alpha_to_coverage_enabled: false,
                },
                fragment: Some(wgpu::FragmentState {
                    module: &scene_shader,
                    entry_point: Some(fragment_entry),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: SCENE_COLOR_FORMAT,
                        blend,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let capsule_pipeline = scene_pipeline(
            "gaitlab solids",
            "vs_capsule",
            "fs_solid",
            &[Some(mesh_layout), Some(capsule_layout)],
            true,
            None,
        );
        let ground_pipeline =
            scene_pipeline("gaitlab ground", "vs_ground", "fs_ground", &[], false, None);
        let terrain_layout = vertex_layout(
            size_of::<[f32; 4]>(),
            wgpu::VertexStepMode::Vertex,
            &wgpu::vertex_attr_array![0 => Float32x4],
        );
        let terrain_pipeline = scene_pipeline(
            "gaitlab terrain",
            "vs_terrain",
            "fs_terrain",
            &[Some(terrain_layout)],
            true,
            None,
        );
        let mark_pipeline = scene_pipeline(
            "gaitlab ground marks",
            "vs_mark",
            "fs_mark",
            &[Some(mark_layout)],
            false,
            min_blend,
        );
        let line_pipeline = scene_pipeline(
            "gaitlab lines",
            "vs_line",
            "fs_line",
            &[Some(line_layout)],
            false,
            alpha_blend,
        );

        let composite_pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("gaitlab composite"),
            layout: Some(&composite_pipeline_layout),
            vertex: wgpu::VertexState {
                module: &composite_shader,
                entry_point: Some("vs_composite"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                cull_mode: None,
                ..wgpu::PrimitiveState::default()
            },
            // egui's pass may carry a depth attachment: match its format, but
            // neither test nor write (the scene did its depth work offscreen).
            depth_stencil: pass.depth.map(|format| wgpu::DepthStencilState {
                format,
                depth_write_enabled: Some(false),
                depth_compare: Some(wgpu::CompareFunction::Always),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState::default(),
            }),
            multisample: wgpu::MultisampleState {
                count: pass.samples.max(1),
                mask: !0,
                alpha_to_coverage_enabled: false,
            },
            fragment: Some(wgpu::FragmentState {
                module: &composite_shader,
                entry_point: Some(if pass.color.is_srgb() {
                    "fs_composite_linear"
                } else {
                    "fs_composite_gamma"
                }),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: pass.color,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });

        Self {
            globals_layout,
            composite_layout,
            sampler,
            capsule: capsule_pipeline,
            ground: ground_pipeline,
            terrain: terrain_pipeline,
            mark: mark_pipeline,
            line: line_pipeline,
            composite: composite_pipeline,
        }
    }
}
