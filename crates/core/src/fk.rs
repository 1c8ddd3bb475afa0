//! Forward kinematics in one top-down pass over the joint tree: O(n), one
//! `sin_cos` per revolute joint (She 2006 §2.2 and §6.1.1.1's `ComputeS` /
//! `ComputeW`; PODA's chained homogeneous transforms `ⁱTⱼ = ⁱTᵢ₊₁ ⋯`).

use glam::{DMat3, DVec3};

use crate::skeleton::AxisKind;
use crate::{JointKind, Pose, RootTransform, Skeleton};

/// World-frame kinematic state of a skeleton for one pose. Reuse one value per
/// skeleton: [`Kinematics::update`] overwrites it without allocating.
#[derive(Clone, Debug, Default)]
pub struct Kinematics {
    /// World position of each joint's origin after its motion, metres.
    pub joint_position: Vec<DVec3>,
    /// World orientation of each joint's moving frame.
    pub joint_rotation: Vec<DMat3>,
    /// World direction of each joint axis (unit).
    pub joint_axis: Vec<DVec3>,
    /// World position of each joint's axis anchor (origin before a prismatic slide), metres.
    pub joint_anchor: Vec<DVec3>,
    /// World position of each end effector, metres.
    pub effector_position: Vec<DVec3>,
    /// World orientation of each end effector.
    pub effector_rotation: Vec<DMat3>,
}

/// Rotation by `angle` radians about the unit vector `axis` (Rodrigues), one `sin_cos`.
#[must_use]
pub fn axis_angle(axis: DVec3, angle: f64) -> DMat3 {
    let (s, c) = crate::trig::sin_cos(angle);
    let t = 1.0 - c;
    let (x, y, z) = (axis.x, axis.y, axis.z);
    DMat3::from_cols(
        DVec3::new(t * x * x + c, t * x * y + s * z, t * x * z - s * y),
        DVec3::new(t * x * y - s * z, t * y * y + c, t * y * z + s * x),
        DVec3::new(t * x * z + s * y, t * y * z - s * x, t * z * z + c),
    )
}

/// `frame · R(axis, angle)`, with the cheap column rotations when the axis is a
/// (signed) coordinate axis of the joint frame.
fn rotate_about(frame: DMat3, kind: AxisKind, axis: DVec3, angle: f64) -> DMat3 {
    let (s, c) = crate::trig::sin_cos(angle);
    let (f0, f1, f2) = (frame.x_axis, frame.y_axis, frame.z_axis);
    match kind {
        AxisKind::X(sign) => {
            let s = s * sign;
            DMat3::from_cols(f0, f1 * c + f2 * s, f2 * c - f1 * s)
        }
        AxisKind::Y(sign) => {
            let s = s * sign;
            DMat3::from_cols(f0 * c - f2 * s, f1, f0 * s + f2 * c)
        }
        AxisKind::Z(sign) => {
            let s = s * sign;
            DMat3::from_cols(f0 * c + f1 * s, f1 * c - f0 * s, f2)
        }
        AxisKind::General => frame * axis_angle(axis, angle),
    }
}

impl Kinematics {
    /// State sized for `skeleton`, all zero until the first update.
    #[must_use]
    pub fn new(skeleton: &Skeleton) -> Self {
        let n = skeleton.joint_count();
        let k = skeleton.effector_count();
        Self {
            joint_position: vec![DVec3::ZERO; n],
            joint_rotation: vec![DMat3::IDENTITY; n],
            joint_axis: vec![DVec3::ZERO; n],
            joint_anchor: vec![DVec3::ZERO; n],
            effector_position: vec![DVec3::ZERO; k],
            effector_rotation: vec![DMat3::IDENTITY; k],
        }
    }

    /// State for `pose`, freshly allocated (convenience for tests and one-off use).
    #[must_use]
    pub fn of(skeleton: &Skeleton, pose: &Pose) -> Self {
        let mut state = Self::new(skeleton);
        state.update(skeleton, &pose.root, &pose.joints);
        state
    }

    /// Recomputes every joint and effector for root `root` and joint values `values`.
    ///
    /// # Panics
    /// If `values` is shorter than the skeleton's joint count (a programming error).
    pub fn update(&mut self, skeleton: &Skeleton, root: &RootTransform, values: &[f64]) {
        let n = skeleton.joint_count();
        assert!(values.len() >= n, "one value per joint");
        if self.joint_position.len() != n
            || self.effector_position.len() != skeleton.effector_count()
        {
            *self = Self::new(skeleton);
        }
        let joints = skeleton.joints();
        let rotations = &mut self.joint_rotation[..n];
        let positions = &mut self.joint_position[..n];
        let axes = &mut self.joint_axis[..n];
        let anchors = &mut self.joint_anchor[..n];
        for (j, (joint, &value)) in joints.iter().zip(values).enumerate() {
            let (parent_rotation, parent_position) = match joint.parent {
                Some(p) => (rotations[p], positions[p]),
                None => (root.rotation, root.position),
            };
            let anchor = parent_position + parent_rotation * joint.offset;
            let shape = skeleton.joint_shape(j);
            let frame = if shape.identity_frame {
                parent_rotation
            } else {
                parent_rotation * joint.frame
            };
            let axis = match shape.axis {
                AxisKind::X(sign) => frame.x_axis * sign,
                AxisKind::Y(sign) => frame.y_axis * sign,
                AxisKind::Z(sign) => frame.z_axis * sign,
                AxisKind::General => frame * joint.axis,
            };
            let (rotation, position) = match joint.kind {
                JointKind::Revolute => (rotate_about(frame, shape.axis, joint.axis, value), anchor),
                JointKind::Prismatic => (frame, anchor + axis * value),
            };
            anchors[j] = anchor;
            axes[j] = axis;
            rotations[j] = rotation;
            positions[j] = position;
        }
        for (e, effector) in skeleton.effectors().iter().enumerate() {
            let rotation = self.joint_rotation[effector.joint];
            self.effector_position[e] =
                self.joint_position[effector.joint] + rotation * effector.offset;
            self.effector_rotation[e] = rotation;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::skeleton::AxisKind;

    #[test]
    fn coordinate_axis_fast_paths_equal_the_general_rotation() {
        let frame = DMat3::from_axis_angle(DVec3::new(0.3, -0.5, 0.8).normalize(), 0.9);
        let cases = [
            (AxisKind::X(1.0), DVec3::X),
            (AxisKind::X(-1.0), DVec3::NEG_X),
            (AxisKind::Y(1.0), DVec3::Y),
            (AxisKind::Y(-1.0), DVec3::NEG_Y),
            (AxisKind::Z(1.0), DVec3::Z),
            (AxisKind::Z(-1.0), DVec3::NEG_Z),
        ];
        for (kind, axis) in cases {
            for angle in [-2.5, -0.3, 0.0, 0.7, 3.0] {
                let fast = rotate_about(frame, kind, axis, angle);
                let general = frame * axis_angle(axis, angle);
                let worst = (fast - general)
                    .to_cols_array()
                    .iter()
                    .fold(0.0_f64, |m, x| m.max(x.abs()));
                assert!(worst < 1e-15, "{kind:?} at {angle}: {worst:e}");
            }
        }
    }
}
