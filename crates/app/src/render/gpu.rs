//! The wgpu side of the 3-D view: pipelines, per-view render targets and
//! instance buffers, and the [`egui_wgpu::CallbackTrait`] that draws a
//! [`SceneFrame`](super::scene::SceneFrame).
//!
//! # How a frame is drawn
//! 1. [`install`] (once, at start-up) builds a [`SceneRenderer`] — shaders,
//!    pipelines, the unit capsule mesh — and stores it in egui-wgpu's
//!    [`egui_wgpu::CallbackResources`].
//! 2. [`super::viewport::show`] adds a [`SceneCallback`] holding an `Arc` of the
//!    frame's primitives and a copy of the camera.
//! 3. `prepare` (before egui's pass, on egui's encoder) uploads the uniforms
//!    and instance buffers, then renders the scene in its own pass into the
//!    view's offscreen targets: 4× multisampled colour (`Rgba8Unorm`, holding
//!    sRGB-encoded values) and depth (`Depth24Plus`, cleared to 1.0, compare
//!    `Less`), resolved into a sampleable texture. Draw order: lit capsules and
//!    spheres (depth write) → ground with fading grid (depth test only) → blob
//!    shadows (depth test, Min blend) → lines (depth test, alpha blend).
//! 4. `paint` (inside egui's pass, viewport already set to the callback rect)
//!    draws that texture with one triangle.
//!
//! # Depth
//! The scene owns its depth buffer, so it never depends on egui's pass having
//! one and can use MSAA even though egui's web pass has a single sample. Only
//! the compositing pipeline must match egui's pass: its colour format
//! (`RenderState::target_format`), sample count (1 on the web) and depth
//! format (`egui_wgpu::depth_format_from_bits(WebOptions::depth_buffer, 0)`,
//! e.g. `Depth24Plus` for `depth_buffer: 24`, `None` for 0); it neither tests
//! nor writes depth. [`PassFormat`] carries those three facts to [`install`].
//!
//! # WebGL2
//! Vertex + instance buffers and one uniform buffer per view at offset 0; no
//! storage buffers, no dynamic offsets, no flat varyings, no base instance;
//! texture sizes clamped to the device's `max_texture_dimension_2d`; MSAA only
//! where the device guarantees 4× for both target formats.

use std::collections::HashMap;
use std::sync::Arc;

use bytemuck::{Pod, Zeroable};
use egui_wgpu::wgpu;
use glam::Vec3;
use wgpu::util::DeviceExt as _;

use super::camera::Camera;
use super::mesh;
use super::scene::{Capsule, GROUND_Y, GroundMark, SHADOW_FADE_HEIGHT, SceneFrame, Segment};
use crate::view::ViewOptions;

/// Colour format of the offscreen scene target (holds sRGB-encoded values).
pub const SCENE_COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
/// Depth format of the offscreen scene target.
pub const SCENE_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24Plus;
/// Multisampling of the scene target where the device supports it.
pub const SCENE_MSAA_SAMPLES: u32 = 4;
/// Views not drawn for this many egui frames give their GPU targets back.
const STALE_FRAMES: u64 = 120;
/// Smallest instance buffer, bytes.
const MIN_INSTANCE_BYTES: u64 = 4096;

/// What egui's render pass looks like; the compositing pipeline must match it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PassFormat {
    /// Colour format of egui's target (`RenderState::target_format`).
    pub color: wgpu::TextureFormat,
    /// Depth format of egui's pass, or `None` without a depth attachment.
    pub depth: Option<wgpu::TextureFormat>,
    /// Sample count of egui's pass (1 on the web: eframe's web painter has no MSAA).
    pub samples: u32,
}

impl PassFormat {
    /// egui's pass in eframe: the render state's target format, no MSAA, and
    /// the depth format of `depth_buffer_bits` (eframe's `WebOptions::depth_buffer`
    /// / `NativeOptions::depth_buffer`, 0 for none).
    #[must_use]
    pub fn eframe(render_state: &egui_wgpu::RenderState, depth_buffer_bits: u8) -> Self {
        Self {
            color: render_state.target_format,
            depth: egui_wgpu::depth_format_from_bits(depth_buffer_bits, 0),
            samples: 1,
        }
    }
}

fn installed_id() -> egui::Id {
    egui::Id::unique("gaitlab-render-gpu-installed")
}

