//! The wgpu path of the 3-D view end to end, headless: an egui frame with
//! `viewport::show` goes through `egui_wgpu::Renderer` exactly as eframe's web
//! painter drives it (callback `prepare` → our offscreen scene pass; egui's
//! pass with a `Depth24Plus` attachment, as `depth_buffer: 24` gives, → our
//! composite), then the pixels are read back and checked: the figure is where
//! the camera puts it, nearer solids hide farther ones, two views keep their
//! own targets, and a resize reallocates them.
//!
//! Runs on every adapter wgpu finds here (GL — the WebGL2-like path, with
//! WebGL2's limits — and Vulkan); passes with a note when there is none. wgpu
//! validation errors panic. Set `GAITLAB_RENDER_PNG=dir` to save the frames.

use std::future::Future;
use std::task::{Context, Poll, Waker};

use egui_wgpu::wgpu;
use gaitlab_app::render::gpu::{self, PassFormat, ViewStyle};
use gaitlab_app::render::scene::{Capsule, Sphere};
use gaitlab_app::render::{Camera, Scene, SceneFrame, viewport};
use gaitlab_app::view::ViewOptions;
use glam::Vec3;

const TARGET_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24Plus;

fn block_on<F: Future>(future: F) -> F::Output {
    let mut future = std::pin::pin!(future);
    let mut cx = Context::from_waker(Waker::noop());
    loop {
        if let Poll::Ready(value) = future.as_mut().poll(&mut cx) {
            return value;
        }
        std::thread::yield_now();
    }
}

struct Gpu {
    name: String,
    device: wgpu::Device,
    queue: wgpu::Queue,
}

fn gpu(backends: wgpu::Backends) -> Option<Gpu> {
    let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle();
    descriptor.backends = backends;
    descriptor.flags = wgpu::InstanceFlags::VALIDATION | wgpu::InstanceFlags::DEBUG;
    let instance = wgpu::Instance::new(descriptor);
    let adapter =
        block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default())).ok()?;
    let info = adapter.get_info();
    // What egui-wgpu asks for (WebGL2's limits on GL), see its setup.rs.
    let base = if info.backend == wgpu::Backend::Gl {
        wgpu::Limits::downlevel_webgl2_defaults()
    } else {
        wgpu::Limits::default()
    };
    let limits = wgpu::Limits {
        max_texture_dimension_2d: 8192,
        ..base
    }
    .using_resolution(adapter.limits());
    let (device, queue) = block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("gaitlab render test"),
        required_limits: limits,
        ..wgpu::DeviceDescriptor::default()
    }))
    .ok()?;
    Some(Gpu {
        name: format!("{:?} {}", info.backend, info.name),
        device,
        queue,
    })
}

fn gpus() -> Vec<Gpu> {
    let found: Vec<Gpu> = [wgpu::Backends::GL, wgpu::Backends::VULKAN]
        .into_iter()
        .filter_map(gpu)
        .collect();
    if found.is_empty() {
        eprintln!("render_gpu: no wgpu adapter here; the GPU checks were skipped");
    }
    found
}

fn human_scene(view: &ViewOptions) -> (Scene, Vec<Vec3>) {
    let creature = gaitlab_core::preset::load_bundled("human")
        .expect("bundled human")
        .expect("valid human");
    let pose = gaitlab_core::Pose {
        root: gaitlab_core::RootTransform {
            position: creature.root_position,
            ..gaitlab_core::RootTransform::default()
        },
        joints: creature.skeleton.rest_values(),
    };
    let kin = gaitlab_core::Kinematics::of(&creature.skeleton, &pose);
    let mut scene = Scene::new();
    scene.fill(&creature.skeleton, &kin, creature.root_position, None, view);
    let feet = kin.effector_position.iter().map(|p| p.as_vec3()).collect();
    (scene, feet)
}

/// egui + egui-wgpu set up like eframe's web painter with `depth_buffer: 24`.
struct Frame {
    ctx: egui::Context,
    renderer: egui_wgpu::Renderer,
}

impl Frame {
    fn new(gpu: &Gpu) -> Self {
        Self::with_samples(gpu, gpu::SCENE_MSAA_SAMPLES)
    }

