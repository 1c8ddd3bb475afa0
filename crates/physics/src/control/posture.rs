//! Posture control (Raibert & Hodgins 1991, eq. 4): the linear servo
//! `τ = −k_p(ϕ − ϕ_d) − k_v·ϕ̇` on the trunk's attitude, applied in support
//! through the hips of the supporting legs (biped, quadruped) as the
//! reaction of the torque the trunk needs.

use glam::{DMat3, DQuat, DVec3};

use crate::world::sim::Drive;

/// Eq. 4 on every axis at once: the torque the trunk needs (world, N·m) for
/// attitude error `error` (rad, a rotation vector) and angular rate `rate`
/// (rad/s), with gains already scaled.
#[must_use]
pub fn trunk_torque(error: DVec3, rate: DVec3, kp: f64, kv: f64) -> DVec3 {
    -error * kp - rate * kv
}

/// Eq. 4 about one axis (N·m): error `error` (rad) and rate `rate` (rad/s).
#[must_use]
pub fn axis_torque(error: f64, rate: f64, kp: f64, kv: f64) -> f64 {
    -(error * kp + rate * kv)
}

/// Apply `torque` (world, N·m) to the trunk through a gimbal or ball hip's
/// roll and pitch joints (`hip[0]` turns about the trunk's z, `hip[1]` then
/// about x; `roll_q` is the roll joint's angle): each joint exerts the
/// reaction, limited to `max` (N·m).
pub fn through_hip(
    drives: &mut [Drive],
    hip: &[usize],
    roll_q: f64,
    trunk_rot: DMat3,
    torque: DVec3,
    max: f64,
) {
    let roll_axis = trunk_rot * DVec3::Z;
    let pitch_axis = trunk_rot * (DQuat::from_rotation_z(roll_q) * DVec3::X);
    drives[hip[0]].torque((-torque.dot(roll_axis)).clamp(-max, max));
    drives[hip[1]].torque((-torque.dot(pitch_axis)).clamp(-max, max));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_servo_opposes_error_and_rate() {
        let t = trunk_torque(
            DVec3::new(0.1, 0.0, -0.2),
            DVec3::new(0.0, 1.0, 0.0),
            100.0,
            5.0,
        );
        assert!((t - DVec3::new(-10.0, -5.0, 20.0)).length() < 1e-12);
        assert!((axis_torque(0.1, -2.0, 100.0, 5.0) - 0.0).abs() < 1e-12);
    }

    #[test]
    fn an_upright_hip_reacts_a_pitch_torque_on_its_pitch_joint() {
        let mut drives = vec![Drive::default(); 2];
        // Trunk upright, hip at zero roll: a torque about +x (pitch) is
        // reacted by the pitch joint alone.
        through_hip(
            &mut drives,
            &[0, 1],
            0.0,
            DMat3::IDENTITY,
            DVec3::new(3.0, 0.0, 0.0),
            10.0,
        );
        assert_eq!(drives[0].feedforward, 0.0);
        assert_eq!(drives[1].feedforward, -3.0);
        through_hip(
            &mut drives,
            &[0, 1],
            0.0,
            DMat3::IDENTITY,
            DVec3::new(0.0, 0.0, 30.0),
            10.0,
        );
        assert_eq!(drives[0].feedforward, -10.0, "limited to max");
    }
}
