//! A heading in the ground plane (the x–z plane, y up) as a unit vector:
//! `direction_deg` 0° is +x, 90° is +z. Portable trigonometry
//! ([`crate::trig::sin_cos`]), so every build gives the same heights.

use glam::DVec3;

/// The unit vector of `direction_deg` in the ground plane: (cos a, 0, sin a).
#[must_use]
pub fn ground_direction(direction_deg: f64) -> DVec3 {
    let (s, c) = crate::trig::sin_cos(direction_deg.to_radians());
    DVec3::new(c, 0.0, s)
}

/// How far (x, z) lies along `direction`, metres.
#[must_use]
pub fn along(direction: DVec3, x: f64, z: f64) -> f64 {
    direction.x * x + direction.z * z
}
