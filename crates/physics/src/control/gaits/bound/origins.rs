//! Where the bound's and the gallop's named parameters come from (Raibert
//! & Hodgins 1991, "Gaits", Figure 4 on pairs, eqs. 1–5, Table 2).

use gaitlab_core::params::Origin;

use crate::control::gaits::bound::QuadrupedBound;
use crate::control::gaits::gait::Gait;
use crate::control::gaits::origins::{
    ControllerParam, EQ4, FIG4_FLIGHT, GALLOP, LAB, LAB_TRIM, LEG_DAMPING, LEG_STIFFNESS,
    LEG_TRAVEL_M, MAX_HIP_TORQUE, MAX_THRUST_M, PITCH_KV, PLACEMENT_GAIN_S, ROLL_KP, ROLL_KV,
    SPEED_INTEGRAL_GAIN, STANDING, SWING_KP, SWING_KV, SWING_ROLL_FOLLOW, THRUST_M, YAW_KV,
    flight_gain_row, pitch_kp_row, posture_force_ratio_row, row, yaw_kp_row,
};

/// [`QuadrupedBoundParams`](crate::control::gaits::bound::params::QuadrupedBoundParams)' parameters (bound and gallop), in
/// [`NamedParameters::NAMES`](crate::control::gaits::parameters::NamedParameters::NAMES) order.
pub const ORIGINS: &[ControllerParam] = &[
    LEG_STIFFNESS,
    LEG_TRAVEL_M,
    LEG_DAMPING,
    row(
        "leg_air_damping",
        "Leg damping while the foot is in the air",
        "N·s/m",
        LAB,
        Origin::Lab,
        "A second damping so a lengthened leg does not ring before landing; eq. 1 has one b",
    ),
    row(
        "landing_rest_m",
        "Leg rest length for landing",
        "m",
        STANDING,
        Origin::Open,
        "The paper reduced the legs' standing length for the bound without saying by how much",
    ),
    row(
        "short_rest_m",
        "Shortened leg's rest length",
        "m",
        FIG4_FLIGHT,
        Origin::Open,
        "Figure 4 shortens the idle (virtual) leg without a length",
    ),
    THRUST_M,
    row(
        "rear_extra_thrust_m",
        "Rear pair's extra thrust",
        "m",
        LAB,
        Origin::Lab,
        "A term of the lab's (0 by default: both pairs thrust alike)",
    ),
    MAX_THRUST_M,
    row(
        "min_thrust_m",
        "Smallest thrust",
        "m",
        LAB,
        Origin::Lab,
        "Bound of the lab's flight-regulated thrust (below 0 it takes energy out)",
    ),
    row(
        "stride_flight_s",
        "Desired flight per stride, gathered + extended",
        "s",
        "Raibert & Hodgins 1991 Table 2 (Quadruped Bound); eq. 2",
        Origin::Paper,
        "Table 2's animated bound flies 0.22 + 0.03 = 0.25 s a stride (the bundled bound's)",
    ),
    flight_gain_row(
        "An integrator on the stride's flight-time error; the paper does not say how it sets eq. 2",
    ),
    row(
        "gathered_flight_s",
        "Desired gathered flight",
        "s",
        "Raibert & Hodgins 1991 Table 2 (Quadruped Bound)",
        Origin::Paper,
        "Table 2's animated gathered flight, 0.22 s (the bundled bound's)",
    ),
    row(
        "extended_flight_s",
        "Desired extended flight",
        "s",
        "Raibert & Hodgins 1991 Table 2 (Quadruped Bound)",
        Origin::Paper,
        "Table 2's animated extended flight, 0.03 s",
    ),
    row(
        "pair_flight_gain",
        "Per-pair flight-time integrator",
        "m/s",
        LAB,
        Origin::Lab,
        "An integrator trimming each pair's thrust on its own flight; not in the paper",
    ),
    row(
        "thrust_end",
        "Fraction of the thrust that ends Thrust",
        "",
        "Raibert & Hodgins 1991 Figure 4 (Unloading)",
        Origin::Open,
        "Figure 4 unloads as the spring approaches full length, with no threshold printed",
    ),
    row(
        "min_short_s",
        "Least time a pair stays short after lift-off",
        "s",
        LAB,
        Origin::Lab,
        "A wait of the lab's before lengthening for landing; Figure 4 has none",
    ),
    row(
        "stance_s",
        "First guess of the stance time T_s (eq. 3)",
        "s",
        "Raibert & Hodgins 1991 eq. 3; Table 2 (Quadruped Bound)",
        Origin::Open,
        "eq. 3 uses the last measured stance; before one, 0.09 s, between Table 2's 0.10 and 0.08",
    ),
    PLACEMENT_GAIN_S,
    SPEED_INTEGRAL_GAIN,
    row(
        "speed_bias_cap",
        "Largest speed trim, as a fraction of the desired speed",
        "",
        LAB_TRIM,
        Origin::Lab,
        "Bound of the lab's integral speed trim",
    ),
    row(
        "min_stride_s",
        "Shortest stride",
        "s",
        LAB,
        Origin::Lab,
        "A rear bounce sooner than this does not end the lab's flight and speed measure",
    ),
    row(
        "front_offset_m",
        "Front feet's extra forward placement",
        "m",
        LAB,
        Origin::Lab,
        "A term added to eq. 3's neutral point (0 by default: eq. 3 as printed)",
    ),
    row(
        "pitch_bias",
        "Desired stance pitch ϕ_d (eq. 4)",
        "rad",
        EQ4,
        Origin::Open,
        "eq. 4's ϕ_d for the bound; the paper prints none (0: level)",
    ),
    pitch_kp_row(
        "eq. 4's k_p, weak so the bound's pitching stays the gait's own; no value printed",
    ),
    PITCH_KV,
    ROLL_KP,
    ROLL_KV,
    yaw_kp_row(
        "A yaw servo toward the heading by fore–aft foot forces; eq. 4 servoes pitch and roll",
    ),
    YAW_KV,
    posture_force_ratio_row(
        "Caps eq. 4's torques at a friction-safe force; the paper's feet never slip",
    ),
    row(
        "sweep_s",
        "Leg sweep look-ahead before touchdown",
        "s",
        LAB,
        Origin::Lab,
        "The leg sweeps back to match ground speed, which the paper's animations do not do",
    ),
    SWING_KP,
    SWING_KV,
    SWING_ROLL_FOLLOW,
    MAX_HIP_TORQUE,
    row(
        "gallop_shorter_m",
        "Gallop: second leg of a pair lands shorter",
        "m",
        GALLOP,
        Origin::Open,
        "The paper's gallop lands a pair apart in time, not saying how: a shorter leg lands later",
    ),
    row(
        "gallop_spread_m",
        "Gallop: second foot lands further forward",
        "m",
        GALLOP,
        Origin::Open,
        "The paper's gallop lands a pair's feet apart in space, no distance printed",
    ),
    row(
        "gallop_lag_s",
        "Gallop: delay before the second leg lengthens for landing",
        "s",
        GALLOP,
        Origin::Open,
        "Separates a pair's stances in time (single, double, single support); no value printed",
    ),
];

impl Gait for QuadrupedBound {
    fn origins(&self) -> &'static [ControllerParam] {
        ORIGINS
    }

    /// The bound and the gallop are this one state machine in two styles:
    /// the running one takes the other's parameters and runs on.
    fn adopt(&mut self, fresh: &dyn Gait) -> bool {
        match fresh.as_any().downcast_ref::<QuadrupedBound>() {
            Some(fresh) => {
                self.set_params(fresh.params);
                true
            }
            None => false,
        }
    }
}
