//! Every number of a gait controller's parameters by name — a preset's
//! `scenario.physics.controller` map (`gaitlab run … --set
//! 'scenario.physics.controller={"thrust_m": 0.05}'`), set before the
//! controller is built, so values it derives at the start (thrust, rest
//! lengths, stance time) follow. The tunable gains ([`crate::control::gaits::gains`]) are a
//! few of these, changeable while running. Speed, heading and hop height are
//! the preset's own fields, not listed here.

use crate::control::gaits::biped_gallop::params::BipedGallopParams;
use crate::control::gaits::biped_run::params::BipedRunParams;
use crate::control::gaits::bound::params::QuadrupedBoundParams;
use crate::control::gaits::kangaroo_hop::params::KangarooHopParams;
use crate::control::gaits::trot::params::QuadrupedRunParams;

/// The parameters a hop height command (`scenario.physics.hop_height_m`)
/// takes the place of: the trot's and pace's flights and the height they ask
/// eq. 2 for, the bound's and gallop's stride and pair flights, the
/// kangaroo's rise. With a hop height given, a value written for one of
/// them changes nothing.
pub const REPLACED_BY_HOP_HEIGHT: &[&str] = &[
    "flight0_s",
    "flight1_s",
    "eq2_hop_m",
    "stride_flight_s",
    "gathered_flight_s",
    "extended_flight_s",
    "hop_rise_m",
];

/// A gait controller's parameters, readable and settable by name.
pub trait NamedParameters: Copy {
    /// Every name [`NamedParameters::slot`] takes.
    const NAMES: &'static [&'static str];

    /// The field named `name`; `None` when there is none.
    fn slot(&mut self, name: &str) -> Option<&mut f64>;

    /// Sets the parameter `name` to `value`; `false` when there is none.
    fn set_parameter(&mut self, name: &str, value: f64) -> bool {
        self.slot(name).map(|v| *v = value).is_some()
    }

    /// The parameter `name`'s value; `None` when there is none.
    fn parameter(&self, name: &str) -> Option<f64> {
        let mut copy = *self;
        copy.slot(name).map(|v| *v)
    }
}

/// The names `params`'s type takes (for a controller that has the value,
/// not the type, at hand).
#[must_use]
pub fn names_of<P: NamedParameters>(_params: &P) -> &'static [&'static str] {
    P::NAMES
}

/// Implements [`NamedParameters`] over plain `f64` fields, in groups: `[a, b]`
/// for fields of the parameters themselves, `sub [c, d]` for fields of
/// their `sub` struct.
macro_rules! named_parameters {
    ($params:ty $(; $($path:ident).* [$($field:ident),* $(,)?])+) => {
        impl NamedParameters for $params {
            const NAMES: &'static [&'static str] = &[$($(stringify!($field),)*)+];

            fn slot(&mut self, name: &str) -> Option<&mut f64> {
                $(if [$(stringify!($field)),*].contains(&name) {
                    let fields = &mut (*self)$(.$path)*;
                    return match name {
                        $(stringify!($field) => Some(&mut fields.$field),)*
                        _ => None,
                    };
                })+
                None
            }
        }
    };
}

crate::with_hopper_fields!(named_parameters!(BipedRunParams));

crate::with_hopper_fields!(named_parameters!(BipedGallopParams; [
    trail_offset_m, lead_offset_m, lead_retract_m, lead_delay_s, lead_extend_mps,
    trail_extend_mps, trail_unload_mps, pitch_feedforward]));

named_parameters!(KangarooHopParams; [
    speed_ramp_mps2, speed_integral_gain, speed_integral_max_mps, hop_gain, ankle_stiffness,
    ankle_damping, ankle_rest_rad, max_thrust_rad, placement_gain_s, landing_leg_m,
    flight_retract_m, stance_guess_s, hip_kp, hip_kv, stance_hip_kp, stance_hip_kv, knee_kp,
    knee_kv, posture_kp, posture_kv, pitch_rad, tail_stiffness, tail_damping, tail_mean_rad,
    tail_step_rad, tail_pitch_gain, tail_rate_gain_s, tail_tip_stiffness, tail_tip_damping,
    neck_kp, neck_kv, max_torque, jump_clearance_m, jump_stiffness_factor,
    landing_damping_factor]);

