//! Drivers: the one interface every engine implements (DESIGN.md "Data flow":
//! a driver advances by `dt` and yields a [`Pose`] plus metrics), and the IK
//! tracking report and metrics shared by the IK-based drivers (She 2006 §5.3's
//! distance `d` between each end effector and its target).
//!
//! Front ends (browser app, CLI, tests) only ever see drivers, poses and
//! metrics. The core reads no clocks: wall-time figures such as µs per IK
//! iteration are measured by the caller around [`Driver::step`] and divided by
//! [`IkMetrics::iterations`].

use glam::DVec3;

use crate::Skeleton;
use crate::ik::Targets;
use crate::pose::Pose;

/// An engine that animates one figure: advance by `dt`, read the pose.
///
/// Object safe, so front ends can hold a `Box<dyn Driver>`.
pub trait Driver {
    /// Advances the animation by `dt` seconds (one frame). A non-positive or
    /// non-finite `dt` leaves the state unchanged.
    fn step(&mut self, dt: f64);

    /// Simulated time since the last reset, seconds.
    fn time(&self) -> f64;

    /// Returns to the initial state: time 0, rest pose, metrics cleared.
    fn reset(&mut self);

    /// The figure being animated.
    fn skeleton(&self) -> &Skeleton;

    /// The current pose (root transform and one value per joint).
    fn pose(&self) -> &Pose;

    /// World position of every end effector in the current pose, metres, in the
    /// skeleton's effector order.
    fn effector_positions(&self) -> &[DVec3];

    /// The targets the effectors are tracking this frame (for drawing), if the
    /// engine has targets.
    fn targets(&self) -> Option<&Targets> {
        None
    }

    /// What the IK did in the last frame, for IK-driven engines.
    fn ik_report(&self) -> Option<&IkFrameReport> {
        None
    }

    /// IK tracking figures accumulated since the last reset, for IK-driven engines.
    fn ik_metrics(&self) -> Option<&IkMetrics> {
        None
    }
}

/// What the IK did in one frame.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IkFrameReport {
    /// Distance from each effector to its target after the frame's iterations,
    /// metres, in the skeleton's effector order (She 2006 §5.3's `d`).
    pub effector_error_m: Vec<f64>,
    /// IK iterations run this frame.
    pub iterations: usize,
    /// Largest of `effector_error_m`, metres.
    pub max_error_m: f64,
    /// Joints held at a limit in the frame's last iteration.
    pub clamped_joints: usize,
    /// Whether the solve produced non-finite joint values and the frame's
    /// starting values were restored (an instability warning).
    pub restored: bool,
}

impl IkFrameReport {
    /// A report for `effectors` effectors, all errors zero.
    #[must_use]
    pub fn new(effectors: usize) -> Self {
        Self {
            effector_error_m: vec![0.0; effectors],
            ..Self::default()
        }
    }
}

/// IK tracking figures accumulated over frames (DESIGN.md metric keys
/// `frames`, `sim_seconds`, `effectors: [{mean_error_m, max_error_m}]`; divide
/// the caller's measured wall time by `iterations` for `us_per_iteration`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IkMetrics {
    /// Frames recorded.
    pub frames: u64,
    /// Simulated seconds recorded.
    pub sim_seconds: f64,
    /// IK iterations run in all recorded frames.
    pub iterations: u64,
    /// Frames in which some effector error was not finite (counted as an
    /// infinite maximum, left out of the means).
    pub non_finite_frames: u64,
    /// Frames whose solve went non-finite and was undone ([`IkFrameReport::restored`]).
    pub restored_frames: u64,
    error_sum_m: Vec<f64>,
    error_max_m: Vec<f64>,
    finite_frames: u64,
}

impl IkMetrics {
    /// Empty metrics for `effectors` effectors.
    #[must_use]
    pub fn new(effectors: usize) -> Self {
        Self {
            error_sum_m: vec![0.0; effectors],
            error_max_m: vec![0.0; effectors],
            ..Self::default()
        }
    }

    /// Clears every figure, keeping the effector count.
    pub fn clear(&mut self) {
        let effectors = self.error_sum_m.len();
        *self = Self::new(effectors);
    }

    /// Number of effectors tracked.
    #[must_use]
    pub fn effector_count(&self) -> usize {
        self.error_sum_m.len()
    }

    /// Adds one frame of `dt` seconds. Allocates nothing once the effector
    /// count matches the report's.
    pub fn record(&mut self, dt: f64, report: &IkFrameReport) {
        if report.effector_error_m.len() != self.error_sum_m.len() {
            *self = Self::new(report.effector_error_m.len());
        }
        self.frames += 1;
        self.sim_seconds += dt;
        self.iterations += report.iterations as u64;
        self.restored_frames += u64::from(report.restored);
        if report.effector_error_m.iter().all(|e| e.is_finite()) {
            self.finite_frames += 1;
            for ((sum, max), &error) in self
                .error_sum_m
                .iter_mut()
                .zip(self.error_max_m.iter_mut())
                .zip(&report.effector_error_m)
            {
                *sum += error;
                *max = max.max(error);
            }
        } else {
            self.non_finite_frames += 1;
            for (max, &error) in self.error_max_m.iter_mut().zip(&report.effector_error_m) {
                if !error.is_finite() {
                    *max = f64::INFINITY;
                }
            }
        }
    }

    /// Mean distance of effector `e` to its target over the recorded frames,
    /// metres (0 before any frame; `None` if `e` is out of range).
    #[must_use]
    pub fn mean_error_m(&self, e: usize) -> Option<f64> {
        let sum = *self.error_sum_m.get(e)?;
        Some(if self.finite_frames == 0 {
            0.0
        } else {
            sum / self.finite_frames as f64
        })
    }

    /// Largest distance of effector `e` to its target over the recorded frames,
    /// metres (`None` if `e` is out of range).
    #[must_use]
    pub fn max_error_m(&self, e: usize) -> Option<f64> {
        self.error_max_m.get(e).copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn metrics_average_and_maximum_over_frames() {
        let mut metrics = IkMetrics::new(2);
        let mut report = IkFrameReport::new(2);
        report.iterations = 3;
        report.effector_error_m.copy_from_slice(&[0.001, 0.004]);
        metrics.record(0.5, &report);
        report.effector_error_m.copy_from_slice(&[0.003, 0.002]);
        metrics.record(0.5, &report);
        assert_eq!(metrics.frames, 2);
        assert_eq!(metrics.iterations, 6);
        assert!((metrics.sim_seconds - 1.0).abs() < 1e-12);
        assert!((metrics.mean_error_m(0).unwrap_or(f64::NAN) - 0.002).abs() < 1e-12);
        assert!((metrics.mean_error_m(1).unwrap_or(f64::NAN) - 0.003).abs() < 1e-12);
        assert_eq!(metrics.max_error_m(1), Some(0.004));
        assert_eq!(metrics.mean_error_m(2), None);
    }

    #[test]
    fn non_finite_errors_surface_as_infinite_maximum() {
        let mut metrics = IkMetrics::new(1);
        let mut report = IkFrameReport::new(1);
        report.effector_error_m[0] = f64::NAN;
        metrics.record(0.1, &report);
        assert_eq!(metrics.non_finite_frames, 1);
        assert_eq!(metrics.max_error_m(0), Some(f64::INFINITY));
        assert_eq!(metrics.mean_error_m(0), Some(0.0));
        metrics.clear();
        assert_eq!(metrics.frames, 0);
        assert_eq!(metrics.effector_count(), 1);
    }
}
