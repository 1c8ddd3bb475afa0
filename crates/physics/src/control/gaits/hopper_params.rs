//! The one-legged hopper's parameters that the biped's run and both gallops
//! share (Raibert & Hodgins 1991, Figure 4 and eqs. 1–4): the leg spring and
//! its rest lengths (eq. 1), thrust for hop height (eq. 2), foot placement
//! (eq. 3), the posture servo (eq. 4) and the hip servos (eq. 5), at scale 1.
//! Each gait keeps its commands and its own parameters beside these.

use crate::control::laws::attitude::com_state;
use crate::control::laws::hop_height::{Compressed, thrust_for_apex};
use crate::control::laws::scale::Scale;
use crate::world::sim::ControlInput;

/// A biped hopper's parameters; lengths are leg-spring coordinates (metres
/// of extension, 0 = the leg at full length). The defaults are the run's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HopperParams {
    /// Leg spring stiffness k of eq. 1 (N/m).
    pub leg_stiffness: f64,
    /// Leg spring damping b of eq. 1 (N·s/m).
    pub leg_damping: f64,
    /// How far the telescoping leg can shorten from full length (m).
    pub leg_travel_m: f64,
    /// Rest length for landing (m of extension).
    pub landing_rest_m: f64,
    /// Extra rest length during thrust (m), eq. 2; the start of what each
    /// hop's apex error adapts.
    pub thrust_m: f64,
    /// Rest length of the shortened idle or swinging leg (m of extension).
    pub idle_rest_m: f64,
    /// How much each hop's apex error changes the thrust (m of thrust per m).
    pub hop_gain: f64,
    /// Foot placement gain k_ẋ of eq. 3 (s), applied to each leg.
    pub placement_gain_s: f64,
    /// Integral gain of the lab's speed trim on each stride's speed error
    /// (m/s of correction per m/s of error), while the trim is on.
    pub speed_integral_gain: f64,
    /// Hip servo stiffness for swinging and holding legs (N·m/rad).
    pub swing_kp: f64,
    /// Hip servo damping for swinging and holding legs (N·m·s/rad).
    pub swing_kv: f64,
    /// Posture servo stiffness k_p of eq. 4 (N·m/rad).
    pub posture_kp: f64,
    /// Posture servo damping k_v of eq. 4 (N·m·s/rad).
    pub posture_kv: f64,
    /// Trunk yaw servo stiffness in stance, through the hips' yaw joints
    /// (N·m/rad).
    pub yaw_kp: f64,
    /// Trunk yaw damping in stance (N·m·s/rad).
    pub yaw_kv: f64,
    /// Stiffness of an airborne leg's own yaw joint; the leg spins on a tiny
    /// inertia, so it is small (N·m/rad).
    pub leg_yaw_kp: f64,
    /// Damping of an airborne leg's yaw joint (N·m·s/rad).
    pub leg_yaw_kv: f64,
    /// Largest hip torque (N·m).
    pub max_hip_torque: f64,
    /// Largest trunk-yaw torque through the stance legs' yaw joints, all
    /// together (N·m).
    pub max_yaw_torque: f64,
    /// How fast a leg's rest length may change (m/s): a leg snapped short
    /// would jerk the trunk through the offset hips.
    pub leg_rate_mps: f64,
}

impl Default for HopperParams {
    fn default() -> Self {
        Self {
            leg_stiffness: 20_000.0,
            leg_damping: 20.0,
            leg_travel_m: 0.25,
            landing_rest_m: -0.03,
            thrust_m: 0.03,
            idle_rest_m: -0.18,
            hop_gain: 0.3,
            placement_gain_s: 0.12,
            speed_integral_gain: 0.1,
            swing_kp: 150.0,
            swing_kv: 8.0,
            posture_kp: 1000.0,
            posture_kv: 160.0,
            yaw_kp: 200.0,
            yaw_kv: 20.0,
            leg_yaw_kp: 2.0,
            leg_yaw_kv: 0.1,
            max_hip_torque: 400.0,
            max_yaw_torque: 30.0,
            leg_rate_mps: 1.0,
        }
    }
}

impl HopperParams {
    /// Eq. 2 for one hopper leg ([`thrust_for_apex`]): the leg standing at
    /// rest `rest` and length `q` (m of extension, at scale `s`), the thrust
    /// beyond `landing` (m of extension) whose predicted apex is `target_m`,
    /// between none and the leg's full length.
    #[must_use]
    pub fn eq2_thrust(
        &self,
        input: &ControlInput<'_>,
        s: Scale,
        (rest, q): (f64, f64),
        landing: f64,
        target_m: f64,
    ) -> f64 {
        let (com, v) = com_state(input.creature, input.data);
        let leg = [Compressed {
            stiffness: self.leg_stiffness * s.stiffness(),
            compression: rest - q,
        }];
        let mass = input.creature.model.total_mass();
        let step = thrust_for_apex(&leg, mass, com.y, v.y, target_m);
        (rest + step - landing).clamp(0.0, (-landing).max(0.0))
    }
}

/// Calls `$callback!($($args)*; hopper [every field of HopperParams])`: the
/// hopper's names listed once for the parameter maps that include them.
#[macro_export]
#[doc(hidden)]
macro_rules! with_hopper_fields {
    ($callback:ident!($($args:tt)*)) => {
        $callback!($($args)*; hopper [
            leg_stiffness, leg_damping, leg_travel_m, landing_rest_m, thrust_m, idle_rest_m,
            hop_gain, placement_gain_s, speed_integral_gain, swing_kp, swing_kv, posture_kp,
            posture_kv, yaw_kp, yaw_kv, leg_yaw_kp, leg_yaw_kv, max_hip_torque, max_yaw_torque,
            leg_rate_mps
        ]);
    };
}