    fn with_samples(gpu: &Gpu, max_samples: u32) -> Self {
        let ctx = egui::Context::default();
        let mut renderer = egui_wgpu::Renderer::new(
            &gpu.device,
            TARGET_FORMAT,
            egui_wgpu::RendererOptions {
                msaa_samples: 1,
                depth_stencil_format: Some(DEPTH_FORMAT),
                dithering: false,
                predictable_texture_filtering: false,
            },
        );
        let pass = PassFormat {
            color: TARGET_FORMAT,
            depth: Some(DEPTH_FORMAT),
            samples: 1,
        };
        gpu::install_into(
            &ctx,
            &mut renderer.callback_resources,
            gpu::SceneRenderer::with_max_samples(&gpu.device, pass, max_samples),
        );
        Self { ctx, renderer }
    }

    /// Runs `ui` in a `size_points` window at `ppp` and returns the RGBA pixels.
    fn render(
        &mut self,
        gpu: &Gpu,
        size_points: egui::Vec2,
        ppp: f32,
        mut ui: impl FnMut(&mut egui::Ui),
    ) -> Image {
        let mut input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(egui::Pos2::ZERO, size_points)),
            ..egui::RawInput::default()
        };
        if let Some(viewport) = input.viewports.get_mut(&egui::ViewportId::ROOT) {
            viewport.native_pixels_per_point = Some(ppp);
        }
        let mut output = self.ctx.run_ui(input, |root| ui(root));
        for (id, deltas) in &output.textures_delta.set {
            for delta in deltas {
                self.renderer
                    .update_texture(&gpu.device, &gpu.queue, *id, delta);
            }
        }
        for id in &output.textures_delta.free {
            self.renderer.free_texture(id);
        }
        output.textures_delta.clear();
        let primitives = self.ctx.tessellate(output.shapes, output.pixels_per_point);
        let width = (size_points.x * ppp).round() as u32;
        let height = (size_points.y * ppp).round() as u32;
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [width, height],
            pixels_per_point: output.pixels_per_point,
        };
        let extent = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let target = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("egui target"),
            size: extent,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: TARGET_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let depth = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("egui depth"),
            size: extent,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        });
        let target_view = target.create_view(&wgpu::TextureViewDescriptor::default());
        let depth_view = depth.create_view(&wgpu::TextureViewDescriptor::default());
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        let callback_buffers = self.renderer.update_buffers(
            &gpu.device,
            &gpu.queue,
            &mut encoder,
            &primitives,
            &screen,
        );
        {
            let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("egui_render"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &target_view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
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
            self.renderer
                .render(&mut pass.forget_lifetime(), &primitives, &screen);
        }
        let row_bytes = (width * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: u64::from(row_bytes * height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &target,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(row_bytes),
                    rows_per_image: Some(height),
                },
            },
            extent,
        );
        gpu.queue
            .submit(callback_buffers.into_iter().chain([encoder.finish()]));
        readback.map_async(wgpu::MapMode::Read, .., |result| {
            result.expect("map the readback buffer");
        });
        gpu.device
            .poll(wgpu::PollType::Wait {
                submission_index: None,
                timeout: None,
            })
            .expect("the GPU finishes");
        let mapped = readback.get_mapped_range(..).expect("mapped");
        let mut pixels = Vec::with_capacity((width * height * 4) as usize);
        for row in mapped.chunks_exact(row_bytes as usize) {
            pixels.extend_from_slice(&row[..(width * 4) as usize]);
        }
        drop(mapped);
        readback.unmap();
        Image {
            width,
            height,
            pixels,
        }
    }
}

struct Image {
    width: u32,
    height: u32,
    pixels: Vec<u8>,
}

