//! The PODA engine in the lab (Girard & Maciejewski 1985): a PODA preset
//! switches the lab to the gait engine, `gait` and the gait values change it
//! through the same command API the browser uses, every edit keeps eq. 7–8
//! true, and bad gait commands name their key.

use gaitlab_app::{Lab, Settings};
use serde_json::Value;

fn state(lab: &Lab) -> Value {
    serde_json::from_str(&lab.state_json()).expect("state is JSON")
}

fn number(s: &Value, key: &str) -> f64 {
    s["poda"][key].as_f64().unwrap_or(f64::NAN)
}

/// Eq. 7 (support = stroke / speed), duty = support / P and eq. 8 (P = support + transfer).
#[track_caller]
fn assert_gait_relations(s: &Value) {
    let (p, duty, speed, stroke) = (
        number(s, "period_s"),
        number(s, "duty_factor"),
        number(s, "speed_mps"),
        number(s, "stroke_m"),
    );
    let (support, transfer) = (number(s, "support_s"), number(s, "transfer_s"));
    assert!((support - stroke / speed).abs() < 1e-9, "eq. 7: {s}");
    assert!((duty - support / p).abs() < 1e-9, "duty: {s}");
    assert!((p - support - transfer).abs() < 1e-9, "eq. 8: {s}");
}

#[test]
fn the_quadruped_trots_then_gallops() {
    let mut lab = Lab::new(Settings::default());
    lab.command(r#"{"preset":"poda-quadruped","gait":"trot"}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(s["engine"], "poda");
    assert_eq!(s["gait"], "trot");
    assert_eq!(s["joints"], 63);
    assert_eq!(s["poda"]["legs"].as_array().map(Vec::len), Some(4));
    for _ in 0..60 {
        lab.advance(1.0 / 60.0);
    }
    lab.command(r#"{"gait":"transverse_gallop"}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(s["gait"], "transverse_gallop");
    assert_eq!(s["poda"]["blending"], true);
    for _ in 0..90 {
        lab.advance(1.0 / 60.0);
    }
    let s = state(&lab);
    assert_eq!(s["poda"]["blending"], false);
    assert!((number(&s, "duty_factor") - 0.3).abs() < 1e-12);
    assert!(number(&s, "foot_slip_max_m") <= 0.001, "{s}");
    // The feet track their targets: the effector error plot has data.
    let errors = s["views"][0]["effectors"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    assert!(errors.iter().any(|e| e["error_m"].is_number()));
    assert!(s["last_error"].is_null());
}

#[test]
fn every_gait_edit_keeps_eq_7_and_8_and_says_what_it_derived() {
    let mut lab = Lab::new(Settings::default());
    lab.command(r#"{"preset":"hexapod"}"#).expect("valid");
    assert_gait_relations(&state(&lab));
    for (command, derived) in [
        (r#"{"period_s": 1.2}"#, "stroke_m"),
        (r#"{"duty_factor": 0.6}"#, "support_s"),
        (r#"{"speed_mps": 0.3}"#, "period_s"),
        (r#"{"stroke_m": 0.12}"#, "period_s"),
    ] {
        lab.command(command).expect("valid edit");
        let s = state(&lab);
        assert_gait_relations(&s);
        let said: Vec<&str> = s["poda"]["derived"]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(Value::as_str)
            .collect();
        assert!(said.contains(&derived), "{command} derived {said:?}");
    }
    // Speed 0.3 m/s at stroke 0.12 m: support 0.4 s.
    let s = state(&lab);
    assert!((number(&s, "support_s") - 0.4).abs() < 1e-9);
}

#[test]
fn bad_gait_commands_name_their_key_and_change_nothing() {
    let mut lab = Lab::new(Settings::default());
    let error = lab
        .command(r#"{"gait":"trot"}"#)
        .expect_err("no gaits on ik");
    assert!(error.starts_with("gait:"), "{error}");
    lab.command(r#"{"preset":"hexapod"}"#).expect("valid");
    let error = lab
        .command(r#"{"gait":"gallop"}"#)
        .expect_err("unknown gait");
    assert!(
        error.starts_with("gait:") && error.contains("tripod"),
        "{error}"
    );
    let before = state(&lab);
    let error = lab
        .command(r#"{"duty_factor": 1.5}"#)
        .expect_err("out of range");
    assert!(error.starts_with("duty_factor"), "{error}");
    let error = lab
        .command(r#"{"speed_mps": "fast"}"#)
        .expect_err("not a number");
    assert!(error.starts_with("speed_mps"), "{error}");
    let after = state(&lab);
    assert_eq!(before["poda"], after["poda"]);
    // Back to the IK engine: the thesis panels' state returns.
    lab.command(r#"{"preset":"human","mode":"run"}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(s["engine"], "ik");
    assert!(s["gait"].is_null());
}
