//! The thesis driver: She 2006 §5.1's control → calculation → animation loop.
//! Each frame it advances the script (§5.2.2), moves the root forward
//! ("moving forward", §6.2), places the four targets in the world, runs the
//! chosen Jacobian IK method (§4.4, §5.3) and, in the wounded modes, applies the
//! per-joint weights (§5.1.1, §5.2.3): to the IK step (`wound_form` `step`) or
//! to the angles mapped onto the body (`angle`, the IK keeping its own angles).

use std::sync::Arc;

use gaitlab_core::driver::{Driver, IkFrameReport, IkMetrics};
use gaitlab_core::ik::{IkOptions, IkSolver, JointWeight, Method, Targets};
use gaitlab_core::preset::Creature;
use gaitlab_core::preset::thesis::{EffectorRoles, ThesisMode, ThesisParams, WoundForm};
use gaitlab_core::{Kinematics, Pose, RootTransform, Skeleton};
use glam::{DMat3, DVec3};

use crate::error::DriverError;
use crate::held::HeldTargets;
use crate::ik_stage::{IkStage, IterationRecord};
use crate::script::{Limb, ScriptSample, ThesisScript};
use crate::stretch::{LimbReach, StretchOptions};

/// Most IK iterations per frame a parameter set may ask for (the preset limit).
pub use gaitlab_core::preset::MAX_ITERATIONS_PER_FRAME;
use gaitlab_core::preset::check_thesis_values;

/// Animates a skeleton with the thesis target script and Jacobian IK.
///
/// The root is placed by the script, not by the IK: at the ground point
/// `origin + heading·(0, 0, distance)` raised by the script's root height, with
/// the origin's orientation (use a heading, a rotation about y). Effectors
/// other than the four roles track their rest position relative to the root.
/// After a reset the four targets blend from their rest positions into the
/// cycle over `start_ramp_s`, and a running mode starts as the matching
/// walking mode and breaks into the run over the next `start_ramp_s`; live
/// mode changes blend the same way (see [`ThesisParams::start_ramp_s`]).
/// Before each frame's IK iterations the joints relax toward their PODA center
/// angles by `posture_gain` (see [`ThesisParams::posture_gain`]).
#[derive(Clone, Debug)]
pub struct ThesisDriver {
    skeleton: Arc<Skeleton>,
    params: ThesisParams,
    mode: ThesisMode,
    origin: RootTransform,
    /// Effector index per [`Limb`].
    roles: [usize; 4],
    /// Resolved wounded weights: joint index and weight.
    wounded: Vec<(usize, JointWeight)>,
    /// Rest position of every effector relative to the root, body frame.
    rest_offset: Vec<DVec3>,
    /// Rest orientation of every effector relative to the root.
    rest_rotation: Vec<DMat3>,
    stage: IkStage,
    /// The IK's joint angles; the pose shows them, weighted in the wounded
    /// modes when `wound_form` is `angle`.
    ik_joints: Vec<f64>,
    pose: Pose,
    time: f64,
    phase: f64,
    distance: f64,
    sample: ScriptSample,
    /// The motion being blended out of (equal to `mode` when none is).
    transition_from: ThesisMode,
    /// Time at which the blend from `transition_from` to `mode` starts, seconds.
    transition_start: f64,
    /// The singularity scenario, when on: its options and each limb's reach.
    stretch: Option<(StretchOptions, [Option<LimbReach>; 4])>,
    /// Targets held or pinned by hand (the lab's grab and pull).
    held: HeldTargets,
    /// Iterations done of a frame opened by [`ThesisDriver::step_iteration`]
    /// (0: none open), and that frame's length, seconds.
    open_frame: (usize, f64),
}

/// Where a one-iteration step left the frame it belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IterationStep {
    /// Iterations of the frame done, this one included (1 to `of`).
    pub done: usize,
    /// Iterations the frame has.
    pub of: usize,
}

