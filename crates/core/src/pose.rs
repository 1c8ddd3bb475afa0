//! A figure's configuration: the root transform plus one value per joint
//! (She 2006 §3.1: "the whole body's complete configuration is a set of scalars θ1…θn",
//! with the root node moving the entire skeleton).

use glam::{DMat3, DVec3};

/// World placement of the skeleton's root (the node near the hip, She 2006 §3.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RootTransform {
    /// Root position in world coordinates, metres.
    pub position: DVec3,
    /// Root orientation (body frame to world frame).
    pub rotation: DMat3,
}

impl Default for RootTransform {
    fn default() -> Self {
        Self {
            position: DVec3::ZERO,
            rotation: DMat3::IDENTITY,
        }
    }
}

/// Root transform plus joint values: radians for revolute joints, metres for prismatic ones.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Pose {
    /// Placement of the root in the world.
    pub root: RootTransform,
    /// One value per joint, in the skeleton's joint order.
    pub joints: Vec<f64>,
}
