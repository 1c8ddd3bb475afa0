//! A height field (issue 45 item 1): a grid of ground heights `cell_m`
//! apart, `cols` samples along +x and `rows` along +z from `origin_m`, each
//! cell split into two triangles the way MuJoCo splits an `hfield`'s, so the
//! planner, the ground springs and an exported model agree on every height.
//!
//! # The split, and why this diagonal
//! MuJoCo walks a height field's rows as a triangle strip: in its own frame
//! (z up) cell (r, c) is the triangles {(c, r+1), (c, r), (c+1, r+1)} and
//! {(c, r), (c+1, r+1), (c+1, r)}, split along the diagonal from sample
//! (c, r) to (c+1, r+1). An exported field lies in gaitlab's y-up world with
//! its z axis turned onto +y, which turns its rows onto −z; MuJoCo stores
//! gaitlab's rows in reverse order, and its diagonal is then the one from
//! (x low, z high) to (x high, z low). So here a cell with fractions u
//! (along x) and w (along z) is split along u + w = 1: the triangle of
//! samples (0, 0), (1, 0), (0, 1) where u + w ≤ 1, and (1, 0), (0, 1),
//! (1, 1) beyond.
//!
//! Outside the grid the ground is the floor, height 0; heights are 0 or
//! more (a field raises ground above the floor, as MuJoCo's floor plane lies
//! under it).

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::error::{TerrainError, finite_within};

/// The most samples a field may have (1024 × 1024).
pub const MAX_SAMPLES: usize = 1 << 20;

/// The highest sample and the widest cell, metres.
pub const MAX_HEIGHT_M: f64 = 100.0;

/// The highest friction coefficient a cell may have.
pub const MAX_FRICTION: f64 = 10.0;

/// A grid of ground heights.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct HeightField {
    /// Distance between neighbouring samples, metres (> 0).
    pub cell_m: f64,
    /// Samples along +x (≥ 2).
    pub cols: usize,
    /// Samples along +z (≥ 2).
    pub rows: usize,
    /// Where sample (row 0, column 0) lies, `[x, z]` metres. Default: the
    /// grid centred on the origin.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub origin_m: Option<[f64; 2]>,
    /// Heights, metres, `rows × cols` of them, row by row (row 0 first, each
    /// row from column 0), each 0 to 100.
    pub heights_m: Vec<f64>,
    /// Friction coefficient per cell, `(rows − 1) × (cols − 1)` of them in
    /// the same order, each 0 to 10; left out, the engine's own.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<Vec<f64>>,
}

/// A point's cell and its fractions in it.
struct InCell {
    row: usize,
    col: usize,
    u: f64,
    w: f64,
}

impl HeightField {
    /// Sample (row 0, column 0), `[x, z]` metres.
    #[must_use]
    pub fn origin(&self) -> [f64; 2] {
        self.origin_m.unwrap_or_else(|| {
            let half = |n: usize| -0.5 * self.cell_m * (n.saturating_sub(1)) as f64;
            [half(self.cols), half(self.rows)]
        })
    }

    fn sample(&self, row: usize, col: usize) -> f64 {
        self.heights_m
            .get(row * self.cols + col)
            .copied()
            .unwrap_or(0.0)
    }

