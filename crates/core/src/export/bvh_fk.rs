//! Forward kinematics of a BVH hierarchy, written from the BVH format's own
//! rules (see [`Bvh`]): each joint's world transform is its parent's
//! world transform times `Trans(t) · R₁ · R₂ · R₃`, with one rotation per
//! rotation channel in the listed order, angles in degrees.
//!
//! This is deliberately independent of gaitlab's [`crate::fk`], so tests can
//! check an exported file against gaitlab's own kinematics.

use glam::{DMat3, DVec3};

use super::{Bvh, BvhChannel};

/// World-frame state of every joint of a [`Bvh`] for one frame. Reuse one
/// value per file: [`BvhKinematics::update`] overwrites it without allocating.
#[derive(Clone, Debug, Default)]
pub struct BvhKinematics {
    /// World position of each joint, file units.
    pub joint_position: Vec<DVec3>,
    /// World orientation of each joint's frame.
    pub joint_rotation: Vec<DMat3>,
    /// World position of each joint's End Site, where it has one.
    pub end_site_position: Vec<Option<DVec3>>,
}

impl BvhKinematics {
    /// State sized for `bvh`, at the origin until the first update.
    #[must_use]
    pub fn new(bvh: &Bvh) -> Self {
        let n = bvh.joints.len();
        Self {
            joint_position: vec![DVec3::ZERO; n],
            joint_rotation: vec![DMat3::IDENTITY; n],
            end_site_position: vec![None; n],
        }
    }

    /// State for frame `frame` of `bvh`, freshly allocated; `None` past the last frame.
    #[must_use]
    pub fn of_frame(bvh: &Bvh, frame: usize) -> Option<Self> {
        let mut state = Self::new(bvh);
        state.update(bvh, bvh.frame(frame)?);
        Some(state)
    }

    /// Recomputes every joint for the channel values `values` (one frame, in
    /// channel order). Missing values read as 0, so a hand-built [`Bvh`] that
    /// breaks the reader's invariants gives wrong numbers, never a panic.
    pub fn update(&mut self, bvh: &Bvh, values: &[f64]) {
        let n = bvh.joints.len();
        if self.joint_position.len() != n {
            *self = Self::new(bvh);
        }
        for (j, joint) in bvh.joints.iter().enumerate() {
            let mut translation = joint.offset;
            let mut rotation = DMat3::IDENTITY;
            for (c, &channel) in joint.channels.iter().enumerate() {
                let value = joint
                    .first_channel
                    .checked_add(c)
                    .and_then(|i| values.get(i))
                    .copied()
                    .unwrap_or(0.0);
                match channel {
                    BvhChannel::Xposition => translation.x = value,
                    BvhChannel::Yposition => translation.y = value,
                    BvhChannel::Zposition => translation.z = value,
                    BvhChannel::Xrotation => rotation *= DMat3::from_rotation_x(value.to_radians()),
                    BvhChannel::Yrotation => rotation *= DMat3::from_rotation_y(value.to_radians()),
                    BvhChannel::Zrotation => rotation *= DMat3::from_rotation_z(value.to_radians()),
                }
            }
            let (parent_rotation, parent_position) = match joint.parent.filter(|&p| p < j) {
                Some(p) => (self.joint_rotation[p], self.joint_position[p]),
                None => (DMat3::IDENTITY, DVec3::ZERO),
            };
            let world_rotation = parent_rotation * rotation;
            let world_position = parent_position + parent_rotation * translation;
            self.joint_rotation[j] = world_rotation;
            self.joint_position[j] = world_position;
            self.end_site_position[j] = joint
                .end_site
                .map(|tip| world_position + world_rotation * tip);
        }
    }
}

impl Bvh {
    /// World positions of every joint at frame `frame` (convenience; allocates).
    /// `None` past the last frame.
    #[must_use]
    pub fn world_positions(&self, frame: usize) -> Option<Vec<DVec3>> {
        BvhKinematics::of_frame(self, frame).map(|state| state.joint_position)
    }
}
