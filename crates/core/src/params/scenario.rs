//! The parameter table's rows every engine shares: the scenario's mode,
//! method and frame rate (She 2006 §5's four motions, §4.4's methods).

use super::spec::{Domain, Origin, ParamSpec};
use crate::preset::MAX_FPS;

/// `scenario.mode`, `scenario.method`, `scenario.fps`.
pub const SCENARIO_PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "scenario.mode",
        command: Some("mode"),
        label: "Motion: walk, run, wounded walk or wounded run",
        unit: "",
        domain: Domain::Choice {
            options: &["walk", "run", "wounded_walk", "wounded_run"],
        },
        live: true,
        reference: "She 2006 §5.1, §5.2",
        origin: Origin::Paper,
        why: "the thesis' four motions",
    },
    ParamSpec {
        key: "scenario.method",
        command: Some("method"),
        label: "IK method",
        unit: "",
        domain: Domain::Choice {
            options: &["transpose", "pinv", "dls", "sdls", "ccd"],
        },
        live: true,
        reference: "She 2006 §4.4; CCD: Wang & Chen 1991",
        origin: Origin::Paper,
        why: "the thesis compares transpose, pinv, DLS and SDLS; CCD is the lab's non-Jacobian contrast",
    },
    ParamSpec {
        key: "scenario.fps",
        command: None,
        label: "Frames per second of the motion (one IK or gait step per frame)",
        unit: "1/s",
        domain: Domain::Integer {
            min: 1,
            max: MAX_FPS as i64, // u32 → i64: lossless
        },
        live: false,
        reference: "README, Presets",
        origin: Origin::Open,
        why: "the papers name no frame rate; 60 is the page's display rate",
    },
    ParamSpec {
        key: "heading_deg",
        command: Some("heading_deg"),
        label: "Walking direction",
        unit: "deg",
        domain: Domain::closed(-180.0, 180.0),
        live: true,
        reference: "README, The page",
        origin: Origin::Open,
        why: "the papers walk ahead; the page turns the start (physics: the creature turns toward it)",
    },
];
