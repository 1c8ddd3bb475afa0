//! A recorded effector-target track: target positions of `k` effectors at a
//! strictly increasing sequence of times, sampled by linear interpolation
//! (what `gaitlab track` follows; read from CSV by [`super::parse_target_csv`]).

use glam::DVec3;

use super::csv_error::CsvError;

/// Most data rows (not counting the header) a target track may have.
pub const MAX_TARGET_ROWS: usize = 1_000_000;

/// Effector targets over time. Invariants (checked by [`TargetTrack::new`]):
/// at least one row, times finite and strictly increasing, every position
/// finite, `positions.len() == times.len() · effector_count`.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetTrack {
    times: Vec<f64>,
    positions: Vec<DVec3>,
    effector_count: usize,
}

impl TargetTrack {
    /// A track from row times (seconds) and row-major positions (metres):
    /// row `r`, effector `e` is `positions[r · effector_count + e]`.
    ///
    /// # Errors
    /// A [`CsvError`] without line or column (the data did not come from text)
    /// if an invariant does not hold; the reason names the row.
    pub fn new(
        times: Vec<f64>,
        positions: Vec<DVec3>,
        effector_count: usize,
    ) -> Result<Self, CsvError> {
        if times.is_empty() {
            return Err(CsvError::detached("a target track needs at least one row"));
        }
        if times.len() > MAX_TARGET_ROWS {
            return Err(CsvError::detached(format!(
                "{} rows is more than the limit of {MAX_TARGET_ROWS}",
                times.len()
            )));
        }
        if times.len().checked_mul(effector_count) != Some(positions.len()) {
            return Err(CsvError::detached(format!(
                "{} positions for {} rows of {effector_count} effectors",
                positions.len(),
                times.len()
            )));
        }
        for (row, &t) in times.iter().enumerate() {
            if !t.is_finite() {
                return Err(CsvError::detached(format!(
                    "row {row}: time {t} is not finite"
                )));
            }
            if row > 0 && t <= times[row - 1] {
                return Err(CsvError::detached(format!(
                    "row {row}: time {t} is not after the previous time {}",
                    times[row - 1]
                )));
            }
        }
        if let Some(i) = positions.iter().position(|p| !p.is_finite()) {
            let row = i / effector_count.max(1);
            return Err(CsvError::detached(format!(
                "row {row}: a target position is not finite"
            )));
        }
        Ok(Self {
            times,
            positions,
            effector_count,
        })
    }

    /// Number of effectors per row, `k`.
    #[must_use]
    pub fn effector_count(&self) -> usize {
        self.effector_count
    }

    /// Number of rows (samples in time).
    #[must_use]
    pub fn row_count(&self) -> usize {
        self.times.len()
    }

    /// Row times, seconds, strictly increasing.
    #[must_use]
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// All positions, row-major (`row · k + effector`), metres.
    #[must_use]
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// The `k` targets of row `row`, or `None` past the last row.
    #[must_use]
    pub fn row(&self, row: usize) -> Option<&[DVec3]> {
        let start = row.checked_mul(self.effector_count)?;
        self.positions
            .get(start..start.checked_add(self.effector_count)?)
    }

    /// Time of the first row, seconds.
    #[must_use]
    pub fn start_time(&self) -> f64 {
        self.times.first().copied().unwrap_or(0.0)
    }

    /// Time of the last row, seconds.
    #[must_use]
    pub fn end_time(&self) -> f64 {
        self.times.last().copied().unwrap_or(0.0)
    }

    /// Writes the targets at time `t` (seconds) into `out`: linear interpolation
    /// between the rows around `t`, the first row before the start and the last
    /// row after the end (a NaN `t` reads as the start). Fills
    /// `min(out.len(), k)` entries; allocates nothing.
    pub fn sample(&self, t: f64, out: &mut [DVec3]) {
        let k = self.effector_count;
        let last = self.times.len().saturating_sub(1);
        // Rows a and b around t, and the weight of b.
        let (a, b, weight) = if t.is_nan() || t <= self.start_time() {
            (0, 0, 0.0)
        } else if t >= self.end_time() {
            (last, last, 0.0)
        } else {
            // times[0] < t < times[last], so 1 <= b <= last.
            let b = self.times.partition_point(|&time| time <= t);
            let (t0, t1) = (self.times[b - 1], self.times[b]);
            (b - 1, b, (t - t0) / (t1 - t0))
        };
        for (e, slot) in out.iter_mut().take(k).enumerate() {
            let from = self.positions[a * k + e];
            let to = self.positions[b * k + e];
            *slot = from.lerp(to, weight);
        }
    }
}