/// Builds the scene renderer for `render_state` and registers it with egui-wgpu,
/// so [`super::viewport::show`] draws with wgpu from now on (without it, the
/// view falls back to egui's 2-D painter). Call once, e.g. in eframe's app
/// creator: `install(&cc.egui_ctx, render_state, PassFormat::eframe(render_state, 24))`
/// where 24 is the `depth_buffer` given to eframe.
///
/// On a software rasterizer (a CPU adapter, e.g. SwiftShader in headless
/// browsers) the scene is drawn without MSAA, which costs 4× the fill there.
pub fn install(ctx: &egui::Context, render_state: &egui_wgpu::RenderState, pass: PassFormat) {
    let software = render_state.adapter.get_info().device_type == wgpu::DeviceType::Cpu;
    let max_samples = if software { 1 } else { SCENE_MSAA_SAMPLES };
    let scene = SceneRenderer::with_max_samples(&render_state.device, pass, max_samples);
    render_state
        .renderer
        .write()
        .callback_resources
        .insert(scene);
    mark_installed(ctx);
}

fn mark_installed(ctx: &egui::Context) {
    ctx.data_mut(|data| data.insert_temp(installed_id(), true));
}

/// [`install`] for a hand-made egui-wgpu setup (a headless test, another
/// integration): stores `scene` (built for that setup's device and pass) in
/// `resources`, the `callback_resources` of the `egui_wgpu::Renderer` that
/// paints `ctx`.
pub fn install_into(
    ctx: &egui::Context,
    resources: &mut egui_wgpu::CallbackResources,
    scene: SceneRenderer,
) {
    resources.insert(scene);
    mark_installed(ctx);
}

/// Whether [`install`] ran for this context.
#[must_use]
pub fn is_installed(ctx: &egui::Context) -> bool {
    ctx.data(|data| data.get_temp::<bool>(installed_id()))
        .unwrap_or(false)
}

/// Theme colours of the 3-D view (sRGB).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewStyle {
    /// Behind everything; the ground fades into it.
    pub background: [f32; 4],
    /// The ground plane.
    pub ground: [f32; 4],
    /// Grid lines.
    pub grid: [f32; 4],
}

impl ViewStyle {
    /// Colours that sit well with egui's dark or light theme.
    #[must_use]
    pub fn from_visuals(visuals: &egui::Visuals) -> Self {
        if visuals.dark_mode {
            Self {
                background: [0.105, 0.115, 0.135, 1.0],
                ground: [0.165, 0.175, 0.195, 1.0],
                grid: [0.33, 0.35, 0.40, 1.0],
            }
        } else {
            Self {
                background: [0.86, 0.88, 0.91, 1.0],
                ground: [0.79, 0.81, 0.84, 1.0],
                grid: [0.60, 0.63, 0.68, 1.0],
            }
        }
    }
}

/// Per-view uniforms; field order and meaning mirror `Globals` in scene.wgsl
/// (vec4s and one mat4: the same layout under WGSL and std140 rules).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct Globals {
    view_proj: [f32; 16],
    eye: [f32; 4],
    forward: [f32; 4],
    viewport: [f32; 4],
    ground: [f32; 4],
    flags: [f32; 4],
    background: [f32; 4],
    ground_color: [f32; 4],
    grid_color: [f32; 4],
    light: [f32; 4],
}

/// Strength of blob shadows and contact marks (0 none, 1 as authored).
const SHADOW_STRENGTH: f32 = 0.9;

impl Globals {
    fn new(
        camera: &Camera,
        size_px: [u32; 2],
        pixels_per_point: f32,
        style: &ViewStyle,
        grid: bool,
    ) -> Self {
        let (width, height) = (size_px[0].max(1) as f32, size_px[1].max(1) as f32);
        let eye = camera.eye();
        let forward = camera.forward();
        let (fade_start, fade_end) = camera.ground_fade();
        // A studio key light that stays above-left of the viewer as the camera orbits.
        let light =
            (camera.back() * 0.55 + Vec3::Y * 0.9 - camera.right() * 0.45).normalize_or(Vec3::Y);
        Self {
            view_proj: camera.view_projection(width / height).to_cols_array(),
            eye: [
                eye.x,
                eye.y,
                eye.z,
                if camera.perspective { 1.0 } else { 0.0 },
            ],
            forward: [forward.x, forward.y, forward.z, pixels_per_point],
            viewport: [width, height, 1.0 / width, 1.0 / height],
            ground: [eye.x, eye.z, fade_start, fade_end],
            flags: [
                f32::from(u8::from(grid)),
                SHADOW_STRENGTH,
                GROUND_Y,
                SHADOW_FADE_HEIGHT,
            ],
            background: style.background,
            ground_color: style.ground,
            grid_color: style.grid,
            light: [light.x, light.y, light.z, 0.0],
        }
    }
}

