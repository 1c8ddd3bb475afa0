//! The lab's integral speed trim (`lab_additions.speed_trim`, not in Raibert
//! & Hodgins 1991): after each step or stride, the desired speed handed to
//! eq. 3 is corrected by that stride's mean-speed error, so a steady
//! placement error is integrated away. Off, the correction stays exactly
//! zero and eq. 3 runs as the paper writes it.

use glam::DVec3;

/// The running correction and where the stride being measured began.
#[derive(Clone, Copy, Debug, Default)]
pub struct SpeedTrim {
    /// Added to the desired speed (m/s).
    pub bias_mps: f64,
    /// Time (s) and position (world, m) at the start of the stride.
    mark: Option<(f64, DVec3)>,
}

impl SpeedTrim {
    /// The mean speed along `along` (a unit vector) from the mark to `time`
    /// (s) and `position` (m), when the mark is more than `min_s` seconds
    /// old.
    #[must_use]
    pub fn mean_since(&self, time: f64, position: DVec3, along: DVec3, min_s: f64) -> Option<f64> {
        let (t0, p0) = self.mark?;
        (time - t0 > min_s).then(|| along.dot(position - p0) / (time - t0))
    }

    /// Correct the bias by `gain` × `error_mps` (when `on`; off, the bias
    /// stays exactly zero), within ±`cap_mps`.
    pub fn correct(&mut self, on: bool, gain: f64, error_mps: f64, cap_mps: f64) {
        let gain = if on { gain } else { 0.0 };
        self.bias_mps = (self.bias_mps + gain * error_mps).clamp(-cap_mps, cap_mps);
    }

    /// Start the next stride at `time` (s) and `position` (world, m).
    pub fn mark(&mut self, time: f64, position: DVec3) {
        self.mark = Some((time, position));
    }

    /// Move the mark into a clock `elapsed_s` (s) later and a world moved
    /// by `-moved` (m): the same stride, seen from a new origin.
    pub fn move_origin(&mut self, elapsed_s: f64, moved: DVec3) {
        if let Some((t, p)) = &mut self.mark {
            *t -= elapsed_s;
            *p -= moved;
        }
    }

    /// Close a stride at `time` and `position`: correct the bias by the
    /// stride's mean-speed error against `desired_mps` along `along`, then
    /// start the next one.
    #[allow(clippy::too_many_arguments)]
    pub fn stride(
        &mut self,
        on: bool,
        gain: f64,
        desired_mps: f64,
        cap_mps: f64,
        time: f64,
        position: DVec3,
        along: DVec3,
        min_s: f64,
    ) {
        if let Some(mean) = self.mean_since(time, position, along, min_s) {
            self.correct(on, gain, desired_mps - mean, cap_mps);
        }
        self.mark(time, position);
    }
}

impl SpeedTrim {
    /// [`SpeedTrim::stride`] for a creature at `heading` (rad) wanting
    /// `desired_mps` (at its scale), the correction capped at half the
    /// desired speed and at least 0.25 m/s × `velocity_scale` (Table 1's
    /// √L), measured at the centre of mass `com` (world, m).
    #[allow(clippy::too_many_arguments)]
    pub fn stride_at_heading(
        &mut self,
        on: bool,
        gain: f64,
        desired_mps: f64,
        velocity_scale: f64,
        time: f64,
        com: DVec3,
        heading: f64,
    ) {
        let cap = 0.5 * desired_mps.abs().max(0.5 * velocity_scale);
        let along = crate::control::laws::attitude::heading_forward(heading);
        self.stride(on, gain, desired_mps, cap, time, com, along, 0.0);
    }
}

impl SpeedTrim {
    /// [`SpeedTrim::stride_at_heading`] closing the stride `input` sees:
    /// its time and centre of mass, the commanded speed and heading.
    pub fn stride_at_input(
        &mut self,
        on: bool,
        gain: f64,
        velocity_scale: f64,
        input: &crate::world::sim::ControlInput<'_>,
    ) {
        let com = crate::dynamics::energy::center_of_mass(&input.creature.model, input.data);
        let c = input.commands;
        let (speed, heading) = (c.speed_mps, c.heading_rad);
        self.stride_at_heading(on, gain, speed, velocity_scale, input.time, com, heading);
    }
}

/// A position along one axis as a point, for [`SpeedTrim`] with
/// `along = DVec3::Z` (the same bits as the scalar difference).
#[must_use]
pub fn along_z(x_m: f64) -> DVec3 {
    DVec3::new(0.0, 0.0, x_m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slow_stride_raises_the_bias_within_its_cap_and_off_it_stays_zero() {
        let mut trim = SpeedTrim::default();
        trim.stride(true, 0.5, 2.0, 0.3, 0.0, along_z(0.0), DVec3::Z, 0.0);
        assert_eq!(trim.bias_mps, 0.0, "no stride measured yet");
        // 1 m in 1 s against 2 m/s: error 1 m/s, half of it, capped at 0.3.
        trim.stride(true, 0.5, 2.0, 0.3, 1.0, along_z(1.0), DVec3::Z, 0.0);
        assert_eq!(trim.bias_mps, 0.3);
        let mut off = SpeedTrim::default();
        off.stride(false, 0.5, 2.0, 0.3, 0.0, along_z(0.0), DVec3::Z, 0.0);
        off.stride(false, 0.5, 2.0, 0.3, 1.0, along_z(1.0), DVec3::Z, 0.0);
        assert_eq!(off.bias_mps, 0.0);
        // A stride shorter than `min_s` is not measured.
        let mut trim = SpeedTrim::default();
        trim.mark(0.0, DVec3::ZERO);
        assert_eq!(trim.mean_since(0.0005, DVec3::Z, DVec3::Z, 1e-3), None);
        assert_eq!(trim.mean_since(0.5, DVec3::Z, DVec3::Z, 1e-3), Some(2.0));
    }
}