impl ThesisDriver {
    /// A driver for `skeleton` in `mode`, at time 0 in the rest pose, at the
    /// world origin facing +z.
    ///
    /// # Errors
    /// If `params` fails [`validate_params`] or names an effector or wounded
    /// joint the skeleton does not have.
    pub fn new(
        skeleton: impl Into<Arc<Skeleton>>,
        params: ThesisParams,
        mode: ThesisMode,
        options: IkOptions,
    ) -> Result<Self, DriverError> {
        let skeleton = skeleton.into();
        let (roles, wounded) = resolve(&skeleton, &params)?;
        let rest = Kinematics::of(
            &skeleton,
            &Pose {
                root: RootTransform::default(),
                joints: skeleton.rest_values(),
            },
        );
        let stage = IkStage::new(&skeleton, options);
        let skeleton_effectors = skeleton.effector_count();
        let sample = ThesisScript::new(&params, mode).at_phase(0.0);
        let mut driver = Self {
            pose: Pose {
                root: RootTransform::default(),
                joints: skeleton.rest_values(),
            },
            ik_joints: skeleton.rest_values(),
            rest_offset: rest.effector_position.clone(),
            rest_rotation: rest.effector_rotation.clone(),
            skeleton,
            params,
            mode,
            origin: RootTransform::default(),
            roles,
            wounded,
            stage,
            time: 0.0,
            phase: 0.0,
            distance: 0.0,
            sample,
            transition_from: mode,
            transition_start: 0.0,
            stretch: None,
            held: HeldTargets::new(skeleton_effectors),
            open_frame: (0, 0.0),
        };
        driver.apply_weights();
        driver.reset();
        Ok(driver)
    }

    /// A driver for a built preset: its skeleton, its scenario's thesis
    /// parameters, mode and IK options, starting on the ground below the
    /// preset's root position, facing +z.
    ///
    /// # Errors
    /// As [`ThesisDriver::new`].
    pub fn for_creature(creature: &Creature) -> Result<Self, DriverError> {
        let scenario = &creature.scenario;
        let mut driver = Self::new(
            creature.skeleton.clone(),
            scenario.thesis.clone(),
            scenario.mode,
            scenario.ik_options(),
        )?;
        driver.set_origin(RootTransform {
            position: creature.root_position,
            rotation: DMat3::IDENTITY,
        });
        driver.reset();
        Ok(driver)
    }

    /// The parameters.
    #[must_use]
    pub fn params(&self) -> &ThesisParams {
        &self.params
    }

    /// Replaces the parameters (live; the cycle phase and distance carry on).
    ///
    /// # Errors
    /// As [`ThesisDriver::new`]; the driver is unchanged on error.
    pub fn set_params(&mut self, params: ThesisParams) -> Result<(), DriverError> {
        let (roles, wounded) = resolve(&self.skeleton, &params)?;
        self.params = params;
        self.roles = roles;
        self.wounded = wounded;
        self.apply_weights();
        Ok(())
    }

    /// The motion.
    #[must_use]
    pub fn mode(&self) -> ThesisMode {
        self.mode
    }

    /// Switches the motion (live), applying or clearing the wounded weights.
    /// The targets, cycle frequency and speed blend from the old motion to the
    /// new one over `start_ramp_s` seconds (the wounded weights switch at once).
    pub fn set_mode(&mut self, mode: ThesisMode) {
        if mode != self.mode {
            self.transition_from = self.mode;
            self.transition_start = self.time;
        }
        self.mode = mode;
        self.apply_weights();
    }

    /// The IK options.
    #[must_use]
    pub fn options(&self) -> &IkOptions {
        self.stage.solver.options()
    }

    /// Replaces the IK options (take effect at the next iteration).
    pub fn set_options(&mut self, options: IkOptions) {
        *self.stage.solver.options_mut() = options;
    }

    /// The IK solver, as its last iteration left it (its Jacobian, error
    /// and step: what the Jacobian panel reads).
    #[must_use]
    pub fn solver(&self) -> &IkSolver {
        &self.stage.solver
    }

    /// Switches the IK method (She 2006 §6.2 method panel).
    pub fn set_method(&mut self, method: Method) {
        self.stage.solver.options_mut().method = method;
    }

    /// Where the figure starts: the ground point below `origin.position` and the
    /// heading `origin.rotation`. Takes effect at the next reset.
    pub fn set_origin(&mut self, origin: RootTransform) {
        self.origin = origin;
    }

    /// Turns the singularity scenario on (every limb target pulled along the
    /// limb to about its full reach, see [`crate::stretch`]) or off. Takes
    /// effect at the next frame.
    pub fn set_stretch(&mut self, stretch: Option<StretchOptions>) {
        self.stretch = stretch.map(|options| {
            let rest = Kinematics::of(
                &self.skeleton,
                &Pose {
                    root: RootTransform::default(),
                    joints: self.skeleton.rest_values(),
                },
            );
            let limbs = Limb::ALL
                .map(|limb| LimbReach::of(&self.skeleton, &rest, self.roles[limb.index()]));
            (options, limbs)
        });
    }

