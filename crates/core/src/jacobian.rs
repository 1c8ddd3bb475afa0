//! The geometric Jacobian: `∂sᵢ/∂θⱼ = vⱼ × (sᵢ − pⱼ)` for revolute joints and
//! `vⱼ` for prismatic ones (She 2006 §4.3.1), with PODA eq. 3's extra
//! orientation rows (`aⱼ` for revolute, 0 for prismatic). Columns are filled only
//! for joints on each effector's chain; every other entry is zero.

use nalgebra::DMatrix;

use crate::{JointKind, Kinematics, Skeleton};

/// Writes the m×n Jacobian of `skeleton` at the state `kin` into `jacobian`,
/// resizing it only if its shape is wrong. Rows: for each effector in order,
/// 3 position rows, then 3 orientation rows if the effector has orientation.
/// Forward kinematics ([`Kinematics::update`]) must have run for the current pose.
pub fn fill_jacobian(skeleton: &Skeleton, kin: &Kinematics, jacobian: &mut DMatrix<f64>) {
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
        let s = kin.effector_position[e];
        for &j in skeleton.chain(e) {
            let axis = kin.joint_axis[j];
            let (linear, angular) = match joints[j].kind {
                JointKind::Revolute => (axis.cross(s - kin.joint_anchor[j]), axis),
                JointKind::Prismatic => (axis, glam::DVec3::ZERO),
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
