//! The page's `state().metrics` and `gaitlab run --json` report the same
//! figures for the same frames (the engine layer's one metrics type): the lab,
//! paused and stepped exactly K frames through the command API, against the
//! binary run for K frames at the preset's fps, for an IK, a PODA and a physics
//! creature. Wall-time fields differ by nature and are left out.

use std::process::Command;

use gaitlab_app::{Lab, Settings};
use serde_json::Value;

const TIMING_KEYS: [&str; 5] = [
    "wall_ms",
    "us_per_frame",
    "us_per_iteration",
    "steps_per_second",
    "realtime_factor",
];

fn without_timing(value: Value) -> Value {
    match value {
        Value::Object(map) => Value::Object(
            map.into_iter()
                .filter(|(key, _)| !TIMING_KEYS.contains(&key.as_str()))
                .map(|(key, v)| (key, without_timing(v)))
                .collect(),
        ),
        Value::Array(items) => Value::Array(items.into_iter().map(without_timing).collect()),
        other => other,
    }
}

fn cli_metrics(preset: &str, seconds: &str) -> Value {
    let output = Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .args(["run", preset, "--seconds", seconds, "--json"])
        .output()
        .expect("the gaitlab binary runs");
    assert!(
        output.status.success(),
        "{preset}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("one JSON object")
}

fn lab_metrics(preset: &str, frames: usize) -> Value {
    let mut lab = Lab::new(Settings::default());
    lab.command(&serde_json::json!({"preset": preset}).to_string())
        .expect("preset");
    lab.command(r#"{"paused": true, "reset": true}"#)
        .expect("pause");
    for _ in 0..frames {
        lab.command(r#"{"step": true}"#).expect("step");
        lab.advance(0.0);
    }
    let state: Value = serde_json::from_str(&lab.state_json()).expect("state is JSON");
    state["metrics"].clone()
}

#[test]
fn the_page_and_the_cli_report_the_same_figures() {
    // 90 frames: 1.5 s at the thesis and PODA presets' 60 fps, 3 s at 30.
    for preset in ["human", "poda-quadruped", "raibert-kangaroo"] {
        let lab = lab_metrics(preset, 90);
        let fps = lab["fps"].as_f64().unwrap_or(60.0);
        let seconds = format!("{}", 90.0 / fps);
        let cli = cli_metrics(preset, &seconds);
        assert_eq!(lab["engine"], cli["engine"], "{preset}");
        assert_eq!(
            without_timing(lab),
            without_timing(cli),
            "{preset}: page and CLI figures differ after 90 frames"
        );
    }
}
