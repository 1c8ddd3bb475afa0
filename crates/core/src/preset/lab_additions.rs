//! The lab's additions in force for a She 2006 (IK) or a Girard & Maciejewski
//! 1985 (PODA) run: each a name for `lab_additions` (the CLI's `--json`, the
//! page's `state()`) and a one-line reason. Everything not listed runs as the
//! paper says; values a paper leaves open (λ, the clamp's 0.2 rad) are not
//! additions. The physics engine lists its own (`control/additions.rs`).

use super::listing::{TargetScript, WoundForm};
use super::poda::PodaParams;
use super::thesis::{ThesisMode, ThesisParams};
use crate::ik::{IkOptions, Method, TransposeAlpha};
use crate::terrain::Terrain;

/// One lab addition: its name and why it is there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LabAddition {
    /// The name listed in `lab_additions`.
    pub name: &'static str,
    /// What it is and where the thesis differs, in one line.
    pub reason: &'static str,
}

const CLAMP_EVERY_METHOD: LabAddition = LabAddition {
    name: "clamp_every_method",
    reason: "max_step also clamps transpose and DLS; §4.4.2 clamps pinv only (Buss's code clamps every method)",
};
const TARGET_CLAMP: LabAddition = LabAddition {
    name: "target_clamp",
    reason: "each effector's error is clamped to target_clamp_m before the solve (Buss's code; the thesis clamps no target)",
};
const BUSS_ALPHA: LabAddition = LabAddition {
    name: "buss_alpha",
    reason: "transpose's α is Buss's ⟨e, JJᵀe⟩/‖JJᵀe‖², twice §4.4.1's Δs·Δt/(2|Δt|²)",
};
const NULL_SPACE_PULL: LabAddition = LabAddition {
    name: "null_space_pull",
    reason: "PODA eq. 6's pull toward the centre angles in J's null space; the thesis has none",
};
const CCD: LabAddition = LabAddition {
    name: "ccd",
    reason: "cyclic coordinate descent (Wang & Chen 1991), the lab's non-Jacobian contrast; not one of the thesis' four methods",
};
const LIMIT_RE_SOLVE: LabAddition = LabAddition {
    name: "limit_re_solve",
    reason: "a joint past its limit is clamped and the rest solved again; §6.1.1.1 only clamps",
};
const LAB_SCRIPT: LabAddition = LabAddition {
    name: "lab_script",
    reason: "gaitlab's target script (foot strokes with a lift, hands in front, a bouncing root), not §5.2.2's listing",
};
const POSTURE_PULL: LabAddition = LabAddition {
    name: "posture_pull",
    reason: "each frame every joint relaxes toward its centre angle before the IK iterations",
};
const START_RAMP: LabAddition = LabAddition {
    name: "start_ramp",
    reason: "the targets blend in from standing after a reset; the thesis' start at once",
};
const STEP_WOUNDS: LabAddition = LabAddition {
    name: "step_wounds",
    reason: "wounded weights scale the IK step; §5.1.1 applies them to the angle shown",
};

const TURN_WITHIN_REACH: LabAddition = LabAddition {
    name: "turn_within_reach",
    reason: "the body follows its path only as tightly as the legs reach (the lab's reading of \"Horizontal Control\")",
};
const YAW_TOWARD_ACTUAL: LabAddition = LabAddition {
    name: "yaw_toward_actual",
    reason: "each leg turns the body from its actual yaw, so a yaw error is corrected (a reading of \"Rotational Control\")",
};
const FORE_AFT_SURGE: LabAddition = LabAddition {
    name: "fore_aft_surge",
    reason: "the fore-aft surge of \"Horizontal Control\" with a magnitude the lab derived (each leg pushes along itself)",
};
const TERRAIN_FEET: LabAddition = LabAddition {
    name: "terrain_feet",
    reason: "on ground that is not flat: footholds moved off uneven spots, transfers that clear the ground, the body following the ground under its legs (the paper's creatures walk on a floor)",
};
const GAIT_BY_SPEED: LabAddition = LabAddition {
    name: "gait_by_speed",
    reason: "the gait and stride picked from the speed by Alexander's Froude rule, not by the user",
};
const WITHOUT_BODY_PITCH: LabAddition = LabAddition {
    name: "without_body_pitch",
    reason: "Figure 2's body pitch from the front and rear legs' vertical motion is left out",
};

const WITHOUT_FOOT_ORIENTATION: LabAddition = LabAddition {
    name: "without_foot_orientation",
    reason: "eq. 2's foot orientation is left out: every foot holds its position alone",
};