impl Image {
    fn at(&self, x: u32, y: u32) -> [u8; 3] {
        let i = ((y.min(self.height - 1) * self.width + x.min(self.width - 1)) * 4) as usize;
        [self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]]
    }

    /// Pixels whose colour is within `tolerance` (per channel) of `color`.
    fn count(&self, color: [u8; 3], tolerance: u8) -> usize {
        self.pixels
            .chunks_exact(4)
            .filter(|p| (0..3).all(|c| p[c].abs_diff(color[c]) <= tolerance))
            .count()
    }

    /// Bounding box (x0, y0, x1, y1) of pixels where `pred` holds.
    fn bbox(&self, pred: impl Fn([u8; 3]) -> bool) -> Option<(u32, u32, u32, u32)> {
        let mut bbox: Option<(u32, u32, u32, u32)> = None;
        for y in 0..self.height {
            for x in 0..self.width {
                if pred(self.at(x, y)) {
                    bbox = Some(match bbox {
                        None => (x, y, x, y),
                        Some((x0, y0, x1, y1)) => (x0.min(x), y0.min(y), x1.max(x), y1.max(y)),
                    });
                }
            }
        }
        bbox
    }

    fn save(&self, name: &str) {
        let Some(dir) = std::env::var_os("GAITLAB_RENDER_PNG") else {
            return;
        };
        let path = std::path::Path::new(&dir).join(format!("{name}.png"));
        std::fs::write(&path, png(self)).expect("write the PNG");
    }
}

/// A minimal RGBA PNG encoder (stored for eyeballing, never compared).
fn png(image: &Image) -> Vec<u8> {
    fn crc32(bytes: &[u8]) -> u32 {
        let mut crc = !0u32;
        for &b in bytes {
            crc ^= u32::from(b);
            for _ in 0..8 {
                crc = if crc & 1 == 1 {
                    (crc >> 1) ^ 0xEDB8_8320
                } else {
                    crc >> 1
                };
            }
        }
        !crc
    }
    fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
        out.extend_from_slice(&u32::try_from(data.len()).unwrap_or(0).to_be_bytes());
        let start = out.len();
        out.extend_from_slice(kind);
        out.extend_from_slice(data);
        let crc = crc32(&out[start..]);
        out.extend_from_slice(&crc.to_be_bytes());
    }
    let mut raw = Vec::with_capacity(image.pixels.len() + image.height as usize);
    for row in image.pixels.chunks_exact(image.width as usize * 4) {
        raw.push(0);
        raw.extend_from_slice(row);
    }
    let mut header = Vec::new();
    header.extend_from_slice(&image.width.to_be_bytes());
    header.extend_from_slice(&image.height.to_be_bytes());
    header.extend_from_slice(&[8, 6, 0, 0, 0]);
    let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
    chunk(&mut out, b"IHDR", &header);
    chunk(
        &mut out,
        b"IDAT",
        &miniz_oxide::deflate::compress_to_vec_zlib(&raw, 6),
    );
    chunk(&mut out, b"IEND", &[]);
    out
}

/// A red upright capsule at the origin, a green sphere in front of it and a
/// blue sphere hidden behind it, seen from +z.
fn depth_scene() -> Scene {
    Scene::from(SceneFrame {
        capsules: vec![Capsule::new(
            Vec3::new(0.0, 0.3, 0.0),
            Vec3::new(0.0, 1.3, 0.0),
            0.15,
            [0.95, 0.1, 0.1, 1.0],
        )],
        spheres: vec![
            Sphere::new(Vec3::new(0.0, 0.8, 0.3), 0.08, [0.1, 0.95, 0.1, 1.0]),
            Sphere::new(Vec3::new(0.0, 1.0, -0.35), 0.1, [0.1, 0.1, 0.95, 1.0]),
        ],
        ..SceneFrame::default()
    })
}

fn front_camera() -> Camera {
    Camera {
        target: Vec3::new(0.0, 0.8, 0.0),
        yaw: 0.0,
        pitch: 0.0,
        distance: 3.0,
        framed: true,
        ..Camera::default()
    }
}

/// Whether channel `c` of `p` is bright and at least twice each other channel.
fn dominant(p: [u8; 3], c: usize) -> bool {
    let v = u16::from(p[c]);
    v > 60 && (0..3).filter(|&o| o != c).all(|o| v > 2 * u16::from(p[o]))
}

fn is_red(p: [u8; 3]) -> bool {
    dominant(p, 0)
}

fn is_green(p: [u8; 3]) -> bool {
    dominant(p, 1)
}

fn is_blue(p: [u8; 3]) -> bool {
    dominant(p, 2)
}

