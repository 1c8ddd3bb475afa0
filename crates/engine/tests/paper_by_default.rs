//! Paper by default (issue 41 item 2): every bundled preset run "paper
//! alone" has no lab addition in force, in every gait or mode it offers; a
//! `gaitlab-preset/2` file with every optional key that names an addition
//! left out runs the paper alone too, in every engine (PODA with Figure 2's
//! body pitch and eq. 2's foot orientation on).

use gaitlab_core::Creature;
use gaitlab_core::preset::{bundled, paper_alone};
use gaitlab_engine::{AnyDriver, Overrides, driver_for, switch_gait};
use serde_json::Value;

fn names(driver: &AnyDriver) -> Vec<&'static str> {
    driver.lab_additions().iter().map(|a| a.name).collect()
}

fn driver(json: &Value) -> (Creature, AnyDriver) {
    let creature = Creature::from_json(&json.to_string()).expect("preset loads");
    let driver = driver_for(&creature, &Overrides::default()).expect("driver");
    (creature, driver)
}

/// Each gait the physics creatures offer (the gait table's), to switch to
/// and list again.
fn physics_gaits() -> impl Iterator<Item = &'static str> {
    use gaitlab_engine::catalog::{Species, physics_gaits};
    [Species::Biped, Species::Quadruped, Species::Kangaroo]
        .into_iter()
        .flat_map(|s| physics_gaits(s).iter().copied())
}

#[test]
fn every_bundled_preset_runs_the_paper_alone_on_request() {
    for (name, json) in bundled() {
        let mut preset: Value = serde_json::from_str(json).expect("json");
        paper_alone(&mut preset).expect("paper alone");
        let (creature, mut driver) = driver(&preset);
        assert_eq!(names(&driver), Vec::<&str>::new(), "{name}");
        if creature.scenario.physics.is_some() {
            for gait in physics_gaits() {
                if switch_gait(&mut driver, gait).is_ok() {
                    assert_eq!(names(&driver), Vec::<&str>::new(), "{name} {gait}");
                }
            }
        }
    }
}

/// Removes `key` (a dotted path) from `preset` if present.
fn remove(preset: &mut Value, key: &str) {
    let (parent, last) = key.rsplit_once('.').expect("dotted");
    let pointer = format!("/{}", parent.replace('.', "/"));
    if let Some(map) = preset.pointer_mut(&pointer).and_then(Value::as_object_mut) {
        map.remove(last);
    }
}

#[test]
fn a_version_2_file_without_the_optional_keys_runs_the_paper() {
    let optional = [
        "scenario.ik",
        "scenario.thesis.script",
        "scenario.thesis.wound_form",
        "scenario.thesis.posture_gain",
        "scenario.thesis.start_ramp_s",
        "scenario.poda.turn_within_reach",
        "scenario.poda.yaw_toward_actual",
        "scenario.poda.fore_aft_surge",
        "scenario.poda.gait_by_speed",
        "scenario.poda.body_pitch",
        "scenario.poda.foot_orientation",
        "scenario.poda.vertical_gain",
        "scenario.physics.lab_additions",
        "scenario.physics.switch_to_start",
    ];
    let mut seen = 0;
    for (name, json) in bundled() {
        let mut preset: Value = serde_json::from_str(json).expect("json");
        preset["format"] = Value::from("gaitlab-preset/2");
        for key in optional {
            remove(&mut preset, key);
        }
        if preset.pointer("/scenario/method") == Some(&Value::from("ccd")) {
            preset["scenario"]["method"] = Value::from("sdls");
        }
        let (_, driver) = driver(&preset);
        assert_eq!(names(&driver), Vec::<&str>::new(), "{name}");
        seen += 1;
    }
    assert!(seen >= 10);
}
