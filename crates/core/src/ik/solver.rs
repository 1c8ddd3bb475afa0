//! One IK iteration — forward kinematics, Jacobian, solve, update — for any of
//! She 2006's four methods (§4.4), with joint limits (§5.1.1: "the control
//! system provides a solution to adjust the rotation within the limit range"),
//! wounded weights (§5.1.1) and PODA's null-space term (eq. 6).
//!
//! Joint limits: a step that would carry a joint past a limit moves it exactly to
//! the limit, freezes it (its column drops out) and the remaining joints re-solve
//! for what is left of the error. A joint pushed into its limit therefore rests
//! there instead of flip-flopping between "clamped" and "free" from one
//! iteration to the next.
//!
//! Control way (She 2006 §3.2, [`JacobianAt`]): the Jacobian's revolute
//! columns are taken at the effectors (default) or at the targets; the error
//! is e = t − s either way.
//!
//! Weights: a multiply weight wⱼ scales column j (Δθ = W Δφ with Δφ solved for
//! J W), so every method sees it; an add weight is added to the joint's step.

use glam::{DQuat, DVec3};
use nalgebra::DMatrix;

use super::ccd::CcdWorkspace;
use super::dls::DlsWorkspace;
use super::nullspace::add_null_space;
use super::pinv::{filtered_step, pinv_step};
use super::sdls::{SdlsWorkspace, clamp_max_abs};
use super::spectrum::Spectrum;
use super::svd::ThinSvd;
use super::transpose::transpose_step;
use super::{IkOptions, IkStatus, JacobianAt, JointWeight, Method, Targets};
use crate::jacobian::fill_jacobian_at;
use crate::skeleton::TaskBlock;
use crate::{Kinematics, RootTransform, Skeleton};

/// A Jacobian IK solver that keeps its workspace between calls: after the
/// first iteration, iterating allocates nothing.
#[derive(Clone, Debug)]
pub struct IkSolver {
    options: IkOptions,
    weights: Vec<JointWeight>,
    kinematics: Kinematics,
    /// J (m×n).
    jacobian: DMatrix<f64>,
    /// J with each column scaled by its weight (0 for frozen joints).
    weighted: DMatrix<f64>,
    /// Task error e (m).
    error: Vec<f64>,
    /// e minus what the frozen joints' fixed steps achieve (m).
    residual: Vec<f64>,
    /// Scratch of length m.
    scratch: Vec<f64>,
    /// Solution in weighted coordinates Δφ (n).
    free: Vec<f64>,
    /// Final step Δθ (n).
    step: Vec<f64>,
    /// Fixed steps of frozen joints (n).
    fixed: Vec<f64>,
    /// Whether each joint still takes part in the solve.
    active: Vec<bool>,
    /// ∇H = 2αⱼ(θⱼ − θcⱼ) at the current pose (n).
    center_gradient: Vec<f64>,
    /// Null-space gradient scratch (n).
    gradient: Vec<f64>,
    /// Independent blocks of J ([`Skeleton::task_blocks`]).
    blocks: Vec<TaskBlock>,
    svd: ThinSvd,
    dls: DlsWorkspace,
    sdls: SdlsWorkspace,
    ccd: CcdWorkspace,
}

impl IkSolver {
    /// A solver for `skeleton` with `options`.
    #[must_use]
    pub fn new(skeleton: &Skeleton, options: IkOptions) -> Self {
        let n = skeleton.joint_count();
        let m = skeleton.task_rows();
        Self {
            options,
            weights: vec![JointWeight::default(); n],
            kinematics: Kinematics::new(skeleton),
            jacobian: DMatrix::zeros(m, n),
            weighted: DMatrix::zeros(m, n),
            error: vec![0.0; m],
            residual: vec![0.0; m],
            scratch: vec![0.0; m],
            free: vec![0.0; n],
            step: vec![0.0; n],
            fixed: vec![0.0; n],
            active: vec![true; n],
            center_gradient: vec![0.0; n],
            gradient: vec![0.0; n],
            blocks: skeleton.task_blocks(),
            svd: ThinSvd::default(),
            dls: DlsWorkspace::default(),
            sdls: SdlsWorkspace::default(),
            ccd: CcdWorkspace::default(),
        }
    }

    /// Current options.
    #[must_use]
    pub fn options(&self) -> &IkOptions {
        &self.options
    }

    /// Mutable options (they take effect at the next iteration).
    pub fn options_mut(&mut self) -> &mut IkOptions {
        &mut self.options
    }

    /// Sets joint `joint`'s wounded weight. Out-of-range indices are ignored.
    pub fn set_weight(&mut self, joint: usize, weight: JointWeight) {
        if let Some(slot) = self.weights.get_mut(joint) {
            *slot = weight;
        }
    }

    /// The weight of every joint.
    #[must_use]
    pub fn weights(&self) -> &[JointWeight] {
        &self.weights
    }

    /// Resets every weight to the default (multiply 1, add 0).
    pub fn clear_weights(&mut self) {
        self.weights.fill(JointWeight::default());
    }

