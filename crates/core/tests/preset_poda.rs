//! The PODA scenario section (`scenario.poda`): accepted on engine `poda`,
//! rejected on engine `ik`, and every bad leg or value named by its JSON path.

use gaitlab_core::preset::{self, Engine, Preset};
use serde_json::{Value, json};

/// The human skeleton with a PODA scenario whose legs are its two feet.
fn human_poda(poda: Value) -> String {
    let mut value: Value =
        serde_json::from_str(preset::bundled_json("human").expect("human is bundled"))
            .expect("human.json is JSON");
    value["scenario"] = json!({"engine": "poda", "poda": poda});
    serde_json::to_string(&value).expect("serialises")
}

fn legs() -> Value {
    json!([
        {"name": "left", "effector": "left_foot", "hip": "left_hip_flex"},
        {"name": "right", "effector": "right_foot", "hip": "right_hip_flex"}
    ])
}

#[track_caller]
fn rejected(json: &str, path: &str, reason: &str) {
    match Preset::from_json(json) {
        Ok(_) => panic!("accepted, expected `{path}: …{reason}…`"),
        Err(error) => {
            assert_eq!(error.path, path, "path of `{error}`");
            assert!(error.reason.contains(reason), "reason of `{error}`");
        }
    }
}

#[test]
fn a_biped_with_two_legs_is_accepted_and_keeps_its_values() {
    let json =
        human_poda(json!({"legs": legs(), "gait": "walk", "period_s": 1.2, "speed_mps": 0.8}));
    let preset = Preset::from_json(&json).expect("valid PODA preset");
    assert_eq!(preset.scenario.engine, Engine::Poda);
    let poda = preset.scenario.poda_params();
    assert_eq!(poda.legs.len(), 2);
    assert_eq!(poda.gait.as_deref(), Some("walk"));
    assert!((poda.period_s - 1.2).abs() < 1e-12);
    assert!((poda.speed_mps - 0.8).abs() < 1e-12);
}

#[test]
fn legs_must_name_an_effector_and_a_hip_on_its_chain() {
    rejected(
        &human_poda(json!({"legs": [{"effector": "nose", "hip": "left_hip_flex"}]})),
        "scenario.poda.legs[0].effector",
        "no effector",
    );
    rejected(
        &human_poda(json!({"legs": [{"effector": "left_foot", "hip": "no_such_joint"}]})),
        "scenario.poda.legs[0].hip",
        "no joint",
    );
    rejected(
        &human_poda(json!({"legs": [{"effector": "left_foot", "hip": "right_hip_flex"}]})),
        "scenario.poda.legs[0].hip",
        "not on the chain",
    );
    rejected(
        &human_poda(json!({"legs": [
            {"effector": "left_foot", "hip": "left_hip_flex"},
            {"effector": "left_foot", "hip": "left_hip_flex"}]})),
        "scenario.poda.legs[1].effector",
        "already leg 0",
    );
    // The human has no DH limbs, so legs must be listed.
    rejected(
        &human_poda(json!({})),
        "scenario.poda.legs",
        "name the legs",
    );
}

#[test]
fn out_of_range_values_name_their_field() {
    let cases = [
        (json!({"period_s": 0.0}), "scenario.poda.period_s"),
        (json!({"period_s": 0.05}), "scenario.poda.period_s"),
        (json!({"duty_factor": 1.0}), "scenario.poda.duty_factor"),
        (json!({"speed_mps": -1.0}), "scenario.poda.speed_mps"),
        (json!({"step_height_m": 0.0}), "scenario.poda.step_height_m"),
        (
            json!({"transfer_keys": [[0.5, 1.0], [0.4, 0.5]]}),
            "scenario.poda.transfer_keys[1]",
        ),
        (
            json!({"transfer_keys": [[0.5, 3.0]]}),
            "scenario.poda.transfer_keys[0]",
        ),
        (
            json!({"path": {"points": [[0, 0]]}}),
            "scenario.poda.path.points",
        ),
        (json!({"body_mass_kg": 0.0}), "scenario.poda.body_mass_kg"),
        (
            json!({"iterations_per_frame": 0}),
            "scenario.poda.iterations_per_frame",
        ),
        (json!({"phases": [0.0]}), "scenario.poda.phases"),
    ];
    for (mut poda, path) in cases {
        poda["legs"] = legs();
        rejected(&human_poda(poda), path, "");
    }
}

#[test]
fn a_poda_section_on_the_ik_engine_is_rejected() {
    let mut value: Value =
        serde_json::from_str(preset::bundled_json("human").expect("human is bundled"))
            .expect("human.json is JSON");
    value["scenario"]["poda"] = json!({"period_s": 1.0});
    rejected(
        &serde_json::to_string(&value).expect("serialises"),
        "scenario.poda",
        "engine",
    );
}
