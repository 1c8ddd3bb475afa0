//! Ground that is not flat (issue 45 item 1): one terrain model for every
//! engine and front end — flat, a sloped plane, stairs, or a height field
//! split into triangles as MuJoCo splits an `hfield` — giving the ground's
//! height, normal and friction at any (x, z). World frame: metres, y up.
//!
//! # Files
//! - `ground`: [`Terrain`], the four kinds and what they answer.
//! - `plane`, `stairs`, `height_field`, `rough`: each kind (rough ground is a
//!   height field made from a seed and a difficulty).
//! - `direction`: headings in the ground plane (0° is +x, 90° is +z).
//! - `mjcf`: the terrain as MuJoCo geoms and an `hfield` asset.
//! - `error`: [`TerrainError`], the field and the reason.

mod direction;
mod error;
mod ground;
mod height_field;
mod mjcf;
mod plane;
mod rough;
mod stairs;

pub use direction::{along, ground_direction};
pub use error::TerrainError;
pub use ground::Terrain;
pub use height_field::{HeightField, MAX_FRICTION, MAX_HEIGHT_M, MAX_SAMPLES};
pub use mjcf::{EXTENT_M, TerrainMjcf, to_mjcf};
pub use plane::{MAX_SLOPE_DEG, Plane};
pub use rough::Rough;
pub use stairs::{MAX_STEP_M, MAX_STEPS, Stairs};
