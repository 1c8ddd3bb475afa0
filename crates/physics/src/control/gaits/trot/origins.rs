//! Where the trot's named parameters come from (Raibert & Hodgins 1991,
//! "Gaits", Figure 4 on virtual legs, eqs. 1–5, Table 2).

use gaitlab_core::params::Origin;

use crate::control::gaits::origins::{
    ControllerParam, EQ4, FIG4_FLIGHT, LAB, LEG_DAMPING, LEG_STIFFNESS, LEG_TRAVEL_M,
    MAX_HIP_TORQUE, MAX_THRUST_M, PITCH_KV, PLACEMENT_GAIN_S, ROLL_KP, ROLL_KV, STANDING, SWING_KP,
    SWING_KV, SWING_ROLL_FOLLOW, THRUST_M, YAW_KV, flight_gain_row, pitch_kp_row,
    posture_force_ratio_row, row, yaw_kp_row,
};

/// [`QuadrupedRunParams`](crate::control::gaits::trot::params::QuadrupedRunParams)' parameters (the trot), in
/// [`NamedParameters::NAMES`](crate::control::gaits::parameters::NamedParameters::NAMES) order.
pub const ORIGINS: &[ControllerParam] = &[
    LEG_STIFFNESS,
    LEG_DAMPING,
    row(
        "leg_air_damping",
        "Leg damping while the foot is off the ground",
        "N·s/m",
        LAB,
        Origin::Lab,
        "A second damping so a lengthened leg does not ring before landing; eq. 1 has one b",
    ),
    LEG_TRAVEL_M,
    row(
        "landing_rest_m",
        "Leg rest length for landing and standing",
        "m",
        STANDING,
        Origin::Open,
        "The paper reduced the legs' standing length for the trot without saying by how much",
    ),
    row(
        "idle_rest_m",
        "Idle pair's shortened rest length",
        "m",
        FIG4_FLIGHT,
        Origin::Open,
        "Figure 4 keeps the idle (virtual) leg short without a length",
    ),
    THRUST_M,
    row(
        "flight0_s",
        "Desired flight after pair 0's lift-off",
        "s",
        "Raibert & Hodgins 1991 Table 2 (Quadruped Trot)",
        Origin::Paper,
        "Table 2's animated trot flight, 0.18 s",
    ),
    row(
        "flight1_s",
        "Desired flight after pair 1's lift-off",
        "s",
        "Raibert & Hodgins 1991 Table 2 (Quadruped Trot)",
        Origin::Paper,
        "Table 2's animated trot flight, 0.18 s",
    ),
    row(
        "eq2_hop_m",
        "Hop height eq. 2 is asked for without a command",
        "m",
        "Raibert & Hodgins 1991 eq. 2, Table 2 (Quadruped Trot)",
        Origin::Open,
        "The paper gives no trot hop height: 0.11 m asked gives Table 2's 0.18 s flight at 2.3 m/s",
    ),
    row(
        "stance_s",
        "First guess of the stance time T_s (eq. 3)",
        "s",
        "Raibert & Hodgins 1991 eq. 3; Table 2 (Quadruped Trot)",
        Origin::Paper,
        "eq. 3 uses the last measured stance; before one, Table 2's animated trot stance, 0.09 s",
    ),
    PLACEMENT_GAIN_S,
    pitch_kp_row("eq. 4's k_p; the paper prints no value"),
    PITCH_KV,
    ROLL_KP,
    ROLL_KV,
    row(
        "pitch_d",
        "Desired stance pitch ϕ_d (eq. 4)",
        "rad",
        EQ4,
        Origin::Open,
        "eq. 4's ϕ_d for the trot; the paper prints none (0: level)",
    ),
    row(
        "speed_gain",
        "Speed integral gain per stride",
        "",
        LAB,
        Origin::Lab,
        "An integral speed correction of the lab's (0 by default: eq. 3 alone holds the trot)",
    ),
    row(
        "pitch_swing",
        "Desired pitch alternating between the pairs' stances",
        "rad",
        LAB,
        Origin::Lab,
        "A term added to eq. 4's ϕ_d (0 by default); the paper's ϕ_d is one angle",
    ),
    posture_force_ratio_row(
        "Caps eq. 4's torques at a friction-safe force (∞: none); the paper's feet never slip",
    ),
    flight_gain_row(
        "lab_additions.hop_integrator (on unless the file says; the bundled trot runs without): each flight's time error",
    ),
    MAX_THRUST_M,
    yaw_kp_row(
        "A yaw servo toward the heading through the stance hips; eq. 4 servoes pitch and roll",
    ),
    YAW_KV,
    SWING_KP,
    SWING_KV,
    SWING_ROLL_FOLLOW,
    MAX_HIP_TORQUE,
    row(
        "unison_liftoff",
        "A pair leaves the ground as one virtual leg (1) or leg by leg (0)",
        "",
        "Raibert & Hodgins 1991, \"Gaits\" (virtual legs)",
        Origin::Paper,
        "\"The members of each pair strike the ground in unison and leave the ground in unison\"",
    ),
];
