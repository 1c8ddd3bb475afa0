//! The IK goal for one solve: a target position (and optional orientation) per effector.

use glam::{DMat3, DVec3};

use crate::Kinematics;

/// Targets for every effector: a position, and an orientation used only by
/// effectors with orientation rows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Targets {
    /// Target position per effector, world metres.
    pub position: Vec<DVec3>,
    /// Target orientation per effector; effectors without an entry here (or
    /// without orientation rows) get no orientation error.
    pub rotation: Vec<DMat3>,
}

impl Targets {
    /// Targets at the effectors' current positions and orientations.
    #[must_use]
    pub fn at(kinematics: &Kinematics) -> Self {
        Self {
            position: kinematics.effector_position.clone(),
            rotation: kinematics.effector_rotation.clone(),
        }
    }
}
