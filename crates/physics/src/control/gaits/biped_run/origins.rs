//! Where the biped run's named parameters come from (Raibert & Hodgins
//! 1991, Figure 4, eqs. 1–5): the one-legged hopper's rows.

use gaitlab_core::params::Origin;

use crate::control::gaits::biped_run::BipedRun;
use crate::control::gaits::gait::Gait;
use crate::control::gaits::origins::{
    ControllerParam, EQ1, EQ2_THRUST, EQ4, EQ5, EQ5_SWING, FIG4_FLIGHT, LAB, LEG_TRAVEL_M,
    MAX_HIP_TORQUE, SPEED_INTEGRAL_GAIN, TORSION, TORSION_DAMPING, placement_gain_s_row, row,
    yaw_kp_row,
};

/// The one-legged hopper's rows the biped run and both biped gallops share
/// (`hopper_params.rs`), in the order of `with_hopper_fields!`.
pub(crate) const HOPPER: [ControllerParam; 20] = [
    row(
        "leg_stiffness",
        "Leg spring stiffness k (eq. 1)",
        "N/m",
        EQ1,
        Origin::Open,
        "eq. 1's k; the paper prints no value: 20 kN/m for the run, 12 kN/m for the gallops",
    ),
    row(
        "leg_damping",
        "Leg spring damping b (eq. 1)",
        "N·s/m",
        EQ1,
        Origin::Open,
        "eq. 1's b; the paper prints no value: light, so most of a landing's energy returns",
    ),
    LEG_TRAVEL_M,
    row(
        "landing_rest_m",
        "Leg rest length for landing",
        "m",
        FIG4_FLIGHT,
        Origin::Open,
        "Figure 4 lengthens the active leg for landing without saying how far: 3 cm short",
    ),
    row(
        "thrust_m",
        "Thrust: extra rest length in Thrust (eq. 2)",
        "m",
        EQ2_THRUST,
        Origin::Open,
        "The hop integrator's first thrust (eq. 2 sets each thrust without it); none printed: 3 cm",
    ),
    row(
        "idle_rest_m",
        "Idle leg's shortened rest length",
        "m",
        FIG4_FLIGHT,
        Origin::Open,
        "Figure 4 keeps the idle leg short without a length: 18 cm, clear of the ground",
    ),
    row(
        "hop_gain",
        "Hop-height integrator (thrust per m of apex error)",
        "",
        LAB,
        Origin::Lab,
        "lab_additions.hop_integrator (off): the paper sets the thrust by eq. 2's prediction alone",
    ),
    placement_gain_s_row(
        "eq. 3's gain; the paper prints none: 0.12 s leaves 4–6 % (inside its 10 %)",
    ),
    SPEED_INTEGRAL_GAIN,
    row(
        "swing_kp",
        "Swing hip stiffness (eq. 5)",
        TORSION,
        EQ5_SWING,
        Origin::Open,
        "eq. 5's position gain positioning the leg for landing; the paper prints none",
    ),
    row(
        "swing_kv",
        "Swing hip damping (eq. 5)",
        TORSION_DAMPING,
        EQ5_SWING,
        Origin::Open,
        "eq. 5's velocity gain positioning the leg for landing; the paper prints none",
    ),
    row(
        "posture_kp",
        "Posture stiffness k_p (eq. 4)",
        TORSION,
        EQ4,
        Origin::Open,
        "eq. 4's k_p through the active hip; the paper prints no value",
    ),
    row(
        "posture_kv",
        "Posture damping k_v (eq. 4)",
        TORSION_DAMPING,
        EQ4,
        Origin::Open,
        "eq. 4's k_v through the active hip; the paper prints no value",
    ),
    yaw_kp_row(
        "A yaw servo toward the heading through the hips' yaw joints; eq. 4 servoes pitch and roll",
    ),
    row(
        "yaw_kv",
        "Trunk yaw damping in stance",
        TORSION_DAMPING,
        LAB,
        Origin::Lab,
        "Damping of the lab's yaw servo (the bundled biped's 40 keeps its yaw within ±5°)",
    ),
    row(
        "leg_yaw_kp",
        "Airborne leg's yaw-joint stiffness (eq. 5)",
        TORSION,
        EQ5,
        Origin::Open,
        "eq. 5's servo on the ball hip's third axis, holding the leg unturned; no value printed",
    ),
    row(
        "leg_yaw_kv",
        "Airborne leg's yaw-joint damping (eq. 5)",
        TORSION_DAMPING,
        EQ5,
        Origin::Open,
        "eq. 5's servo on the ball hip's third axis; no value printed",
    ),
    MAX_HIP_TORQUE,
    row(
        "max_yaw_torque",
        "Largest trunk-yaw torque through the stance hips",
        "N·m",
        LAB,
        Origin::Lab,
        "Bounds the lab's yaw servo to what the foot's torsional grip holds",
    ),
    row(
        "leg_rate_mps",
        "Largest rate of change of a leg's rest length",
        "m/s",
        LAB,
        Origin::Lab,
        "Figure 4 sets rest lengths at no rate; the lab limits it so a leg does not jerk the trunk",
    ),
];

/// [`BipedRunParams`](crate::control::gaits::biped_run::params::BipedRunParams)' parameters, in [`NamedParameters::NAMES`](crate::control::gaits::parameters::NamedParameters::NAMES) order.
pub const ORIGINS: &[ControllerParam] = &HOPPER;

impl Gait for BipedRun {
    fn origins(&self) -> &'static [ControllerParam] {
        ORIGINS
    }
}
