//! Posture control (Raibert & Hodgins 1991, eq. 4): the linear servo
//! `τ = −k_p(ϕ − ϕ_d) − k_v·ϕ̇` on the trunk's attitude, applied in support
//! through the hips of the supporting legs (biped, quadruped) as the
//! reaction of the torque the trunk needs.

use glam::{DMat3, DQuat, DVec3};

use crate::creatures::Leg;
use crate::dynamics::data::Data;
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

/// The world axes of a gimbal hip's roll joint (the trunk's z) and pitch
/// joint (x turned by the roll angle `roll_q`), for a trunk at `trunk_rot`.
#[must_use]
pub fn hip_axes(trunk_rot: DMat3, roll_q: f64) -> (DVec3, DVec3) {
    (
        trunk_rot * DVec3::Z,
        trunk_rot * (DQuat::from_rotation_z(roll_q) * DVec3::X),
    )
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
    let (roll_axis, pitch_axis) = hip_axes(trunk_rot, roll_q);
    drives[hip[0]].torque((-torque.dot(roll_axis)).clamp(-max, max));
    drives[hip[1]].torque((-torque.dot(pitch_axis)).clamp(-max, max));
}

/// Eq. 4 shared by the supporting legs of a pair through their gimbal hips
/// (the trot's diagonal pairs, the bound's front and rear pairs).
#[derive(Clone, Copy, Debug)]
pub struct StanceShare {
    /// The torque the trunk needs (world, N·m), shared by `legs` legs.
    pub torque: DVec3,
    /// How many legs share it.
    pub legs: f64,
    /// Yaw by horizontal foot forces about the centre of mass:
    /// `G = c·(ŷ × r)` at each foot, `c` = yaw torque / Σ|r_xz|² (N/m).
    pub yaw_per_m2: f64,
    /// Largest hip torque (N·m).
    pub max: f64,
    /// The pitch torque a foot's grip allows, per newton of leg force and
    /// metre of leg (see [`grip_limit`]).
    pub force_ratio: f64,
}

/// One supporting leg of a [`StanceShare`].
#[derive(Clone, Copy, Debug)]
pub struct StanceLeg<'a> {
    /// Its hip joints: roll (about the trunk's z), then pitch.
    pub hip: &'a [usize],
    /// The roll joint's angle (rad).
    pub roll_q: f64,
    /// The hip's position (world, m).
    pub hip_world: DVec3,
    /// The foot's position (world, m).
    pub foot: DVec3,
    /// The leg spring's push (N, ≥ 0).
    pub spring_force_n: f64,
    /// The leg's length (m).
    pub length_m: f64,
}

impl<'a> StanceLeg<'a> {
    /// Leg `leg` of a creature in state `data`: its hip at `hip_world`, its
    /// foot at `foot`, its spring pushing `spring_force_n`, `full_length_m`
    /// long with the spring at zero.
    #[must_use]
    pub fn new(
        leg: &'a Leg,
        data: &Data,
        hip_world: DVec3,
        foot: DVec3,
        spring_force_n: f64,
        full_length_m: f64,
    ) -> Self {
        Self {
            hip: &leg.hip,
            roll_q: data.q[leg.hip[0]],
            hip_world,
            foot,
            spring_force_n,
            length_m: full_length_m + data.q[leg.spring],
        }
    }
}

impl StanceShare {
    /// Apply `leg`'s share through its roll and pitch joints, the trunk at
    /// `trunk_rot` and the centre of mass at `com`.
    pub fn apply(&self, drives: &mut [Drive], trunk_rot: DMat3, com: DVec3, leg: &StanceLeg<'_>) {
        let (roll_axis, pitch_axis) = hip_axes(trunk_rot, leg.roll_q);
        let r = leg.foot - com;
        let g = DVec3::Y.cross(DVec3::new(r.x, 0.0, r.z)) * self.yaw_per_m2;
        let moment = (leg.foot - leg.hip_world).cross(g);
        let roll_tau = -self.torque.dot(roll_axis) / self.legs - roll_axis.dot(moment);
        let pitch_tau = -self.torque.dot(pitch_axis) / self.legs - pitch_axis.dot(moment);
        let max = self.max;
        let lim = grip_limit(self.force_ratio, leg.spring_force_n, leg.length_m, max);
        drives[leg.hip[0]].torque(roll_tau.clamp(-max, max));
        drives[leg.hip[1]].torque(pitch_tau.clamp(-lim, lim));
        drives[leg.hip[0]].spring.max_force = max;
        drives[leg.hip[1]].spring.max_force = max;
    }
}

/// The largest pitch torque a stance leg may apply (N·m): `ratio` × the leg
/// spring's force (N) × the leg's length (m), within `[0, max]` (a leg
/// driven past its stop has a negative length; a non-finite ratio means no
/// limit but `max`).
#[must_use]
pub fn grip_limit(ratio: f64, spring_force: f64, length_m: f64, max: f64) -> f64 {
    if ratio.is_finite() {
        (ratio * spring_force * length_m).min(max).max(0.0)
    } else {
        max
    }
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
    fn a_stance_share_splits_the_torque_and_limits_pitch_by_grip() {
        let mut drives = vec![Drive::default(); 2];
        let share = StanceShare {
            torque: DVec3::new(4.0, 0.0, 2.0),
            legs: 2.0,
            yaw_per_m2: 0.0,
            max: 10.0,
            force_ratio: 0.5,
        };
        let leg = StanceLeg {
            hip: &[0, 1],
            roll_q: 0.0,
            hip_world: DVec3::new(0.0, 1.0, 0.0),
            foot: DVec3::ZERO,
            spring_force_n: 2.0,
            length_m: 1.0,
        };
        share.apply(&mut drives, DMat3::IDENTITY, DVec3::ZERO, &leg);
        assert_eq!(drives[0].feedforward, -1.0, "half the roll torque");
        assert_eq!(
            drives[1].feedforward, -1.0,
            "half the pitch torque, limited to 1"
        );
        assert_eq!(grip_limit(1.0, 5.0, -0.1, 10.0), 0.0);
        assert_eq!(grip_limit(f64::INFINITY, 5.0, 1.0, 10.0), 10.0);
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