    /// Kinematic state at the start of the last iteration.
    #[must_use]
    pub fn kinematics(&self) -> &Kinematics {
        &self.kinematics
    }

    /// The Jacobian of the last iteration (m×n).
    #[must_use]
    pub fn jacobian(&self) -> &DMatrix<f64> {
        &self.jacobian
    }

    /// The task error e = t − s at the start of the last iteration (m).
    #[must_use]
    pub fn error(&self) -> &[f64] {
        &self.error
    }

    /// The last iteration's Jacobian as the running method sees it: its
    /// singular values and the method's gain along them (see [`Spectrum`]),
    /// with the clamps evaluated for an error of `amplitude_m` metres along
    /// a direction.
    ///
    /// # Errors
    /// [`NoConvergence`](super::NoConvergence) when the Jacobian holds
    /// non-finite values.
    pub fn spectrum(
        &self,
        amplitude_m: f64,
        out: &mut Spectrum,
    ) -> Result<(), super::NoConvergence> {
        out.compute(
            &self.jacobian,
            &self.blocks,
            &self.options,
            &self.error,
            amplitude_m,
        )
    }

    /// The step Δθ applied by the last iteration.
    #[must_use]
    pub fn last_step(&self) -> &[f64] {
        &self.step
    }

    /// One iteration: forward kinematics at `values`, Jacobian (at the effectors
    /// or at the targets, [`IkOptions::jacobian_at`]), solve with the
    /// configured method, then `values += Δθ` within the joint limits.
    ///
    /// # Panics
    /// If `values` or `targets.position` are shorter than the skeleton's joint and
    /// effector counts (a programming error, not an input error).
    pub fn iterate(
        &mut self,
        skeleton: &Skeleton,
        root: &RootTransform,
        values: &mut [f64],
        targets: &Targets,
    ) -> IkStatus {
        let n = skeleton.joint_count();
        assert!(values.len() >= n, "one value per joint");
        assert!(
            targets.position.len() >= skeleton.effector_count(),
            "one target per effector"
        );
        if self.step.len() != n || self.error.len() != skeleton.task_rows() {
            *self = Self::new(skeleton, self.options.clone());
        }
        self.kinematics.update(skeleton, root, values);
        if self.options.method == Method::Ccd {
            self.step.copy_from_slice(&values[..n]);
            let status = self.ccd.sweep(
                skeleton,
                &self.kinematics,
                values,
                targets,
                &self.weights,
                &self.options,
            );
            for (step, value) in self.step.iter_mut().zip(values.iter()) {
                *step = value - *step;
            }
            return status;
        }
        let points = match self.options.jacobian_at {
            JacobianAt::Effectors => &self.kinematics.effector_position,
            JacobianAt::Targets => &targets.position,
        };
        fill_jacobian_at(skeleton, &self.kinematics, points, &mut self.jacobian);
        let mut status = self.task_error(skeleton, targets);

        let joints = skeleton.joints();
        for (j, joint) in joints.iter().enumerate() {
            self.fixed[j] = 0.0;
            self.active[j] = self.weights[j].multiply != 0.0;
            self.center_gradient[j] = 2.0 * joint.gain * (values[j] - joint.center);
        }
        let passes = if self.options.enforce_limits {
            self.options.limit_passes.max(1)
        } else {
            1
        };
        for _ in 0..passes {
            status.solves += 1;
            match self.solve_active() {
                Some(rank) => status.rank = rank,
                None => {
                    status.failed = true;
                    return status;
                }
            }
            if !self.options.enforce_limits {
                break;
            }
            let mut newly_frozen = 0;
            for (j, joint) in joints.iter().enumerate() {
                if !self.active[j] {
                    continue;
                }
                let proposed = values[j] + self.step[j];
                let clamped = joint.clamp(proposed);
                if clamped != proposed {
                    self.fixed[j] = clamped - values[j];
                    self.active[j] = false;
                    newly_frozen += 1;
                }
            }
            if newly_frozen == 0 {
                break;
            }
            // If the passes run out, the frozen joints keep their clamped steps.
            for j in 0..n {
                if !self.active[j] {
                    self.step[j] = self.fixed[j];
                }
            }
        }
        let mut largest: f64 = 0.0;
        for (j, joint) in joints.iter().enumerate() {
            let step = self.step[j] + self.weights[j].add;
            let updated = if self.options.enforce_limits {
                joint.clamp(values[j] + step)
            } else {
                values[j] + step
            };
            if self.options.enforce_limits
                && joint
                    .limits
                    .is_some_and(|(lo, hi)| updated <= lo || updated >= hi)
            {
                status.clamped_joints += 1;
            }
            largest = largest.max((updated - values[j]).abs());
            values[j] = updated;
        }
        status.max_step = largest;
        status
    }

