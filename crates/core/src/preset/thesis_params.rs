//! The thesis script's rows of the parameter table (She 2006 §5.1.1's
//! control module — step frequency, slowdown factor, speed, moving forward,
//! wounded — and §5.2.2's listing), with the lab's script, posture pull,
//! start ramp and wound form named as the lab's.

use crate::params::{Domain, Origin, ParamSpec};

/// Lowest thesis `slowdown` (1 = real time).
pub const MIN_SLOWDOWN: f64 = 1.0;
/// Highest thesis `slowdown`.
pub const MAX_SLOWDOWN: f64 = 100.0;
/// Highest forward speed, m/s.
pub const MAX_SPEED_MPS: f64 = 20.0;
/// Most IK iterations per frame a preset may ask for.
pub const MAX_ITERATIONS_PER_FRAME: usize = 100;
/// Longest thesis start ramp, seconds.
pub const MAX_START_RAMP_S: f64 = 10.0;

#[expect(
    clippy::cast_possible_wrap,
    reason = "a small constant count as i64 in a const"
)]
const MAX_ITERATIONS: i64 = MAX_ITERATIONS_PER_FRAME as i64;

/// `scenario.thesis.*`.
pub const THESIS_PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "scenario.thesis.script",
        command: None,
        label: "Target script: the lab's cycle shapes or the thesis' listing",
        unit: "",
        domain: Domain::Choice {
            options: &["lab", "listing"],
        },
        live: false,
        reference: "She 2006 §5.2.2",
        origin: Origin::Lab,
        why: "\"listing\" is §5.2.2's sinusoids (she-2006 runs it); \"lab\", the code's default, is the lab's richer script",
    },
    ParamSpec {
        key: "scenario.thesis.listing",
        command: None,
        label: "The listing's targets (script \"listing\")",
        unit: "m, Hz",
        domain: Domain::Structured {
            shape: "walk and run cycles: frequency_hz, root_height_m, per-effector centre and amplitude",
        },
        live: false,
        reference: "She 2006 §5.2.2",
        origin: Origin::Paper,
        why: "the thesis' printed targets",
    },
    ParamSpec {
        key: "scenario.thesis.walk",
        command: None,
        label: "The lab script's walking cycle",
        unit: "m, Hz",
        domain: Domain::Structured {
            shape: "frequency_hz, front_foot, back_foot, step_height_m, front_hand, back_hand, root_height_m, bounce_m",
        },
        live: false,
        reference: "docs/she-2006.md",
        origin: Origin::Lab,
        why: "the lab's script (script \"lab\")",
    },
    ParamSpec {
        key: "scenario.thesis.run",
        command: None,
        label: "The lab script's running cycle",
        unit: "m, Hz",
        domain: Domain::Structured {
            shape: "frequency_hz, front_foot, back_foot, step_height_m, front_hand, back_hand, root_height_m, bounce_m",
        },
        live: false,
        reference: "docs/she-2006.md",
        origin: Origin::Lab,
        why: "the lab's script (script \"lab\")",
    },
    ParamSpec {
        key: "scenario.thesis.wound_form",
        command: None,
        label: "Where the wounded weights act: the IK step or the angle shown",
        unit: "",
        domain: Domain::Choice {
            options: &["step", "angle"],
        },
        live: false,
        reference: "She 2006 §5.1.1, §5.2.3",
        origin: Origin::Lab,
        why: "\"angle\" is the thesis' (weights applied \"before mapping rotation angles to joints\"); \"step\", the code's default, is the lab's reading",
    },
    ParamSpec {
        key: "scenario.thesis.wounded",
        command: None,
        label: "Joints weighted in the wounded modes",
        unit: "",
        domain: Domain::Structured {
            shape: "list of {joint, multiply in [0, 10], add in [-0.5, 0.5] rad}",
        },
        live: false,
        reference: "She 2006 §5.1.1, §5.2.3",
        origin: Origin::Paper,
        why: "the thesis' wounded effect",
    },
    ParamSpec {
        key: "scenario.thesis.slowdown",
        command: None,
        label: "Slowdown factor (time is divided by it)",
        unit: "",
        domain: Domain::closed(MIN_SLOWDOWN, MAX_SLOWDOWN),
        live: false,
        reference: "She 2006 §5.1.1",
        origin: Origin::Paper,
        why: "the control module's \"Slowdown Factor\"",
    },
    ParamSpec {
        key: "scenario.thesis.moving_forward",
        command: None,
        label: "Moving forward (the root advances, the targets with it)",
        unit: "",
        domain: Domain::Bool,
        live: false,
        reference: "She 2006 §6.2",
        origin: Origin::Paper,
        why: "the thesis' \"Moving Forward\" effect",
    },
    ParamSpec {
        key: "scenario.thesis.speed_mps",
        command: None,
        label: "Forward speed (left out: the stride's)",
        unit: "m/s",
        domain: Domain::closed(0.0, MAX_SPEED_MPS),
        live: false,
        reference: "She 2006 §5.1.1",
        origin: Origin::Paper,
        why: "the control module's \"Speed\"; left out, the speed that keeps a planted foot at rest at mid-stance",
    },
    ParamSpec {
        key: "scenario.thesis.iterations_per_frame",
        command: None,
        label: "IK iterations per frame",
        unit: "",
        domain: Domain::Integer {
            min: 1,
            max: MAX_ITERATIONS,
        },
        live: false,
        reference: "She 2006 §4.4",
        origin: Origin::Open,
        why: "the thesis gives no count; a few iterations per frame is Buss's demos'",
    },
    ParamSpec {
        key: "scenario.thesis.posture_gain",
        command: None,
        label: "Posture pull toward the centre angles, per frame",
        unit: "",
        domain: Domain::closed(0.0, 1.0),
        live: false,
        reference: "docs/she-2006.md",
        origin: Origin::Lab,
        why: "the thesis has no posture term; it keeps redundant joints from drifting for every method (0 turns it off)",
    },
    ParamSpec {
        key: "scenario.thesis.start_ramp_s",
        command: None,
        label: "Start ramp: blend from standing into the cycle",
        unit: "s",
        domain: Domain::closed(0.0, MAX_START_RAMP_S),
        live: false,
        reference: "docs/she-2006.md",
        origin: Origin::Lab,
        why: "the thesis starts the cycle at once; the ramp keeps a knee that starts straight out of its limit (0 turns it off)",
    },
    ParamSpec {
        key: "scenario.thesis.roles",
        command: None,
        label: "Which effector is which foot and hand",
        unit: "",
        domain: Domain::Structured {
            shape: "left_foot, right_foot, left_hand, right_hand: effector names",
        },
        live: false,
        reference: "She 2006 §5.2.2",
        origin: Origin::Paper,
        why: "the thesis' four targets",
    },
];
