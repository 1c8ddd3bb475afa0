//! Rough ground from a seed and a difficulty (issue 45 item 4): smooth random
//! bumps as a [`HeightField`], so a link carries a few numbers instead of the
//! heights. The bumps are value noise: a random height in [0, 1) at every
//! point of a lattice [`Rough::feature_m`] apart (each from the seed and the
//! point's indices by SplitMix64 — our own few lines, so every build and the
//! browser draw the same ground from the same seed), blended between lattice
//! points by a smoothstep in x and z, scaled by `difficulty ×
//! max_height_m`, and faded to the floor over one feature at the field's
//! border, so walking off it has no step. Difficulty 0 is the floor.

use std::sync::OnceLock;

use serde::{Deserialize, Serialize};

use super::error::{TerrainError, finite_within};
use super::height_field::{HeightField, MAX_HEIGHT_M, MAX_SAMPLES};

/// The finest bump spacing, metres.
pub const MIN_FEATURE_M: f64 = 0.01;
/// The finest cell, metres.
pub const MIN_CELL_M: f64 = 0.001;

/// Rough ground's parameters (and, once asked, its heights).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Rough {
    /// The random seed: the same seed, the same ground.
    #[serde(default)]
    pub seed: u64,
    /// 0 (flat) to 1 (bumps up to `max_height_m`).
    pub difficulty: f64,
    /// The bumps' height at difficulty 1, metres. Default 0.08.
    #[serde(default = "default_max_height_m")]
    pub max_height_m: f64,
    /// The distance between the bumps' lattice points, metres. Default 0.4.
    #[serde(default = "default_feature_m")]
    pub feature_m: f64,
    /// The height field's cell, metres. Default 0.05.
    #[serde(default = "default_cell_m")]
    pub cell_m: f64,
    /// The rough patch's size `[along x, along z]`, metres. Default 6 × 24.
    #[serde(default = "default_size_m")]
    pub size_m: [f64; 2],
    /// The patch's corner of least x and z, `[x, z]` metres. Default
    /// `[-3, -2]` (the creatures start at the origin facing +z).
    #[serde(default = "default_origin_m")]
    pub origin_m: [f64; 2],
    /// The heights, made on first use.
    #[serde(skip)]
    #[cfg_attr(feature = "schema", schemars(skip))]
    field: OnceLock<HeightField>,
}

fn default_max_height_m() -> f64 {
    0.08
}
fn default_feature_m() -> f64 {
    0.4
}
fn default_cell_m() -> f64 {
    0.05
}
fn default_size_m() -> [f64; 2] {
    [6.0, 24.0]
}
fn default_origin_m() -> [f64; 2] {
    [-3.0, -2.0]
}

impl PartialEq for Rough {
    fn eq(&self, other: &Self) -> bool {
        self.seed == other.seed
            && self.difficulty == other.difficulty
            && self.max_height_m == other.max_height_m
            && self.feature_m == other.feature_m
            && self.cell_m == other.cell_m
            && self.size_m == other.size_m
            && self.origin_m == other.origin_m
    }
}

