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
    /// joint's anchor (`joint_anchor`, as `Kinematics::joint_anchor`) or, for
    /// a limb without joints, the effector joint's origin (`joint_position`).
    /// Forward kinematics must have run for the pose.
    #[must_use]
    pub fn anchor(&self, joint_anchor: &[DVec3], joint_position: &[DVec3]) -> DVec3 {
        match self.joints.first() {
            Some(&first) => joint_anchor[first],
            None => joint_position[self.effector_joint],
        }
    }

    /// How far `target` lies beyond the limb's reach in the pose whose joint
    /// anchors and positions are given, metres: |target − anchor| − length.
    /// Zero or negative means reachable (She 2006 §5.3's `d ≤ 0`); NaN for a
    /// non-finite target.
    #[must_use]
    pub fn out_of_reach_m(
        &self,
        joint_anchor: &[DVec3],
        joint_position: &[DVec3],
        target: DVec3,
    ) -> f64 {
        target.distance(self.anchor(joint_anchor, joint_position)) - self.length_m
    }
}
