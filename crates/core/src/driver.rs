//! Drivers: the one interface every engine implements (DESIGN.md "Data flow":
//! a driver advances by `dt` and yields a [`Pose`] plus metrics), and the IK
//! tracking report and metrics shared by the IK-based drivers (She 2006 §5.3's
//! distance `d` between each end effector and its target, split into reachable
//! and unreachable targets, and the oscillation and jitter of each limb's joints
//! that §5.3 describes in words; docs/ik-metrics.md).
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
    /// How far each effector's target lies beyond its limb's reach this frame,
    /// metres, in effector order: |target − limb anchor| − limb length
    /// ([`crate::skeleton::Limb`]); zero or negative means reachable (She 2006
    /// §5.3's `d ≤ 0`). Zero for engines that do not measure it.
    pub out_of_reach_m: Vec<f64>,
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
            out_of_reach_m: vec![0.0; effectors],
            ..Self::default()
        }
    }
}

/// Smallest |Δθ| per frame that counts as motion when counting reversals, radians.
pub const REVERSAL_THRESHOLD_RAD: f64 = 1e-6;

/// One joint's motion history for the oscillation and jitter figures.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct JointMotion {
    /// Values seen so far, saturating at 2 (Δθ needs 2, Δ²θ needs 3).
    seen: u8,
    /// Last frame's value.
    previous: f64,
    /// Last frame's Δθ.
    delta: f64,
    /// Sign of the last Δθ of at least [`REVERSAL_THRESHOLD_RAD`] (0 before one).
    sign: f64,
    /// Times a significant Δθ had the opposite sign of the one before.
    reversals: u64,
    /// Sum of |Δ²θ| over the frames that have one, radians.
    jitter_sum: f64,
    /// Frames that have a Δ²θ.
    jitter_frames: u64,
}

impl JointMotion {
    fn record(&mut self, value: f64) {
        if self.seen >= 1 {
            let delta = value - self.previous;
            if delta.abs() >= REVERSAL_THRESHOLD_RAD {
                let sign = delta.signum();
                if self.sign != 0.0 && sign != self.sign {
                    self.reversals += 1;
                }
                self.sign = sign;
            }
            if self.seen >= 2 {
                self.jitter_sum += (delta - self.delta).abs();
                self.jitter_frames += 1;
            }
            self.delta = delta;
        }
        self.previous = value;
        self.seen = self.seen.saturating_add(1).min(2);
    }
}

/// One effector's reachability counts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct ReachCounts {
    /// Frames whose target was within reach.
    reachable_frames: u64,
    /// Finite frames with the target within reach, and their error sum (metres).
    reachable_finite: u64,
    reachable_error_sum_m: f64,
    /// Finite frames with the target out of reach, and their error sum (metres).
    unreachable_finite: u64,
    unreachable_error_sum_m: f64,
}

/// IK tracking figures accumulated over frames (DESIGN.md metric keys
/// `frames`, `sim_seconds`, `effectors: [{mean_error_m, max_error_m, reachable,
/// oscillation_hz}]`; divide the caller's measured wall time by `iterations`
/// for `us_per_iteration`). Per effector also the mean error over the frames
/// its target was (un)reachable and the jitter of its limb's joints; see
/// docs/ik-metrics.md. Allocation-free per frame.
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
    reach: Vec<ReachCounts>,
    /// Each effector's limb joints ([`crate::skeleton::Limb::joints`]).
    limb_joints: Vec<Vec<usize>>,
    /// One motion history per joint of the skeleton.
    motion: Vec<JointMotion>,
}

impl IkMetrics {
    /// Empty metrics for `skeleton`'s effectors, limbs and joints.
    #[must_use]
    pub fn new(skeleton: &Skeleton) -> Self {
        let effectors = skeleton.effector_count();
        Self {
            error_sum_m: vec![0.0; effectors],
            error_max_m: vec![0.0; effectors],
            reach: vec![ReachCounts::default(); effectors],
            limb_joints: skeleton.limbs().iter().map(|l| l.joints.clone()).collect(),
            motion: vec![JointMotion::default(); skeleton.joint_count()],
            ..Self::default()
        }
    }

    /// Clears every figure, keeping the effectors, limbs and joints.
    pub fn clear(&mut self) {
        *self = Self {
            error_sum_m: vec![0.0; self.error_sum_m.len()],
            error_max_m: vec![0.0; self.error_max_m.len()],
            reach: vec![ReachCounts::default(); self.reach.len()],
            limb_joints: std::mem::take(&mut self.limb_joints),
            motion: vec![JointMotion::default(); self.motion.len()],
            ..Self::default()
        };
    }

    /// Number of effectors tracked.
    #[must_use]
    pub fn effector_count(&self) -> usize {
        self.error_sum_m.len()
    }

