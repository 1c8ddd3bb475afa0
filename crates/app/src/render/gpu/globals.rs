//! The per-view uniform block of `scene.wgsl` (`Globals`): the camera's
//! transform and eye, the viewport, the ground fade, the theme colours and the
//! key light.

use bytemuck::{Pod, Zeroable};
use glam::Vec3;

use super::style::ViewStyle;
use crate::render::camera::Camera;
use crate::render::scene::{GROUND_Y, SHADOW_FADE_HEIGHT};

/// Per-view uniforms; field order and meaning mirror `Globals` in scene.wgsl
/// (vec4s and one mat4: the same layout under WGSL and std140 rules).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(super) struct Globals {
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
    pub(super) fn new(
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
