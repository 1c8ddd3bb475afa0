//! Texture formats of the 3-D view: the scene's offscreen colour and depth
//! targets, [`PassFormat`] (what egui's render pass looks like, which the
//! compositing pipeline must match) and where 4× MSAA is available.

use egui_wgpu::wgpu;

/// Colour format of the offscreen scene target (holds sRGB-encoded values).
pub const SCENE_COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
/// Depth format of the offscreen scene target.
pub const SCENE_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24Plus;
/// Multisampling of the scene target where the device supports it.
pub const SCENE_MSAA_SAMPLES: u32 = 4;

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

/// Whether `format` can be rendered 4× multisampled (and resolved) on `device`
/// without adapter-specific features.
pub(super) fn msaa_supported(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    resolve: bool,
) -> bool {
    let features = format.guaranteed_format_features(device.features());
    features.flags.sample_count_supported(SCENE_MSAA_SAMPLES)
        && (!resolve
            || features
                .flags
                .contains(wgpu::TextureFormatFeatureFlags::MULTISAMPLE_RESOLVE))
}
