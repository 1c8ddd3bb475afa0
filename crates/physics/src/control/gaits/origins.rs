//! Where every named gait-controller parameter comes from (Raibert & Hodgins
//! 1991, eqs. 1–5, Figure 4, Tables 2 and 3, "Kangaroo control"): for each
//! name of [`NamedParameters::NAMES`] a label, its unit, where the paper
//! speaks of it and its [`Origin`] — the paper's value or law, a value the
//! paper's law needs but does not print (open: the lab picked it), or a term
//! the paper does not have (the lab's).
//!
//! The paper prints the laws (eq. 1's spring, eq. 2's energy, eq. 3's
//! placement, eq. 4's posture servo, eq. 5's joint servos, Figure 4's states)
//! but none of their gains, so those are open; the few values it does print
//! that a controller takes (Table 2's flight and stance times, the
//! kangaroo's level trunk) are the paper's; integrators on hop height,
//! flight time or speed, rate limits, clamps, feedforwards and extra servos
//! are the lab's (`docs/physics.md`, "The lab's additions").

use gaitlab_core::params::Origin;

use crate::control::gaits::biped_gallop::params::BipedGallopParams;
use crate::control::gaits::biped_run::params::BipedRunParams;
use crate::control::gaits::bound::params::QuadrupedBoundParams;
use crate::control::gaits::controller::GaitController;
use crate::control::gaits::kangaroo_hop::params::KangarooHopParams;
use crate::control::gaits::parameters::NamedParameters;
use crate::control::gaits::trot::params::QuadrupedRunParams;

/// One named parameter of a gait controller, for the engine's parameter table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ControllerParam {
    /// The name a preset's `scenario.physics.controller` map sets
    /// (an entry of [`NamedParameters::NAMES`]).
    pub name: &'static str,
    /// What it is, in a few words for people.
    pub label: &'static str,
    /// Unit (`N/m`, `s`, `m`, `rad`, `N·m/rad`, …; empty for a pure number).
    pub unit: &'static str,
    /// Where the paper speaks of it (equation, figure, table, section), or
    /// `docs/physics.md` for the lab's.
    pub reference: &'static str,
    /// The paper's, a value the paper leaves open, or the lab's.
    pub origin: Origin,
    /// Why this origin, or this value, in one line.
    pub why: &'static str,
}

/// One row (positional, to keep the tables short).
const fn row(
    name: &'static str,
    label: &'static str,
    unit: &'static str,
    reference: &'static str,
    origin: Origin,
    why: &'static str,
) -> ControllerParam {
    ControllerParam {
        name,
        label,
        unit,
        reference,
        origin,
        why,
    }
}

/// `a` then `b` as one array of `N = A + B` rows.
const fn concat<const A: usize, const B: usize, const N: usize>(
    a: &[ControllerParam; A],
    b: &[ControllerParam; B],
) -> [ControllerParam; N] {
    assert!(A > 0 && A + B == N, "N must be A + B");
    let mut out = [a[0]; N];
    let mut i = 0;
    while i < A {
        out[i] = a[i];
        i += 1;
    }
    while i < N {
        out[i] = b[i - A];
        i += 1;
    }
    out
}

const EQ1: &str = "Raibert & Hodgins 1991 eq. 1";
const EQ2_THRUST: &str = "Raibert & Hodgins 1991 eq. 2; Figure 4 (Thrust)";
const EQ3: &str = "Raibert & Hodgins 1991 eq. 3";
const EQ4: &str = "Raibert & Hodgins 1991 eq. 4";
const EQ5_SWING: &str = "Raibert & Hodgins 1991 eq. 5; Figure 4 (Flight)";
const EQ5: &str = "Raibert & Hodgins 1991 eq. 5 (Modeling)";
const FIG4_FLIGHT: &str = "Raibert & Hodgins 1991 Figure 4 (Flight)";
const TABLE3: &str = "Raibert & Hodgins 1991 Table 3";
const ACTUATORS: &str = "Raibert & Hodgins 1991, Discussion (actuator torque)";
const KANGAROO: &str = "Raibert & Hodgins 1991, Kangaroo control";
const JUMP: &str = "Raibert & Hodgins 1991, Results (the jump's states)";
const GALLOP: &str = "Raibert & Hodgins 1991, Gaits (galloping)";
const STANDING: &str = "Raibert & Hodgins 1991, Results (standing length reduced)";
const LAB: &str = "docs/physics.md";
const LAB_TRIM: &str = "docs/physics.md, The lab's additions (speed_trim)";
const LAB_RAMP: &str = "docs/physics.md, The lab's additions (speed_ramp)";
const LAB_TAIL: &str = "docs/physics.md, The lab's additions (tail_feedback)";