/// Every PODA addition in force with `params` on `terrain` (the feet's
/// rules for ground that is not flat), and Figure 2's body pitch and eq. 2's
/// foot orientation where they are left out.
#[must_use]
pub fn poda_lab_additions(params: &PodaParams, terrain: &Terrain) -> Vec<LabAddition> {
    [
        (!terrain.is_flat()).then_some(TERRAIN_FEET),
        params.turn_within_reach.then_some(TURN_WITHIN_REACH),
        params.yaw_toward_actual.then_some(YAW_TOWARD_ACTUAL),
        params.fore_aft_surge.then_some(FORE_AFT_SURGE),
        params.gait_by_speed.then_some(GAIT_BY_SPEED),
        (!params.body_pitch).then_some(WITHOUT_BODY_PITCH),
        (!params.foot_orientation).then_some(WITHOUT_FOOT_ORIENTATION),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The additions to the solver that act with `ik` (its method included).
pub fn ik_lab_additions(ik: &IkOptions) -> impl Iterator<Item = LabAddition> + use<> {
    let method = ik.method;
    [
        (ik.clamp_every_method && matches!(method, Method::Transpose | Method::Dls))
            .then_some(CLAMP_EVERY_METHOD),
        (ik.target_clamp_m > 0.0 && method != Method::Ccd).then_some(TARGET_CLAMP),
        (ik.transpose_alpha == TransposeAlpha::Buss && method == Method::Transpose)
            .then_some(BUSS_ALPHA),
        (ik.null_space_gain > 0.0 && matches!(method, Method::Pinv | Method::Dls))
            .then_some(NULL_SPACE_PULL),
        (ik.enforce_limits && ik.limit_passes > 1).then_some(LIMIT_RE_SOLVE),
        (method == Method::Ccd).then_some(CCD),
    ]
    .into_iter()
    .flatten()
}

/// Every addition in force for the thesis' motion `mode` with `params` and `ik`.
#[must_use]
pub fn thesis_lab_additions(
    params: &ThesisParams,
    ik: &IkOptions,
    mode: ThesisMode,
) -> Vec<LabAddition> {
    let mut out: Vec<LabAddition> = ik_lab_additions(ik).collect();
    out.extend(
        [
            (params.script == TargetScript::Lab).then_some(LAB_SCRIPT),
            (params.posture_gain > 0.0).then_some(POSTURE_PULL),
            (params.start_ramp_s > 0.0).then_some(START_RAMP),
            (params.wound_form == WoundForm::Step && mode.wounded() && !params.wounded.is_empty())
                .then_some(STEP_WOUNDS),
        ]
        .into_iter()
        .flatten(),
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::bundled::load_bundled;

    fn names(list: &[LabAddition]) -> Vec<&'static str> {
        list.iter().map(|a| a.name).collect()
    }

    /// Issue 41 item 2: a bundled IK preset keeps an addition only where
    /// the thesis alone fails one of its claims (docs/parameters.md "Both
    /// ways"): the human and she-2006 none, ik-quadruped the lab's script
    /// (the listing's feet are out of reach of its legs).
    #[test]
    fn the_bundled_ik_presets_keep_only_what_a_claim_needs() {
        for (name, kept) in [
            ("she-2006", &[][..]),
            ("human", &[][..]),
            ("ik-quadruped", &["lab_script"][..]),
        ] {
            let Some(Ok(creature)) = load_bundled(name) else {
                panic!("{name}")
            };
            let scenario = &creature.scenario;
            for method in Method::ALL.into_iter().filter(|m| *m != Method::Ccd) {
                for mode in ThesisMode::ALL {
                    let ik = IkOptions {
                        method,
                        ..scenario.ik.clone()
                    };
                    let found = thesis_lab_additions(&scenario.thesis, &ik, mode);
                    assert_eq!(names(&found), kept, "{name} {method:?} {mode:?}");
                }
            }
        }
    }

    #[test]
    fn the_bundled_poda_presets_name_what_they_add() {
        for name in ["hexapod", "poda-quadruped", "poda-biped", "insect-14"] {
            let Some(Ok(creature)) = load_bundled(name) else {
                panic!("{name}")
            };
            let found =
                poda_lab_additions(&creature.scenario.poda_params(), &creature.scenario.terrain);
            assert_eq!(
                names(&found),
                ["turn_within_reach", "yaw_toward_actual", "fore_aft_surge"],
                "{name}"
            );
        }
        assert!(poda_lab_additions(&PodaParams::default(), &Terrain::Flat).is_empty());
        let stairs: Terrain =
            serde_json::from_str(r#"{"kind": "stairs", "rise_m": 0.05, "run_m": 0.3, "count": 4}"#)
                .expect("stairs");
        assert_eq!(
            names(&poda_lab_additions(&PodaParams::default(), &stairs)),
            ["terrain_feet"]
        );
        let level = PodaParams {
            body_pitch: false,
            foot_orientation: false,
            ..PodaParams::default()
        };
        assert_eq!(
            names(&poda_lab_additions(&level, &Terrain::Flat)),
            ["without_body_pitch", "without_foot_orientation"]
        );
    }

    #[test]
    fn the_code_defaults_are_the_thesis_and_each_lab_choice_is_named() {
        let wounded = vec![crate::preset::thesis::WoundedJoint {
            joint: "a".to_owned(),
            multiply: 0.5,
            add: 0.0,
        }];
        // The code's defaults: the thesis as printed, nothing of the lab's.
        for method in Method::ALL {
            let ik = IkOptions {
                method,
                ..IkOptions::default()
            };
            let params = ThesisParams {
                wounded: wounded.clone(),
                ..ThesisParams::default()
            };
            let found = thesis_lab_additions(&params, &ik, ThesisMode::WoundedWalk);
            let expected: &[&str] = if method == Method::Ccd { &["ccd"] } else { &[] };
            assert_eq!(names(&found), expected, "{method:?}");
        }
        // What a gaitlab-preset/1 file without the keys runs: every choice named.
        let ik = IkOptions {
            method: Method::Transpose,
            clamp_every_method: true,
            transpose_alpha: TransposeAlpha::Buss,
            limit_passes: crate::preset::versions::V1_LIMIT_PASSES,
            ..IkOptions::default()
        };
        let params = ThesisParams {
            wounded,
            ..ThesisParams::lab()
        };
        let found = thesis_lab_additions(&params, &ik, ThesisMode::WoundedWalk);
        assert_eq!(
            names(&found),
            [
                "clamp_every_method",
                "buss_alpha",
                "limit_re_solve",
                "lab_script",
                "posture_pull",
                "start_ramp",
                "step_wounds"
            ]
        );
        // SDLS has its own γmax and no α: neither solver addition acts.
        let sdls = IkOptions {
            method: Method::Sdls,
            ..ik
        };
        assert!(ik_lab_additions(&sdls).all(|a| a.name == "limit_re_solve"));
    }
}