#[test]
fn render_places_the_scene_where_the_camera_puts_it_with_depth_and_high_dpi() {
    // With 4x MSAA and without (what software rasterizers get).
    for (gpu, samples) in gpus().into_iter().flat_map(|gpu| {
        let gpu = std::rc::Rc::new(gpu);
        [
            (std::rc::Rc::clone(&gpu), gpu::SCENE_MSAA_SAMPLES),
            (gpu, 1),
        ]
    }) {
        let name = format!("{} {samples}x", gpu.name);
        let mut frame = Frame::with_samples(&gpu, samples);
        let scene = depth_scene();
        let mut camera = front_camera();
        let view = ViewOptions::figure_only();
        let ppp = 1.5;
        let panel = 120.0;
        let image = frame.render(&gpu, egui::vec2(520.0, 300.0), ppp, |ui| {
            egui::Panel::left("side")
                .exact_size(panel)
                .show(ui, |ui| ui.label("panel"));
            egui::CentralPanel::default()
                .frame(egui::Frame::NONE)
                .show(ui, |ui| {
                    viewport::show(ui, &scene, &mut camera, &view);
                });
        });
        image.save(&format!("depth-{}", name.replace(' ', "_")));

        // The view's background fills the area right of the panel.
        let background = ViewStyle::from_visuals(&egui::Visuals::dark())
            .background
            .map(|c| (c * 255.0).round() as u8);
        let corner = image.at(image.width - 3, 3);
        assert!(
            (0..3).all(|c| corner[c].abs_diff(background[c]) <= 2),
            "{}: corner {corner:?}, background {background:?}",
            name
        );
        // The capsule is centred in the view (not the window): the view spans
        // x in [panel, 520] points.
        let (x0, y0, x1, y1) = image
            .bbox(is_red)
            .unwrap_or_else(|| panic!("{}: no capsule", name));
        let centre_x = 0.5 * (x0 + x1) as f32 / ppp;
        let view_centre = 0.5 * (panel + 520.0);
        assert!(
            (centre_x - view_centre).abs() < 3.0,
            "{}: capsule centred at x = {centre_x} pt, view centre {view_centre} pt",
            name
        );
        // Upright (taller than wide), and its height matches the projection:
        // 1.3 m tall (with caps) at 3 m, 40° field of view, 300 pt high view.
        let tall = (y1 - y0) as f32 / ppp;
        let expected = 1.3 / (3.0 * (20_f32.to_radians()).tan()) * 150.0;
        assert!(tall > (x1 - x0) as f32 / ppp, "{}: upright", name);
        assert!(
            (tall - expected).abs() < 0.08 * expected,
            "{}: capsule {tall} pt tall, expected about {expected}",
            name
        );
        // The green sphere in front is drawn over the capsule; the blue one behind is hidden.
        assert!(
            image.count_pred(is_green) > 100,
            "{}: green sphere in front",
            name
        );
        assert_eq!(image.count_pred(is_blue), 0, "{}: blue sphere hidden", name);
        // Lit: the capsule is not one flat colour.
        let reds: Vec<u8> = (x0..=x1)
            .map(|x| image.at(x, (y0 + y1) / 2 + 40)[0])
            .collect();
        let (lo, hi) = (
            reds.iter().min().copied().unwrap_or(0),
            reds.iter().max().copied().unwrap_or(0),
        );
        assert!(
            hi - lo > 30,
            "{}: shading across the capsule {lo}..{hi}",
            name
        );
        // egui still paints its own panel in the same pass.
        let panel_pixel = image.at((20.0 * ppp) as u32, image.height - 10);
        assert_ne!(
            panel_pixel,
            image.at(image.width - 3, image.height - 10),
            "{}",
            name
        );
    }
}

impl Image {
    fn count_pred(&self, pred: impl Fn([u8; 3]) -> bool) -> usize {
        self.pixels
            .chunks_exact(4)
            .filter(|p| pred([p[0], p[1], p[2]]))
            .count()
    }
}

