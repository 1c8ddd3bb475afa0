//! A plane through the origin, rising at `slope_deg` toward `direction_deg`
//! (issue 45 item 1: a slope in any direction): height = tan(slope) · s,
//! s the distance along the uphill direction.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::direction::{along, ground_direction};
use super::error::{TerrainError, finite_within};

/// The steepest slope a plane may have, degrees.
pub const MAX_SLOPE_DEG: f64 = 60.0;

/// A sloped plane through the origin.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Plane {
    /// The slope, degrees, 0 to 60 (negative: falling toward `direction_deg`).
    pub slope_deg: f64,
    /// The uphill heading, degrees: 0 is +x, 90 is +z. Default 0.
    #[serde(default)]
    pub direction_deg: f64,
}

impl Plane {
    /// Ground height at (x, z), metres.
    #[must_use]
    pub fn height_m(&self, x: f64, z: f64) -> f64 {
        self.rise_per_m() * along(ground_direction(self.direction_deg), x, z)
    }

    /// The unit surface normal (the same everywhere).
    #[must_use]
    pub fn normal(&self) -> DVec3 {
        let d = ground_direction(self.direction_deg);
        let g = self.rise_per_m();
        DVec3::new(-g * d.x, 1.0, -g * d.z).normalize()
    }

    /// tan(slope): metres of rise per metre along the uphill direction.
    fn rise_per_m(&self) -> f64 {
        let (s, c) = crate::trig::sin_cos(self.slope_deg.to_radians());
        s / c
    }

    /// Checks the slope and heading.
    ///
    /// # Errors
    /// A [`TerrainError`] naming `slope_deg` or `direction_deg`.
    pub fn check(&self) -> Result<(), TerrainError> {
        finite_within("slope_deg", self.slope_deg, MAX_SLOPE_DEG)?;
        finite_within("direction_deg", self.direction_deg, 360.0)
    }
}
