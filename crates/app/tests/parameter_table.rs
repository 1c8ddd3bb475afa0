//! The engine contract's parameter table (`gaitlab params`) against what
//! the front ends accept: every command key of the JS API that sets a value
//! (the command schema walked key by key), every `--edit` key and every
//! preset path in the table appear in it, exactly once per preset; each
//! preset row's value in force reads back through `--set`; and each numeric
//! range is the one a preset is checked with (a value just past either end is
//! refused naming the key, the ends themselves are accepted).

use std::collections::{BTreeMap, BTreeSet};

use gaitlab_app::api::schema::command_schema;
use gaitlab_core::Creature;
use gaitlab_core::params::Domain;
use gaitlab_core::preset::{bundled, set_preset_value};
use gaitlab_engine::live::EDIT_KEYS;
use gaitlab_engine::{Overrides, Parameter, driver_for, parameters};
use serde_json::Value;

/// Command keys that are not a value of the motion: the session, playback,
/// views, recording, lessons, the editor and the comparison (whose
/// per-view options are the table's IK rows), and `gains` (the map form of
/// the table's `gain.NAME` rows).
const NOT_PARAMETERS: &[&str] = &[
    "engine",
    "preset",
    "preset_json",
    "compare",
    "paused",
    "pause",
    "reset",
    "push_mps",
    "step",
    "iterate",
    "drag_target",
    "pinned_targets",
    "playback_rate",
    "step_back_s",
    "rewind_to_frame",
    "measure_lambda_tradeoff",
    "plots",
    "plot_joints",
    "record",
    "last_s",
    "save",
    "video_size",
    "record_video",
    "theme",
    "narrow",
    "help",
    "jacobian_panel",
    "lesson",
    "lesson_note_open",
    "track",
    "views",
    "camera",
    "editor_open",
    "editor_text",
    "editor_revert",
    "editor_apply",
    "download_preset",
    "show_link",
    "paper_alone",
    "gains",
];

fn tables() -> Vec<(&'static str, Vec<Parameter>)> {
    bundled()
        .iter()
        .map(|(name, json)| {
            let creature = Creature::from_json(json).expect("bundled preset");
            let driver = driver_for(&creature, &Overrides::default()).expect("driver");
            (*name, parameters(&creature, &driver))
        })
        .collect()
}

/// The command key a row answers to (`gain.leg_stiffness` → `gain`).
fn command_key(p: &Parameter) -> Option<&str> {
    p.command
        .as_deref()
        .map(|c| c.split('.').next().unwrap_or(c))
}

#[test]
fn every_command_and_edit_key_is_a_row_and_no_row_is_twice() {
    let tables = tables();
    let mut answered = BTreeSet::new();
    for (name, table) in &tables {
        let mut keys = BTreeMap::new();
        let mut commands = BTreeMap::new();
        for p in table {
            *keys.entry(p.key.as_str()).or_insert(0) += 1;
            if let Some(c) = &p.command {
                *commands.entry(c.as_str()).or_insert(0) += 1;
            }
            answered.extend(command_key(p));
        }
        let twice: Vec<_> = keys
            .iter()
            .chain(commands.iter())
            .filter(|(_, n)| **n > 1)
            .collect();
        assert!(twice.is_empty(), "{name}: rows twice: {twice:?}");
        assert!(table.len() >= 5, "{name}: only {} rows", table.len());
    }
    let schema = command_schema();
    let properties = schema["properties"]
        .as_object()
        .expect("command properties");
    let mut missing = Vec::new();
    for key in properties.keys() {
        let key = key.as_str();
        if !NOT_PARAMETERS.contains(&key) && !answered.contains(key) {
            missing.push(key);
        }
    }
    assert!(
        missing.is_empty(),
        "command keys no preset's table answers: {missing:?}"
    );
    for key in NOT_PARAMETERS {
        assert!(
            properties.contains_key(*key),
            "{key} is listed as a command but the API has no such key"
        );
        assert!(!answered.contains(key), "{key} is both a row and not one");
    }
    let unknown: Vec<_> = answered
        .iter()
        .filter(|k| !properties.contains_key(**k))
        .collect();
    assert!(
        unknown.is_empty(),
        "rows name commands the API lacks: {unknown:?}"
    );
    for key in EDIT_KEYS {
        assert!(answered.contains(key), "--edit {key} is no row's command");
    }
}

/// The preset with `key` set to `value`, parsed and checked.
fn with(json: &str, key: &str, value: Value) -> Result<Creature, String> {
    let mut preset: Value = serde_json::from_str(json).expect("json");
    set_preset_value(&mut preset, key, value).map_err(|e| e.to_string())?;
    Creature::from_json(&preset.to_string()).map_err(|e| e.to_string())
}

#[test]
fn each_preset_row_reads_back_and_its_range_is_the_presets() {
    let mut probed = 0;
    for ((name, json), (_, table)) in bundled().iter().zip(tables()) {
        for p in table.iter().filter(|p| p.key.starts_with("scenario.")) {
            if !p.value.is_null() {
                with(json, &p.key, p.value.clone())
                    .unwrap_or_else(|e| panic!("{name}: {} = {} refused: {e}", p.key, p.value));
            }
            // The controller's rows: only the preset's bound is checked there
            // (a gain's lower bound of 0 is the live setter's).
            let controller = p.key.starts_with("scenario.physics.controller.");
            let (lo, hi, integer) = match p.domain {
                Domain::Real { min, max, .. } => (min, max, false),
                #[expect(clippy::cast_precision_loss, reason = "small bounds")]
                Domain::Integer { min, max } => (min as f64, max as f64, true),
                _ => continue,
            };
            let past = |x: f64, up: bool| {
                if integer {
                    x + if up { 1.0 } else { -1.0 }
                } else {
                    let step = (x.abs() * 1e-6).max(1e-9);
                    x + if up { step } else { -step }
                }
            };
            let number = |x: f64| {
                if integer {
                    #[expect(clippy::cast_possible_truncation, reason = "whole and small")]
                    Value::from(x as i64)
                } else {
                    Value::from(x)
                }
            };
            for (end, outside) in [(hi, past(hi, true)), (lo, past(lo, false))] {
                if controller && end == lo {
                    continue;
                }
                let open = matches!(
                    p.domain,
                    Domain::Real { min_open: true, min, .. } if min == end
                ) || matches!(
                    p.domain,
                    Domain::Real { max_open: true, max, .. } if max == end
                );
                // An end that a preset also refuses for another reason (a
                // physics speed past the legs, a period whose stroke leaves
                // its range) is not this range's to say; the outside value is.
                if let Err(e) = with(json, &p.key, number(outside)) {
                    assert!(
                        e.starts_with(&p.key),
                        "{name}: {} = {outside} refused, but not by its key: {e}",
                        p.key
                    );
                } else {
                    panic!(
                        "{name}: {} = {outside} (outside {}) accepted",
                        p.key, p.range
                    );
                }
                if !open && let Err(e) = with(json, &p.key, number(end)) {
                    assert!(
                        !e.starts_with(&format!("{}:", p.key)),
                        "{name}: {} = {end} (an end of {}) refused by its own key: {e}",
                        p.key,
                        p.range
                    );
                }
                probed += 1;
            }
        }
    }
    assert!(probed > 100, "only {probed} ends probed");
}
