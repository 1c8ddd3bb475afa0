//! The Method panel's λ trade-off (She 2006 §4.4.3): the command measures the
//! running thesis motion at the sweep's λ values and `state().ik` carries the
//! figures; the panel's button does the same; other engines get an error.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use gaitlab_app::{App, Settings};
use serde_json::Value;

fn lab(preset: &str) -> App {
    let mut lab = App::new(Settings::default());
    lab.set_paused(true);
    if let Err(error) = lab.command(&format!(r#"{{"preset":"{preset}"}}"#)) {
        panic!("{error}");
    }
    lab
}

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).unwrap_or(Value::Null)
}

#[test]
fn the_command_measures_the_thesis_walk_and_state_carries_the_tradeoff() {
    let mut lab = lab("she-2006");
    assert_eq!(state(&lab)["ik"]["lambda_tradeoff"], Value::Null);
    let frame = state(&lab)["frame"].clone();
    if let Err(error) = lab.command(r#"{"measure_lambda_tradeoff":true}"#) {
        panic!("{error}");
    }
    let s = state(&lab);
    let sweep = &s["ik"]["lambda_tradeoff"];
    assert_eq!(sweep["preset"], "she-2006");
    assert_eq!(sweep["mode"], "walk");
    let Some(points) = sweep["points"].as_array() else {
        panic!("no points in {sweep}")
    };
    let lambdas: Vec<f64> = points
        .iter()
        .filter_map(|p| p["lambda_m"].as_f64())
        .collect();
    assert_eq!(lambdas, [0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0]);
    // The docs' figures at λ = 0.2 m: the feet 2.0 mm off, the hands'
    // jitter 0.27 mrad/frame², against 215 at 0.05 m.
    let at = |lambda: f64, key: &str| {
        points
            .iter()
            .find(|p| p["lambda_m"].as_f64() == Some(lambda))
            .and_then(|p| p[key].as_f64())
            .unwrap_or(f64::NAN)
    };
    assert!(
        (at(0.2, "reachable_error_m") - 0.002).abs() < 2e-4,
        "{sweep}"
    );
    assert!(
        (at(0.2, "unreachable_jitter_rad") - 2.7e-4).abs() < 2e-5,
        "{sweep}"
    );
    assert!(at(0.05, "unreachable_jitter_rad") > 100.0 * at(0.2, "unreachable_jitter_rad"));
    // The motion on screen was not touched.
    assert_eq!(s["frame"], frame);
    assert_eq!(s["method"], "sdls");
}

#[test]
fn other_engines_are_told_the_tradeoff_is_the_thesis() {
    let mut lab = lab("hexapod");
    let error = lab
        .command(r#"{"measure_lambda_tradeoff":true}"#)
        .err()
        .unwrap_or_default();
    assert!(error.contains("thesis motion (engine ik)"), "{error}");
    assert_eq!(state(&lab)["ik"]["lambda_tradeoff"], Value::Null);
}

#[test]
fn the_method_panels_button_measures_it() {
    let lab = lab("she-2006");
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1200.0, 1400.0))
        .build_ui_state(|ui, lab: &mut App| lab.ui(ui), lab);
    harness.run();
    harness.get_by_label("Method").click();
    harness.run();
    harness.get_by_label("λ trade-off (§4.4.3)").click();
    harness.run();
    harness.get_by_label("Measure").click();
    harness.run();
    let measured = harness.state().lambda_tradeoff().map(|t| t.points.len());
    assert_eq!(measured, Some(7));
}
