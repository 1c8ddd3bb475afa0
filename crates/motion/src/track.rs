//! Recorded-target tracking (`gaitlab track`): effector targets come from a
//! recording instead of She 2006 §5.2.2's sinusoids, and the same Jacobian IK
//! (§4.4) follows them frame by frame with the same metrics (§5.3's `d`).

use std::sync::Arc;

use gaitlab_core::driver::{Driver, IkFrameReport, IkMetrics};
use gaitlab_core::export::TargetTrack;
use gaitlab_core::ik::{IkOptions, Method, Targets};
use gaitlab_core::preset::Creature;
use gaitlab_core::{Pose, RootTransform, Skeleton};
use glam::DVec3;

use crate::error::DriverError;
use crate::ik_stage::IkStage;
use crate::thesis_driver::MAX_ITERATIONS_PER_FRAME;

/// Where recorded targets come from: world positions, one per effector, at any time.
pub trait TargetSource {
    /// Number of effectors the source has targets for.
    fn effector_count(&self) -> usize;

    /// Length of the recording, seconds (a caller runs `0..=duration`).
    fn duration_s(&self) -> f64;

    /// Writes the target of every effector at time `t`, world metres, into
    /// `out` (`out.len() == effector_count()`). Must not allocate.
    fn sample(&self, t: f64, out: &mut [DVec3]);
}

/// A [`TargetSource`] from a closure `f(t, out)`.
#[derive(Clone, Debug)]
pub struct FnTargets<F> {
    effectors: usize,
    duration_s: f64,
    sample: F,
}

impl<F: Fn(f64, &mut [DVec3])> FnTargets<F> {
    /// A source of `effectors` targets over `duration_s` seconds written by `sample`.
    #[must_use]
    pub fn new(effectors: usize, duration_s: f64, sample: F) -> Self {
        Self {
            effectors,
            duration_s,
            sample,
        }
    }
}

impl<F: Fn(f64, &mut [DVec3])> TargetSource for FnTargets<F> {
    fn effector_count(&self) -> usize {
        self.effectors
    }

    fn duration_s(&self) -> f64 {
        self.duration_s
    }

    fn sample(&self, t: f64, out: &mut [DVec3]) {
        (self.sample)(t, out);
    }
}

/// A recorded track read from CSV (`gaitlab track --targets FILE.csv`): the
/// driver's time is the CSV's `t` column; before the first row and after the
/// last the track holds its end rows.
impl TargetSource for TargetTrack {
    fn effector_count(&self) -> usize {
        TargetTrack::effector_count(self)
    }

    fn duration_s(&self) -> f64 {
        self.end_time().max(0.0)
    }

    fn sample(&self, t: f64, out: &mut [DVec3]) {
        TargetTrack::sample(self, t, out);
    }
}

/// Options of a [`TrackDriver`].
#[derive(Clone, Debug, PartialEq)]
pub struct TrackOptions {
    /// The IK options (method, damping, limits). Default [`IkOptions::default`] (SDLS).
    pub ik: IkOptions,
    /// IK iterations per frame. Default 4.
    pub iterations_per_frame: usize,
    /// Where the root sits (fixed; the recording is in world coordinates).
    /// Default: the world origin, facing +z.
    pub root: RootTransform,
}

impl Default for TrackOptions {
    fn default() -> Self {
        Self {
            ik: IkOptions::default(),
            iterations_per_frame: 4,
            root: RootTransform::default(),
        }
    }
}

impl TrackOptions {
    /// Options for a built preset: its scenario's IK options and iterations per
    /// frame, the root fixed at the preset's root position.
    #[must_use]
    pub fn for_creature(creature: &Creature) -> Self {
        Self {
            ik: creature.scenario.ik_options(),
            iterations_per_frame: creature.scenario.thesis.iterations_per_frame,
            root: RootTransform {
                position: creature.root_position,
                ..RootTransform::default()
            },
        }
    }
}

/// Follows recorded effector targets with Jacobian IK.
#[derive(Clone, Debug)]
pub struct TrackDriver<S> {
    skeleton: Arc<Skeleton>,
    source: S,
    iterations_per_frame: usize,
    stage: IkStage,
    pose: Pose,
    time: f64,
}

