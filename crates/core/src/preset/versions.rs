//! What a preset of an older format meant by leaving a key out (DESIGN.md
//! "Versions"): after parsing, a `gaitlab-preset/1` file gets, for each key
//! that version did not have, the behaviour such files ran with, so that it
//! replays as it was made. A key the file does give is kept as given.
//!
//! | key (new in `/2`) | left out in `/1` | left out in `/2` |
//! | --- | --- | --- |
//! | `scenario.ik.clamp_every_method` | true: the step clamp on transpose and DLS too | false: pinv only (She 2006 §4.4.2) |
//! | `scenario.ik.transpose_alpha` | `buss` | `thesis` (§4.4.1) |
//! | `scenario.ik.lambda` | 0.05 m | 0.2 m (the measured choice, docs/she-2006.md) |
//! | `scenario.poda.foot_orientation` | false: positions alone | true: eq. 2's orientation where a leg has six joints |
//! | `scenario.physics.controller_by_gait.trot.unison_liftoff` (quadruped; or in `controller`) | 0: each leg of a pair unloads on its own | 1: the pair leaves the ground as one virtual leg ("Gaits") |
//!
//! and, for a key that both versions have, a `/2` file takes the paper's
//! behaviour where a `/1` file took the lab's:
//!
//! | key | left out in `/1` | left out in `/2` |
//! | --- | --- | --- |
//! | `scenario.ik.limit_passes` | 4: re-solve without clamped joints | 1: clamp (She 2006 §6.1.1.1) |
//! | `scenario.thesis.script` | `lab` | `listing` (§5.2.2) |
//! | `scenario.thesis.wound_form` | `step` | `angle` (§5.1.1) |
//! | `scenario.thesis.posture_gain` | 0.1 | 0: no posture pull |
//! | `scenario.thesis.start_ramp_s` | 1 s | 0: the cycle at once |
//! | `scenario.poda.body_pitch` | false: level | true: Figure 2's pitch |
//! | `scenario.physics.lab_additions` | every addition the gait offers on, with the controllers' earlier defaults | none: the paper's laws |
//! | `scenario.physics.lab_additions.<name>` | the gait's own default (the speed trim on for the gallops and the bound, the kangaroo's ramp and tail feedback) | off |

use serde::Deserialize;
use serde::de::IgnoredAny;

use super::physics::PhysicsModel;
use super::schema::{Format, Preset};
use super::thesis::V1_THESIS;
use crate::ik::TransposeAlpha;

/// Which of the keys new in `gaitlab-preset/2` a file gives. Unknown keys are
/// ignored here: the full parse has already checked the file.
#[derive(Default, Deserialize)]
struct Given {
    #[serde(default)]
    scenario: GivenScenario,
}

#[derive(Default, Deserialize)]
struct GivenScenario {
    #[serde(default)]
    ik: GivenIk,
    #[serde(default)]
    thesis: GivenThesis,
    #[serde(default)]
    poda: Option<GivenPoda>,
}

#[derive(Default, Deserialize)]
struct GivenPoda {
    body_pitch: Option<IgnoredAny>,
    foot_orientation: Option<IgnoredAny>,
}

#[derive(Default, Deserialize)]
struct GivenThesis {
    script: Option<IgnoredAny>,
    wound_form: Option<IgnoredAny>,
    posture_gain: Option<IgnoredAny>,
    start_ramp_s: Option<IgnoredAny>,
}

#[derive(Default, Deserialize)]
struct GivenIk {
    clamp_every_method: Option<IgnoredAny>,
    transpose_alpha: Option<IgnoredAny>,
    lambda: Option<IgnoredAny>,
    limit_passes: Option<IgnoredAny>,
}

/// The DLS damping every `gaitlab-preset/1` file without `lambda` ran with, metres.
pub const V1_LAMBDA_M: f64 = 0.05;
/// The limit passes every `gaitlab-preset/1` file without `limit_passes` ran with.
pub const V1_LIMIT_PASSES: usize = 4;
/// The trot's lift-off every `gaitlab-preset/1` quadruped file without
/// the key ran with: each leg of a pair unloading on its own (0).
pub const V1_TROT_LIFTOFF: (&str, f64) = ("unison_liftoff", 0.0);

