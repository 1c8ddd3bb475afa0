//! PLACEHOLDER API — being implemented.

use glam::{DMat3, DVec3};

use super::{IkOptions, JointWeight};
use crate::{Kinematics, RootTransform, Skeleton};

/// Targets for every effector: a position, and an orientation used only by effectors with orientation rows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Targets {
    /// Target position per effector, world metres.
    pub position: Vec<DVec3>,
    /// Target orientation per effector (ignored for position-only effectors).
    pub rotation: Vec<DMat3>,
}

/// What one iteration saw and did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct IkStatus {
    /// Largest effector position error before the step, metres.
    pub max_error_m: f64,
    /// Root-mean-square effector position error before the step, metres.
    pub rms_error_m: f64,
    /// Largest absolute joint change applied, radians (or metres).
    pub max_step: f64,
    /// Joints held at a limit in this iteration.
    pub clamped_joints: usize,
    /// Numerical rank of the Jacobian (0 for the transpose method).
    pub rank: usize,
}

/// A Jacobian IK solver that keeps its workspace between calls.
#[derive(Clone, Debug)]
pub struct IkSolver {
    options: IkOptions,
    kinematics: Kinematics,
    weights: Vec<JointWeight>,
}

impl IkSolver {
    /// A solver for `skeleton` with `options`.
    #[must_use]
    pub fn new(skeleton: &Skeleton, options: IkOptions) -> Self {
        Self { options, kinematics: Kinematics::new(skeleton), weights: vec![JointWeight::default(); skeleton.joint_count()] }
    }
    /// Current options.
    #[must_use]
    pub fn options(&self) -> &IkOptions { &self.options }
    /// Mutable options (take effect at the next iteration).
    pub fn options_mut(&mut self) -> &mut IkOptions { &mut self.options }
    /// Sets joint `joint`'s wounded weight.
    pub fn set_weight(&mut self, joint: usize, weight: JointWeight) { self.weights[joint] = weight; }
    /// Resets every weight to the default.
    pub fn clear_weights(&mut self) { self.weights.fill(JointWeight::default()); }
    /// Kinematic state at the start of the last iteration.
    #[must_use]
    pub fn kinematics(&self) -> &Kinematics { &self.kinematics }
    /// One iteration: FK, Jacobian, solve, update `values` in place (within limits).
    pub fn iterate(&mut self, _skeleton: &Skeleton, _root: &RootTransform, _values: &mut [f64], _targets: &Targets) -> IkStatus {
        unimplemented!()
    }
}
