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
//!    spheres (depth write) → ground with fading grid (depth test only), or on
//!    ground that is not flat the terrain's triangles (depth write; no blob
//!    shadows there) → blob shadows (depth test, Min blend) → lines (depth
//!    test, alpha blend).
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
//!
//! # Files
//! - `formats`: the scene target's formats, [`PassFormat`] (egui's pass) and MSAA support.
//! - `setup`: [`install`] / [`install_into`] put a [`SceneRenderer`] where egui-wgpu finds it.
//! - `style`: [`ViewStyle`], the view's theme colours.
//! - `globals`: the per-view uniform block (camera, viewport, ground, light).
//! - `pipelines`: shaders (`scene.wgsl`, `composite.wgsl`), bind group layouts and pipelines.
//! - `capsule_mesh`: the unit capsule mesh's vertex and index buffers.
//! - `instance_buffer`: a growing vertex buffer of per-instance primitives.
//! - `targets`: one view's offscreen textures, uniforms and instance buffers.
//! - `terrain_buffers`: one view's copy of the terrain's triangles, uploaded once per mesh.
//! - `renderer`: [`SceneRenderer`], the scene pass and the compositing draw.
//! - `callback`: [`SceneCallback`], one view's frame handed to egui-wgpu.

mod callback;
mod capsule_mesh;
mod formats;
mod globals;
mod instance_buffer;
mod pipelines;
mod renderer;
mod setup;
mod style;
mod targets;
mod terrain_buffers;

pub use callback::SceneCallback;
pub use formats::{PassFormat, SCENE_COLOR_FORMAT, SCENE_DEPTH_FORMAT, SCENE_MSAA_SAMPLES};
pub use renderer::SceneRenderer;
pub use setup::{install, install_into, is_installed};
pub use style::ViewStyle;
