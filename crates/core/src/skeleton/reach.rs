//! Limb chains and their reach, for She 2006 §5.3's split of targets into
//! reachable and unreachable ones (Figure 5.10): an effector's target is
//! reachable when it lies within its limb's length of the limb's first joint.
//!
//! # Reading of "limb", "shared root" and "length"
//! - The *shared root* of an effector's chain is the last joint its chain shares
//!   with any other effector's chain, or the skeleton root if it shares none.
//! - The *limb* is the joints from the first joint below the shared root down to
//!   the effector's joint (for the human preset: `*_hip_flex … *_ankle` for a
//!   foot, `*_shoulder_flex … *_wrist` for a hand, both hands sharing
//!   `thorax_twist`).
//! - Its *length* is the sum of the link lengths from the first joint's anchor to
//!   the effector: the |offset| of each later limb joint plus the effector's
//!   |offset|. Prismatic slides add nothing (the reach is the rigid links').
//! - If an effector's own joint is shared (two effectors on one joint), its limb
//!   has no joints and is measured from that joint's origin, length |offset|.
//!
//! Computed once when the [`Skeleton`](super::Skeleton) is built.

use glam::DVec3;

use super::{Effector, Joint};
use crate::Kinematics;

/// One effector's limb: the part of its chain no other effector depends on.
#[derive(Clone, Debug, PartialEq)]
pub struct Limb {
    /// The last joint the effector's chain shares with another effector's
    /// chain; `None` when it shares none (the limb hangs from the skeleton root).
    pub shared_root: Option<usize>,
    /// The limb's joints, from the first joint below the shared root down to the
    /// effector's joint (empty when the effector's own joint is shared).
    pub joints: Vec<usize>,
    /// Sum of the link lengths from the first joint's anchor to the effector, metres.
    pub length_m: f64,
    /// The joint carrying the effector (the anchor of a limb without joints).
    effector_joint: usize,
}

impl Limb {
    /// The limb of effector `e`, given every effector's root-first chain.
    pub(super) fn of(
        chains: &[Vec<usize>],
        joints: &[Joint],
        effectors: &[Effector],
        e: usize,
    ) -> Self {
        let chain = &chains[e];
        // Chains are root-first ancestor paths, so two chains share a prefix.
        let shared = chains
            .iter()
            .enumerate()
            .filter(|&(f, _)| f != e)
            .map(|(_, other)| chain.iter().zip(other).take_while(|(a, b)| a == b).count())
            .max()
            .unwrap_or(0);
        let limb: Vec<usize> = chain[shared..].to_vec();
        let effector = &effectors[e];
        let links: f64 = limb
            .iter()
            .skip(1)
            .map(|&j| joints[j].offset.length())
            .sum();
        Self {
            shared_root: shared.checked_sub(1).map(|i| chain[i]),
            joints: limb,
            length_m: links + effector.offset.length(),
            effector_joint: effector.joint,
        }
    }

    /// World position the reach is measured from, metres: the first limb
    /// joint's anchor in `kinematics`' pose (the effector joint's origin for a
    /// limb without joints). Forward kinematics must have run for the pose.
    #[must_use]
    pub fn anchor(&self, kinematics: &Kinematics) -> DVec3 {
        match self.joints.first() {
            Some(&first) => kinematics.joint_anchor[first],
            None => kinematics.joint_position[self.effector_joint],
        }
    }

