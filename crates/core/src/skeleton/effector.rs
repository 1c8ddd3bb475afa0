//! End effectors: named points fixed to a joint's moving frame whose position
//! (and optionally orientation) the IK drives toward targets (She 2006 §3.2).

use glam::DVec3;

/// A point attached to a joint that tracks a target.
#[derive(Clone, Debug, PartialEq)]
pub struct Effector {
    /// Unique name, e.g. `left_foot`.
    pub name: String,
    /// Index of the joint that carries the effector.
    pub joint: usize,
    /// Position in that joint's moving frame, metres.
    pub offset: DVec3,
    /// Whether the Jacobian gets 3 extra orientation rows for this effector.
    pub orientation: bool,
}
