//! One 1-DOF joint: a revolute or prismatic degree of freedom with its fixed
//! placement in the parent's frame, limits, rest value and PODA's center angle and gain.

use glam::{DMat3, DVec3};

/// What a joint's variable moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JointKind {
    /// Rotation about the joint axis; the value is an angle in radians.
    Revolute,
    /// Translation along the joint axis; the value is a distance in metres.
    Prismatic,
}

/// A 1-DOF joint of a [`Skeleton`](super::Skeleton).
///
/// The joint's local transform relative to its parent's moving frame is
/// `Trans(offset) · frame · Motion(axis, value)`, where `Motion` rotates about
/// (revolute) or translates along (prismatic) the unit `axis`, expressed in the
/// joint's own frame (after `frame`).
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// Unique name (used by presets, BVH export and the UI).
    pub name: String,
    /// Index of the parent joint; `None` for joints attached to the root. Always
    /// smaller than this joint's own index.
    pub parent: Option<usize>,
    /// Revolute or prismatic.
    pub kind: JointKind,
    /// Unit joint axis in the joint frame.
    pub axis: DVec3,
    /// Origin of this joint in the parent's moving frame (or the root frame), metres.
    pub offset: DVec3,
    /// Fixed rotation of the joint frame relative to the parent's moving frame.
    pub frame: DMat3,
    /// Lower and upper limit of the joint value (radians or metres); `min <= max`.
    pub limits: Option<(f64, f64)>,
    /// Value at reset (radians or metres).
    pub rest: f64,
    /// PODA center angle θc (radians or metres): the value the null-space term pulls toward.
    pub center: f64,
    /// PODA center gain α in [0, 1]: how strongly the joint is pulled toward `center`.
    pub gain: f64,
    /// Drawing radius of the bone that ends at this joint, metres (She 2006 §6.1.1.1 "size").
    pub size: f64,
}

impl Joint {
    /// A revolute joint about `axis` at `offset` with no limits, rest 0 and no center gain.
    #[must_use]
    pub fn revolute(name: &str, parent: Option<usize>, offset: DVec3, axis: DVec3) -> Self {
        Self {
            name: name.to_owned(),
            parent,
            kind: JointKind::Revolute,
            axis: axis.normalize_or(DVec3::Z),
            offset,
            frame: DMat3::IDENTITY,
            limits: None,
            rest: 0.0,
            center: 0.0,
            gain: 0.0,
            size: 0.03,
        }
    }

    /// A prismatic joint along `axis` at `offset`.
    #[must_use]
    pub fn prismatic(name: &str, parent: Option<usize>, offset: DVec3, axis: DVec3) -> Self {
        Self {
            kind: JointKind::Prismatic,
            ..Self::revolute(name, parent, offset, axis)
        }
    }

    /// Sets the limits, builder style.
    #[must_use]
    pub fn with_limits(mut self, min: f64, max: f64) -> Self {
        self.limits = Some((min, max));
        self
    }

    /// Clamps `value` into the joint's limits (identity when unlimited).
    #[must_use]
    pub fn clamp(&self, value: f64) -> f64 {
        match self.limits {
            Some((lo, hi)) => value.clamp(lo, hi),
            None => value,
        }
    }
}