/// SplitMix64's step: a well-mixed 64-bit value from `x`.
fn mix(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

/// Smoothstep: 0 at 0, 1 at 1, flat at both ends.
fn smooth(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

impl Rough {
    /// Rough ground of `difficulty` from `seed`, every other value its default.
    #[must_use]
    pub fn new(seed: u64, difficulty: f64) -> Self {
        Self {
            seed,
            difficulty,
            max_height_m: default_max_height_m(),
            feature_m: default_feature_m(),
            cell_m: default_cell_m(),
            size_m: default_size_m(),
            origin_m: default_origin_m(),
            field: OnceLock::new(),
        }
    }

    /// The lattice's random height in [0, 1) at indices `(i, k)`.
    fn lattice(&self, i: i64, k: i64) -> f64 {
        let bits = mix(self.seed ^ mix(i.cast_unsigned() ^ mix(k.cast_unsigned())));
        (bits >> 11) as f64 / (1_u64 << 53) as f64
    }

    /// The noise in [0, 1) at `(x, z)` relative to the patch's corner.
    fn noise(&self, u: f64, w: f64) -> f64 {
        let (gu, gw) = (u / self.feature_m, w / self.feature_m);
        let (fu, fw) = (gu.floor(), gw.floor());
        #[expect(
            clippy::cast_possible_truncation,
            reason = "the patch is at most 1000 m across and the spacing at least 1 cm"
        )]
        let (i, k) = (fu as i64, fw as i64);
        let (su, sw) = (smooth(gu - fu), smooth(gw - fw));
        let (i1, k1) = (i.wrapping_add(1), k.wrapping_add(1));
        let a = self.lattice(i, k) + su * (self.lattice(i1, k) - self.lattice(i, k));
        let b = self.lattice(i, k1) + su * (self.lattice(i1, k1) - self.lattice(i, k1));
        a + sw * (b - a)
    }

    /// Samples along x and along z.
    fn samples(&self) -> (usize, usize) {
        let count = |size: f64| {
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "check() keeps the count within MAX_SAMPLES"
            )]
            let n = (size / self.cell_m).round().max(1.0) as usize + 1;
            n
        };
        (count(self.size_m[0]), count(self.size_m[1]))
    }

    /// The ground as a height field (made once; [`Rough::check`] first).
    #[must_use]
    pub fn field(&self) -> &HeightField {
        self.field.get_or_init(|| self.make_field())
    }

    fn make_field(&self) -> HeightField {
        let (cols, rows) = self.samples();
        let amplitude = self.difficulty * self.max_height_m;
        let [width, depth] = self.size_m;
        let mut heights_m = Vec::with_capacity(rows * cols);
        for r in 0..rows {
            for c in 0..cols {
                let (u, w) = (self.cell_m * c as f64, self.cell_m * r as f64);
                let edge = u.min(width - u).min(w).min(depth - w).max(0.0);
                let fade = smooth(edge / self.feature_m);
                heights_m.push((amplitude * fade * self.noise(u, w)).max(0.0));
            }
        }
        HeightField {
            cell_m: self.cell_m,
            cols,
            rows,
            origin_m: Some(self.origin_m),
            heights_m,
            friction: None,
        }
    }

    /// Checks every value.
    ///
    /// # Errors
    /// A [`TerrainError`] naming the field.
    pub fn check(&self) -> Result<(), TerrainError> {
        finite_within("difficulty", self.difficulty, 1.0)?;
        if self.difficulty < 0.0 {
            return Err(TerrainError::new(
                "difficulty",
                format!("{} is below 0 (0 is flat, 1 the roughest)", self.difficulty),
            ));
        }
        finite_within("max_height_m", self.max_height_m, MAX_HEIGHT_M)?;
        if self.max_height_m < 0.0 {
            return Err(TerrainError::new(
                "max_height_m",
                format!("{} is below 0", self.max_height_m),
            ));
        }
        for (field, value, least) in [
            ("feature_m", self.feature_m, MIN_FEATURE_M),
            ("cell_m", self.cell_m, MIN_CELL_M),
        ] {
            finite_within(field, value, MAX_HEIGHT_M)?;
            if value < least {
                return Err(TerrainError::new(
                    field,
                    format!("{value} is below {least} m"),
                ));
            }
        }
        for (i, size) in self.size_m.iter().enumerate() {
            finite_within(&format!("size_m[{i}]"), *size, 1000.0)?;
            if *size < self.cell_m {
                return Err(TerrainError::new(
                    format!("size_m[{i}]"),
                    format!("{size} is less than one cell ({} m)", self.cell_m),
                ));
            }
        }
        for (i, at) in self.origin_m.iter().enumerate() {
            finite_within(&format!("origin_m[{i}]"), *at, 1000.0)?;
        }
        let along = |i: usize| (self.size_m[i] / self.cell_m).round() + 1.0;
        let samples = along(0) * along(1);
        #[expect(clippy::cast_precision_loss, reason = "a limit, compared")]
        if samples > MAX_SAMPLES as f64 {
            return Err(TerrainError::new(
                "cell_m",
                format!(
                    "{} × {} samples of {} m; at most {MAX_SAMPLES}",
                    along(0),
                    along(1),
                    self.cell_m
                ),
            ));
        }
        Ok(())
    }
}