const TORSION: &str = "N·m/rad";
const TORSION_DAMPING: &str = "N·m·s/rad";

/// The one-legged hopper's rows the biped run and both biped gallops share
/// (`hopper_params.rs`), in the order of `with_hopper_fields!`.
const HOPPER: [ControllerParam; 20] = [
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
        "Figure 4's leg extension injects eq. 2's energy; no length printed: 3 cm to start",
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
        "The paper predicts the hop by eq. 2; correcting the thrust from each apex is the lab's",
    ),
    row(
        "placement_gain_s",
        "Foot placement gain k_ẋ (eq. 3)",
        "s",
        EQ3,
        Origin::Open,
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
    row(
        "yaw_kp",
        "Trunk yaw stiffness in stance",
        TORSION,
        LAB,
        Origin::Lab,
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

/// The biped gallop's own rows, before the hopper's.
const GALLOP_OWN: [ControllerParam; 8] = [
    row(
        "trail_offset_m",
        "Trailing foot's extra forward placement",
        "m",
        LAB,
        Origin::Lab,
        "A term added to eq. 3's neutral point (0 by default: eq. 3 as printed)",
    ),
    row(
        "lead_offset_m",
        "Leading foot's extra forward placement",
        "m",
        LAB,
        Origin::Lab,
        "A term added to eq. 3's neutral point (0 by default: eq. 3 as printed)",
    ),
    row(
        "lead_retract_m",
        "Leading leg held short before the trailing touchdown",
        "m",
        GALLOP,
        Origin::Open,
        "The paper's gallop lands the legs apart in time without saying how: the lead 8 cm short",
    ),
    row(
        "lead_delay_s",
        "Delay before the leading leg lengthens for landing",
        "s",
        GALLOP,
        Origin::Open,
        "Spaces the two touchdowns in time, as the paper's gallop does; no value printed",
    ),
    row(
        "lead_extend_mps",
        "Leading leg's lengthening rate for landing",
        "m/s",
        LAB,
        Origin::Lab,
        "A rate of the lab's: Figure 4 lengthens the leg for landing without one",
    ),
    row(
        "trail_extend_mps",
        "Trailing leg's lengthening rate in flight",
        "m/s",
        LAB,
        Origin::Lab,
        "A rate of the lab's: Figure 4 lengthens the leg for landing without one",
    ),
    row(
        "trail_unload_mps",
        "Trailing leg's shortening rate in unloading",
        "m/s",
        LAB,
        Origin::Lab,
        "A rate of the lab's, handing the load to the leading leg; Figure 4 gives none",
    ),
    row(
        "pitch_feedforward",
        "Stance pitch feedforward against the flight's pitching",
        "",
        LAB,
        Origin::Lab,
        "A feedforward setting eq. 4's ϕ_d from the flight's pitching; the paper's ϕ_d is fixed",
    ),
];

const BIPED_GALLOP_ROWS: [ControllerParam; 28] = concat(&GALLOP_OWN, &HOPPER);

// Rows that two or three controllers share word for word.

/// `leg_travel_m`, the same in every controller that has it.
const LEG_TRAVEL_M: ControllerParam = row(
    "leg_travel_m",
    "Telescoping leg's travel",
    "m",
    TABLE3,
    Origin::Open,
    "The leg's stop: Table 3 gives the links' lengths, not how far the leg telescopes",
);

/// `speed_integral_gain`, the same in every controller that has it.
const SPEED_INTEGRAL_GAIN: ControllerParam = row(
    "speed_integral_gain",
    "Speed trim integral gain",
    "",
    LAB_TRIM,
    Origin::Lab,
    "Gain of the lab's integral speed trim (lab_additions.speed_trim); eq. 3 has no integral",
);

/// `max_hip_torque`, the same in every controller that has it.
const MAX_HIP_TORQUE: ControllerParam = row(
    "max_hip_torque",
    "Largest hip torque",
    "N·m",
    ACTUATORS,
    Origin::Open,
    "The paper names the actuators' available torque as shaping the motion, gives none",
);

/// `leg_stiffness`, the same in every controller that has it.
const LEG_STIFFNESS: ControllerParam = row(
    "leg_stiffness",
    "Leg spring stiffness k (eq. 1)",
    "N/m",
    EQ1,
    Origin::Open,
    "eq. 1's k per leg; the paper prints no value",
);

/// `leg_damping`, the same in every controller that has it.
const LEG_DAMPING: ControllerParam = row(
    "leg_damping",
    "Leg spring damping b in stance (eq. 1)",
    "N·s/m",
    EQ1,
    Origin::Open,
    "eq. 1's b; the paper prints no value",
);

/// `thrust_m`, the same in every controller that has it.
const THRUST_M: ControllerParam = row(
    "thrust_m",
    "Initial thrust: extra rest length in Thrust (eq. 2)",
    "m",
    EQ2_THRUST,
    Origin::Open,
    "Figure 4's leg extension injects eq. 2's energy; no length printed",
);

/// `max_thrust_m`, the same in every controller that has it.
const MAX_THRUST_M: ControllerParam = row(
    "max_thrust_m",
    "Largest thrust",
    "m",
    LAB,
    Origin::Lab,
    "Bound of the lab's flight-regulated thrust",
);

/// `placement_gain_s`, the same in every controller that has it.
const PLACEMENT_GAIN_S: ControllerParam = row(
    "placement_gain_s",
    "Foot placement gain k_ẋ (eq. 3)",
    "s",
    EQ3,
    Origin::Open,
    "eq. 3's gain; the paper prints none",
);

/// `pitch_kv`, the same in every controller that has it.
const PITCH_KV: ControllerParam = row(
    "pitch_kv",
    "Pitch damping k_v (eq. 4)",
    TORSION_DAMPING,
    EQ4,
    Origin::Open,
    "eq. 4's k_v; the paper prints no value",
);

/// `roll_kp`, the same in every controller that has it.
const ROLL_KP: ControllerParam = row(
    "roll_kp",
    "Roll stiffness (eq. 4)",
    TORSION,
    EQ4,
    Origin::Open,
    "eq. 4 on roll; the paper prints no value",
);

/// `roll_kv`, the same in every controller that has it.
const ROLL_KV: ControllerParam = row(
    "roll_kv",
    "Roll damping (eq. 4)",
    TORSION_DAMPING,
    EQ4,
    Origin::Open,
    "eq. 4 on roll; the paper prints no value",
);

/// `yaw_kv`, the same in every controller that has it.
const YAW_KV: ControllerParam = row(
    "yaw_kv",
    "Trunk yaw damping in stance",
    TORSION_DAMPING,
    LAB,
    Origin::Lab,
    "Damping of the lab's yaw servo",
);

/// `swing_kp`, the same in every controller that has it.
const SWING_KP: ControllerParam = row(
    "swing_kp",
    "Swing hip stiffness (eq. 5)",
    TORSION,
    EQ5_SWING,
    Origin::Open,
    "eq. 5's position gain positioning the legs for landing; the paper prints none",
);

/// `swing_kv`, the same in every controller that has it.
const SWING_KV: ControllerParam = row(
    "swing_kv",
    "Swing hip damping (eq. 5)",
    TORSION_DAMPING,
    EQ5_SWING,
    Origin::Open,
    "eq. 5's velocity gain positioning the legs for landing; the paper prints none",
);

/// `swing_roll_follow`, the same in every controller that has it.
const SWING_ROLL_FOLLOW: ControllerParam = row(
    "swing_roll_follow",
    "Share of trunk roll in eq. 3's leg aim",
    "",
    EQ3,
    Origin::Open,
    "The paper does not say which attitude eq. 3's kinematic transformation uses",
);

/// [`BipedRunParams`]' parameters, in [`NamedParameters::NAMES`] order.
pub const BIPED_RUN: &[ControllerParam] = &HOPPER;

/// [`BipedGallopParams`]' parameters (both styles), in
/// [`NamedParameters::NAMES`] order.
pub const BIPED_GALLOP: &[ControllerParam] = &BIPED_GALLOP_ROWS;

/// [`KangarooHopParams`]' parameters, in [`NamedParameters::NAMES`] order.
pub const KANGAROO_HOP: &[ControllerParam] = &[
    row(
        "speed_ramp_mps2",
        "Speed ramp rate",
        "m/s²",
        LAB_RAMP,
        Origin::Lab,
        "Rate of the lab's speed ramp (lab_additions.speed_ramp); the paper's speed is not ramped",
    ),
    SPEED_INTEGRAL_GAIN,
    row(
        "speed_integral_max_mps",
        "Largest speed trim correction",
        "m/s",
        LAB_TRIM,
        Origin::Lab,
        "Bound of the lab's integral speed trim",
    ),
    row(
        "hop_gain",
        "Apex-correction integrator (m of target per m of error)",
        "",
        LAB,
        Origin::Lab,
        "Learns eq. 2's losses from each measured apex; the paper uses eq. 2's prediction alone",
    ),
    row(
        "ankle_stiffness",
        "Ankle spring stiffness (eq. 1)",
        TORSION,
        EQ1,
        Origin::Open,
        "The paper tuned the ankle spring to return much of the energy, printing no value",
    ),
    row(
        "ankle_damping",
        "Ankle spring damping (eq. 1)",
        TORSION_DAMPING,
        EQ1,
        Origin::Open,
        "eq. 1's b at the ankle; the paper prints no value",
    ),
    row(
        "ankle_rest_rad",
        "Ankle rest angle for landing (eq. 1's x_r)",
        "rad",
        KANGAROO,
        Origin::Open,
        "The ankle spring's adjustable rest, landing value not printed: −1.2 rad",
    ),
    row(
        "max_thrust_rad",
        "Largest thrust step of the ankle rest",
        "rad",
        LAB,
        Origin::Lab,
        "A bound the lab puts on eq. 2's thrust step; the paper states none",
    ),
    row(
        "placement_gain_s",
        "Foot placement gain k_ẋ (eq. 3)",
        "s",
        EQ3,
        Origin::Open,
        "eq. 3's gain; the paper prints none (the bundled kangaroo's 0.06 s is the tuner's)",
    ),
    row(
        "landing_leg_m",
        "Hip-to-toe distance at touchdown",
        "m",
        KANGAROO,
        Origin::Open,
        "The leg length eq. 3's kinematic transformation places the toe at; not printed: 0.46 m",
    ),
    row(
        "flight_retract_m",
        "Toe drawn in while the body rises",
        "m",
        LAB,
        Origin::Lab,
        "Keeps the swinging toe off the ground after a low hop (its scuff tipped the fast gaits)",
    ),
    row(
        "stance_guess_s",
        "First guess of the stance time T_s (eq. 3)",
        "s",
        "Raibert & Hodgins 1991 eq. 3; Table 2 (Kangaroo Hop)",
        Origin::Paper,
        "eq. 3 uses the last measured stance; before one, Table 2's animated stance, 0.11 s",
    ),
    row(
        "hip_kp",
        "Hip servo stiffness in flight (eq. 5)",
        TORSION,
        EQ5,
        Origin::Open,
        "eq. 5's gain placing the toe in flight; the paper prints none",
    ),
    row(
        "hip_kv",
        "Hip servo damping in flight (eq. 5)",
        TORSION_DAMPING,
        EQ5,
        Origin::Open,
        "eq. 5's gain placing the toe in flight; the paper prints none",
    ),
    row(
        "stance_hip_kp",
        "Hip servo stiffness keeping the knee on the thrust line",
        TORSION,
        KANGAROO,
        Origin::Open,
        "The paper servoes the hip to keep the knee on the thrust line, with no gains printed",
    ),
    row(
        "stance_hip_kv",
        "Hip servo damping keeping the knee on the thrust line",
        TORSION_DAMPING,
        KANGAROO,
        Origin::Open,
        "The paper servoes the hip to keep the knee on the thrust line, with no gains printed",
    ),
    row(
        "knee_kp",
        "Knee servo stiffness in flight (eq. 5)",
        TORSION,
        EQ5,
        Origin::Open,
        "eq. 5's gain placing the toe in flight; the paper prints none",
    ),
    row(
        "knee_kv",
        "Knee servo damping in flight (eq. 5)",
        TORSION_DAMPING,
        EQ5,
        Origin::Open,
        "eq. 5's gain placing the toe in flight; the paper prints none",
    ),
    row(
        "posture_kp",
        "Posture stiffness k_p at the knee (eq. 4)",
        TORSION,
        EQ4,
        Origin::Open,
        "eq. 4 acts at the kangaroo's knee; the paper prints no gains",
    ),
    row(
        "posture_kv",
        "Posture damping k_v at the knee (eq. 4)",
        TORSION_DAMPING,
        EQ4,
        Origin::Open,
        "eq. 4 acts at the kangaroo's knee; the paper prints no gains",
    ),
    row(
        "pitch_rad",
        "Desired trunk pitch ϕ_d (eq. 4)",
        "rad",
        "Raibert & Hodgins 1991 eq. 4; Kangaroo control",
        Origin::Paper,
        "The paper keeps the kangaroo's body in a level posture: ϕ_d = 0",
    ),
    row(
        "tail_stiffness",
        "Tail-base spring stiffness",
        TORSION,
        "Raibert & Hodgins 1991, Kangaroo control; Results",
        Origin::Open,
        "Tuned so the tail's natural frequency is about the hop's, the value not printed",
    ),
    row(
        "tail_damping",
        "Tail-base spring damping",
        TORSION_DAMPING,
        "Raibert & Hodgins 1991, Kangaroo control; Results",
        Origin::Open,
        "Tuned with the stiffness to oscillate with the hop, the value not printed",
    ),
    row(
        "tail_mean_rad",
        "Tail-base mean rest angle",
        "rad",
        KANGAROO,
        Origin::Open,
        "The angle the paper's stepped tail rest steps about; not printed",
    ),
    row(
        "tail_step_rad",
        "Step of the tail-base rest between flight and stance",
        "rad",
        KANGAROO,
        Origin::Open,
        "The paper's step change of the tail's rest, its size not printed",
    ),
    row(
        "tail_pitch_gain",
        "Tail rest feedback on trunk pitch",
        "",
        LAB_TAIL,
        Origin::Lab,
        "Gain of the lab's tail feedback (lab_additions.tail_feedback); the paper only steps it",
    ),
    row(
        "tail_rate_gain_s",
        "Tail rest feedback on trunk pitch rate",
        "s",
        LAB_TAIL,
        Origin::Lab,
        "Gain of the lab's tail feedback (lab_additions.tail_feedback); the paper only steps it",
    ),
    row(
        "tail_tip_stiffness",
        "Distal tail joints' stiffness",
        TORSION,
        KANGAROO,
        Origin::Open,
        "The paper's two peripheral tail joints are fixed-rest spring-dampers; no values",
    ),
    row(
        "tail_tip_damping",
        "Distal tail joints' damping",
        TORSION_DAMPING,
        KANGAROO,
        Origin::Open,
        "The paper's two peripheral tail joints are fixed-rest spring-dampers; no values",
    ),
    row(
        "neck_kp",
        "Neck servo stiffness (head level)",
        TORSION,
        KANGAROO,
        Origin::Open,
        "The paper servoes the head level; no gains printed",
    ),
    row(
        "neck_kv",
        "Neck servo damping (head level)",
        TORSION_DAMPING,
        KANGAROO,
        Origin::Open,
        "The paper servoes the head level; no gains printed",
    ),
    row(
        "max_torque",
        "Largest hip and knee torque",
        "N·m",
        ACTUATORS,
        Origin::Open,
        "The paper names the actuators' available torque as shaping the motion, gives none",
    ),
    row(
        "jump_clearance_m",
        "Toe's clearance over an obstacle",
        "m",
        "Raibert & Hodgins 1991 Figure 2 (how high to jump)",
        Origin::Open,
        "The paper's animator says how high to jump; the lab asks for 8 cm over the box",
    ),
    row(
        "jump_stiffness_factor",
        "Ankle stiffness factor for a jump's take-off",
        "",
        JUMP,
        Origin::Open,
        "The paper's jump stiffens the legs for take-off without saying how much: ×1.5",
    ),
    row(
        "landing_damping_factor",
        "Ankle damping factor landing after a jump",
        "",
        JUMP,
        Origin::Open,
        "The paper's jump adds dissipation to the landing without a value: ×4",
    ),
];

/// [`QuadrupedBoundParams`]' parameters (bound and gallop), in
/// [`NamedParameters::NAMES`] order.
pub const QUADRUPED_BOUND: &[ControllerParam] = &[
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
    row(
        "flight_gain",
        "Flight-time integrator (thrust change per s of error)",
        "m/s",
        LAB,
        Origin::Lab,
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
    row(
        "pitch_kp",
        "Pitch stiffness k_p (eq. 4)",
        TORSION,
        EQ4,
        Origin::Open,
        "eq. 4's k_p, weak so the bound's pitching stays the gait's own; no value printed",
    ),
    PITCH_KV,
    ROLL_KP,
    ROLL_KV,
    row(
        "yaw_kp",
        "Trunk yaw stiffness in stance",
        TORSION,
        LAB,
        Origin::Lab,
        "A yaw servo toward the heading by fore–aft foot forces; eq. 4 servoes pitch and roll",
    ),
    YAW_KV,
    row(
        "posture_force_ratio",
        "Largest posture foot force, as a fraction of the spring's",
        "",
        LAB,
        Origin::Lab,
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

/// [`QuadrupedRunParams`]' parameters (the trot), in
/// [`NamedParameters::NAMES`] order.
pub const QUADRUPED_RUN: &[ControllerParam] = &[
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
        "stance_s",
        "First guess of the stance time T_s (eq. 3)",
        "s",
        "Raibert & Hodgins 1991 eq. 3; Table 2 (Quadruped Trot)",
        Origin::Paper,
        "eq. 3 uses the last measured stance; before one, Table 2's animated trot stance, 0.09 s",
    ),
    PLACEMENT_GAIN_S,
    row(
        "pitch_kp",
        "Pitch stiffness k_p (eq. 4)",
        TORSION,
        EQ4,
        Origin::Open,
        "eq. 4's k_p; the paper prints no value",
    ),
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
    row(
        "posture_force_ratio",
        "Largest posture foot force, as a fraction of the spring's",
        "",
        LAB,
        Origin::Lab,
        "Caps eq. 4's torques at a friction-safe force (∞: none); the paper's feet never slip",
    ),
    row(
        "flight_gain",
        "Flight-time integrator (thrust change per s of error)",
        "m/s",
        LAB,
        Origin::Lab,
        "An integrator on each flight's time error; the paper does not say how it sets eq. 2",
    ),
    MAX_THRUST_M,
    row(
        "yaw_kp",
        "Trunk yaw stiffness in stance",
        TORSION,
        LAB,
        Origin::Lab,
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

/// The table of the parameters type whose names are `names` (a
/// controller's [`parameter_names`](crate::world::sim::Controller::parameter_names));
/// empty for names of no gait controller's.
#[must_use]
pub fn table_for_names(names: &[&str]) -> &'static [ControllerParam] {
    if names == BipedRunParams::NAMES {
        BIPED_RUN
    } else if names == BipedGallopParams::NAMES {
        BIPED_GALLOP
    } else if names == KangarooHopParams::NAMES {
        KANGAROO_HOP
    } else if names == QuadrupedBoundParams::NAMES {
        QUADRUPED_BOUND
    } else if names == QuadrupedRunParams::NAMES {
        QUADRUPED_RUN
    } else {
        &[]
    }
}

impl GaitController {
    /// Where each of this controller's named parameters comes from, in its
    /// parameters' [`NamedParameters::NAMES`] order.
    #[must_use]
    pub fn parameter_origins(&self) -> &'static [ControllerParam] {
        match self {
            GaitController::BipedRun(_) => BIPED_RUN,
            GaitController::BipedGallop(_) => BIPED_GALLOP,
            GaitController::Quadruped(_) => QUADRUPED_RUN,
            GaitController::QuadrupedBound(_) => QUADRUPED_BOUND,
            GaitController::Kangaroo(_) => KANGAROO_HOP,
        }
    }
}

#[cfg(test)]
mod tests {
    use std::collections::HashSet;

    use gaitlab_core::preset::load_bundled;

    use super::*;
    use crate::control::gaits::controller::gait_names;
    use crate::engine::driver::PhysicsDriver;
    use crate::world::sim::Controller;

    /// Every table with its parameters type's names.
    fn tables() -> [(
        &'static str,
        &'static [ControllerParam],
        &'static [&'static str],
    ); 5] {
        [
            ("BipedRunParams", BIPED_RUN, BipedRunParams::NAMES),
            ("BipedGallopParams", BIPED_GALLOP, BipedGallopParams::NAMES),
            ("KangarooHopParams", KANGAROO_HOP, KangarooHopParams::NAMES),
            (
                "QuadrupedBoundParams",
                QUADRUPED_BOUND,
                QuadrupedBoundParams::NAMES,
            ),
            (
                "QuadrupedRunParams",
                QUADRUPED_RUN,
                QuadrupedRunParams::NAMES,
            ),
        ]
    }

    #[test]
    fn each_table_names_exactly_its_parameters() {
        for (what, table, names) in tables() {
            let rows: Vec<&str> = table.iter().map(|r| r.name).collect();
            let set: HashSet<&str> = rows.iter().copied().collect();
            assert_eq!(set.len(), rows.len(), "{what}: a name twice");
            let want: HashSet<&str> = names.iter().copied().collect();
            let missing: Vec<_> = want.difference(&set).collect();
            let extra: Vec<_> = set.difference(&want).collect();
            assert!(missing.is_empty(), "{what}: no row for {missing:?}");
            assert!(extra.is_empty(), "{what}: rows for no parameter {extra:?}");
            assert_eq!(rows, names, "{what}: rows in the names' order");
            assert_eq!(table_for_names(names), table, "{what}: found by its names");
        }
        assert!(table_for_names(&[]).is_empty());
    }

    #[test]
    fn every_row_has_words_and_a_unit_its_name_agrees_with() {
        // The first suffix a name ends with decides its unit.
        let suffixes = [
            ("_mps2", "m/s²"),
            ("_mps", "m/s"),
            ("_rad", "rad"),
            ("_m", "m"),
            ("_s", "s"),
        ];
        for (what, table, _) in tables() {
            for r in table {
                let name = r.name;
                assert!(!r.label.trim().is_empty(), "{what}.{name}: label");
                assert!(!r.why.trim().is_empty(), "{what}.{name}: why");
                assert!(!r.reference.trim().is_empty(), "{what}.{name}: reference");
                if let Some((_, unit)) = suffixes.iter().find(|(s, _)| name.ends_with(s)) {
                    assert_eq!(r.unit, *unit, "{what}.{name}: unit");
                }
                if r.origin == Origin::Lab {
                    assert!(
                        r.reference.starts_with("docs/"),
                        "{what}.{name}: lab's docs"
                    );
                }
            }
        }
    }

    #[test]
    fn a_bundled_drivers_table_is_its_running_controllers() {
        let mut seen: Vec<&'static [ControllerParam]> = Vec::new();
        for name in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"] {
            let preset = load_bundled(name)
                .expect("bundled")
                .expect("a valid preset");
            let base = preset.scenario.physics.clone().expect("a physics section");
            let driver = PhysicsDriver::new(&preset).expect("driver");
            let species = driver.sim().creature.species;
            for gait in gait_names(species) {
                let mut params = base.clone();
                params.gait = Some((*gait).to_owned());
                let driver = PhysicsDriver::with_params(&preset, params).expect("driver");
                let table = driver.controller_parameters();
                assert!(!table.is_empty(), "{name} {gait}: a table");
                seen.push(table);
                assert_eq!(table.len(), driver.parameter_names().len(), "{name} {gait}");
                for row in table {
                    assert!(
                        driver.parameter(row.name).is_some(),
                        "{name} {gait}: {} answers",
                        row.name
                    );
                }
            }
        }
        for (what, table, _) in tables() {
            assert!(seen.contains(&table), "no bundled gait runs {what}");
        }
    }

    #[test]
    fn each_controller_gives_its_own_table() {
        let params = KangarooHopParams::default();
        let c = GaitController::Kangaroo(Box::new(
            crate::control::gaits::kangaroo_hop::KangarooHop::new(params),
        ));
        assert_eq!(c.parameter_origins(), KANGAROO_HOP);
        assert_eq!(table_for_names(c.parameter_names()), KANGAROO_HOP);
    }
}
