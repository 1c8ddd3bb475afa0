//! Playback: how much simulated time each UI frame advances (fixed frames of
//! the preset's frame length, at most [`MAX_FRAME_ADVANCE_S`] of wall time per
//! UI frame), pause and single steps, and the smoothed display frame rate and
//! simulation cost.

/// Longest real time one UI frame may advance the animation, seconds (a tab
/// that was hidden does not fast-forward).
pub const MAX_FRAME_ADVANCE_S: f64 = 0.1;

/// Slowest and fastest playback rate (simulated seconds per wall second).
pub const PLAYBACK_RATES: std::ops::RangeInclusive<f64> = 0.1..=2.0;

/// Most single steps queued at once.
const MAX_PENDING_STEPS: u32 = 600;

/// A monotonic clock in milliseconds, supplied by the platform (the core and the
/// lab read no clocks themselves).
pub type Clock = Box<dyn Fn() -> f64>;

/// Pause, pending steps, the wall-time accumulator and the smoothed timings.
#[derive(Default)]
pub struct Playback {
    /// Whether the animation is paused.
    pub(crate) paused: bool,
    pending_steps: u32,
    accumulator_s: f64,
    /// Smoothed display frame rate, frames per second.
    pub(crate) fps: f64,
    /// Smoothed time spent advancing the driver per animation frame, µs.
    pub(crate) sim_us_per_frame: f64,
    pub(crate) clock: Option<Clock>,
    /// Simulated seconds per wall second ([`PLAYBACK_RATES`]; 0 reads as 1):
    /// the same fixed frames, fewer or more of them each second, so a slow
    /// replay shows exactly the motion a real-time one does.
    pub(crate) rate: f64,
}

impl Playback {
    /// Queues one frame to advance on the next update, even when paused.
    pub fn single_step(&mut self) {
        self.pending_steps = self.pending_steps.saturating_add(1).min(MAX_PENDING_STEPS);
    }

    /// Forgets partial frames (after a reset).
    pub fn clear_accumulator(&mut self) {
        self.accumulator_s = 0.0;
    }

    /// How many frames of `frame_s` seconds to advance for `real_dt` seconds
    /// of wall time; paused, only the requested single steps.
    pub fn steps_for(&mut self, real_dt: f64, frame_s: f64) -> u32 {
        let mut steps = 0;
        if self.paused {
            steps = self.pending_steps;
            self.accumulator_s = 0.0;
        } else if real_dt.is_finite() && real_dt > 0.0 {
            let rate = if self.rate > 0.0 { self.rate } else { 1.0 };
            self.accumulator_s += real_dt.min(MAX_FRAME_ADVANCE_S) * rate;
            while self.accumulator_s >= frame_s {
                self.accumulator_s -= frame_s;
                steps += 1;
            }
            steps += self.pending_steps;
        }
        self.pending_steps = 0;
        steps
    }

    /// The playback rate, simulated seconds per wall second.
    #[must_use]
    pub fn rate(&self) -> f64 {
        if self.rate > 0.0 { self.rate } else { 1.0 }
    }

    /// Sets the playback rate, within [`PLAYBACK_RATES`].
    pub fn set_rate(&mut self, rate: f64) {
        self.rate = rate.clamp(*PLAYBACK_RATES.start(), *PLAYBACK_RATES.end());
    }

    /// The clock's time in milliseconds, when there is a clock.
    #[must_use]
    pub fn now_ms(&self) -> Option<f64> {
        self.clock.as_ref().map(|clock| clock())
    }

    /// Notes that `steps` frames took since `started` (milliseconds).
    pub fn note_sim_time(&mut self, started: Option<f64>, steps: u32) {
        if let (Some(started), Some(now)) = (started, self.now_ms()) {
            let per_frame_us = (now - started) * 1e3 / f64::from(steps);
            self.sim_us_per_frame = if self.sim_us_per_frame == 0.0 {
                per_frame_us
            } else {
                0.9 * self.sim_us_per_frame + 0.1 * per_frame_us
            };
        }
    }

    /// Records the display frame rate from the UI's frame time.
    pub fn note_frame_time(&mut self, dt: f64) {
        if dt > 0.0 && dt.is_finite() {
            let fps = 1.0 / dt;
            self.fps = if self.fps == 0.0 {
                fps
            } else {
                0.95 * self.fps + 0.05 * fps
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A second of wall time in 60 UI frames advances the frames of `rate`
    /// seconds of simulation.
    fn frames_in_a_second(rate: Option<f64>) -> u32 {
        let mut playback = Playback::default();
        if let Some(rate) = rate {
            playback.set_rate(rate);
        }
        (0..60)
            .map(|_| playback.steps_for(1.0 / 60.0, 1.0 / 60.0))
            .sum()
    }

    #[test]
    fn the_rate_scales_the_frames_a_wall_second_advances() {
        assert_eq!(frames_in_a_second(None), 60);
        assert_eq!(frames_in_a_second(Some(1.0)), 60);
        assert_eq!(frames_in_a_second(Some(0.1)), 6);
        assert_eq!(frames_in_a_second(Some(2.0)), 120);
        // Out of range: clamped.
        let mut playback = Playback::default();
        playback.set_rate(50.0);
        assert_eq!(playback.rate(), 2.0);
        playback.set_rate(0.0);
        assert_eq!(playback.rate(), 0.1);
    }
}