    /// How far `target` lies beyond the limb's reach in `kinematics`' pose,
    /// metres: |target − anchor| − length. Zero or negative means reachable
    /// (She 2006 §5.3's `d ≤ 0`); NaN for a non-finite target.
    #[must_use]
    pub fn out_of_reach_m(&self, kinematics: &Kinematics, target: DVec3) -> f64 {
        target.distance(self.anchor(kinematics)) - self.length_m
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use crate::{Effector, Joint, Kinematics, RootTransform, Skeleton};

    fn effector(name: &str, joint: usize, offset: DVec3) -> Effector {
        Effector {
            name: name.to_owned(),
            joint,
            offset,
            orientation: false,
        }
    }

    /// A 2-link planar arm hanging from the root at (0, 1, 0): links 0.5 m and
    /// 0.3 m, reach 0.8 m from the shoulder.
    fn two_link() -> Skeleton {
        let joints = vec![
            Joint::revolute("shoulder", None, DVec3::new(0.0, 1.0, 0.0), DVec3::Z),
            Joint::revolute("elbow", Some(0), DVec3::new(0.5, 0.0, 0.0), DVec3::Z),
        ];
        Skeleton::new(joints, vec![effector("hand", 1, DVec3::new(0.3, 0.0, 0.0))])
            .unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn a_two_link_arm_reaches_the_sum_of_its_links() {
        let skeleton = two_link();
        let limb = skeleton.limb(0);
        assert_eq!(limb.shared_root, None);
        assert_eq!(limb.joints, vec![0, 1]);
        assert!((limb.length_m - 0.8).abs() < 1e-12);
        let mut kinematics = Kinematics::new(&skeleton);
        kinematics.update(&skeleton, &RootTransform::default(), &[0.7, -1.2]);
        let anchor = limb.anchor(&kinematics);
        assert!(anchor.distance(DVec3::new(0.0, 1.0, 0.0)) < 1e-12);
        // 1 m to the right of the shoulder: 0.2 m out of reach, whatever the pose.
        let beyond = limb.out_of_reach_m(&kinematics, DVec3::new(1.0, 1.0, 0.0));
        assert!((beyond - 0.2).abs() < 1e-12);
        // 0.6 m below it: 0.2 m inside.
        let inside = limb.out_of_reach_m(&kinematics, DVec3::new(0.0, 0.4, 0.0));
        assert!((inside + 0.2).abs() < 1e-12);
    }

    #[test]
    fn a_shared_trunk_is_not_part_of_either_limb() {
        // trunk → two arms of 0.4 + 0.1 m; a third effector on the trunk itself.
        let joints = vec![
            Joint::revolute("trunk", None, DVec3::ZERO, DVec3::Y),
            Joint::revolute("left", Some(0), DVec3::new(0.2, 0.5, 0.0), DVec3::X),
            Joint::revolute("left_elbow", Some(1), DVec3::new(0.0, -0.4, 0.0), DVec3::X),
            Joint::revolute("right", Some(0), DVec3::new(-0.2, 0.5, 0.0), DVec3::X),
        ];
        let effectors = vec![
            effector("left_hand", 2, DVec3::new(0.0, -0.1, 0.0)),
            effector("right_hand", 3, DVec3::new(0.0, -0.3, 0.0)),
            effector("head", 0, DVec3::new(0.0, 0.7, 0.0)),
        ];
        let skeleton = Skeleton::new(joints, effectors).unwrap_or_else(|e| panic!("{e}"));
        let left = skeleton.limb(0);
        assert_eq!(left.shared_root, Some(0));
        assert_eq!(left.joints, vec![1, 2]);
        assert!((left.length_m - 0.5).abs() < 1e-12);
        let right = skeleton.limb(1);
        assert_eq!(right.joints, vec![3]);
        assert!((right.length_m - 0.3).abs() < 1e-12);
        // The head's joint is shared: no limb joints, measured from the trunk's origin.
        let head = skeleton.limb(2);
        assert_eq!(head.shared_root, Some(0));
        assert!(head.joints.is_empty());
        assert!((head.length_m - 0.7).abs() < 1e-12);
        let mut kinematics = Kinematics::new(&skeleton);
        kinematics.update(&skeleton, &RootTransform::default(), &[0.3, 0.0, 0.0, 0.0]);
        assert!(head.anchor(&kinematics).length() < 1e-12);
    }
}
