//! The body's pose on the ground plane (position and yaw), and the body ↔ world frame changes it defines.

use glam::{DMat3, DVec2, DVec3};

/// The body's pose on the ground plane: position `(x, z)` and yaw (0 faces +z).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GroundPose {
    /// Position `(x, z)`, metres.
    pub position: DVec2,
    /// Heading, radians (0 faces +z, positive turns toward +x).
    pub yaw_rad: f64,
}

impl GroundPose {
    /// Rotation from the body frame to the world.
    #[must_use]
    pub fn rotation(self) -> DMat3 {
        DMat3::from_rotation_y(self.yaw_rad)
    }

    fn origin(self) -> DVec3 {
        DVec3::new(self.position.x, 0.0, self.position.y)
    }

    /// A body-frame point in the world.
    #[must_use]
    pub fn to_world(self, p: DVec3) -> DVec3 {
        self.origin() + self.rotation() * p
    }

    /// A world point in the body frame.
    #[must_use]
    pub fn to_body(self, p: DVec3) -> DVec3 {
        self.rotation().transpose() * (p - self.origin())
    }
}
