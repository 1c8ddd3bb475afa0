//! The IK stage shared by the IK drivers: run the frame's iterations of She
//! 2006 §5.1.2's calculation module, then measure each effector's distance to
//! its target (§5.3's `d`) and how far the target lies beyond its limb's reach
//! (§5.3's reachable / unreachable targets), and accumulate the metrics
//! (docs/ik-metrics.md); plus a posture relaxation toward PODA's center angles.
//! Allocation-free per frame.

use gaitlab_core::driver::{IkFrameReport, IkMetrics};
use gaitlab_core::ik::{IkOptions, IkSolver, Targets};
use gaitlab_core::preset::MAX_ITERATIONS_PER_FRAME;
use gaitlab_core::{Kinematics, RootTransform, Skeleton};
use glam::{DMat3, DVec3};

/// Solver, kinematic workspace, targets and figures of one IK-driven figure.
#[derive(Clone, Debug)]
pub(crate) struct IkStage {
    pub(crate) solver: IkSolver,
    pub(crate) kinematics: Kinematics,
    pub(crate) targets: Targets,
    pub(crate) report: IkFrameReport,
    pub(crate) metrics: IkMetrics,
    /// Joint values at the start of the frame, restored if the solve goes non-finite.
    last_good: Vec<f64>,
    /// This frame's iterations so far (capacity for the most a frame may have).
    log: Vec<IterationRecord>,
}

/// One IK iteration's figures, for the Jacobian panel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct IterationRecord {
    /// The largest effector error when the iteration started, metres.
    pub error_before_m: f64,
    /// ‖Δθ‖ of the step it took (Euclidean, radians and metres mixed as
    /// the joints are).
    pub step_norm: f64,
}

impl IkStage {
    pub(crate) fn new(skeleton: &Skeleton, options: IkOptions) -> Self {
        let k = skeleton.effector_count();
        Self {
            solver: IkSolver::new(skeleton, options),
            kinematics: Kinematics::new(skeleton),
            targets: Targets {
                position: vec![DVec3::ZERO; k],
                rotation: vec![DMat3::IDENTITY; k],
            },
            report: IkFrameReport::new(k),
            metrics: IkMetrics::new(skeleton),
            last_good: vec![0.0; skeleton.joint_count()],
            log: Vec::with_capacity(MAX_ITERATIONS_PER_FRAME),
        }
    }

    /// Forward kinematics for the current pose, then the report's errors and
    /// each target's distance beyond its limb's reach (from the limb's anchor
    /// in this pose).
    pub(crate) fn measure(&mut self, skeleton: &Skeleton, root: &RootTransform, values: &[f64]) {
        self.kinematics.update(skeleton, root, values);
        let mut max = 0.0_f64;
        for ((error, effector), target) in self
            .report
            .effector_error_m
            .iter_mut()
            .zip(&self.kinematics.effector_position)
            .zip(&self.targets.position)
        {
            *error = effector.distance(*target);
            max = if error.is_nan() {
                f64::INFINITY
            } else {
                max.max(*error)
            };
        }
        self.report.max_error_m = max;
        for ((beyond, limb), target) in self
            .report
            .out_of_reach_m
            .iter_mut()
            .zip(skeleton.limbs())
            .zip(&self.targets.position)
        {
            *beyond = limb.out_of_reach_m(
                &self.kinematics.joint_anchor,
                &self.kinematics.joint_position,
                *target,
            );
        }
    }

    /// Runs `iterations` IK iterations on `values` toward the current targets,
    /// measures the result and records a frame of `dt` seconds. If the joint
    /// values go non-finite they are restored to the frame's starting values.
    pub(crate) fn solve(
        &mut self,
        skeleton: &Skeleton,
        root: &RootTransform,
        values: &mut [f64],
        iterations: usize,
        dt: f64,
    ) {
        self.iterate(skeleton, root, values, iterations);
        self.finish(skeleton, root, values, dt);
    }

    /// Runs `iterations` IK iterations on `values` toward the current targets
    /// without measuring or recording; if the joint values go non-finite they
    /// are restored to their starting values. Call [`IkStage::finish`] with the
    /// pose the figure shows to close the frame. The same as
    /// [`IkStage::begin`], `iterations` × [`IkStage::iterate_once`] and
    /// [`IkStage::end`], which the one-iteration step runs one at a time.
    pub(crate) fn iterate(
        &mut self,
        skeleton: &Skeleton,
        root: &RootTransform,
        values: &mut [f64],
        iterations: usize,
    ) {
        self.begin(values);
        for _ in 0..iterations {
            self.iterate_once(skeleton, root, values);
        }
        self.end(values, iterations);
    }

    /// Opens a frame's iterations: remembers `values` to restore them if the
    /// solve goes non-finite.
    pub(crate) fn begin(&mut self, values: &[f64]) {
        self.last_good.copy_from_slice(values);
        self.report.clamped_joints = 0;
        self.log.clear();
        // A clone's log has lost its capacity: reserved again once.
        self.log.reserve_exact(MAX_ITERATIONS_PER_FRAME);
    }

    /// One IK iteration on `values` toward the current targets.
    pub(crate) fn iterate_once(
        &mut self,
        skeleton: &Skeleton,
        root: &RootTransform,
        values: &mut [f64],
    ) {
        let status = self.solver.iterate(skeleton, root, values, &self.targets);
        self.report.clamped_joints = status.clamped_joints;
        if self.log.len() < MAX_ITERATIONS_PER_FRAME {
            self.log.push(IterationRecord {
                error_before_m: status.max_error_m,
                step_norm: self
                    .solver
                    .last_step()
                    .iter()
                    .map(|x| x * x)
                    .sum::<f64>()
                    .sqrt(),
            });
        }
    }

    /// The iterations of the frame last run (or still open).
    pub(crate) fn iteration_log(&self) -> &[IterationRecord] {
        &self.log
    }

    /// Closes a frame's `iterations` iterations: restores the starting values
    /// if they went non-finite and notes the iteration count.
    pub(crate) fn end(&mut self, values: &mut [f64], iterations: usize) {
        let restored = !values.iter().all(|v| v.is_finite());
        if restored {
            values.copy_from_slice(&self.last_good);
        }
        self.report.iterations = iterations;
        self.report.restored = restored;
    }

    /// Closes a frame of `dt` seconds: measures the shown pose `values` against
    /// the targets and records the frame's figures.
    pub(crate) fn finish(
        &mut self,
        skeleton: &Skeleton,
        root: &RootTransform,
        values: &[f64],
        dt: f64,
    ) {
        self.measure(skeleton, root, values);
        self.metrics.record(dt, &self.report, values);
    }

    /// Moves every joint toward its PODA center angle by
    /// `gain · joint.gain · (center − value)`, within its limits.
    pub(crate) fn relax(skeleton: &Skeleton, values: &mut [f64], gain: f64) {
        if gain <= 0.0 {
            return;
        }
        for (value, joint) in values.iter_mut().zip(skeleton.joints()) {
            *value = joint.clamp(*value + gain * joint.gain * (joint.center - *value));
        }
    }

    /// Clears the report and metrics.
    pub(crate) fn clear(&mut self) {
        self.report = IkFrameReport::new(self.report.effector_error_m.len());
        self.metrics.clear();
    }
}
