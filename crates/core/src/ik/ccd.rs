//! Cyclic coordinate descent (Wang & Chen 1991; the standard formulation used
//! as the non-Jacobian contrast to She 2006 §4.4): one sweep visits every joint
//! from the effectors back to the root and turns it, alone, by the angle that
//! best brings the effectors it moves onto their targets.
//!
//! For a revolute joint with world axis a at anchor p, let uₑ and vₑ be the
//! effector and target offsets (sₑ − p, tₑ − p) projected onto the plane normal
//! to a. The rotation θ minimising Σₑ ‖R(a, θ)uₑ − vₑ‖² over the effectors the
//! joint moves is θ = atan2(Σₑ a·(uₑ × vₑ), Σₑ uₑ·vₑ) (one effector: the angle
//! from uₑ to vₑ). A prismatic joint slides by the mean error along its axis.
//! The step is scaled by the joint's multiply weight, clamped to
//! [`IkOptions::max_step`], shifted by its add weight and kept inside the
//! joint's limits, as with the Jacobian methods. Only effector positions are
//! tracked (orientation rows are ignored). The effectors are moved with each
//! joint's turn without a new forward-kinematics pass: a joint's anchor and axis
//! depend only on its ancestors, which the sweep has not reached yet.

use crate::portable::Portable;
use glam::DVec3;

use super::{IkOptions, IkStatus, JointWeight, Targets};
use crate::fk::axis_angle;
use crate::{JointKind, Kinematics, Skeleton};

/// Workspace for CCD sweeps: which effectors each joint moves, and the
/// effector positions as the sweep moves them. Allocates only when the
/// skeleton's shape changes.
#[derive(Clone, Debug, Default)]
pub struct CcdWorkspace {
    /// `moves[j · k + e]`: joint j is on effector e's chain.
    moves: Vec<bool>,
    /// Effector positions during the sweep, world metres.
    positions: Vec<DVec3>,
    joints: usize,
    effectors: usize,
}

impl CcdWorkspace {
    fn fit(&mut self, skeleton: &Skeleton) {
        let (n, k) = (skeleton.joint_count(), skeleton.effector_count());
        if self.joints == n && self.effectors == k && self.moves.len() == n * k {
            return;
        }
        self.joints = n;
        self.effectors = k;
        self.moves = vec![false; n * k];
        for e in 0..k {
            for &j in skeleton.chain(e) {
                self.moves[j * k + e] = true;
            }
        }
        self.positions = vec![DVec3::ZERO; k];
    }

    /// One CCD sweep on `values` toward `targets`, starting from the forward
    /// kinematics in `kinematics` (which must be up to date for `values`).
    /// Returns the errors before the sweep and what the sweep did.
    pub fn sweep(
        &mut self,
        skeleton: &Skeleton,
        kinematics: &Kinematics,
        values: &mut [f64],
        targets: &Targets,
        weights: &[JointWeight],
        options: &IkOptions,
    ) -> IkStatus {
        self.fit(skeleton);
        let k = self.effectors;
        self.positions
            .copy_from_slice(&kinematics.effector_position);
        let mut status = IkStatus {
            solves: 1,
            ..IkStatus::default()
        };
        let mut sum_sq = 0.0;
        for (position, target) in self.positions.iter().zip(&targets.position) {
            let distance = position.distance(*target);
            status.max_error_m = status.max_error_m.max(distance);
            sum_sq += distance * distance;
        }
        status.rms_error_m = (sum_sq / k.max(1) as f64).sqrt();

        let joints = skeleton.joints();
        for j in (0..joints.len()).rev() {
            let joint = &joints[j];
            let weight = weights.get(j).copied().unwrap_or_default();
            let moved = &self.moves[j * k..(j + 1) * k];
            let anchor = kinematics.joint_anchor[j];
            let axis = kinematics.joint_axis[j];
            let mut wanted = match joint.kind {
                JointKind::Revolute => best_turn(axis, anchor, moved, &self.positions, targets),
                JointKind::Prismatic => best_slide(axis, moved, &self.positions, targets),
            };
            wanted *= weight.multiply;
            wanted = wanted.clamp(-options.max_step, options.max_step) + weight.add;
            if !wanted.is_finite() {
                status.failed = true;
                return status;
            }
            let updated = if options.enforce_limits {
                joint.clamp(values[j] + wanted)
            } else {
                values[j] + wanted
            };
            if options.enforce_limits
                && joint
                    .limits
                    .is_some_and(|(lo, hi)| updated <= lo || updated >= hi)
            {
                status.clamped_joints += 1;
            }
            let applied = updated - values[j];
            values[j] = updated;
            status.max_step = status.max_step.max(applied.abs());
            if applied == 0.0 {
                continue;
            }
            match joint.kind {
                JointKind::Revolute => {
                    let turn = axis_angle(axis, applied);
                    for (position, _) in self.positions.iter_mut().zip(moved).filter(|(_, m)| **m) {
                        *position = anchor + turn * (*position - anchor);
                    }
                }
                JointKind::Prismatic => {
                    for (position, _) in self.positions.iter_mut().zip(moved).filter(|(_, m)| **m) {
                        *position += axis * applied;
                    }
                }
            }
        }
        status
    }
}

/// The turn about `axis` through `anchor` that best carries the moved effectors
/// onto their targets, radians (0 when no effector has an offset off the axis).
fn best_turn(
    axis: DVec3,
    anchor: DVec3,
    moved: &[bool],
    positions: &[DVec3],
    targets: &Targets,
) -> f64 {
    let (mut sine, mut cosine) = (0.0, 0.0);
    for ((position, target), _) in positions
        .iter()
        .zip(&targets.position)
        .zip(moved)
        .filter(|(_, m)| **m)
    {
        let from = *position - anchor;
        let to = *target - anchor;
        let from = from - axis * axis.dot(from);
        let to = to - axis * axis.dot(to);
        sine += axis.dot(from.cross(to));
        cosine += from.dot(to);
    }
    if sine == 0.0 && cosine == 0.0 {
        0.0
    } else {
        sine.patan2(cosine)
    }
}

/// The slide along `axis` that best carries the moved effectors onto their
/// targets: the mean error along the axis, metres.
fn best_slide(axis: DVec3, moved: &[bool], positions: &[DVec3], targets: &Targets) -> f64 {
    let mut sum = 0.0;
    let mut count = 0_u32;
    for ((position, target), _) in positions
        .iter()
        .zip(&targets.position)
        .zip(moved)
        .filter(|(_, m)| **m)
    {
        sum += axis.dot(*target - *position);
        count += 1;
    }
    if count == 0 {
        0.0
    } else {
        sum / f64::from(count)
    }
}