/// A vertex/instance buffer that grows (to the next power of two) but never shrinks.
struct InstanceBuffer {
    buffer: wgpu::Buffer,
    label: &'static str,
    /// Instances written by the last upload.
    count: u32,
}

impl InstanceBuffer {
    fn new(device: &wgpu::Device, label: &'static str) -> Self {
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

    fn upload<T: Pod>(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, items: &[T]) {
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
    fn slice<T>(&self) -> wgpu::BufferSlice<'_> {
        self.buffer
            .slice(..u64::from(self.count) * size_of::<T>() as u64)
    }
}

/// One view's offscreen targets, uniforms and instance buffers.
struct ViewTargets {
    size: [u32; 2],
    /// Multisampled colour target (`None` without MSAA: draw straight into `color`).
    msaa: Option<wgpu::TextureView>,
    /// Resolved colour, sampled by the compositing pass.
    color: wgpu::TextureView,
    depth: wgpu::TextureView,
    composite: wgpu::BindGroup,
    globals: wgpu::Buffer,
    globals_group: wgpu::BindGroup,
    /// Capsules, then the spheres as zero-length capsules.
    solids: InstanceBuffer,
    segments: InstanceBuffer,
    marks: InstanceBuffer,
    /// egui frame number of the last prepare.
    last_frame: u64,
}

/// Pipelines, layouts and the unit mesh shared by every view, plus each view's
/// targets. Lives in [`egui_wgpu::CallbackResources`].
pub struct SceneRenderer {
    pass: PassFormat,
    samples: u32,
    max_size: u32,
    globals_layout: wgpu::BindGroupLayout,
    composite_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    capsule_pipeline: wgpu::RenderPipeline,
    ground_pipeline: wgpu::RenderPipeline,
    mark_pipeline: wgpu::RenderPipeline,
    line_pipeline: wgpu::RenderPipeline,
    composite_pipeline: wgpu::RenderPipeline,
    mesh_vertices: wgpu::Buffer,
    mesh_indices: wgpu::Buffer,
    mesh_index_count: u32,
    views: HashMap<u64, ViewTargets>,
    /// Scratch list of the frame's solids (capsules and spheres), reused.
    solids: Vec<Capsule>,
}

/// Whether `format` can be rendered 4× multisampled (and resolved) on `device`
/// without adapter-specific features.
fn msaa_supported(device: &wgpu::Device, format: wgpu::TextureFormat, resolve: bool) -> bool {
    let features = format.guaranteed_format_features(device.features());
    features.flags.sample_count_supported(SCENE_MSAA_SAMPLES)
        && (!resolve
            || features
                .flags
                .contains(wgpu::TextureFormatFeatureFlags::MULTISAMPLE_RESOLVE))
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

impl SceneRenderer {
    /// Compiles the shaders and builds the pipelines for egui's pass `pass`,
    /// with 4× MSAA where the device supports it.
    #[must_use]
    pub fn new(device: &wgpu::Device, pass: PassFormat) -> Self {
        Self::with_max_samples(device, pass, SCENE_MSAA_SAMPLES)
    }

    /// [`Self::new`] with at most `max_samples` (1 turns MSAA off).
    #[must_use]
    pub fn with_max_samples(device: &wgpu::Device, pass: PassFormat, max_samples: u32) -> Self {
        let samples = if max_samples >= SCENE_MSAA_SAMPLES
            && msaa_supported(device, SCENE_COLOR_FORMAT, true)
            && msaa_supported(device, SCENE_DEPTH_FORMAT, false)
        {
            SCENE_MSAA_SAMPLES
        } else {
            1
        };
        let max_size = device.limits().max_texture_dimension_2d.max(1);
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
            pass,
            samples,
            max_size,
            globals_layout,
            composite_layout,
            sampler,
            capsule_pipeline,
            ground_pipeline,
            mark_pipeline,
            line_pipeline,
            composite_pipeline,
            mesh_vertices,
            mesh_indices,
            mesh_index_count: u32::try_from(indices.len()).unwrap_or(0),
            views: HashMap::new(),
            solids: Vec::new(),
        }
    }

    /// egui's pass this renderer composites into.
    #[must_use]
    pub fn pass_format(&self) -> PassFormat {
        self.pass
    }

    /// Samples per pixel of the scene target (4, or 1 where MSAA is unavailable).
    #[must_use]
    pub fn msaa_samples(&self) -> u32 {
        self.samples
    }

    /// Number of views with live GPU targets.
    #[must_use]
    pub fn view_count(&self) -> usize {
        self.views.len()
    }

    /// Render-target size of `size_px`, scaled down (keeping the aspect) to the
    /// device's texture limit; returns the size and the scale applied.
    fn target_size(&self, size_px: [u32; 2]) -> ([u32; 2], f32) {
        let largest = size_px[0].max(size_px[1]).max(1);
        if largest <= self.max_size {
            return (size_px, 1.0);
        }
        let scale = self.max_size as f32 / largest as f32;
        let fit = |v: u32| ((v as f32 * scale).floor() as u32).clamp(1, self.max_size);
        ([fit(size_px[0]), fit(size_px[1])], scale)
    }

    fn create_view_targets(&self, device: &wgpu::Device, size: [u32; 2]) -> ViewTargets {
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("gaitlab globals"),
            size: size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let globals_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaitlab globals"),
            layout: &self.globals_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals.as_entire_binding(),
            }],
        });
        let (msaa, color, depth, composite) = self.create_textures(device, size);
        ViewTargets {
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
            last_frame: 0,
        }
    }

    fn create_textures(
        &self,
        device: &wgpu::Device,
        size: [u32; 2],
    ) -> (
        Option<wgpu::TextureView>,
        wgpu::TextureView,
        wgpu::TextureView,
        wgpu::BindGroup,
    ) {
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
        let msaa = (self.samples > 1).then(|| {
            texture(
                "gaitlab scene msaa",
                SCENE_COLOR_FORMAT,
                self.samples,
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
            self.samples,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let composite = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaitlab composite"),
            layout: &self.composite_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&color),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&self.sampler),
                },
            ],
        });
        (msaa, color, depth, composite)
    }

    /// Uploads `callback`'s frame and renders it into its view's targets on `encoder`.
    fn prepare_view(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        screen: &egui_wgpu::ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        callback: &SceneCallback,
    ) {
        let viewport = egui::epaint::ViewportInPixels::from_points(
            &callback.rect,
            screen.pixels_per_point,
            screen.size_in_pixels,
        );
        let (Ok(width), Ok(height)) = (
            u32::try_from(viewport.width_px),
            u32::try_from(viewport.height_px),
        ) else {
            return;
        };
        if width == 0 || height == 0 {
            return;
        }
        let (size, scale) = self.target_size([width, height]);

        // Forget views that stopped drawing; then find or make this one.
        let frame_nr = callback.frame_nr;
        self.views
            .retain(|_, view| view.last_frame + STALE_FRAMES >= frame_nr);
        if !self.views.contains_key(&callback.view_id) {
            let view = self.create_view_targets(device, size);
            self.views.insert(callback.view_id, view);
        }
        let needs_resize = self
            .views
            .get(&callback.view_id)
            .is_some_and(|view| view.size != size);
        if needs_resize {
            let textures = self.create_textures(device, size);
            if let Some(view) = self.views.get_mut(&callback.view_id) {
                (view.msaa, view.color, view.depth, view.composite) = textures;
                view.size = size;
            }
        }
        let Some(view) = self.views.get_mut(&callback.view_id) else {
            return;
        };
        view.last_frame = frame_nr;

        let globals = Globals::new(
            &callback.camera,
            size,
            screen.pixels_per_point * scale,
            &callback.style,
            callback.grid,
        );
        queue.write_buffer(&view.globals, 0, bytemuck::bytes_of(&globals));
        let frame = &callback.frame;
        // One draw for every solid: a pipeline fewer to compile at start-up
        // (slow on software WebGL2). The scratch list keeps its capacity.
        self.solids.clear();
        self.solids.extend_from_slice(&frame.capsules);
        self.solids.extend(frame.spheres.iter().map(Capsule::from));
        view.solids.upload(device, queue, &self.solids);
        view.segments.upload(device, queue, &frame.segments);
        if callback.shadow {
            view.marks.upload(device, queue, &frame.ground_marks);
        } else {
            view.marks.count = 0;
        }

        let [r, g, b, a] = callback.style.background.map(f64::from);
        let (target, resolve_target, store) = match &view.msaa {
            Some(msaa) => (msaa, Some(&view.color), wgpu::StoreOp::Discard),
            None => (&view.color, None, wgpu::StoreOp::Store),
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("gaitlab scene"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target,
                depth_slice: None,
                resolve_target,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a }),
                    store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view.depth,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Discard,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_bind_group(0, &view.globals_group, &[]);

        // Opaque, depth-writing solids first.
        pass.set_vertex_buffer(0, self.mesh_vertices.slice(..));
        pass.set_index_buffer(self.mesh_indices.slice(..), wgpu::IndexFormat::Uint16);
        if view.solids.count > 0 {
            pass.set_pipeline(&self.capsule_pipeline);
            pass.set_vertex_buffer(1, view.solids.slice::<Capsule>());
            pass.draw_indexed(0..self.mesh_index_count, 0, 0..view.solids.count);
        }
        // The ground behind them (depth-tested, not written), then its marks.
        if callback.grid {
            pass.set_pipeline(&self.ground_pipeline);
            pass.draw(0..6, 0..1);
        }
        if view.marks.count > 0 {
            pass.set_pipeline(&self.mark_pipeline);
            pass.set_vertex_buffer(0, view.marks.slice::<GroundMark>());
            pass.draw(0..6, 0..view.marks.count);
        }
        if view.segments.count > 0 {
            pass.set_pipeline(&self.line_pipeline);
            pass.set_vertex_buffer(0, view.segments.slice::<Segment>());
            pass.draw(0..6, 0..view.segments.count);
        }
    }
}

