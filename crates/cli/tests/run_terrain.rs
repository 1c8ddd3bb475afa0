//! `gaitlab run` on ground that is not flat (issue 45 item 2): the hexapod
//! with stairs in its preset climbs them — the run's `terrain` figures say
//! how far it got, how high, that no foot went below the ground and how
//! many footholds moved off a riser's edge —, the quadruped bounds up a 10°
//! slope holding its feet with the body eased where its legs fold to their
//! limits (and says how often), the physics biped runs up a slope and says
//! how far and how high, and a physics creature on stairs, or in a gait not
//! made for terrain, is refused with the field named.

mod common;

use common::{gaitlab, gaitlab_ok, json_of};
use serde_json::{Value, json};

fn preset_with(name: &str, terrain: Value) -> std::path::PathBuf {
    let text = gaitlab_core::preset::bundled_json(name).expect("bundled preset");
    let mut preset: Value = serde_json::from_str(text).expect("JSON");
    preset["scenario"]["terrain"] = terrain;
    let path = std::env::temp_dir().join(format!(
        "gaitlab-run-terrain-{name}-{}.json",
        std::process::id()
    ));
    std::fs::write(&path, preset.to_string()).expect("write preset");
    path
}

#[test]
fn the_hexapod_climbs_stairs_from_its_preset_and_says_so() {
    let stairs = json!({"kind": "stairs", "rise_m": 0.05, "run_m": 0.3, "count": 20,
        "direction_deg": 90, "start_m": 0.4});
    let path = preset_with("hexapod", stairs);
    let output = gaitlab_ok(&[
        "run",
        path.to_str().expect("utf-8 path"),
        "--seconds",
        "10",
        "--json",
    ]);
    let figures = json_of(&output);
    let terrain = &figures["terrain"];
    let number = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    assert_eq!(terrain["kind"], "stairs", "{figures}");
    assert!(
        (number(&terrain["made_good_m"]) - 2.0).abs() < 0.05,
        "{terrain}"
    );
    // 2 m of 0.3 m treads from the first riser at 0.4 m: five or six risers.
    assert!(
        (0.25..=0.31).contains(&number(&terrain["climbed_m"])),
        "{terrain}"
    );
    assert!(
        number(&terrain["foot_below_ground_max_m"]) <= 0.001,
        "{terrain}"
    );
    assert!(
        terrain["footholds_moved"].as_u64().unwrap_or(0) > 0,
        "{terrain}"
    );
    assert!(number(&figures["foot_slip_max_m"]) <= 0.001, "{figures}");
    let text = gaitlab_ok(&["run", path.to_str().expect("utf-8 path"), "--seconds", "2"]);
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains("  terrain stairs · made good"), "{stdout}");
    let _ = std::fs::remove_file(path);
}

#[test]
fn the_quadruped_bounds_up_a_slope_and_counts_the_frames_its_body_eased() {
    let text = gaitlab_core::preset::bundled_json("poda-quadruped").expect("bundled preset");
    let mut preset: Value = serde_json::from_str(text).expect("JSON");
    preset["scenario"]["terrain"] = json!({"kind": "plane", "slope_deg": 10, "direction_deg": 90});
    preset["scenario"]["poda"]["gait"] = json!("bound");
    let path = std::env::temp_dir().join(format!(
        "gaitlab-run-terrain-bound-{}.json",
        std::process::id()
    ));
    std::fs::write(&path, preset.to_string()).expect("write preset");
    let output = gaitlab_ok(&[
        "run",
        path.to_str().expect("utf-8 path"),
        "--seconds",
        "6",
        "--json",
    ]);
    let figures = json_of(&output);
    let terrain = &figures["terrain"];
    let number = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    assert!(
        terrain["body_eased_frames"].as_u64().unwrap_or(0) > 0,
        "{terrain}"
    );
    assert!(
        (0.5..1.0).contains(&number(&terrain["body_eased_least_kept"])),
        "{terrain}"
    );
    assert!(
        number(&terrain["foot_below_ground_max_m"]) <= 0.001,
        "{terrain}"
    );
    assert!(number(&figures["foot_slip_max_m"]) <= 0.001, "{figures}");
    let _ = std::fs::remove_file(path);
}

#[test]
fn a_physics_creature_on_stairs_is_refused_with_the_field_named() {
    let stairs = json!({"kind": "stairs", "rise_m": 0.1, "run_m": 0.4, "count": 5});
    let path = preset_with("raibert-biped", stairs);
    let output = gaitlab(&["run", path.to_str().expect("utf-8 path"), "--seconds", "1"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("scenario.terrain: the physics engine does not climb stairs"),
        "{stderr}"
    );
    let _ = std::fs::remove_file(path);
}

#[test]
fn a_physics_gait_not_made_for_terrain_is_refused_with_the_gait_named() {
    let slope = json!({"kind": "plane", "slope_deg": 5, "direction_deg": 90});
    let path = preset_with("raibert-quadruped", slope);
    let path_text = path.to_str().expect("utf-8 path");
    let output = gaitlab(&["run", path_text, "--gait", "bound", "--seconds", "1"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("scenario.terrain: the physics engine runs the bound on flat ground only"),
        "{stderr}"
    );
    let _ = std::fs::remove_file(path);
}

#[test]
fn the_physics_biped_runs_up_a_slope_and_says_how_far_and_how_high() {
    let slope = json!({"kind": "plane", "slope_deg": 5, "direction_deg": 90});
    let path = preset_with("raibert-biped", slope);
    let output = gaitlab_ok(&[
        "run",
        path.to_str().expect("utf-8 path"),
        "--seconds",
        "6",
        "--json",
    ]);
    let figures = json_of(&output);
    let number = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    let terrain = &figures["terrain"];
    assert_eq!(figures["fell"], false, "{figures}");
    assert_eq!(terrain["kind"], "plane", "{figures}");
    // About 1.5 m/s for the 3 s after settling, rising tan 5° per metre.
    let made = number(&terrain["made_good_m"]);
    let climbed = number(&terrain["climbed_m"]);
    assert!((3.5..5.5).contains(&made), "{terrain}");
    let (sin, cos) = gaitlab_core::trig::sin_cos(5f64.to_radians());
    let rise = sin / cos;
    assert!((climbed / made - rise).abs() < 0.01, "{terrain}");
    let text = gaitlab_ok(&["run", path.to_str().expect("utf-8 path"), "--seconds", "4"]);
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains("  terrain plane · made good"), "{stdout}");
    let _ = std::fs::remove_file(path);
}
