//! What the 3-D view draws (She 2006 §6.2 "View panel": axes, perspective,
//! rotation axes, targets; plus gaitlab's ground grid, shadows and camera follow).

use serde::{Deserialize, Serialize};

/// Drawing options of the 3-D view. Persisted with the other settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default)]
pub struct ViewOptions {
    /// Draw the world x (red), y (green), z (blue) axes at the origin.
    pub world_axes: bool,
    /// Draw each joint's rotation axis as a short segment.
    pub joint_axes: bool,
    /// Draw the targets and the error segment from each effector to its target.
    pub targets: bool,
    /// Perspective projection (orthographic when false).
    pub perspective: bool,
    /// Keep the camera centred on the figure as it moves forward.
    pub follow: bool,
    /// Draw the ground grid.
    pub grid: bool,
    /// Draw the figure's shadow and foot contact marks on the ground.
    pub shadow: bool,
    /// Draw each effector's manipulability ellipsoid (its limb's block of
    /// J Jᵀ, semi-axes σᵢ × 0.15 rad) at the effector (issue 44 item 3).
    pub ellipsoids: bool,
    /// Draw each limb's reach shell: the sphere of its full extension
    /// around its first joint.
    pub reach_shells: bool,
}

impl Default for ViewOptions {
    fn default() -> Self {
        Self {
            world_axes: false,
            joint_axes: false,
            targets: true,
            perspective: true,
            follow: true,
            grid: true,
            shadow: true,
            ellipsoids: false,
            reach_shells: false,
        }
    }
}

impl ViewOptions {
    /// The figure alone in perspective: no axes, targets, grid, shadow or follow.
    #[must_use]
    pub fn figure_only() -> Self {
        Self {
            world_axes: false,
            joint_axes: false,
            targets: false,
            perspective: true,
            follow: false,
            grid: false,
            shadow: false,
            ellipsoids: false,
            reach_shells: false,
        }
    }
}