impl<S: TargetSource> TrackDriver<S> {
    /// A driver that makes `skeleton` follow `source`, at time 0 in the rest pose.
    ///
    /// # Errors
    /// If the source's effector count differs from the skeleton's, the duration
    /// is not finite and ≥ 0, the iteration count is outside 1 to
    /// [`MAX_ITERATIONS_PER_FRAME`], or the root transform is not finite.
    pub fn new(
        skeleton: impl Into<Arc<Skeleton>>,
        source: S,
        options: TrackOptions,
    ) -> Result<Self, DriverError> {
        let skeleton = skeleton.into();
        if source.effector_count() != skeleton.effector_count() {
            return Err(DriverError::new(
                "targets",
                format!(
                    "{} effector targets for a skeleton with {} effectors",
                    source.effector_count(),
                    skeleton.effector_count()
                ),
            ));
        }
        if !(source.duration_s().is_finite() && source.duration_s() >= 0.0) {
            return Err(DriverError::new(
                "targets",
                "duration must be finite and ≥ 0",
            ));
        }
        if !(1..=MAX_ITERATIONS_PER_FRAME).contains(&options.iterations_per_frame) {
            return Err(DriverError::new(
                "iterations_per_frame",
                format!("must be between 1 and {MAX_ITERATIONS_PER_FRAME}"),
            ));
        }
        if !(options.root.position.is_finite() && options.root.rotation.is_finite()) {
            return Err(DriverError::new("root", "must be finite"));
        }
        let mut driver = Self {
            stage: IkStage::new(&skeleton, options.ik),
            pose: Pose {
                root: options.root,
                joints: skeleton.rest_values(),
            },
            skeleton,
            source,
            iterations_per_frame: options.iterations_per_frame,
            time: 0.0,
        };
        driver.reset();
        Ok(driver)
    }

    /// The target source.
    #[must_use]
    pub fn source(&self) -> &S {
        &self.source
    }

    /// Length of the recording, seconds.
    #[must_use]
    pub fn duration_s(&self) -> f64 {
        self.source.duration_s()
    }

    /// The IK options.
    #[must_use]
    pub fn options(&self) -> &IkOptions {
        self.stage.solver.options()
    }

    /// Replaces the IK options.
    pub fn set_options(&mut self, options: IkOptions) {
        *self.stage.solver.options_mut() = options;
    }

    /// Switches the IK method.
    pub fn set_method(&mut self, method: Method) {
        self.stage.solver.options_mut().method = method;
    }

    /// Sets the IK iterations per frame, clamped to 1 to [`MAX_ITERATIONS_PER_FRAME`].
    pub fn set_iterations_per_frame(&mut self, iterations: usize) {
        self.iterations_per_frame = iterations.clamp(1, MAX_ITERATIONS_PER_FRAME);
    }

    fn place(&mut self) {
        self.source
            .sample(self.time, &mut self.stage.targets.position);
        for rotation in &mut self.stage.targets.rotation {
            *rotation = self.pose.root.rotation;
        }
    }
}

impl<S: TargetSource> Driver for TrackDriver<S> {
    fn step(&mut self, dt: f64) {
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        self.time += dt;
        self.place();
        self.stage.solve(
            &self.skeleton,
            &self.pose.root,
            &mut self.pose.joints,
            self.iterations_per_frame,
            dt,
        );
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn reset(&mut self) {
        self.time = 0.0;
        for (value, joint) in self.pose.joints.iter_mut().zip(self.skeleton.joints()) {
            *value = joint.rest;
        }
        self.place();
        self.stage.clear();
        self.stage
            .measure(&self.skeleton, &self.pose.root, &self.pose.joints);
    }

    fn skeleton(&self) -> &Skeleton {
        &self.skeleton
    }

    fn pose(&self) -> &Pose {
        &self.pose
    }

    fn effector_positions(&self) -> &[DVec3] {
        &self.stage.kinematics.effector_position
    }

    fn targets(&self) -> Option<&Targets> {
        Some(&self.stage.targets)
    }

    fn ik_report(&self) -> Option<&IkFrameReport> {
        Some(&self.stage.report)
    }

    fn ik_metrics(&self) -> Option<&IkMetrics> {
        Some(&self.stage.metrics)
    }
}
