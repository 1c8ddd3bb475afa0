//! Eq. 4 (Raibert & Hodgins 1991) for a quadruped's virtual legs — the
//! trot's diagonal pairs, the bound's front and rear pairs — as a servo of
//! the hip actuators: the control interval decides which stance legs share
//! the posture torque and sets the servo's target and gains; every
//! integration step the servo turns the trunk's fresh attitude and rate into
//! each leg's hip torques ([`StanceShare`]). So the control may run every
//! few ms (the paper's Figure 2) without holding a stiff posture torque
//! constant between its calls.

use glam::DVec3;

use crate::control::laws::attitude::{attitude_error, heading_forward, trunk_rate};
use crate::control::laws::posture::{StanceLeg, StanceShare, axis_torque};
use crate::dynamics::energy::center_of_mass;
use crate::world::sim::{ControlInput, Drive};

/// Gains of one axis of eq. 4 (scaled: N·m/rad, N·m·s/rad).
pub type AxisGains = (f64, f64);

/// The posture servo of four legs in two pairs, as the last control call
/// set it up.
#[derive(Clone, Copy, Debug, Default)]
pub struct PairPosture {
    /// Heading (rad about +y; 0 = +z) and desired pitch (rad) of the trunk.
    pub heading: f64,
    /// Desired pitch (rad).
    pub pitch_d: f64,
    /// Pitch, roll and yaw gains.
    pub gains: [AxisGains; 3],
    /// Largest hip torque (N·m).
    pub max: f64,
    /// Grip limit ratio of [`crate::control::laws::posture::grip_limit`].
    pub force_ratio: f64,
    /// The leg spring's stiffness (N/m, scaled), for its push.
    pub stiffness: f64,
    /// Legs that share the pair's torque (count toward `legs` and the yaw
    /// lever).
    pub sharing: [bool; 4],
    /// Legs whose hips apply their share now, each with its spring rest in
    /// stance (m) for its push; `None`: the leg applies none.
    pub applying_rest_m: [Option<f64>; 4],
    /// Each leg's hip-to-foot length at full extension (m).
    pub leg_m: [f64; 4],
    /// Share among at least one leg (the trot) rather than among the
    /// sharing legs only (the bound).
    pub at_least_one: bool,
}

impl PairPosture {
    /// Whether any leg applies a share.
    #[must_use]
    pub fn active(&self) -> bool {
        self.applying_rest_m.iter().any(Option::is_some)
    }

    /// Apply each applying leg's share of eq. 4's torque for the state in
    /// `input`, pairs by leg index.
    pub fn apply(&self, input: &ControlInput<'_>, pairs: &[[usize; 2]; 2], drives: &mut [Drive]) {
        if !self.active() {
            return;
        }
        let creature = input.creature;
        let data = input.data;
        let trunk = creature.trunk;
        let trunk_rot = data.world[trunk].rot;
        let trunk_pos = data.world[trunk].pos;
        let com = center_of_mass(&creature.model, data);
        let fwd = heading_forward(self.heading);
        let lateral = DVec3::Y.cross(fwd);
        let err = attitude_error(creature, data, self.heading, self.pitch_d);
        let rate = trunk_rate(creature, data);
        let [(pkp, pkv), (rkp, rkv), (ykp, ykv)] = self.gains;
        let pitch_t = axis_torque(err.dot(lateral), rate.dot(lateral), pkp, pkv);
        let roll_t = axis_torque(err.dot(fwd), rate.dot(fwd), rkp, rkv);
        let yaw_t = axis_torque(err.y, rate.y, ykp, ykv);
        for pair in pairs {
            if !pair.iter().any(|&i| self.applying_rest_m[i].is_some()) {
                continue;
            }
            let mut n = 0.0_f64;
            let mut lever = 0.0;
            for &i in pair {
                if self.sharing[i] {
                    n += 1.0;
                    let r = input.contacts[i].position - com;
                    lever += r.x * r.x + r.z * r.z;
                }
            }
            let share = StanceShare {
                torque: lateral * pitch_t + fwd * roll_t,
                legs: if self.at_least_one { n.max(1.0) } else { n },
                yaw_per_m2: if lever > 1e-6 { yaw_t / lever } else { 0.0 },
                max: self.max,
                force_ratio: self.force_ratio,
            };
            for &i in pair {
                let Some(rest) = self.applying_rest_m[i] else {
                    continue;
                };
                let leg = &creature.legs[i];
                let hip_world = trunk_rot * leg.hip_in_trunk + trunk_pos;
                let q = data.q[leg.spring];
                let spring_force = (self.stiffness * (rest - q)).max(0.0);
                let foot = input.contacts[i].position;
                let stance =
                    StanceLeg::new(leg, data, hip_world, foot, spring_force, self.leg_m[i]);
                share.apply(drives, trunk_rot, com, &stance);
            }
        }
    }
}
