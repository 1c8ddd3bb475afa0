//! The trunk's attitude and travel as the controllers read them: pitch, roll
//! and yaw relative to a heading, the body's angular rate, and the horizontal
//! velocity of the centre of mass (the ϕ, ϕ̇ and ẋ of eqs. 3–4).

use gaitlab_core::portable::Portable;
use glam::{DQuat, DVec3};

use crate::creatures::PhysicalCreature;
use crate::dynamics::data::Data;

/// The unit forward vector on the ground for a heading (rad about +y; 0 = +z).
#[must_use]
pub fn heading_forward(heading: f64) -> DVec3 {
    DVec3::new(heading.psin(), 0.0, heading.pcos())
}

/// The trunk's orientation error from upright at `heading` (plus a desired
/// pitch `pitch_d`, rad) as a world rotation vector (rad): its components on
/// the lateral and forward axes are the pitch and roll errors, on y the yaw error.
#[must_use]
pub fn attitude_error(
    creature: &PhysicalCreature,
    data: &Data,
    heading: f64,
    pitch_d: f64,
) -> DVec3 {
    let actual = DQuat::from_mat3(&data.world[creature.trunk].rot);
    let desired = DQuat::from_rotation_y(heading) * DQuat::from_rotation_x(pitch_d);
    let mut err = actual * desired.inverse();
    if err.w < 0.0 {
        err = -err;
    }
    err.to_scaled_axis()
}

/// The trunk's angular velocity in world coordinates (rad/s).
#[must_use]
pub fn trunk_rate(creature: &PhysicalCreature, data: &Data) -> DVec3 {
    data.world[creature.trunk].rot * data.velocity[creature.trunk].angular
}

/// Position (m) and velocity (m/s) of the whole creature's centre of mass,
/// world coordinates, in one pass over the bodies.
#[must_use]
pub fn com_state(creature: &PhysicalCreature, data: &Data) -> (DVec3, DVec3) {
    let model = &creature.model;
    let (mut p, mut v) = (DVec3::ZERO, DVec3::ZERO);
    for (i, b) in model.bodies().iter().enumerate() {
        if b.mass > 0.0 {
            let w = data.world[i];
            let vel = data.velocity[i];
            p += (w.rot * b.com + w.pos) * b.mass;
            v += w.rot * (vel.linear + vel.angular.cross(b.com)) * b.mass;
        }
    }
    let m = model.total_mass();
    (p / m, v / m)
}

/// Velocity of the whole creature's centre of mass (world, m/s).
#[must_use]
pub fn com_velocity(creature: &PhysicalCreature, data: &Data) -> DVec3 {
    com_state(creature, data).1
}