    /// Adds one frame of `dt` seconds: the report measured on the shown pose
    /// and that pose's joint values (one per joint). Allocates nothing; entries
    /// beyond the skeleton's effector or joint count are ignored.
    pub fn record(&mut self, dt: f64, report: &IkFrameReport, values: &[f64]) {
        for (motion, &value) in self.motion.iter_mut().zip(values) {
            motion.record(value);
        }
        let finite = report.effector_error_m.iter().all(|e| e.is_finite());
        for ((reach, &beyond), &error) in self
            .reach
            .iter_mut()
            .zip(&report.out_of_reach_m)
            .zip(&report.effector_error_m)
        {
            let reachable = beyond <= 0.0;
            reach.reachable_frames += u64::from(reachable);
            if finite {
                if reachable {
                    reach.reachable_finite += 1;
                    reach.reachable_error_sum_m += error;
                } else {
                    reach.unreachable_finite += 1;
                    reach.unreachable_error_sum_m += error;
                }
            }
        }
        self.frames += 1;
        self.sim_seconds += dt;
        self.iterations += report.iterations as u64;
        self.restored_frames += u64::from(report.restored);
        if finite {
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

    /// Fraction of the recorded frames in which effector `e`'s target lay
    /// within its limb's reach (`None` before any frame or if `e` is out of range).
    #[must_use]
    pub fn reachable(&self, e: usize) -> Option<f64> {
        let reach = self.reach.get(e)?;
        (self.frames > 0).then(|| reach.reachable_frames as f64 / self.frames as f64)
    }

    /// Mean distance of effector `e` to its target over the finite frames in
    /// which the target was reachable, metres (`None` without such frames).
    #[must_use]
    pub fn mean_error_reachable_m(&self, e: usize) -> Option<f64> {
        let reach = self.reach.get(e)?;
        (reach.reachable_finite > 0)
            .then(|| reach.reachable_error_sum_m / reach.reachable_finite as f64)
    }

    /// Mean distance of effector `e` to its target over the finite frames in
    /// which the target was out of reach, metres (`None` without such frames).
    #[must_use]
    pub fn mean_error_unreachable_m(&self, e: usize) -> Option<f64> {
        let reach = self.reach.get(e)?;
        (reach.unreachable_finite > 0)
            .then(|| reach.unreachable_error_sum_m / reach.unreachable_finite as f64)
    }

    /// Oscillation of effector `e`'s limb joints, Hz: each joint's reversals
    /// (sign changes of its per-frame Δθ, ignoring |Δθ| below
    /// [`REVERSAL_THRESHOLD_RAD`] and comparing with the last larger step) per
    /// recorded second, averaged over the limb's joints — issue 18's
    /// definition, so a joint moving smoothly as a sinusoid of f Hz gives 2f
    /// and one whose Δθ alternates every frame at 60 fps gives 60. `None` if
    /// `e` is out of range or its limb has no joints; 0 before any time passed.
    #[must_use]
    pub fn oscillation_hz(&self, e: usize) -> Option<f64> {
        let joints = self.limb_joints.get(e).filter(|j| !j.is_empty())?;
        if self.sim_seconds <= 0.0 {
            return Some(0.0);
        }
        let reversals: u64 = joints
            .iter()
            .filter_map(|&j| self.motion.get(j))
            .map(|m| m.reversals)
            .sum();
        Some(reversals as f64 / self.sim_seconds / joints.len() as f64)
    }

    /// Jitter of effector `e`'s limb joints: mean |Δ²θ| over the limb's joints
    /// and the frames that have one (from the third on), radians per frame².
    /// `None` if `e` is out of range or its limb has no joints; 0 before three frames.
    #[must_use]
    pub fn jitter_rad(&self, e: usize) -> Option<f64> {
        let joints = self.limb_joints.get(e).filter(|j| !j.is_empty())?;
        let (sum, frames) = joints
            .iter()
            .filter_map(|&j| self.motion.get(j))
            .fold((0.0, 0_u64), |(sum, frames), m| {
                (sum + m.jitter_sum, frames + m.jitter_frames)
            });
        Some(if frames == 0 {
            0.0
        } else {
            sum / frames as f64
        })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::{Effector, Joint};

    /// Two 2-joint arms hanging from the root: effector 0 on joints 0–1,
    /// effector 1 on joints 2–3.
    fn two_arms() -> Skeleton {
        let joints = vec![
            Joint::revolute("a0", None, DVec3::X, DVec3::Z),
            Joint::revolute("a1", Some(0), DVec3::X, DVec3::Z),
            Joint::revolute("b0", None, -DVec3::X, DVec3::Z),
            Joint::revolute("b1", Some(2), -DVec3::X, DVec3::Z),
        ];
        let effector = |name: &str, joint| Effector {
            name: name.to_owned(),
            joint,
            offset: DVec3::X,
            orientation: false,
        };
        Skeleton::new(joints, vec![effector("a", 1), effector("b", 3)])
            .unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn metrics_average_and_maximum_over_frames() {
        let mut metrics = IkMetrics::new(&two_arms());
        let mut report = IkFrameReport::new(2);
        report.iterations = 3;
        report.effector_error_m.copy_from_slice(&[0.001, 0.004]);
        metrics.record(0.5, &report, &[0.0; 4]);
        report.effector_error_m.copy_from_slice(&[0.003, 0.002]);
        metrics.record(0.5, &report, &[0.0; 4]);
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
        let mut metrics = IkMetrics::new(&two_arms());
        let mut report = IkFrameReport::new(2);
        report.effector_error_m[0] = f64::NAN;
        metrics.record(0.1, &report, &[0.0; 4]);
        assert_eq!(metrics.non_finite_frames, 1);
        assert_eq!(metrics.max_error_m(0), Some(f64::INFINITY));
        assert_eq!(metrics.mean_error_m(0), Some(0.0));
        assert_eq!(metrics.mean_error_reachable_m(0), None);
        metrics.clear();
        assert_eq!(metrics.frames, 0);
        assert_eq!(metrics.effector_count(), 2);
        assert_eq!(metrics.reachable(0), None);
    }

    #[test]
    fn errors_split_by_whether_the_target_was_within_reach() {
        let mut metrics = IkMetrics::new(&two_arms());
        let mut report = IkFrameReport::new(2);
        for (beyond_m, error_m) in [(-0.1, 0.001), (0.2, 0.05), (0.0, 0.003)] {
            report.out_of_reach_m.copy_from_slice(&[beyond_m, -0.5]);
            report.effector_error_m.copy_from_slice(&[error_m, 0.01]);
            metrics.record(0.1, &report, &[0.0; 4]);
        }
        assert!((metrics.reachable(0).unwrap_or(f64::NAN) - 2.0 / 3.0).abs() < 1e-12);
        assert_eq!(metrics.reachable(1), Some(1.0));
        let reachable = metrics.mean_error_reachable_m(0).unwrap_or(f64::NAN);
        assert!((reachable - 0.002).abs() < 1e-12);
        let unreachable = metrics.mean_error_unreachable_m(0).unwrap_or(f64::NAN);
        assert!((unreachable - 0.05).abs() < 1e-12);
        assert_eq!(metrics.mean_error_unreachable_m(1), None);
        assert_eq!(metrics.reachable(2), None);
    }

    #[test]
    fn a_joint_reversing_every_frame_at_60_fps_oscillates_at_about_60_hz() {
        let mut metrics = IkMetrics::new(&two_arms());
        let report = IkFrameReport::new(2);
        let (frames, dt, swing_rad) = (120_u32, 1.0 / 60.0, 0.01);
        for frame in 0..frames {
            let a = if frame % 2 == 0 { 0.0 } else { swing_rad };
            metrics.record(dt, &report, &[a, -a, 0.3, 0.3]);
        }
        // 120 values: 119 Δθ, each reversing the one before: 118 sign changes in 2 s.
        let expected_hz = f64::from(frames - 2) / (f64::from(frames) * dt);
        assert!((expected_hz - 59.0).abs() < 1e-9);
        let hz = metrics.oscillation_hz(0).unwrap_or(f64::NAN);
        assert!((hz - expected_hz).abs() < 1e-9, "{hz} Hz");
        // |Δ²θ| = 2 · swing every frame from the third on.
        let jitter = metrics.jitter_rad(0).unwrap_or(f64::NAN);
        assert!((jitter - 2.0 * swing_rad).abs() < 1e-12, "{jitter} rad");
        assert_eq!(metrics.oscillation_hz(1), Some(0.0));
        assert_eq!(metrics.jitter_rad(1), Some(0.0));
        assert_eq!(metrics.oscillation_hz(2), None);
    }

    #[test]
    fn steps_below_the_threshold_do_not_count_as_reversals() {
        let mut metrics = IkMetrics::new(&two_arms());
        let report = IkFrameReport::new(2);
        let tiny = 0.5 * REVERSAL_THRESHOLD_RAD;
        // Δθ: +, (−tiny), +, (−tiny), −, (+tiny), −: one reversal.
        let deltas = [0.01, -tiny, 0.01, -tiny, -0.01, tiny, -0.01];
        let mut value = 0.0;
        let dt = 0.125;
        metrics.record(dt, &report, &[value, value, 0.0, 0.0]);
        for delta in deltas {
            value += delta;
            metrics.record(dt, &report, &[value, value, 0.0, 0.0]);
        }
        // 8 frames of 0.125 s = 1 s; one sign change.
        assert!((metrics.sim_seconds - 1.0).abs() < 1e-12);
        let hz = metrics.oscillation_hz(0).unwrap_or(f64::NAN);
        assert!((hz - 1.0).abs() < 1e-12, "{hz} Hz");
    }
}