    /// The cell under (x, z), or `None` off the grid.
    fn locate(&self, x: f64, z: f64) -> Option<InCell> {
        if self.cols < 2 || self.rows < 2 || self.cell_m.is_nan() || self.cell_m <= 0.0 {
            return None;
        }
        let [x0, z0] = self.origin();
        let (gx, gz) = ((x - x0) / self.cell_m, (z - z0) / self.cell_m);
        let (last_col, last_row) = ((self.cols - 1) as f64, (self.rows - 1) as f64);
        if !(0.0..=last_col).contains(&gx) || !(0.0..=last_row).contains(&gz) {
            return None;
        }
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "gx and gz are within 0 and the last index"
        )]
        let (col, row) = (
            (gx.floor() as usize).min(self.cols - 2),
            (gz.floor() as usize).min(self.rows - 2),
        );
        Some(InCell {
            row,
            col,
            u: gx - col as f64,
            w: gz - row as f64,
        })
    }

    /// Ground height at (x, z), metres: the height of the cell's triangle
    /// under the point, 0 off the grid.
    #[must_use]
    pub fn height_m(&self, x: f64, z: f64) -> f64 {
        let Some(InCell { row, col, u, w }) = self.locate(x, z) else {
            return 0.0;
        };
        let h00 = self.sample(row, col);
        let h10 = self.sample(row, col + 1);
        let h01 = self.sample(row + 1, col);
        let h11 = self.sample(row + 1, col + 1);
        if u + w <= 1.0 {
            h00 + u * (h10 - h00) + w * (h01 - h00)
        } else {
            h11 + (1.0 - u) * (h01 - h11) + (1.0 - w) * (h10 - h11)
        }
    }

    /// The unit normal of the triangle under (x, z); up off the grid.
    #[must_use]
    pub fn normal(&self, x: f64, z: f64) -> DVec3 {
        let Some(InCell { row, col, u, w }) = self.locate(x, z) else {
            return DVec3::Y;
        };
        let h00 = self.sample(row, col);
        let h10 = self.sample(row, col + 1);
        let h01 = self.sample(row + 1, col);
        let h11 = self.sample(row + 1, col + 1);
        // Slopes dh/dx and dh/dz of the triangle, per cell.
        let (gx, gz) = if u + w <= 1.0 {
            (h10 - h00, h01 - h00)
        } else {
            (h11 - h01, h11 - h10)
        };
        DVec3::new(-gx / self.cell_m, 1.0, -gz / self.cell_m).normalize()
    }

    /// The friction coefficient of the cell under (x, z), when the field
    /// has one.
    #[must_use]
    pub fn friction(&self, x: f64, z: f64) -> Option<f64> {
        let cell = self.locate(x, z)?;
        self.friction
            .as_ref()?
            .get(cell.row * (self.cols - 1) + cell.col)
            .copied()
    }

    /// Checks the grid's sizes and every value.
    ///
    /// # Errors
    /// A [`TerrainError`] naming the field: `cell_m`, `rows`, `cols`, the
    /// grid's size, `heights_m[i]`, `friction[i]`, `origin_m`.
    pub fn check(&self) -> Result<(), TerrainError> {
        finite_within("cell_m", self.cell_m, MAX_HEIGHT_M)?;
        if self.cell_m <= 0.0 {
            return Err(TerrainError::new(
                "cell_m",
                format!("{} must be above 0", self.cell_m),
            ));
        }
        for (field, n) in [("cols", self.cols), ("rows", self.rows)] {
            if n < 2 {
                return Err(TerrainError::new(
                    field,
                    format!("{n} samples; a grid needs at least 2 (one cell)"),
                ));
            }
        }
        let samples = self
            .rows
            .checked_mul(self.cols)
            .filter(|&n| n <= MAX_SAMPLES);
        let Some(samples) = samples else {
            return Err(TerrainError::new(
                "rows",
                format!(
                    "{} × {} samples; at most {MAX_SAMPLES}",
                    self.rows, self.cols
                ),
            ));
        };
        if let Some(origin) = self.origin_m {
            for (i, v) in origin.iter().enumerate() {
                finite_within(&format!("origin_m[{i}]"), *v, 1000.0)?;
            }
        }
        if self.heights_m.len() != samples {
            return Err(TerrainError::new(
                "heights_m",
                format!("{} heights; rows × cols is {samples}", self.heights_m.len()),
            ));
        }
        for (i, &h) in self.heights_m.iter().enumerate() {
            let field = format!("heights_m[{i}]");
            finite_within(&field, h, MAX_HEIGHT_M)?;
            if h < 0.0 {
                return Err(TerrainError::new(
                    field,
                    format!("{h} is below the floor (0): a height field raises the ground"),
                ));
            }
        }
        if let Some(friction) = &self.friction {
            let cells = (self.rows - 1) * (self.cols - 1);
            if friction.len() != cells {
                return Err(TerrainError::new(
                    "friction",
                    format!("{} values; one per cell is {cells}", friction.len()),
                ));
            }
            for (i, &mu) in friction.iter().enumerate() {
                let field = format!("friction[{i}]");
                finite_within(&field, mu, MAX_FRICTION)?;
                if mu < 0.0 {
                    return Err(TerrainError::new(field, format!("{mu} is below 0")));
                }
            }
        }
        Ok(())
    }
}