/// Writes into `preset`, parsed from `json`, what its format meant by each key
/// it leaves out. A `gaitlab-preset/2` file is left as parsed.
pub(super) fn write_in_old_defaults(preset: &mut Preset, json: &str) {
    if preset.format != Format::V1 {
        paper_by_default(preset);
        return;
    }
    // The full parse of the same text succeeded, so this one does too; a
    // failure would leave the current defaults, never an error.
    let given: Given = serde_json::from_str(json).unwrap_or_default();
    let ik = &mut preset.scenario.ik;
    if given.scenario.ik.clamp_every_method.is_none() {
        ik.clamp_every_method = true;
    }
    if given.scenario.ik.transpose_alpha.is_none() {
        ik.transpose_alpha = TransposeAlpha::Buss;
    }
    if given.scenario.ik.lambda.is_none() {
        ik.lambda = V1_LAMBDA_M;
    }
    if given.scenario.ik.limit_passes.is_none() {
        ik.limit_passes = V1_LIMIT_PASSES;
    }
    let (script, wound_form, posture_gain, start_ramp_s) = V1_THESIS;
    let (thesis, keys) = (&mut preset.scenario.thesis, &given.scenario.thesis);
    if keys.script.is_none() {
        thesis.script = script;
    }
    if keys.wound_form.is_none() {
        thesis.wound_form = wound_form;
    }
    if keys.posture_gain.is_none() {
        thesis.posture_gain = posture_gain;
    }
    if keys.start_ramp_s.is_none() {
        thesis.start_ramp_s = start_ramp_s;
    }
    if let Some(physics) = preset.scenario.physics.as_mut()
        && physics.model == PhysicsModel::Quadruped
    {
        let given = physics.controller.contains_key(V1_TROT_LIFTOFF.0)
            || physics
                .controller_by_gait
                .get("trot")
                .is_some_and(|own| own.contains_key(V1_TROT_LIFTOFF.0));
        if !given {
            physics
                .controller_by_gait
                .entry("trot".to_owned())
                .or_default()
                .insert(V1_TROT_LIFTOFF.0.to_owned(), V1_TROT_LIFTOFF.1);
        }
    }
    if let Some(poda) = preset.scenario.poda.as_mut() {
        let keys = given.scenario.poda.unwrap_or_default();
        if keys.body_pitch.is_none() {
            poda.body_pitch = false;
        }
        if keys.foot_orientation.is_none() {
            poda.foot_orientation = false;
        }
    }
}