/// One view's frame for egui-wgpu: the primitives (shared, not copied), the
/// camera and the drawing options.
pub struct SceneCallback {
    /// Which view (its egui id): each view keeps its own GPU targets.
    pub view_id: u64,
    /// egui's frame counter, to retire the targets of views no longer shown.
    pub frame_nr: u64,
    /// The view's rectangle, points (the paint callback's rect).
    pub rect: egui::Rect,
    /// The camera for this frame.
    pub camera: Camera,
    /// The primitives to draw.
    pub frame: Arc<SceneFrame>,
    /// Theme colours.
    pub style: ViewStyle,
    /// Draw the ground grid.
    pub grid: bool,
    /// Draw blob shadows and contact marks.
    pub shadow: bool,
}

impl SceneCallback {
    /// The callback for view `view_id` showing `frame` through `camera` with `view`'s options.
    #[must_use]
    pub fn new(
        view_id: u64,
        frame_nr: u64,
        rect: egui::Rect,
        camera: Camera,
        frame: Arc<SceneFrame>,
        view: &ViewOptions,
        style: ViewStyle,
    ) -> Self {
        Self {
            view_id,
            frame_nr,
            rect,
            camera,
            frame,
            style,
            grid: view.grid,
            shadow: view.shadow,
        }
    }
}

impl egui_wgpu::CallbackTrait for SceneCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        screen_descriptor: &egui_wgpu::ScreenDescriptor,
        egui_encoder: &mut wgpu::CommandEncoder,
        callback_resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        if let Some(renderer) = callback_resources.get_mut::<SceneRenderer>() {
            renderer.prepare_view(device, queue, screen_descriptor, egui_encoder, self);
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        render_pass: &mut wgpu::RenderPass<'static>,
        callback_resources: &egui_wgpu::CallbackResources,
    ) {
        // egui has set the viewport to this callback's rect and the scissor to its clip.
        let Some(renderer) = callback_resources.get::<SceneRenderer>() else {
            return;
        };
        let Some(view) = renderer.views.get(&self.view_id) else {
            return;
        };
        render_pass.set_pipeline(&renderer.composite_pipeline);
        render_pass.set_bind_group(0, &view.composite, &[]);
        render_pass.draw(0..3, 0..1);
    }
}
