//! What the 3-D view draws, in world metres: bones as capsules, joints,
//! effectors and targets as spheres, line segments (She 2006 §6.2's view
//! options: error segments, rotation axes, world axes) and the marks the figure
//! leaves on the ground (blob shadows and foot contacts).
//!
//! [`Scene::fill`] rebuilds everything from a skeleton's forward kinematics
//! once per frame. The lists live in one [`SceneFrame`] behind an [`Arc`](std::sync::Arc): the
//! renderer takes a cheap clone of the `Arc` for the frame it draws, and once
//! that frame is on screen the next `fill` reuses the same allocations (no
//! per-frame allocation after warm-up). Should a drawn frame still be held
//! when `fill` runs, `fill` copies it once instead of waiting.
//!
//! # Conventions
//! - World frame of gaitlab-core: metres, y up, ground plane at y = [`GROUND_Y`].
//! - Positions are `f32` (what the GPU reads); the kinematics are `f64`.
//! - Colours are sRGB-encoded RGBA in `[0, 1]` (like egui's `Color32`), not linear.
//! - Primitive types are `#[repr(C)]` and [`bytemuck::Pod`]: the GPU instance
//!   buffers are byte copies of the lists.
//!
//! # Files
//! - `primitives`: [`Capsule`], [`Sphere`], [`Segment`], [`GroundMark`], the GPU instance types.
//! - `bounds`: [`Bounds`], the box the camera frames and follows.
//! - `frame`: [`SceneFrame`] (one frame's lists) and [`Scene`] (the shared, refilled frame).
//! - `fill`: [`Scene::fill`], the figure from a skeleton's forward kinematics.
//! - `tint`: [`Scene::fill_overlay`], several figures recoloured into one scene (the comparison's overlay).
//! - `reach`: manipulability ellipsoids and reach shells (issue 44 item 3).
//! - `palette`: colours by side (left, right, centre line) and by role.
//! - `sizes`: the ground's height, the sizes of bones, spheres and axes, shadow reach.
//! - `terrain_mesh`: [`TerrainMesh`], ground that is not flat as triangles (issue 45 item 4).

mod bounds;
mod fill;
mod frame;
mod palette;
mod primitives;
mod reach;
mod sizes;
mod terrain_mesh;
mod tint;

pub use bounds::Bounds;
pub use frame::{Scene, SceneFrame, TargetRanges};
pub use palette::{
    CENTRE_COLOR, EFFECTOR_COLOR, ERROR_COLOR, LEFT_COLOR, PRISMATIC_AXIS_COLOR,
    REVOLUTE_AXIS_COLOR, RIGHT_COLOR, SIDE_SERIES_COLOURS, Side, TARGET_COLOR,
    TARGET_OUT_OF_REACH_COLOR, WORLD_AXIS_COLORS, series_colour, side_of,
};
pub use primitives::{Capsule, GroundMark, Segment, Sphere};
pub use reach::{ELLIPSOID_COLOR, ELLIPSOID_STEP_RAD};
pub use sizes::{
    CONTACT_DARKNESS, CONTACT_HEIGHT, GROUND_Y, JOINT_SPHERE_SCALE, MIN_BONE_RADIUS,
    SHADOW_DARKNESS, SHADOW_FADE_HEIGHT, WORLD_AXIS_LENGTH,
};
pub use terrain_mesh::{DRAWN_SAMPLES, REACH_M, TerrainMesh};