#[test]
fn render_ground_shadows_lines_and_two_views_with_their_own_targets() {
    for gpu in gpus() {
        let mut frame = Frame::new(&gpu);
        // The human preset in its rest pose, with every view option on.
        let creature = gaitlab_core::preset::load_bundled("human")
            .expect("bundled human")
            .expect("valid human");
        let pose = gaitlab_core::Pose {
            root: gaitlab_core::RootTransform {
                position: creature.root_position,
                ..gaitlab_core::RootTransform::default()
            },
            joints: creature.skeleton.rest_values(),
        };
        let kin = gaitlab_core::Kinematics::of(&creature.skeleton, &pose);
        let mut targets = gaitlab_core::ik::Targets::at(&kin);
        for target in &mut targets.position {
            target.z += 0.1;
        }
        let all = ViewOptions {
            world_axes: true,
            joint_axes: true,
            ..ViewOptions::default()
        };
        let mut scene = Scene::new();
        scene.fill(
            &creature.skeleton,
            &kin,
            creature.root_position,
            Some(&targets),
            &all,
        );
        let mut left = Camera::default();
        let mut right = Camera {
            perspective: false,
            yaw: -1.2,
            ..Camera::default()
        };
        let plain = ViewOptions {
            grid: false,
            shadow: false,
            ..all.clone()
        };
        let size = egui::vec2(640.0, 360.0);
        let mut draw = |frame: &mut Frame, size: egui::Vec2| {
            frame.render(&gpu, size, 1.0, |ui| {
                ui.columns(2, |columns| {
                    viewport::show(&mut columns[0], &scene, &mut left, &all);
                    viewport::show(&mut columns[1], &scene, &mut right, &plain);
                });
            })
        };
        let image = draw(&mut frame, size);
        image.save(&format!("human-{}", gpu.name.replace(' ', "_")));
        let style = ViewStyle::from_visuals(&egui::Visuals::dark());
        let to_u8 = |c: [f32; 4]| [c[0], c[1], c[2]].map(|v| (v * 255.0).round() as u8);
        let background = to_u8(style.background);
        let half = image.width / 2;
        // Left view: the ground (lighter than the background) fills the lower half.
        let ground_pixels = (0..half - 8)
            .map(|x| image.at(x, image.height - 4))
            .filter(|p| p.iter().zip(background).any(|(a, b)| a.abs_diff(b) > 3))
            .count();
        assert!(
            ground_pixels as u32 > (half - 8) * 9 / 10,
            "{}: ground under the left view",
            gpu.name
        );
        // Right view (grid off): background at the bottom.
        let bottom = image.at(half + half / 2, image.height - 4);
        assert!(
            bottom
                .iter()
                .zip(background)
                .all(|(a, b)| a.abs_diff(b) <= 2),
            "{}: {bottom:?}",
            gpu.name
        );
        // Both views show the figure (side colours) and the red targets / error segments.
        for (from, to) in [(0, half), (half, image.width)] {
            let mut blue = 0;
            let mut red = 0;
            for y in 0..image.height {
                for x in from..to {
                    let p = image.at(x, y);
                    blue += usize::from(p[2] > p[0].saturating_add(40));
                    red += usize::from(is_red(p));
                }
            }
            assert!(
                blue > 200,
                "{}: left-side (blue) limbs in [{from}, {to})",
                gpu.name
            );
            assert!(red > 30, "{}: targets in [{from}, {to})", gpu.name);
        }

        // A resize reallocates the targets (no validation error) and still draws.
        let resized = draw(&mut frame, egui::vec2(500.0, 420.0));
        assert_eq!(resized.width, 500);
        assert!(
            resized.count(to_u8(style.background), 2) > 1000,
            "{}",
            gpu.name
        );
        assert!(
            resized.bbox(is_red).is_some(),
            "{}: targets after the resize",
            gpu.name
        );
    }
}

