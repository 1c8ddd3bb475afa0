//! The paper alone: a preset file with every lab addition of its engine
//! turned off, so it runs as its paper says — She 2006 (§4.4.1's α, the
//! step clamp on pinv only (§4.4.2), joints clamped at their limits
//! (§6.1.1.1), §5.2.2's listing, §5.1.1's weights on the angle shown, no
//! posture pull, no start ramp), Girard & Maciejewski 1985 (Figure 2's body
//! pitch and eq. 2's foot orientation on; no turning within reach, yaw toward the actual, surge or gait by
//! speed) or Raibert & Hodgins 1991 (no named addition; gait changes take
//! over at the next flight). The page's "Run the paper alone" and its
//! `paper_alone` command.

use serde_json::Value;

use super::edit::set_preset_value;
use super::error::PresetError;
use super::schema::FORMAT;

/// The values each engine's additions take when off, by preset path.
const IK_OFF: &[(&str, ValueOf)] = &[
    ("scenario.ik.clamp_every_method", ValueOf::Bool(false)),
    ("scenario.ik.target_clamp_m", ValueOf::Int(0)),
    ("scenario.ik.transpose_alpha", ValueOf::Text("thesis")),
    ("scenario.ik.limit_passes", ValueOf::Int(1)),
    ("scenario.ik.null_space_gain", ValueOf::Int(0)),
    ("scenario.thesis.script", ValueOf::Text("listing")),
    ("scenario.thesis.wound_form", ValueOf::Text("angle")),
    ("scenario.thesis.posture_gain", ValueOf::Int(0)),
    ("scenario.thesis.start_ramp_s", ValueOf::Int(0)),
];
const PODA_OFF: &[(&str, ValueOf)] = &[
    ("scenario.poda.turn_within_reach", ValueOf::Bool(false)),
    ("scenario.poda.yaw_toward_actual", ValueOf::Bool(false)),
    ("scenario.poda.fore_aft_surge", ValueOf::Bool(false)),
    ("scenario.poda.gait_by_speed", ValueOf::Bool(false)),
    ("scenario.poda.body_pitch", ValueOf::Bool(true)),
    ("scenario.poda.foot_orientation", ValueOf::Bool(true)),
    ("scenario.poda.vertical_gain", ValueOf::Int(1)),
];
const PHYSICS_OFF: &[(&str, ValueOf)] = &[
    (
        "scenario.physics.lab_additions.speed_trim",
        ValueOf::Bool(false),
    ),
    (
        "scenario.physics.lab_additions.unloading_posture",
        ValueOf::Bool(false),
    ),
    (
        "scenario.physics.lab_additions.speed_ramp",
        ValueOf::Bool(false),
    ),
    (
        "scenario.physics.lab_additions.tail_feedback",
        ValueOf::Bool(false),
    ),
    (
        "scenario.physics.lab_additions.hop_integrator",
        ValueOf::Bool(false),
    ),
    (
        "scenario.physics.lab_additions.ground_ahead",
        ValueOf::Bool(false),
    ),
    ("scenario.physics.switch_to_start", ValueOf::Empty),
    (
        "scenario.physics.lab_additions_by_gait",
        ValueOf::EmptyObject,
    ),
];

/// A JSON value in a const table.
#[derive(Clone, Copy)]
enum ValueOf {
    Bool(bool),
    Int(i64),
    Text(&'static str),
    Empty,
    EmptyObject,
}

impl ValueOf {
    fn json(self) -> Value {
        match self {
            Self::Bool(b) => Value::from(b),
            Self::Int(i) => Value::from(i),
            Self::Text(t) => Value::from(t),
            Self::Empty => Value::Array(Vec::new()),
            Self::EmptyObject => Value::Object(serde_json::Map::new()),
        }
    }
}

/// Turns every lab addition of `preset` (a parsed preset file) off and marks
/// it `gaitlab-preset/2`, whose left-out keys are the paper's. The IK
/// engine's method becomes SDLS where it was CCD (not one of the thesis'
/// four). Returns the preset paths it set.
///
/// # Errors
/// `scenario.engine: …` when the file names no engine this knows; a path
/// that cannot be set (a non-object where a section belongs) names itself.
pub fn paper_alone(preset: &mut Value) -> Result<Vec<&'static str>, PresetError> {
    let engine = preset
        .pointer("/scenario/engine")
        .and_then(Value::as_str)
        .unwrap_or("ik")
        .to_owned();
    let table = match engine.as_str() {
        "ik" => IK_OFF,
        "poda" => PODA_OFF,
        "physics" => PHYSICS_OFF,
        other => {
            return Err(PresetError::new(
                "scenario.engine",
                format!("unknown engine {other:?} (ik, poda or physics)"),
            ));
        }
    };
    set_preset_value(preset, "format", Value::from(FORMAT))?;
    let mut set = Vec::with_capacity(table.len() + 1);
    for (path, value) in table {
        set_preset_value(preset, path, value.json())?;
        set.push(*path);
    }
    if engine == "ik" && preset.pointer("/scenario/method").and_then(Value::as_str) == Some("ccd") {
        set_preset_value(preset, "scenario.method", Value::from("sdls"))?;
        set.push("scenario.method");
    }
    Ok(set)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::Creature;
    use crate::preset::bundled::bundled;

    #[test]
    fn every_bundled_preset_loads_with_the_paper_alone() {
        for (name, json) in bundled() {
            let mut preset: Value = serde_json::from_str(json).expect("json");
            let set = paper_alone(&mut preset).expect("paper alone");
            assert!(!set.is_empty(), "{name}");
            let creature =
                Creature::from_json(&preset.to_string()).unwrap_or_else(|e| panic!("{name}: {e}"));
            let scenario = &creature.scenario;
            assert!(!scenario.ik.clamp_every_method, "{name}");
            if let Some(poda) = &scenario.poda {
                assert!(poda.body_pitch && !poda.turn_within_reach, "{name}");
            }
            if let Some(physics) = &scenario.physics {
                assert!(physics.switch_to_start.is_empty(), "{name}");
            }
        }
    }

    #[test]
    fn an_unknown_engine_is_named() {
        let mut preset = serde_json::json!({"scenario": {"engine": "warp"}});
        let error = paper_alone(&mut preset).expect_err("refused");
        assert_eq!(error.path, "scenario.engine");
    }
}
