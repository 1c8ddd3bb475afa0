//! Where every named gait-controller parameter comes from (Raibert & Hodgins
//! 1991, eqs. 1–5, Figure 4, Tables 2 and 3, "Kangaroo control"): for each
//! name of [`NamedParameters::NAMES`](crate::control::gaits::parameters::NamedParameters::NAMES) a label, its unit, where the paper
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
//!
//! Each gait's table is its folder's `origins.rs`; here are the row type and
//! the references and rows that several share.

use gaitlab_core::params::Origin;

/// One named parameter of a gait controller, for the engine's parameter table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ControllerParam {
    /// The name a preset's `scenario.physics.controller` map sets
    /// (an entry of [`NamedParameters::NAMES`](crate::control::gaits::parameters::NamedParameters::NAMES)).
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
pub(crate) const fn row(
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

/// `placement_gain_s`, eq. 3's gain, with the gait's own reason `why`.
pub(crate) const fn placement_gain_s_row(why: &'static str) -> ControllerParam {
    row(
        "placement_gain_s",
        "Foot placement gain k_ẋ (eq. 3)",
        "s",
        EQ3,
        Origin::Open,
        why,
    )
}

/// `yaw_kp`, the lab's yaw servo in stance, with the gait's own reason `why`.
pub(crate) const fn yaw_kp_row(why: &'static str) -> ControllerParam {
    row(
        "yaw_kp",
        "Trunk yaw stiffness in stance",
        TORSION,
        LAB,
        Origin::Lab,
        why,
    )
}

/// `flight_gain`, the lab's flight-time integrator, with the gait's own
/// reason `why`.
pub(crate) const fn flight_gain_row(why: &'static str) -> ControllerParam {
    row(
        "flight_gain",
        "Flight-time integrator (thrust change per s of error)",
        "m/s",
        LAB,
        Origin::Lab,
        why,
    )
}

/// `pitch_kp`, eq. 4's pitch stiffness, with the gait's own reason `why`.
pub(crate) const fn pitch_kp_row(why: &'static str) -> ControllerParam {
    row(
        "pitch_kp",
        "Pitch stiffness k_p (eq. 4)",
        TORSION,
        EQ4,
        Origin::Open,
        why,
    )
}

/// `posture_force_ratio`, the lab's cap on eq. 4's foot force, with the
/// gait's own reason `why`.
pub(crate) const fn posture_force_ratio_row(why: &'static str) -> ControllerParam {
    row(
        "posture_force_ratio",
        "Largest posture foot force, as a fraction of the spring's",
        "",
        LAB,
        Origin::Lab,
        why,
    )
}

/// `a` then `b` as one array of `N = A + B` rows.
pub(crate) const fn concat<const A: usize, const B: usize, const N: usize>(
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

pub(crate) const EQ1: &str = "Raibert & Hodgins 1991 eq. 1";
pub(crate) const EQ2_THRUST: &str = "Raibert & Hodgins 1991 eq. 2; Figure 4 (Thrust)";
pub(crate) const EQ3: &str = "Raibert & Hodgins 1991 eq. 3";
pub(crate) const EQ4: &str = "Raibert & Hodgins 1991 eq. 4";
pub(crate) const EQ5_SWING: &str = "Raibert & Hodgins 1991 eq. 5; Figure 4 (Flight)";
pub(crate) const EQ5: &str = "Raibert & Hodgins 1991 eq. 5 (Modeling)";
pub(crate) const FIG4_FLIGHT: &str = "Raibert & Hodgins 1991 Figure 4 (Flight)";
pub(crate) const TABLE3: &str = "Raibert & Hodgins 1991 Table 3";
pub(crate) const ACTUATORS: &str = "Raibert & Hodgins 1991, Discussion (actuator torque)";
pub(crate) const KANGAROO: &str = "Raibert & Hodgins 1991, Kangaroo control";
pub(crate) const JUMP: &str = "Raibert & Hodgins 1991, Results (the jump's states)";
pub(crate) const GALLOP: &str = "Raibert & Hodgins 1991, Gaits (galloping)";
pub(crate) const STANDING: &str = "Raibert & Hodgins 1991, Results (standing length reduced)";
pub(crate) const LAB: &str = "docs/physics.md";
pub(crate) const LAB_TRIM: &str = "docs/physics.md, The lab's additions (speed_trim)";
pub(crate) const LAB_RAMP: &str = "docs/physics.md, The lab's additions (speed_ramp)";
pub(crate) const LAB_TAIL: &str = "docs/physics.md, The lab's additions (tail_feedback)";

pub(crate) const TORSION: &str = "N·m/rad";
pub(crate) const TORSION_DAMPING: &str = "N·m·s/rad";

// Rows that two or three controllers share word for word.

/// `leg_travel_m`, the same in every controller that has it.
pub(crate) const LEG_TRAVEL_M: ControllerParam = row(
    "leg_travel_m",
    "Telescoping leg's travel",
    "m",
    TABLE3,
    Origin::Open,
    "The leg's stop: Table 3 gives the links' lengths, not how far the leg telescopes",
);

/// `speed_integral_gain`, the same in every controller that has it.
pub(crate) const SPEED_INTEGRAL_GAIN: ControllerParam = row(
    "speed_integral_gain",
    "Speed trim integral gain",
    "",
    LAB_TRIM,
    Origin::Lab,
    "Gain of the lab's integral speed trim (lab_additions.speed_trim); eq. 3 has no integral",
);

/// `max_hip_torque`, the same in every controller that has it.
pub(crate) const MAX_HIP_TORQUE: ControllerParam = row(
    "max_hip_torque",
    "Largest hip torque",
    "N·m",
    ACTUATORS,
    Origin::Open,
    "The paper names the actuators' available torque as shaping the motion, gives none",
);

/// `leg_stiffness`, the same in every controller that has it.
pub(crate) const LEG_STIFFNESS: ControllerParam = row(
    "leg_stiffness",
    "Leg spring stiffness k (eq. 1)",
    "N/m",
    EQ1,
    Origin::Open,
    "eq. 1's k per leg; the paper prints no value",
);

/// `leg_damping`, the same in every controller that has it.
pub(crate) const LEG_DAMPING: ControllerParam = row(
    "leg_damping",
    "Leg spring damping b in stance (eq. 1)",
    "N·s/m",
    EQ1,
    Origin::Open,
    "eq. 1's b; the paper prints no value",
);

/// `thrust_m`, the same in every controller that has it.
pub(crate) const THRUST_M: ControllerParam = row(
    "thrust_m",
    "Initial thrust: extra rest length in Thrust (eq. 2)",
    "m",
    EQ2_THRUST,
    Origin::Open,
    "Figure 4's leg extension injects eq. 2's energy; no length printed",
);

/// `max_thrust_m`, the same in every controller that has it.
pub(crate) const MAX_THRUST_M: ControllerParam = row(
    "max_thrust_m",
    "Largest thrust",
    "m",
    LAB,
    Origin::Lab,
    "Bound of the lab's flight-regulated thrust",
);

/// `placement_gain_s`, the same in every controller that has it.
pub(crate) const PLACEMENT_GAIN_S: ControllerParam = row(
    "placement_gain_s",
    "Foot placement gain k_ẋ (eq. 3)",
    "s",
    EQ3,
    Origin::Open,
    "eq. 3's gain; the paper prints none",
);

/// `pitch_kv`, the same in every controller that has it.
pub(crate) const PITCH_KV: ControllerParam = row(
    "pitch_kv",
    "Pitch damping k_v (eq. 4)",
    TORSION_DAMPING,
    EQ4,
    Origin::Open,
    "eq. 4's k_v; the paper prints no value",
);

/// `roll_kp`, the same in every controller that has it.
pub(crate) const ROLL_KP: ControllerParam = row(
    "roll_kp",
    "Roll stiffness (eq. 4)",
    TORSION,
    EQ4,
    Origin::Open,
    "eq. 4 on roll; the paper prints no value",
);

/// `roll_kv`, the same in every controller that has it.
pub(crate) const ROLL_KV: ControllerParam = row(
    "roll_kv",
    "Roll damping (eq. 4)",
    TORSION_DAMPING,
    EQ4,
    Origin::Open,
    "eq. 4 on roll; the paper prints no value",
);

/// `yaw_kv`, the same in every controller that has it.
pub(crate) const YAW_KV: ControllerParam = row(
    "yaw_kv",
    "Trunk yaw damping in stance",
    TORSION_DAMPING,
    LAB,
    Origin::Lab,
    "Damping of the lab's yaw servo",
);

/// `swing_kp`, the same in every controller that has it.
pub(crate) const SWING_KP: ControllerParam = row(
    "swing_kp",
    "Swing hip stiffness (eq. 5)",
    TORSION,
    EQ5_SWING,
    Origin::Open,
    "eq. 5's position gain positioning the legs for landing; the paper prints none",
);

/// `swing_kv`, the same in every controller that has it.
pub(crate) const SWING_KV: ControllerParam = row(
    "swing_kv",
    "Swing hip damping (eq. 5)",
    TORSION_DAMPING,
    EQ5_SWING,
    Origin::Open,
    "eq. 5's velocity gain positioning the legs for landing; the paper prints none",
);

/// `swing_roll_follow`, the same in every controller that has it.
pub(crate) const SWING_ROLL_FOLLOW: ControllerParam = row(
    "swing_roll_follow",
    "Share of trunk roll in eq. 3's leg aim",
    "",
    EQ3,
    Origin::Open,
    "The paper does not say which attitude eq. 3's kinematic transformation uses",
);