named_parameters!(QuadrupedBoundParams; [
    leg_stiffness, leg_travel_m, leg_damping, leg_air_damping, landing_rest_m, short_rest_m, thrust_m,
    rear_extra_thrust_m, max_thrust_m, min_thrust_m, stride_flight_s, flight_gain,
    gathered_flight_s, extended_flight_s, pair_flight_gain, thrust_end, min_short_s, stance_s,
    placement_gain_s, speed_integral_gain, speed_bias_cap, min_stride_s, front_offset_m,
    pitch_bias, pitch_kp, pitch_kv, roll_kp, roll_kv, yaw_kp, yaw_kv, posture_force_ratio,
    sweep_s, swing_kp, swing_kv, swing_roll_follow, max_hip_torque, gallop_shorter_m,
    gallop_spread_m, gallop_lag_s]);

impl NamedParameters for QuadrupedRunParams {
    const NAMES: &'static [&'static str] = &[
        "leg_stiffness",
        "leg_damping",
        "leg_air_damping",
        "leg_travel_m",
        "landing_rest_m",
        "idle_rest_m",
        "thrust_m",
        "flight0_s",
        "flight1_s",
        "eq2_hop_m",
        "stance_s",
        "placement_gain_s",
        "pitch_kp",
        "pitch_kv",
        "roll_kp",
        "roll_kv",
        "pitch_d",
        "speed_gain",
        "pitch_swing",
        "posture_force_ratio",
        "flight_gain",
        "max_thrust_m",
        "yaw_kp",
        "yaw_kv",
        "swing_kp",
        "swing_kv",
        "swing_roll_follow",
        "max_hip_torque",
        "unison_liftoff",
    ];

    fn slot(&mut self, name: &str) -> Option<&mut f64> {
        let t = &mut self.trot;
        Some(match name {
            "leg_stiffness" => &mut t.leg_stiffness,
            "leg_damping" => &mut t.leg_damping,
            "leg_air_damping" => &mut t.leg_air_damping,
            "leg_travel_m" => &mut t.leg_travel_m,
            "landing_rest_m" => &mut t.landing_rest_m,
            "idle_rest_m" => &mut t.idle_rest_m,
            "thrust_m" => &mut t.thrust_m,
            "flight0_s" => &mut t.flight_s[0],
            "flight1_s" => &mut t.flight_s[1],
            "eq2_hop_m" => &mut t.eq2_hop_m,
            "stance_s" => &mut t.stance_s,
            "placement_gain_s" => &mut t.placement_gain_s,
            "pitch_kp" => &mut t.pitch_kp,
            "pitch_kv" => &mut t.pitch_kv,
            "roll_kp" => &mut t.roll_kp,
            "roll_kv" => &mut t.roll_kv,
            "pitch_d" => &mut t.pitch_d,
            "speed_gain" => &mut t.speed_gain,
            "pitch_swing" => &mut t.pitch_swing,
            "posture_force_ratio" => &mut t.posture_force_ratio,
            "flight_gain" => &mut self.flight_gain,
            "max_thrust_m" => &mut self.max_thrust_m,
            "yaw_kp" => &mut self.yaw_kp,
            "yaw_kv" => &mut self.yaw_kv,
            "swing_kp" => &mut self.swing_kp,
            "swing_kv" => &mut self.swing_kv,
            "swing_roll_follow" => &mut self.swing_roll_follow,
            "max_hip_torque" => &mut self.max_hip_torque,
            "unison_liftoff" => &mut t.unison_liftoff,
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn every_name_sets<P: NamedParameters + Default + PartialEq + std::fmt::Debug>() {
        for name in P::NAMES {
            let mut p = P::default();
            assert!(p.set_parameter(name, 12.345), "{name}");
            assert_ne!(p, P::default(), "{name} changed nothing");
            assert_eq!(p.parameter(name), Some(12.345), "{name} reads back");
        }
        assert!(!P::default().set_parameter("no_such_parameter", 1.0));
        assert_eq!(P::default().parameter("no_such_parameter"), None);
    }

    #[test]
    fn every_listed_name_sets_its_field() {
        every_name_sets::<BipedRunParams>();
        every_name_sets::<BipedGallopParams>();
        every_name_sets::<KangarooHopParams>();
        every_name_sets::<QuadrupedBoundParams>();
        every_name_sets::<QuadrupedRunParams>();
    }
}