    /// The singularity scenario's options, when it is on.
    #[must_use]
    pub fn stretch(&self) -> Option<StretchOptions> {
        self.stretch.map(|(options, _)| options)
    }

    /// The script for the current parameters and mode.
    #[must_use]
    pub fn script(&self) -> ThesisScript<'_> {
        ThesisScript::new(&self.params, self.mode)
    }

    /// Left-limb cycle phase, radians (accumulated, so live frequency changes stay smooth).
    #[must_use]
    pub fn phase(&self) -> f64 {
        self.phase
    }

    /// Distance the root has moved forward since the reset, metres.
    #[must_use]
    pub fn distance_m(&self) -> f64 {
        self.distance
    }

    /// The script's output for the current frame, body frame.
    #[must_use]
    pub fn sample(&self) -> &ScriptSample {
        &self.sample
    }

    /// Effector index playing `limb`.
    #[must_use]
    pub fn effector_of(&self, limb: Limb) -> usize {
        self.roles[limb.index()]
    }

    /// Weight of the current mode against `transition_from`, 0 to 1.
    fn transition_weight(&self) -> f64 {
        start_blend(self.time - self.transition_start, self.params.start_ramp_s)
    }

    /// Angular frequency and forward speed, blended across a mode transition.
    fn rates(&self) -> (f64, f64) {
        let to = ThesisScript::new(&self.params, self.mode);
        let from = ThesisScript::new(&self.params, self.transition_from);
        let w = self.transition_weight();
        let omega =
            from.angular_frequency() + (to.angular_frequency() - from.angular_frequency()) * w;
        let speed = from.speed_mps() + (to.speed_mps() - from.speed_mps()) * w;
        (omega, speed)
    }

    /// Places the root and every target for the current phase and distance.
    fn place(&mut self) {
        let to = ThesisScript::new(&self.params, self.mode).at_phase(self.phase);
        self.sample = if self.transition_from == self.mode {
            to
        } else {
            let from = ThesisScript::new(&self.params, self.transition_from).at_phase(self.phase);
            from.lerp(&to, self.transition_weight())
        };
        let blend = start_blend(self.time, self.params.start_ramp_s);
        let heading = self.origin.rotation;
        let mut ground = self.origin.position + heading * DVec3::new(0.0, 0.0, self.distance);
        ground.y = 0.0;
        let root_height = DVec3::new(0.0, self.sample.root_height_m, 0.0);
        let root_position = ground + heading * root_height;
        self.pose.root = RootTransform {
            position: root_position,
            rotation: heading,
        };
        let targets = &mut self.stage.targets;
        for (e, (position, rotation)) in targets
            .position
            .iter_mut()
            .zip(targets.rotation.iter_mut())
            .enumerate()
        {
            *position = root_position + heading * self.rest_offset[e];
            *rotation = heading * self.rest_rotation[e];
        }
        for limb in Limb::ALL {
            let e = self.roles[limb.index()];
            let stretched = self
                .stretch
                .as_ref()
                .and_then(|(options, limbs)| Some(limbs[limb.index()]?.target(options, self.time)));
            let cycle = stretched.unwrap_or_else(|| self.sample.target(limb) - root_height);
            let relative = self.rest_offset[e].lerp(cycle, blend);
            targets.position[e] = root_position + heading * relative;
        }
        self.held
            .apply(self.time, &self.pose.root, &mut targets.position);
    }

    /// Opens a frame of `dt` seconds: advances the clock, the cycle and the
    /// root, places the targets and relaxes the posture.
    fn begin_frame(&mut self, dt: f64) {
        let (omega, speed) = self.rates();
        self.time += dt;
        self.phase = (self.phase + omega * dt) % self.script().phase_period();
        self.distance += speed * start_blend(self.time, self.params.start_ramp_s) * dt;
        self.place();
        IkStage::relax(
            &self.skeleton,
            &mut self.ik_joints,
            self.params.posture_gain,
        );
        self.stage.begin(&self.ik_joints);
    }

    /// Closes a frame of `dt` seconds after its iterations: shows the IK's
    /// angles and records the frame's figures.
    fn end_frame(&mut self, dt: f64) {
        self.stage
            .end(&mut self.ik_joints, self.params.iterations_per_frame);
        self.open_frame = (0, 0.0);
        self.show();
        self.stage
            .finish(&self.skeleton, &self.pose.root, &self.pose.joints, dt);
    }

    /// One IK iteration: the first of the next frame of `dt` seconds (which
    /// it opens), or the next of a frame already open. The frame closes —
    /// its figures recorded — with its last iteration, so `of` calls are
    /// bit-identical to one [`Driver::step`]; between them the figure shows
    /// each iteration's angles. `None` for a bad `dt` with no frame open.
    pub fn step_iteration(&mut self, dt: f64) -> Option<IterationStep> {
        let of = self.params.iterations_per_frame;
        if self.open_frame.0 == 0 {
            if !(dt.is_finite() && dt > 0.0) {
                return None;
            }
            self.begin_frame(dt);
            self.open_frame = (0, dt);
        }
        let (done, length) = self.open_frame;
        if done < of {
            self.stage
                .iterate_once(&self.skeleton, &self.pose.root, &mut self.ik_joints);
        }
        let done = done + 1;
        if done >= of {
            self.end_frame(length);
        } else {
            self.open_frame = (done, length);
            self.show();
            self.stage
                .measure(&self.skeleton, &self.pose.root, &self.pose.joints);
        }
        Some(IterationStep {
            done: done.min(of.max(1)),
            of,
        })
    }

    /// The iterations of the frame last run (or still open): each one's
    /// error before it and ‖Δθ‖.
    #[must_use]
    pub fn iteration_log(&self) -> &[IterationRecord] {
        self.stage.iteration_log()
    }

    /// Whether a one-iteration step has opened a frame not yet closed.
    #[must_use]
    pub fn frame_open(&self) -> bool {
        self.open_frame.0 > 0
    }

    /// Holds effector `e`'s target at the world point `at` (`Some`) or lets
    /// go of it (`None`; a pinned target stays). The targets move at once;
    /// the IK follows as frames run, or at once with [`ThesisDriver::settle`].
    /// Returns whether `e` and `at` were usable.
    pub fn hold_target(&mut self, e: usize, at: Option<DVec3>) -> bool {
        if e >= self.skeleton.effector_count() {
            return false;
        }
        let took = match at {
            Some(at) => self.held.hold(e, at, &self.pose.root),
            None => {
                self.held.release(e, self.time);
                true
            }
        };
        self.place();
        took
    }

    /// Pins (or unpins) effector `e`'s target where it is held: a pinned
    /// target stays after the hand lets go.
    pub fn pin_target(&mut self, e: usize, on: bool) {
        self.held.pin(e, on, self.time);
        self.place();
    }

    /// The held and pinned targets.
    #[must_use]
    pub fn held(&self) -> &HeldTargets {
        &self.held
    }

    /// A paused figure reaching for moved targets: one frame's iterations at
    /// the current time, without advancing the clock or recording figures
    /// (the page runs this while a target is dragged with time stopped).
    pub fn settle(&mut self) {
        if self.open_frame.0 > 0 {
            return;
        }
        self.stage.begin(&self.ik_joints);
        for _ in 0..self.params.iterations_per_frame {
            self.stage
                .iterate_once(&self.skeleton, &self.pose.root, &mut self.ik_joints);
        }
        self.stage
            .end(&mut self.ik_joints, self.params.iterations_per_frame);
        self.show();
        self.stage
            .measure(&self.skeleton, &self.pose.root, &self.pose.joints);
    }

    /// Whether the wounded weights act on the shown angles this frame.
    fn weights_on_angles(&self) -> bool {
        self.mode.wounded() && self.params.wound_form == WoundForm::Angle
    }

    /// Maps the IK's angles onto the body: a copy, or in the wounded modes with
    /// `wound_form` `angle`, `w·θ + add` for each wounded joint, within its limits.
    fn show(&mut self) {
        self.pose.joints.copy_from_slice(&self.ik_joints);
        if self.weights_on_angles() {
            let joints = self.skeleton.joints();
            for &(j, weight) in &self.wounded {
                self.pose.joints[j] =
                    joints[j].clamp(weight.multiply * self.ik_joints[j] + weight.add);
            }
        }
    }

    /// Sets the wounded weights on the IK step in the wounded modes when
    /// `wound_form` is `step`, and clears them otherwise.
    fn apply_weights(&mut self) {
        self.stage.solver.clear_weights();
        if self.mode.wounded() && self.params.wound_form == WoundForm::Step {
            for &(joint, weight) in &self.wounded {
                self.stage.solver.set_weight(joint, weight);
            }
        }
    }
}

