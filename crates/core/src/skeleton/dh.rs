//! Denavit–Hartenberg limbs (PODA, "Modeling Articulated Figures"): the link
//! transform `T_i = RotZ(θ_i) · TransZ(d_i) · TransX(a_i) · RotX(α_i)`, whose
//! matrix PODA writes out column by column (n, o, a, p), turned into gaitlab's
//! offset/frame/axis joints so both descriptions share one FK and one Jacobian.

use glam::{DMat3, DVec3};

use super::{Effector, Joint, JointKind};

/// One row of a DH table. The joint variable is `theta` for a revolute joint
/// and `d` for a prismatic one; the other three are constants.
#[derive(Clone, Debug, PartialEq)]
pub struct DhJoint {
    /// Joint name.
    pub name: String,
    /// Revolute (variable θ) or prismatic (variable d).
    pub kind: JointKind,
    /// Link length a, metres.
    pub a: f64,
    /// Link twist α, radians.
    pub alpha: f64,
    /// Link offset d, metres (the rest value for a prismatic joint).
    pub d: f64,
    /// Joint angle θ, radians (the rest value for a revolute joint).
    pub theta: f64,
    /// Limits of the joint variable.
    pub limits: Option<(f64, f64)>,
    /// PODA center value of the joint variable.
    pub center: f64,
    /// PODA center gain in [0, 1].
    pub gain: f64,
}

/// A serial DH chain attached to a parent joint (or the root) with a base placement.
#[derive(Clone, Debug, PartialEq)]
pub struct DhLimb {
    /// Joint the limb hangs from; `None` attaches it to the root.
    pub parent: Option<usize>,
    /// Origin of DH frame 0 in the parent's moving frame, metres.
    pub base_offset: DVec3,
    /// Orientation of DH frame 0 in the parent's moving frame (its z axis is the first joint axis).
    pub base_frame: DMat3,
    /// The DH rows, proximal first.
    pub joints: Vec<DhJoint>,
    /// Name of the effector placed at the origin of the last DH frame; `None` for no effector.
    pub effector: Option<String>,
}

impl DhJoint {
    /// The constant part of this row's transform that follows the joint motion:
    /// returns (translation, rotation) expressed in the joint's moving frame.
    fn fixed_part(&self) -> (DVec3, DMat3) {
        let twist = DMat3::from_rotation_x(self.alpha);
        match self.kind {
            // RotZ(θ) is the motion; TransZ(d)·TransX(a)·RotX(α) is fixed.
            JointKind::Revolute => (DVec3::new(self.a, 0.0, self.d), twist),
            // TransZ(d) is the motion; RotZ(θ)·TransX(a)·RotX(α) is fixed (RotZ and TransZ commute).
            JointKind::Prismatic => {
                let spin = DMat3::from_rotation_z(self.theta);
                (spin * DVec3::new(self.a, 0.0, 0.0), spin * twist)
            }
        }
    }

    fn rest(&self) -> f64 {
        match self.kind {
            JointKind::Revolute => self.theta,
            JointKind::Prismatic => self.d,
        }
    }
}

impl DhLimb {
    /// Appends the limb's joints (and its effector) to `joints` / `effectors`.
    /// Joint axes are the DH z axes; each joint's offset and frame carry the
    /// previous row's constant part.
    pub fn append_to(&self, joints: &mut Vec<Joint>, effectors: &mut Vec<Effector>) {
        let mut parent = self.parent;
        let mut placement = (self.base_offset, self.base_frame);
        for row in &self.joints {
            let index = joints.len();
            joints.push(Joint {
                name: row.name.clone(),
                parent,
                kind: row.kind,
                axis: DVec3::Z,
                offset: placement.0,
                frame: placement.1,
                limits: row.limits,
                rest: row.rest(),
                center: row.center,
                gain: row.gain,
                size: 0.03,
            });
            parent = Some(index);
            placement = row.fixed_part();
        }
        if let (Some(name), Some(joint)) = (&self.effector, parent)
            && !self.joints.is_empty()
        {
            effectors.push(Effector {
                name: name.clone(),
                joint,
                offset: placement.0,
                orientation: false,
            });
        }
    }
}
