//! The 3-D view (She 2006 §6.2's view panel: perspective, axes, rotation axes,
//! targets; plus gaitlab's ground grid, shadows and camera follow): a wgpu
//! scene rendered offscreen inside an egui paint callback, drawing lit bones
//! (capsules), joint / effector / target spheres, error segments and axes over
//! a fading ground grid with blob shadows, seen through an orbit camera.
//!
//! - [`scene`]: [`Scene`], the primitives of one frame in world metres, filled
//!   from a skeleton's forward kinematics.
//! - [`camera`]: [`Camera`], orbit / pan / zoom / follow and the projection.
//! - [`viewport`]: [`viewport::show`], the egui widget (with a 2-D painter fallback).
//! - [`gpu`]: pipelines, buffers and the egui-wgpu callback; [`gpu::install`]
//!   once at start-up turns the wgpu path on.
//! - [`mesh`]: the unit capsule mesh every solid is instanced from.
//! - [`gait_overlay`]: PODA footprints, planned footholds and the body path on the ground.
//! - [`push_drag`]: a drag on the physics creature's trunk pushes it.

pub mod camera;
pub mod gait_overlay;
pub mod gpu;
pub mod mesh;
pub mod physics_overlay;
pub mod push_drag;
pub mod scene;
pub mod support_overlay;
pub mod viewport;

pub use camera::Camera;
pub use scene::{Bounds, Scene, SceneFrame};
