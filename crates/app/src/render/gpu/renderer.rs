//! [`SceneRenderer`]: what lives in egui-wgpu's callback resources — the
//! pipelines, the unit mesh and every view's targets — and the two halves of
//! drawing a [`SceneCallback`]: `prepare` renders the scene offscreen
//! (solids → ground or terrain → marks → lines), `paint` composites it into egui's pass.

use std::collections::HashMap;

use egui_wgpu::wgpu;

use super::callback::SceneCallback;
use super::capsule_mesh::CapsuleMesh;
use super::formats::{
    PassFormat, SCENE_COLOR_FORMAT, SCENE_DEPTH_FORMAT, SCENE_MSAA_SAMPLES, msaa_supported,
};
use super::globals::Globals;
use super::pipelines::Pipelines;
use super::targets::{STALE_FRAMES, ViewTargets};
use crate::render::scene::{Capsule, GroundMark, Segment};

/// Pipelines, layouts and the unit mesh shared by every view, plus each view's
/// targets. Lives in [`egui_wgpu::CallbackResources`].
pub struct SceneRenderer {
    pass: PassFormat,
    samples: u32,
    max_size: u32,
    pipelines: Pipelines,
    mesh: CapsuleMesh,
    views: HashMap<u64, ViewTargets>,
    /// Scratch list of the frame's solids (capsules and spheres), reused.
    solids: Vec<Capsule>,
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
        Self {
            pass,
            samples,
            max_size,
            pipelines: Pipelines::new(device, pass, samples),
            mesh: CapsuleMesh::new(device),
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
        let view = self
            .views
            .entry(callback.view_id)
            .or_insert_with(|| ViewTargets::new(device, &self.pipelines, self.samples, size));
        if view.size != size {
            view.resize(device, &self.pipelines, self.samples, size);
        }
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
        view.terrain.show(device, frame.terrain.as_deref());
        // Blob shadows lie on the floor: on terrain they would sink into it.
        if callback.shadow && frame.terrain.is_none() {
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
        pass.set_vertex_buffer(0, self.mesh.vertices.slice(..));
        pass.set_index_buffer(self.mesh.indices.slice(..), wgpu::IndexFormat::Uint16);
        if view.solids.count > 0 {
            pass.set_pipeline(&self.pipelines.capsule);
            pass.set_vertex_buffer(1, view.solids.slice::<Capsule>());
            pass.draw_indexed(0..self.mesh.index_count, 0, 0..view.solids.count);
        }
        // The ground behind them (depth-tested, not written), then its marks;
        // or the terrain's triangles, which hide what lies under them.
        if view.terrain.count > 0 {
            pass.set_pipeline(&self.pipelines.terrain);
            view.terrain.draw(&mut pass);
        } else if callback.grid {
            pass.set_pipeline(&self.pipelines.ground);
            pass.draw(0..6, 0..1);
        }
        if view.marks.count > 0 {
            pass.set_pipeline(&self.pipelines.mark);
            pass.set_vertex_buffer(0, view.marks.slice::<GroundMark>());
            pass.draw(0..6, 0..view.marks.count);
        }
        if view.segments.count > 0 {
            pass.set_pipeline(&self.pipelines.line);
            pass.set_vertex_buffer(0, view.segments.slice::<Segment>());
            pass.draw(0..6, 0..view.segments.count);
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
        render_pass.set_pipeline(&renderer.pipelines.composite);
        render_pass.set_bind_group(0, &view.composite, &[]);
        render_pass.draw(0..3, 0..1);
    }
}
