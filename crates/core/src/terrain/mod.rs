//! Ground that is not flat (issue 45 item 1): one terrain model for every
//! engine and front end — flat, a sloped plane, stairs, or a height field
//! split into triangles as MuJoCo splits an `hfield` — giving the ground's
//! height, normal and friction at any (x, z). World frame: metres, y up.
//!
//! # Files
//! - `ground`: [`Terrain`], the four kinds and what they answer.
//! - `plane`, `stairs`, `height_field`: each kind.
//! - `direction`: headings in the ground plane (0° is +x, 90° is +z).
//! - `error`: [`TerrainError`], the field and the reason.

mod direction;
mod error;
mod ground;
mod height_field;
mod plane;
mod stairs;

pub use direction::{along, ground_direction};
pub use error::TerrainError;
pub use ground::Terrain;
pub use height_field::{HeightField, MAX_FRICTION, MAX_HEIGHT_M, MAX_SAMPLES};
pub use plane::{MAX_SLOPE_DEG, Plane};
pub use stairs::{MAX_STEP_M, MAX_STEPS, Stairs};
