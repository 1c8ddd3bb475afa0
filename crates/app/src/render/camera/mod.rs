//! The 3-D view's orbit camera: it circles a target point at a distance, with
//! perspective or orthographic projection of the same apparent size at the
//! target (She 2006 §6.2's "perspective" view option), orbit / pan / zoom from
//! mouse and touch, framing that fits a figure's whole box to the view's
//! aspect ratio, and a follow mode that keeps a walking or running figure in
//! view at any speed.
//!
//! # Conventions
//! - World frame of gaitlab-core: metres, y up, x right, z forward.
//! - `yaw` turns about +y; at `yaw = 0` the camera sits on +z looking toward −z
//!   (it faces a figure walking along +z). `pitch > 0` looks down from above.
//! - Matrices are glam's column-major `Mat4` acting on column vectors, which is
//!   WGSL's `mat4x4<f32>` layout; clip space is wgpu's: x, y in [−1, 1], y up,
//!   depth z in [0, 1] (near → 0).
//! - Input deltas are in egui points.
//!
//! # Files
//! - `orbit`: [`Camera`] (target, yaw, pitch, distance), its limits and its screen basis.
//! - `projection`: the view and projection matrices, clip planes and the ground fade.
//! - `gestures`: [`CameraInput`] from egui's pointer and touch input; orbit, pan and zoom.
//! - `framing`: [`Camera::frame_for`], the figure's whole box fitted to the view's shape.
//! - `follow`: [`Camera::follow`], a critically damped tracker of a moving figure.

mod follow;
mod framing;
mod gestures;
mod orbit;
mod projection;

pub use follow::{FOLLOW_JUMP_DISTANCES, FOLLOW_RATE};
pub use framing::{FRAME_FILL, FRAME_PAD_M, KEEP_FILL};
pub use gestures::{CameraInput, ORBIT_RADIANS_PER_POINT, ZOOM_PER_POINT, gestures};
pub use orbit::{
    Camera, HOME_PITCH, HOME_YAW, MAX_DISTANCE, MIN_DISTANCE, MIN_EYE_HEIGHT, PITCH_LIMIT,
};