/// A `gaitlab-preset/2` file: every lab addition to the physics control
/// that the file does not name is off.
fn paper_by_default(preset: &mut Preset) {
    if let Some(physics) = preset.scenario.physics.as_mut() {
        let additions = physics.lab_additions.get_or_insert_with(Default::default);
        for named in [
            &mut additions.speed_trim,
            &mut additions.unloading_posture,
            &mut additions.speed_ramp,
            &mut additions.tail_feedback,
            &mut additions.hop_integrator,
            &mut additions.ground_ahead,
        ] {
            named.get_or_insert(false);
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::ik::TransposeAlpha;
    use crate::preset::schema::Preset;
    use crate::preset::validate::Purpose;

    fn preset(format: &str, ik: &str) -> Preset {
        let json = format!(
            r#"{{"format": "{format}", "name": "t",
                "skeleton": {{"root": {{"position": [0, 1, 0]}},
                  "joints": [{{"name": "a", "axis": [1, 0, 0], "offset": [0, 0, 0]}}],
                  "effectors": [{{"name": "e", "joint": "a", "offset": [0, -1, 0]}}]}},
                "scenario": {{"engine": "ik", "ik": {ik}}}}}"#
        );
        match Preset::from_json_for(&json, Purpose::Tracking) {
            Ok(preset) => preset,
            Err(error) => panic!("{error}"),
        }
    }

    #[test]
    fn a_version_1_file_runs_as_it_was_made() {
        let ik = preset("gaitlab-preset/1", "{}").scenario.ik;
        assert!(ik.clamp_every_method);
        assert_eq!(ik.transpose_alpha, TransposeAlpha::Buss);
        assert_eq!(ik.lambda, crate::preset::versions::V1_LAMBDA_M);
        assert_eq!(ik.limit_passes, crate::preset::versions::V1_LIMIT_PASSES);
        let thesis = preset("gaitlab-preset/1", "{}").scenario.thesis;
        assert_eq!(thesis, crate::preset::thesis::ThesisParams::lab());
    }

    #[test]
    fn a_version_2_file_runs_the_thesis() {
        let ik = preset("gaitlab-preset/2", "{}").scenario.ik;
        assert!(!ik.clamp_every_method);
        assert_eq!(ik.transpose_alpha, TransposeAlpha::Thesis);
        assert_eq!(ik.lambda, crate::ik::IkOptions::default().lambda);
        assert_eq!(ik.limit_passes, 1);
        let thesis = preset("gaitlab-preset/2", "{}").scenario.thesis;
        assert_eq!(thesis, crate::preset::thesis::ThesisParams::default());
        assert_eq!(thesis.script, crate::preset::thesis::TargetScript::Listing);
    }

    #[test]
    fn a_version_1_poda_file_runs_level_and_a_version_2_file_pitches() {
        let json = include_str!("../../../../presets/hexapod.json");
        let read = |json: &str| match Preset::from_json_for(json, Purpose::Tracking) {
            Ok(preset) => preset.scenario.poda.unwrap_or_default(),
            Err(error) => panic!("{error}"),
        };
        let now = read(json);
        assert!(now.body_pitch && now.foot_orientation);
        let old = json.replacen("gaitlab-preset/2", "gaitlab-preset/1", 1);
        let old = read(&old);
        assert!(!old.body_pitch && !old.foot_orientation);
        // A /1 file that names them keeps what it names.
        let named = json.replacen(
            "\"format\": \"gaitlab-preset/2\",",
            "\"format\": \"gaitlab-preset/1\",",
            1,
        );
        let named = named.replacen(
            "\"turn_within_reach\"",
            "\"body_pitch\": true, \"foot_orientation\": true, \"turn_within_reach\"",
            1,
        );
        assert!(named.contains("gaitlab-preset/1") && named.contains("\"body_pitch\": true"));
        let named = read(&named);
        assert!(named.body_pitch && named.foot_orientation);
    }

    #[test]
    fn a_version_1_quadruped_without_the_key_trots_leg_by_leg() {
        let json = include_str!("../../../../presets/raibert-quadruped.json");
        let unison = |json: &str| match Preset::from_json_for(json, Purpose::Scenario) {
            Ok(preset) => preset.scenario.physics.and_then(|p| {
                p.controller_by_gait
                    .get("trot")
                    .and_then(|own| own.get("unison_liftoff").copied())
            }),
            Err(error) => panic!("{error}"),
        };
        // The bundled file names it: the pair leaves the ground as one.
        assert_eq!(unison(json), Some(1.0));
        // Left out of a /1 file: each leg on its own, as such files ran.
        let mut value: serde_json::Value = serde_json::from_str(json).expect("JSON");
        let trot = &mut value["scenario"]["physics"]["controller_by_gait"]["trot"];
        assert!(
            trot.as_object_mut()
                .is_some_and(|t| t.remove("unison_liftoff").is_some())
        );
        assert_eq!(
            unison(&value.to_string()),
            Some(crate::preset::versions::V1_TROT_LIFTOFF.1)
        );
        // A /2 file without it trots as the paper says.
        value["format"] = "gaitlab-preset/2".into();
        assert_eq!(unison(&value.to_string()), None);
    }

    #[test]
    fn a_key_a_version_1_file_gives_is_kept() {
        let ik = preset(
            "gaitlab-preset/1",
            r#"{"clamp_every_method": false, "transpose_alpha": "thesis", "lambda": 0.3}"#,
        )
        .scenario
        .ik;
        assert!(!ik.clamp_every_method);
        assert_eq!(ik.transpose_alpha, TransposeAlpha::Thesis);
        assert_eq!(ik.lambda, 0.3);
    }
}
