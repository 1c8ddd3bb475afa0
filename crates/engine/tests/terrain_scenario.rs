//! `scenario.terrain` in a preset (issue 45 item 1, first part): a stairs or
//! height-field ground is read and checked with errors that name the field
//! inside `scenario.terrain`; PODA runs on it, the physics biped runs on a
//! slope but not yet up stairs, the IK engine, which walks on flat ground
//! only so far, refuses it by the same path instead of ignoring it; a
//! flat or absent terrain changes nothing and is not written back.

use gaitlab_core::Creature;
use gaitlab_core::terrain::Terrain;
use gaitlab_engine::{Overrides, driver_for};
use serde_json::{Value, json};

fn hexapod_with(terrain: Value) -> Result<Creature, String> {
    preset_with("hexapod", terrain)
}

fn preset_with(name: &str, terrain: Value) -> Result<Creature, String> {
    let path = format!("{}/../../presets/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let mut preset: Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
    preset["scenario"]["terrain"] = terrain;
    Creature::from_json(&preset.to_string()).map_err(|e| format!("{}: {}", e.path, e.reason))
}

#[test]
fn a_preset_carries_its_terrain_checked_and_refused_where_the_engine_cannot_walk_on_it() {
    let stairs = json!({"kind": "stairs", "rise_m": 0.05, "run_m": 0.3, "count": 4});
    let creature = hexapod_with(stairs.clone()).unwrap_or_else(|e| panic!("{e}"));
    assert!(matches!(creature.scenario.terrain, Terrain::Stairs(ref s) if s.count == 4));
    assert!(
        driver_for(&creature, &Overrides::default()).is_ok(),
        "PODA walks on stairs"
    );
    // The physics biped does not climb stairs yet; it runs on a slope.
    let biped = preset_with("raibert-biped", stairs).unwrap_or_else(|e| panic!("{e}"));
    let error = driver_for(&biped, &Overrides::default()).err();
    assert!(
        error
            .as_ref()
            .is_some_and(|e| e.path == "scenario.terrain" && e.reason.contains("stairs")),
        "{error:?}"
    );
    let slope = json!({"kind": "plane", "slope_deg": 5, "direction_deg": 90});
    let biped = preset_with("raibert-biped", slope.clone()).unwrap_or_else(|e| panic!("{e}"));
    assert!(driver_for(&biped, &Overrides::default()).is_ok());
    // The IK engine walks on the floor only.
    let thesis = preset_with("she-2006", slope).unwrap_or_else(|e| panic!("{e}"));
    let error = driver_for(&thesis, &Overrides::default()).err();
    assert!(
        error
            .as_ref()
            .is_some_and(|e| e.path == "scenario.terrain" && e.reason.contains("flat ground")),
        "{error:?}"
    );
    for (terrain, path) in [
        (
            json!({"kind": "height_field", "cell_m": 0.1, "rows": 2, "cols": 2, "heights_m": [0, 0.1, null, 0]}),
            "",
        ),
        (
            json!({"kind": "height_field", "cell_m": 0.1, "rows": 2, "cols": 2, "heights_m": [0, 0.1, -1, 0]}),
            "scenario.terrain.heights_m[2]",
        ),
        (
            json!({"kind": "height_field", "cell_m": 0.1, "rows": 40000, "cols": 40000, "heights_m": []}),
            "scenario.terrain.rows",
        ),
        (
            json!({"kind": "stairs", "rise_m": 0.05, "run_m": 0.3, "count": 0}),
            "scenario.terrain.count",
        ),
        (
            json!({"kind": "plane", "slope_deg": 75}),
            "scenario.terrain.slope_deg",
        ),
        (json!({"kind": "ice"}), "scenario.terrain"),
    ] {
        let error = hexapod_with(terrain.clone()).err().unwrap_or_default();
        assert!(error.starts_with(path), "{terrain}: {error}");
        assert!(!error.is_empty(), "{terrain} is refused");
    }
    // Flat, or left out: runs as before, and is not written back.
    let flat = hexapod_with(json!({"kind": "flat"})).unwrap_or_else(|e| panic!("{e}"));
    assert!(driver_for(&flat, &Overrides::default()).is_ok());
    let written = serde_json::to_value(&flat.scenario).unwrap_or_default();
    assert!(written.get("terrain").is_none(), "{written}");
}