    /// Fills the task error e = target − effector (orientation rows: the rotation
    /// vector taking the effector's orientation to the target's) and returns the
    /// position error figures.
    fn task_error(&mut self, skeleton: &Skeleton, targets: &Targets) -> IkStatus {
        let mut row = 0;
        let mut largest: f64 = 0.0;
        let mut sum_sq = 0.0;
        let clamp = self.options.target_clamp_m;
        for (e, effector) in skeleton.effectors().iter().enumerate() {
            let delta = targets.position[e] - self.kinematics.effector_position[e];
            let distance = delta.length();
            // Buss's target clamp: the solve sees at most `clamp` of the error.
            let seen = if clamp > 0.0 && distance > clamp {
                delta * (clamp / distance)
            } else {
                delta
            };
            self.error[row..row + 3].copy_from_slice(&seen.to_array());
            largest = largest.max(distance);
            sum_sq += distance * distance;
            if effector.orientation {
                let turn = match targets.rotation.get(e) {
                    Some(target) => {
                        let relative = *target * self.kinematics.effector_rotation[e].transpose();
                        DQuat::from_mat3(&relative).to_scaled_axis()
                    }
                    None => DVec3::ZERO,
                };
                self.error[row + 3..row + 6].copy_from_slice(&turn.to_array());
                row += 6;
            } else {
                row += 3;
            }
        }
        let k = skeleton.effector_count().max(1) as f64;
        IkStatus {
            max_error_m: largest,
            rms_error_m: (sum_sq / k).sqrt(),
            ..IkStatus::default()
        }
    }

    /// Solves for the active joints against the error left after the frozen
    /// joints' fixed steps; writes the full step (active and frozen) into `step`.
    /// Returns the rank, or `None` if the linear algebra failed.
    fn solve_active(&mut self) -> Option<usize> {
        let (m, n) = self.jacobian.shape();
        self.residual.copy_from_slice(&self.error);
        // With every joint active at weight 1 the weighted Jacobian is J itself.
        let plain = (0..n).all(|j| self.active[j] && self.weights[j].multiply == 1.0);
        if !plain {
            let source = self.jacobian.as_slice();
            let weighted = self.weighted.as_mut_slice();
            for j in 0..n {
                let col = &source[j * m..(j + 1) * m];
                let out = &mut weighted[j * m..(j + 1) * m];
                if self.active[j] {
                    let w = self.weights[j].multiply;
                    for (o, x) in out.iter_mut().zip(col) {
                        *o = x * w;
                    }
                } else {
                    out.fill(0.0);
                    let fixed = self.fixed[j];
                    if fixed != 0.0 {
                        for (r, x) in self.residual.iter_mut().zip(col) {
                            *r -= x * fixed;
                        }
                    }
                }
            }
        }
        let matrix = if plain {
            &self.jacobian
        } else {
            &self.weighted
        };
        let options = &self.options;
        let null_space =
            options.null_space_gain > 0.0 && matches!(options.method, Method::Pinv | Method::Dls);
        let needs_svd = null_space || matches!(options.method, Method::Pinv | Method::Sdls);
        let mut rank = 0;
        if needs_svd {
            self.svd
                .compute(matrix, &self.blocks, options.rank_tolerance)
                .ok()?;
            rank = self.svd.rank();
        }
        match options.method {
            Method::Transpose => {
                transpose_step(
                    matrix,
                    &self.residual,
                    options.transpose_alpha.factor(),
                    &mut self.scratch,
                    &mut self.free,
                );
            }
            Method::Pinv => pinv_step(&self.svd, &self.residual, &mut self.free),
            Method::Dls if null_space => {
                let lambda2 = options.lambda * options.lambda;
                filtered_step(&self.svd, &self.residual, &mut self.free, |s| {
                    s / (s * s + lambda2)
                });
            }
            Method::Dls => {
                if !self.dls.step(
                    matrix,
                    &self.blocks,
                    &self.residual,
                    options.lambda,
                    &mut self.free,
                ) {
                    return None;
                }
                rank = m.min(n);
            }
            Method::Sdls => self.sdls.step(
                matrix,
                &self.svd,
                &self.blocks,
                &self.residual,
                options.gamma_max,
                &mut self.free,
            ),
            // Handled before the Jacobian is built (see `iterate`).
            Method::Ccd => self.free.fill(0.0),
        }
        let (clamps, max_step) = (options.clamps_step(), options.max_step);
        if null_space {
            self.add_center_pull();
        }
        if clamps {
            clamp_max_abs(&mut self.free, max_step);
        }
        if self.free.iter().any(|x| !x.is_finite()) {
            return None;
        }
        for j in 0..n {
            self.step[j] = if self.active[j] {
                self.free[j] * self.weights[j].multiply
            } else {
                self.fixed[j]
            };
        }
        Some(rank)
    }

    /// Adds PODA's (I − J⁺J)z with z = −k∇H (in weighted coordinates, z_φ = W z)
    /// to the free step.
    fn add_center_pull(&mut self) {
        let gain = self.options.null_space_gain;
        for (j, g) in self.gradient.iter_mut().enumerate() {
            *g = if self.active[j] {
                -gain * self.center_gradient[j] * self.weights[j].multiply
            } else {
                0.0
            };
        }
        add_null_space(&self.svd, &mut self.gradient, &mut self.free);
    }
}