#[test]
fn render_shows_the_figure_from_every_camera_angle() {
    for gpu in gpus() {
        let mut frame = Frame::new(&gpu);
        let creature = gaitlab_core::preset::load_bundled("human")
            .expect("bundled human")
            .expect("valid human");
        let mut values = creature.skeleton.rest_values();
        for (value, joint) in values.iter_mut().zip(creature.skeleton.joints()) {
            if joint.name.contains("knee") {
                *value = joint.clamp(0.6);
            }
        }
        let pose = gaitlab_core::Pose {
            root: gaitlab_core::RootTransform {
                position: creature.root_position,
                ..gaitlab_core::RootTransform::default()
            },
            joints: values,
        };
        let kin = gaitlab_core::Kinematics::of(&creature.skeleton, &pose);
        let targets = gaitlab_core::ik::Targets::at(&kin);
        let view = ViewOptions::default();
        let mut scene = Scene::new();
        scene.fill(
            &creature.skeleton,
            &kin,
            creature.root_position,
            Some(&targets),
            &view,
        );
        let bounds = scene.bounds().expect("bounds");
        let cameras = [
            ("front", 0.0, 0.1, true, 1.0),
            ("three-quarter", 0.8, 0.35, true, 1.0),
            ("top-ortho", 0.3, 1.5, false, 1.0),
            ("low", 2.5, -0.3, true, 1.0),
            ("close", 0.6, 0.2, true, 8.0),
        ];
        for (name, yaw, pitch, perspective, zoom) in cameras {
            let mut camera = Camera::default();
            camera.frame(&bounds);
            camera.yaw = yaw;
            camera.pitch = pitch;
            camera.zoom(zoom);
            let view = ViewOptions {
                perspective,
                ..view.clone()
            };
            let image = frame.render(&gpu, egui::vec2(480.0, 400.0), 1.0, |ui| {
                viewport::show(ui, &scene, &mut camera, &view);
            });
            image.save(&format!("angle-{name}-{}", gpu.name.replace(' ', "_")));
            let limbs = image
                .count_pred(|p| p[2] > p[0].saturating_add(40) || p[0] > p[2].saturating_add(60));
            assert!(
                limbs > 500,
                "{}: {name}: figure visible ({limbs} px)",
                gpu.name
            );
        }
    }
}

#[test]
fn render_shadows_darken_only_the_ground_under_the_figure() {
    for gpu in gpus() {
        let mut frame = Frame::new(&gpu);
        let samples = frame
            .renderer
            .callback_resources
            .get::<gpu::SceneRenderer>()
            .map(gpu::SceneRenderer::msaa_samples);
        eprintln!(
            "render_gpu: {} draws the scene with {samples:?} samples",
            gpu.name
        );
        let lit = ViewOptions {
            targets: false,
            ..ViewOptions::default()
        };
        let unlit = ViewOptions {
            shadow: false,
            ..lit.clone()
        };
        let (scene, feet) = human_scene(&lit);
        let size = egui::vec2(400.0, 400.0);
        let mut render = |view: &ViewOptions| {
            let mut camera = Camera::default();
            camera.frame(&scene.bounds().expect("bounds"));
            camera.pitch = 0.6;
            camera.yaw = 0.4;
            let shown = camera;
            let image = frame.render(&gpu, size, 1.0, |ui| {
                let mut camera = shown;
                viewport::show(ui, &scene, &mut camera, view);
            });
            (image, shown)
        };
        let (with, camera) = render(&lit);
        let (without, _) = render(&unlit);
        with.save(&format!("shadow-{}", gpu.name.replace(' ', "_")));
        let mut darker = 0usize;
        let mut centroid = egui::Vec2::ZERO;
        for (i, (a, b)) in with
            .pixels
            .chunks_exact(4)
            .zip(without.pixels.chunks_exact(4))
            .enumerate()
        {
            for c in 0..3 {
                assert!(
                    a[c] <= b[c].saturating_add(1),
                    "{}: a shadow brightened pixel {i}",
                    gpu.name
                );
            }
            let drop: u32 = (0..3).map(|c| u32::from(b[c] - a[c].min(b[c]))).sum();
            if drop >= 9 {
                darker += 1;
                centroid += egui::vec2(
                    (i as u32 % with.width) as f32,
                    (i as u32 / with.width) as f32,
                );
            }
        }
        assert!(darker > 300, "{}: {darker} shadowed pixels", gpu.name);
        let centroid = centroid / darker as f32;
        // Around the feet's ground points on screen.
        let view_proj = camera.view_projection(1.0);
        let ground_feet: Vec<egui::Pos2> = feet
            .iter()
            .map(|p| {
                let clip = view_proj * Vec3::new(p.x, 0.0, p.z).extend(1.0);
                egui::pos2(
                    (clip.x / clip.w * 0.5 + 0.5) * size.x,
                    (0.5 - clip.y / clip.w * 0.5) * size.y,
                )
            })
            .collect();
        let nearest = ground_feet
            .iter()
            .map(|p| (p.to_vec2() - centroid).length())
            .fold(f32::INFINITY, f32::min);
        assert!(
            nearest < 80.0,
            "{}: shadow centroid {centroid:?} far from the feet {ground_feet:?}",
            gpu.name
        );
    }
}

