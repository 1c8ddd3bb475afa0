//! `state()` keeps its keys, nesting and values: the JSON of a few labs
//! (human at start, poda-quadruped and raibert-kangaroo after some frames, an
//! IK comparison running) equals the fixtures recorded from the hand-built
//! `json!` object that the typed `State` replaced, key for key. Fields that
//! depend on the machine (fps, timings, memory) are left out.
//!
//! Re-record after a deliberate state change:
//! `GAITLAB_UPDATE_STATE=1 cargo test -p gaitlab-app --test state_fixture`.

use std::path::PathBuf;

use gaitlab_app::{App, Settings};
use serde_json::Value;

/// Keys (JSON pointers) whose values depend on wall time or the machine.
const VOLATILE: &[&str] = &[
    "/fps",
    "/sim_us_per_frame",
    "/wasm_memory_bytes",
    "/wasm_heap_live_bytes",
    "/wasm_heap_peak_bytes",
    "/views/0/metrics/step_ms",
    "/views/0/metrics/wall_ms",
    "/views/0/metrics/fps",
    "/views/0/metrics/ms_per_frame",
    "/views/0/metrics/step_ms_per_frame",
    "/views/0/metrics/wall_ms_per_frame",
];

fn labs() -> Vec<(&'static str, App)> {
    let mut out = Vec::new();
    out.push(("human", App::new(Settings::default())));
    let mut poda = App::new(Settings::default());
    poda.command(r#"{"preset":"poda-quadruped","gait":"trot"}"#)
        .expect("poda");
    for _ in 0..30 {
        poda.advance(1.0 / 60.0);
    }
    out.push(("poda_quadruped", poda));
    let mut kangaroo = App::new(Settings::default());
    kangaroo
        .command(r#"{"preset":"raibert-kangaroo"}"#)
        .expect("kangaroo");
    for _ in 0..30 {
        kangaroo.advance(1.0 / 60.0);
    }
    out.push(("raibert_kangaroo", kangaroo));
    let mut compare = App::new(Settings::default());
    compare
        .command(
            r#"{"compare":{"views":["dls","sdls"],"scenario":"singularity"},
                "record":true,"camera":{"yaw_deg":30},"plot_joints":["left_knee"]}"#,
        )
        .expect("compare");
    for _ in 0..20 {
        compare.advance(1.0 / 60.0);
    }
    out.push(("compare", compare));
    out
}

fn stable(text: &str) -> Value {
    let mut value: Value = serde_json::from_str(text).expect("state is JSON");
    for pointer in VOLATILE {
        if let Some(slot) = value.pointer_mut(pointer) {
            *slot = Value::Null;
        }
    }
    value
}

/// Every difference between two JSON values, by pointer.
fn differences(path: &str, a: &Value, b: &Value, out: &mut Vec<String>) {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            for (k, v) in x {
                match y.get(k) {
                    Some(w) => differences(&format!("{path}/{k}"), v, w, out),
                    None => out.push(format!("{path}/{k}: missing now")),
                }
            }
            for k in y.keys().filter(|k| !x.contains_key(*k)) {
                out.push(format!("{path}/{k}: new key"));
            }
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
            for (i, (v, w)) in x.iter().zip(y).enumerate() {
                differences(&format!("{path}/{i}"), v, w, out);
            }
        }
        (Value::Number(x), Value::Number(y))
            if x.as_f64().zip(y.as_f64()).is_some_and(|(x, y)| {
                // serde_json's default parser may be one ulp off on read-back.
                (x - y).abs() <= 1e-12 * x.abs().max(y.abs())
            }) => {}
        _ if a != b => out.push(format!("{path}: {a} then, {b} now")),
        _ => {}
    }
}

#[test]
fn state_matches_the_recorded_fixtures_key_for_key() {
    let dir: PathBuf = [env!("CARGO_MANIFEST_DIR"), "tests", "fixtures"]
        .iter()
        .collect();
    let update = std::env::var_os("GAITLAB_UPDATE_STATE").is_some();
    for (name, lab) in labs() {
        let path = dir.join(format!("state_{name}.json"));
        let now = stable(&lab.state_json());
        if update {
            let text = serde_json::to_string_pretty(&now).expect("json") + "\n";
            std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        }
        let text =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let then: Value = serde_json::from_str(&text).expect("fixture is JSON");
        let mut diffs = Vec::new();
        differences("", &then, &now, &mut diffs);
        assert!(diffs.is_empty(), "{name}: {}", diffs.join("\n"));
    }
}
