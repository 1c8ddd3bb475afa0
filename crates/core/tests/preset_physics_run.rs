//! `scenario.physics`'s run settings — the control rate, the ground's springs
//! and the controller's parameters by name: absent they change nothing (the
//! bundled presets read and write as before), and each value is range-checked
//! with its JSON path.

use gaitlab_core::Creature;
use gaitlab_core::preset::bundled_json;
use serde_json::{Value, json};

fn biped_with(field: &str, value: Value) -> Result<Creature, String> {
    let text = bundled_json("raibert-biped").expect("bundled");
    let mut preset: Value = serde_json::from_str(text).expect("JSON");
    preset["scenario"]["physics"][field] = value;
    Creature::from_json(&preset.to_string()).map_err(|e| e.to_string())
}

#[test]
fn absent_settings_keep_today_s_values() {
    let text = bundled_json("raibert-biped").expect("bundled");
    let mut preset: Value = serde_json::from_str(text).expect("JSON");
    let section = preset["scenario"]["physics"]
        .as_object_mut()
        .expect("a physics section");
    // The bundled biped sets two of them (2 ms control, its yaw damping).
    assert!(section.remove("control_every").is_some());
    assert!(section.remove("controller").is_some());
    let creature = Creature::from_json(&preset.to_string()).expect("valid");
    let physics = creature.scenario.physics.expect("a physics section");
    assert_eq!(physics.control_every, 1);
    assert_eq!(physics.ground, None);
    assert!(physics.controller.is_empty());
    let written = serde_json::to_value(&physics).expect("serializes");
    for key in ["control_every", "ground", "controller"] {
        assert!(written.get(key).is_none(), "{key} written though unset");
    }
}

#[test]
fn good_settings_are_read() {
    let creature = biped_with("control_every", json!(4)).expect("valid");
    assert_eq!(creature.scenario.physics.expect("physics").control_every, 4);
    let ground = json!({"vertical_stiffness": 80000, "tangential_damping": 0});
    let creature = biped_with("ground", ground).expect("valid");
    let spec = creature
        .scenario
        .physics
        .expect("physics")
        .ground
        .expect("ground");
    assert_eq!(spec.vertical_stiffness, Some(80000.0));
    assert_eq!(spec.vertical_damping, None);
    let creature = biped_with("controller", json!({"thrust_m": 0.05})).expect("valid");
    let physics = creature.scenario.physics.expect("physics");
    assert_eq!(physics.controller.get("thrust_m"), Some(&0.05));
}

#[test]
fn bad_settings_name_their_path() {
    for (field, value, expected) in [
        (
            "control_every",
            json!(0),
            "scenario.physics.control_every: must be",
        ),
        (
            "control_every",
            json!(101),
            "scenario.physics.control_every: must be",
        ),
        (
            "ground",
            json!({"vertical_stiffness": 0}),
            "scenario.physics.ground.vertical_stiffness: must be more than 0",
        ),
        (
            "ground",
            json!({"tangential_damping": -1}),
            "scenario.physics.ground.tangential_damping: must be at least 0",
        ),
        ("ground", json!({"stiffness": 1}), "unknown field"),
        (
            "controller",
            json!({"thrust_m": 1e9}),
            "scenario.physics.controller.thrust_m: must be a finite number",
        ),
        (
            "controller",
            json!({"thrust_m": "high"}),
            "scenario.physics.controller",
        ),
    ] {
        let error = biped_with(field, value.clone()).expect_err("refused");
        assert!(error.contains(expected), "{field} = {value}: {error}");
    }
}
