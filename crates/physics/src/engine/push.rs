//! Pushes and recovery (issue 42's robustness test; the paper pushes none
//! of its creatures): a horizontal change of the trunk's velocity at a
//! chosen time — the whole creature's, as an impulse on its body would give
//! it at once — and whether the creature recovered: it did not fall in the
//! [`RECOVERY_S`] seconds after the push, and its forward speed over the
//! last [`WINDOW_S`] of them is within [`SPEED_TOLERANCE`] of the desired
//! speed.

use glam::DVec3;

/// Seconds after a push by which the creature must have recovered.
pub const RECOVERY_S: f64 = 5.0;

/// The window at the end of [`RECOVERY_S`] over which the forward speed is
/// measured (s): about two strides of every gait.
pub const WINDOW_S: f64 = 1.0;

/// The share of the desired speed the forward speed may miss it by (the
/// paper's "within about 10 %").
pub const SPEED_TOLERANCE: f64 = 0.10;

/// One push and what followed it.
#[derive(Clone, Debug, PartialEq)]
pub struct Push {
    /// When it was applied, on the run's clock (s).
    pub at_s: f64,
    /// The change of the trunk's velocity, world x (sideways) and z
    /// (forward at heading 0), m/s.
    pub dv_mps: [f64; 2],
    /// The desired speed when it was applied (m/s).
    pub desired_mps: f64,
    /// The heading's forward direction then (world, horizontal, unit).
    forward: DVec3,
    /// The centre of mass at the start of the window.
    window_start: Option<DVec3>,
    /// Forward speed over the window (m/s), once measured.
    pub speed_after_mps: Option<f64>,
    /// Whether the creature fell (or was put back) within [`RECOVERY_S`].
    pub fell: bool,
}

impl Push {
    /// A push of `dv_mps` at `at_s` while the creature is asked to run at
    /// `desired_mps` along `forward`.
    #[must_use]
    pub fn new(at_s: f64, dv_mps: [f64; 2], desired_mps: f64, forward: DVec3) -> Self {
        Self {
            at_s,
            dv_mps,
            desired_mps,
            forward: DVec3::new(forward.x, 0.0, forward.z).normalize_or(DVec3::Z),
            window_start: None,
            speed_after_mps: None,
            fell: false,
        }
    }

    /// Whether the recovery is still being watched at run time `now_s`.
    #[must_use]
    pub fn open(&self, now_s: f64) -> bool {
        !self.fell && self.speed_after_mps.is_none() && now_s >= self.at_s
    }

    /// Watch one step: the run's clock `now_s`, the centre of mass `com`,
    /// and when the creature last fell or was put back (run time, s), if
    /// ever: one at or after the push ends its recovery.
    pub fn observe(&mut self, now_s: f64, com: DVec3, fell_at_s: Option<f64>) {
        if !self.open(now_s) {
            return;
        }
        if fell_at_s.is_some_and(|t| t >= self.at_s) {
            self.fell = true;
            return;
        }
        let since = now_s - self.at_s;
        match self.window_start {
            None if since >= RECOVERY_S - WINDOW_S => self.window_start = Some(com),
            Some(start) if since >= RECOVERY_S => {
                let travelled = (com - start).dot(self.forward);
                self.speed_after_mps = Some(travelled / (since - (RECOVERY_S - WINDOW_S)));
            }
            _ => {}
        }
    }

    /// `Some(true)` when the creature recovered, `Some(false)` when it fell
    /// or its speed missed, `None` while the run has not reached
    /// [`RECOVERY_S`] after the push.
    #[must_use]
    pub fn recovered(&self) -> Option<bool> {
        if self.fell {
            return Some(false);
        }
        let speed = self.speed_after_mps?;
        let desired = self.desired_mps.abs().max(1e-9);
        Some((speed - self.desired_mps).abs() <= SPEED_TOLERANCE * desired)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn watched(speed: f64, fall_at: Option<f64>) -> Push {
        let mut p = Push::new(2.0, [0.3, 0.0], 2.0, DVec3::Z);
        let dt = 0.01;
        for k in 0..1000 {
            let t = k as f64 * dt;
            let com = DVec3::new(0.5 * t, 0.6, speed * t);
            p.observe(t, com, fall_at.filter(|&f| t >= f));
        }
        p
    }

    #[test]
    fn a_creature_back_at_speed_after_five_seconds_recovered() {
        let on = watched(2.1, None);
        // Measured over [6, 7] s along the heading, sideways drift ignored.
        let v = on.speed_after_mps.expect("measured");
        assert!((v - 2.1).abs() < 0.02, "{v}");
        assert_eq!(on.recovered(), Some(true));
        // 12 % slow: not recovered.
        assert_eq!(watched(1.76, None).recovered(), Some(false));
        // A fall within the five seconds: not recovered, whatever the speed.
        let fell = watched(2.0, Some(4.0));
        assert_eq!((fell.fell, fell.recovered()), (true, Some(false)));
        // A fall before the push is not this push's.
        assert!(!watched(2.0, Some(1.0)).fell);
    }

    #[test]
    fn a_run_that_ends_early_has_no_verdict() {
        let mut p = Push::new(8.0, [0.0, -0.3], 2.0, DVec3::Z);
        p.observe(9.0, DVec3::ZERO, None);
        assert_eq!(p.recovered(), None);
        assert!(p.open(9.0));
    }
}