/// Issue 45 item 4: ground that is not flat is drawn as the terrain's
/// triangles — a stairs' risers shaded apart from its treads, so a step shows
/// from the side, and what lies under the ground hidden by it.
#[test]
fn render_stairs_show_their_risers_and_hide_what_is_under_them() {
    use gaitlab_core::terrain::{Stairs, Terrain};
    for gpu in gpus() {
        let mut frame = Frame::new(&gpu);
        let view = ViewOptions {
            follow: false,
            targets: false,
            ..ViewOptions::default()
        };
        // A green ball sunk under the top of the flight (the plateau is at 0.6 m).
        let buried = || {
            Scene::from(SceneFrame {
                spheres: vec![Sphere::new(
                    Vec3::new(2.5, 0.3, 0.37),
                    0.15,
                    [0.1, 0.95, 0.1, 1.0],
                )],
                ..SceneFrame::default()
            })
        };
        let floor = buried();
        let mut stairs = buried();
        stairs.set_terrain(&Terrain::Stairs(Stairs {
            rise_m: 0.2,
            run_m: 0.5,
            count: 3,
            direction_deg: 0.0,
            start_m: 0.0,
        }));
        let camera = Camera {
            target: Vec3::new(1.0, 0.3, 0.37),
            yaw: -std::f32::consts::FRAC_PI_2 + 0.35,
            pitch: 0.35,
            distance: 4.0,
            framed: true,
            ..Camera::default()
        };
        let size = egui::vec2(400.0, 400.0);
        let drawn_with = std::cell::Cell::new(camera);
        let mut render = |scene: &Scene| {
            frame.render(&gpu, size, 1.0, |ui| {
                let mut shown = camera;
                viewport::show(ui, scene, &mut shown, &view);
                drawn_with.set(shown);
            })
        };
        let on_floor = render(&floor);
        let on_stairs = render(&stairs);
        on_stairs.save(&format!("stairs-{}", gpu.name.replace(' ', "_")));
        let greens = |image: &Image| image.bbox(is_green).is_some();
        assert!(
            greens(&on_floor),
            "{}: the ball shows over the floor",
            gpu.name
        );
        assert!(
            !greens(&on_stairs),
            "{}: the ball under the top tread is hidden by it",
            gpu.name
        );
        let view_proj = drawn_with.get().view_projection(1.0);
        let pixel = |image: &Image, p: Vec3| {
            let clip = view_proj * p.extend(1.0);
            let x = (clip.x / clip.w * 0.5 + 0.5) * size.x;
            let y = (0.5 - clip.y / clip.w * 0.5) * size.y;
            image.at(x as u32, y as u32)
        };
        let apart = |a: [u8; 3], b: [u8; 3]| -> u32 {
            (0..3).map(|c| u32::from(a[c].abs_diff(b[c]))).sum()
        };
        // Between two 5 cm contour lines.
        let riser = pixel(&on_stairs, Vec3::new(0.5, 0.325, 0.37));
        for tread in [Vec3::new(0.37, 0.2, 0.37), Vec3::new(0.87, 0.4, 0.37)] {
            let top = pixel(&on_stairs, tread);
            assert!(
                apart(riser, top) >= 15,
                "{}: riser {riser:?} and tread {top:?} look alike",
                gpu.name
            );
        }
        // A tread is level: it reads as the floor does.
        let tread = pixel(&on_stairs, Vec3::new(0.87, 0.4, 0.37));
        let floor_near = pixel(&on_floor, Vec3::new(-0.63, 0.0, 0.37));
        assert!(
            apart(tread, floor_near) <= 12,
            "{}: a tread {tread:?} against the floor {floor_near:?}",
            gpu.name
        );
    }
}