impl Driver for ThesisDriver {
    fn step(&mut self, dt: f64) {
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        if self.open_frame.0 > 0 {
            // Finish the frame a one-iteration step opened.
            let (done, length) = self.open_frame;
            for _ in done..self.params.iterations_per_frame {
                self.stage
                    .iterate_once(&self.skeleton, &self.pose.root, &mut self.ik_joints);
            }
            self.end_frame(length);
            return;
        }
        self.begin_frame(dt);
        for _ in 0..self.params.iterations_per_frame {
            self.stage
                .iterate_once(&self.skeleton, &self.pose.root, &mut self.ik_joints);
        }
        self.end_frame(dt);
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn reset(&mut self) {
        self.time = 0.0;
        self.phase = 0.0;
        self.distance = 0.0;
        // A run starts as a walk and breaks into the run after the start ramp.
        self.transition_from = walking(self.mode);
        self.transition_start = self.params.start_ramp_s;
        for (value, joint) in self.ik_joints.iter_mut().zip(self.skeleton.joints()) {
            *value = joint.rest;
        }
        self.open_frame = (0, 0.0);
        self.held.reset();
        self.show();
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

/// The walking counterpart of `mode` (itself for the walking modes).
fn walking(mode: ThesisMode) -> ThesisMode {
    match mode {
        ThesisMode::Run => ThesisMode::Walk,
        ThesisMode::WoundedRun => ThesisMode::WoundedWalk,
        walk => walk,
    }
}

/// Weight of the cycle against the rest pose `t` seconds after a reset: a
/// smoothstep from 0 to 1 over `ramp_s` seconds (1 at once if `ramp_s` is 0).
fn start_blend(t: f64, ramp_s: f64) -> f64 {
    if ramp_s > 0.0 && t < ramp_s {
        let x = (t / ramp_s).clamp(0.0, 1.0);
        x * x * (3.0 - 2.0 * x)
    } else {
        1.0
    }
}

/// Checks every value of `params` against the same ranges a preset must meet
/// ([`check_thesis_values`]: cycle shapes, slowdown, speed, iterations per frame,
/// posture gain, start ramp, wounded weights), so that a live edit and a shared
/// link accept exactly the same parameters.
///
/// # Errors
/// A [`DriverError`] whose path is relative to the parameters (`walk.frequency_hz`).
pub fn validate_params(params: &ThesisParams) -> Result<(), DriverError> {
    check_thesis_values("", params).map_err(|e| DriverError::new(e.path, e.reason))
}

type Resolved = ([usize; 4], Vec<(usize, JointWeight)>);

/// Validates `params` and looks up the effector roles and wounded joints.
fn resolve(skeleton: &Skeleton, params: &ThesisParams) -> Result<Resolved, DriverError> {
    validate_params(params)?;
    let EffectorRoles {
        left_foot,
        right_foot,
        left_hand,
        right_hand,
    } = &params.roles;
    let mut roles = [0; 4];
    for (slot, (field, name)) in roles.iter_mut().zip([
        ("left_foot", left_foot),
        ("right_foot", right_foot),
        ("left_hand", left_hand),
        ("right_hand", right_hand),
    ]) {
        *slot = skeleton.effector_index(name).ok_or_else(|| {
            DriverError::new(
                format!("roles.{field}"),
                format!("no effector named {name:?}"),
            )
        })?;
    }
    for (i, a) in roles.iter().enumerate() {
        if roles[..i].contains(a) {
            return Err(DriverError::new(
                "roles",
                "each role needs its own effector",
            ));
        }
    }
    let wounded = params
        .wounded
        .iter()
        .enumerate()
        .map(|(i, w)| {
            let joint = skeleton.joint_index(&w.joint).ok_or_else(|| {
                DriverError::new(
                    format!("wounded[{i}].joint"),
                    format!("no joint named {:?}", w.joint),
                )
            })?;
            Ok((
                joint,
                JointWeight {
                    multiply: w.multiply,
                    add: w.add,
                },
            ))
        })
        .collect::<Result<Vec<_>, DriverError>>()?;
    Ok((roles, wounded))
}
