//! A flight of stairs (issue 45 item 1): `count` steps of `rise_m`, each
//! tread `run_m` deep, climbing toward `direction_deg`, the first riser at
//! `start_m` along that heading from the origin; flat at 0 before it and at
//! `count × rise_m` after the last tread. Treads are level: the normal is up
//! everywhere (a riser is a vertical step between two treads, see
//! [`Stairs::riser_between`]).

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::direction::{along, ground_direction};
use super::error::{TerrainError, finite_within};

/// The most steps a flight may have.
pub const MAX_STEPS: u32 = 1000;

/// The highest rise and the deepest tread, metres.
pub const MAX_STEP_M: f64 = 10.0;

/// A flight of stairs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Stairs {
    /// Height of each step, metres (negative: stairs down).
    pub rise_m: f64,
    /// Depth of each tread, metres (> 0).
    pub run_m: f64,
    /// Number of steps, 1–1000.
    pub count: u32,
    /// The heading the stairs climb toward, degrees: 0 is +x, 90 is +z.
    #[serde(default)]
    pub direction_deg: f64,
    /// Distance from the origin along that heading to the first riser,
    /// metres. Default 1.
    #[serde(default = "default_start_m")]
    pub start_m: f64,
}

fn default_start_m() -> f64 {
    1.0
}

impl Stairs {
    /// How many risers lie between the start and `s` metres along the
    /// heading (0 before the first, `count` after the last).
    fn steps_below(&self, s: f64) -> f64 {
        let k = ((s - self.start_m) / self.run_m).floor() + 1.0;
        k.clamp(0.0, f64::from(self.count))
    }

    /// Ground height at (x, z), metres. On a riser's own line the upper
    /// tread's height.
    #[must_use]
    pub fn height_m(&self, x: f64, z: f64) -> f64 {
        let s = along(ground_direction(self.direction_deg), x, z);
        self.rise_m * self.steps_below(s)
    }

    /// The unit surface normal: up (treads are level).
    #[must_use]
    pub fn normal(&self) -> DVec3 {
        DVec3::Y
    }

    /// Whether a riser lies between (x, z) points `a` and `b` (a foot
    /// moving from one to the other crosses a step's vertical face).
    #[must_use]
    pub fn riser_between(&self, a: [f64; 2], b: [f64; 2]) -> bool {
        let d = ground_direction(self.direction_deg);
        let (sa, sb) = (along(d, a[0], a[1]), along(d, b[0], b[1]));
        self.rise_m != 0.0 && self.steps_below(sa) != self.steps_below(sb)
    }

    /// Checks the sizes and the count.
    ///
    /// # Errors
    /// A [`TerrainError`] naming the field.
    pub fn check(&self) -> Result<(), TerrainError> {
        finite_within("rise_m", self.rise_m, MAX_STEP_M)?;
        finite_within("run_m", self.run_m, MAX_STEP_M)?;
        if self.run_m <= 0.0 {
            return Err(TerrainError::new(
                "run_m",
                format!("{} must be above 0", self.run_m),
            ));
        }
        if !(1..=MAX_STEPS).contains(&self.count) {
            return Err(TerrainError::new(
                "count",
                format!("{} steps; 1 to {MAX_STEPS}", self.count),
            ));
        }
        finite_within("direction_deg", self.direction_deg, 360.0)?;
        finite_within("start_m", self.start_m, 1000.0)
    }
}
