//! The ground every engine stands on (issue 45 item 1; DESIGN.md: the world
//! a driver moves in is core's): flat, a plane, stairs or a height field,
//! with `height_m(x, z)`, `normal(x, z)` and an optional friction per place.
//! In a preset it is `scenario.terrain`, an object tagged by `kind`.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::error::TerrainError;
use super::height_field::HeightField;
use super::plane::Plane;
use super::rough::Rough;
use super::stairs::Stairs;

/// The ground.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Terrain {
    /// The floor, height 0 everywhere (every paper's ground).
    #[default]
    Flat,
    /// A plane through the origin, sloped in any direction.
    Plane(Plane),
    /// A flight of stairs.
    Stairs(Stairs),
    /// A grid of heights, split into triangles as MuJoCo splits an hfield.
    HeightField(HeightField),
    /// Smooth random bumps from a seed and a difficulty (a height field made
    /// from them).
    Rough(Rough),
}

impl Terrain {
    /// Whether this is the flat floor.
    #[must_use]
    pub fn is_flat(&self) -> bool {
        matches!(self, Terrain::Flat)
    }

    /// The kind's name, as `kind` writes it.
    #[must_use]
    pub fn kind_name(&self) -> &'static str {
        match self {
            Terrain::Flat => "flat",
            Terrain::Plane(_) => "plane",
            Terrain::Stairs(_) => "stairs",
            Terrain::HeightField(_) => "height_field",
            Terrain::Rough(_) => "rough",
        }
    }

    /// Ground height at (x, z), metres.
    #[must_use]
    pub fn height_m(&self, x: f64, z: f64) -> f64 {
        match self {
            Terrain::Flat => 0.0,
            Terrain::Plane(plane) => plane.height_m(x, z),
            Terrain::Stairs(stairs) => stairs.height_m(x, z),
            Terrain::HeightField(field) => field.height_m(x, z),
            Terrain::Rough(rough) => rough.field().height_m(x, z),
        }
    }

    /// The unit surface normal at (x, z).
    #[must_use]
    pub fn normal(&self, x: f64, z: f64) -> DVec3 {
        match self {
            Terrain::Flat => DVec3::Y,
            Terrain::Plane(plane) => plane.normal(),
            Terrain::Stairs(stairs) => stairs.normal(),
            Terrain::HeightField(field) => field.normal(x, z),
            Terrain::Rough(rough) => rough.field().normal(x, z),
        }
    }

    /// The friction coefficient at (x, z) where the terrain sets one (a
    /// height field's cells); `None`: the engine's own.
    #[must_use]
    pub fn friction(&self, x: f64, z: f64) -> Option<f64> {
        match self {
            Terrain::HeightField(field) => field.friction(x, z),
            _ => None,
        }
    }

    /// Checks every value.
    ///
    /// # Errors
    /// A [`TerrainError`] naming the field inside the terrain object.
    pub fn check(&self) -> Result<(), TerrainError> {
        match self {
            Terrain::Flat => Ok(()),
            Terrain::Plane(plane) => plane.check(),
            Terrain::Stairs(stairs) => stairs.check(),
            Terrain::HeightField(field) => field.check(),
            Terrain::Rough(rough) => rough.check(),
        }
    }
}
