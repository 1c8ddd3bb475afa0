//! The geometric Jacobian: `∂sᵢ/∂θⱼ = vⱼ × (sᵢ − pⱼ)` for revolute joints and
//! `vⱼ` for prismatic ones (She 2006 §4.3.1), with PODA eq. 3's extra
//! orientation rows (`aⱼ` for revolute, 0 for prismatic). Columns are filled only
//! for joints on each effector's chain; every other entry is zero.
//!
//! [`fill_jacobian_at`] takes the point per effector where the revolute lever
//! arm ends: the effector sᵢ (the usual Jacobian) or its target tᵢ, Buss's
//! `Jtarget` with columns `vⱼ × (tᵢ − pⱼ)` — She 2006 §3.2's two control ways
//! ([`crate::ik::JacobianAt`]).

use glam::DVec3;
use nalgebra::DMatrix;

use crate::{JointKind, Kinematics, Skeleton};

/// Writes the m×n Jacobian of `skeleton` at the state `kin` into `jacobian`,
/// resizing it only if its shape is wrong. Rows: for each effector in order,
/// 3 position rows, then 3 orientation rows if the effector has orientation.
/// Forward kinematics ([`Kinematics::update`]) must have run for the current pose.
pub fn fill_jacobian(skeleton: &Skeleton, kin: &Kinematics, jacobian: &mut DMatrix<f64>) {
    fill_jacobian_at(skeleton, kin, &kin.effector_position, jacobian);
}

/// As [`fill_jacobian`], with revolute position columns `vⱼ × (points[i] − pⱼ)`
/// for effector i: `points` are world metres, one per effector (the effector
/// positions give [`fill_jacobian`]; the target positions give She 2006 §3.2's
/// "move targets towards the end effectors" way). Prismatic columns and
/// orientation rows do not depend on the point. Allocates nothing once
/// `jacobian` has its shape.
///
/// # Panics
/// If `points` has fewer entries than the skeleton has effectors (a
/// programming error).
pub fn fill_jacobian_at(
    skeleton: &Skeleton,
    kin: &Kinematics,
    points: &[DVec3],
    jacobian: &mut DMatrix<f64>,
) {
    assert!(
        points.len() >= skeleton.effector_count(),
        "one point per effector"
    );
    let rows = skeleton.task_rows();
    let cols = skeleton.joint_count();
    if jacobian.shape() != (rows, cols) {
        *jacobian = DMatrix::zeros(rows, cols);
    } else {
        jacobian.as_mut_slice().fill(0.0);
    }
    let joints = skeleton.joints();
    let data = jacobian.as_mut_slice();
    let mut row = 0;
    for (e, effector) in skeleton.effectors().iter().enumerate() {
        let s = points[e];
        for &j in skeleton.chain(e) {
            let axis = kin.joint_axis[j];
            let (linear, angular) = match joints[j].kind {
                JointKind::Revolute => (axis.cross(s - kin.joint_anchor[j]), axis),
                JointKind::Prismatic => (axis, DVec3::ZERO),
            };
            let column = &mut data[j * rows + row..];
            column[..3].copy_from_slice(&linear.to_array());
            if effector.orientation {
                column[3..6].copy_from_slice(&angular.to_array());
            }
        }
        row += if effector.orientation { 6 } else { 3 };
    }
}
