//! Start-up of the wgpu path: [`install`] builds a [`SceneRenderer`] and
//! registers it with egui-wgpu (or [`install_into`] for a hand-made setup), and
//! [`is_installed`] tells the viewport whether to draw with wgpu or egui's 2-D painter.

use egui_wgpu::wgpu;

use super::formats::{PassFormat, SCENE_MSAA_SAMPLES};
use super::renderer::SceneRenderer;

fn installed_id() -> egui::Id {
    egui::Id::unique("gaitlab-render-gpu-installed")
}

/// Builds the scene renderer for `render_state` and registers it with egui-wgpu,
/// so [`crate::render::viewport::show`] draws with wgpu from now on (without it, the
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
