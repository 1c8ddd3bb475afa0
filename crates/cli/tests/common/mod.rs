//! What the CLI's test binaries share: running the `gaitlab` binary and reading
//! its output, scratch files, the bundled presets from the core (not from
//! disk), and a metrics object without its timing fields.

#![allow(dead_code, reason = "each test binary uses a part of this")]

use std::path::PathBuf;
use std::process::{Command, Output};

use serde_json::Value;

/// The timing fields of `--json`, which differ from run to run.
pub const TIMING_KEYS: [&str; 5] = [
    "wall_ms",
    "us_per_frame",
    "us_per_iteration",
    "steps_per_second",
    "realtime_factor",
];

/// Runs `gaitlab ARGS…`.
pub fn gaitlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .args(args)
        .output()
        .expect("the gaitlab binary runs")
}

/// Runs `gaitlab ARGS…`, which must succeed.
pub fn gaitlab_ok(args: &[&str]) -> Output {
    let output = gaitlab(args);
    assert!(
        output.status.success(),
        "gaitlab {args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// The one JSON object a successful `--json` command printed.
pub fn json_of(output: &Output) -> Value {
    assert!(
        output.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("one JSON object on stdout")
}

/// `gaitlab run PRESET --seconds S --json ARGS…`'s metrics.
pub fn run_json(preset: &str, seconds: &str, args: &[&str]) -> Value {
    let mut all = vec!["run", preset, "--seconds", seconds, "--json"];
    all.extend_from_slice(args);
    json_of(&gaitlab_ok(&all))
}

/// `value` without the [`TIMING_KEYS`], at any depth.
pub fn without_timing(value: Value) -> Value {
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

/// A path for `name` in this test process's own scratch folder.
pub fn scratch(name: &str) -> PathBuf {
    let binary = std::env::current_exe()
        .ok()
        .and_then(|p| p.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .unwrap_or_default();
    let dir =
        std::env::temp_dir().join(format!("gaitlab-cli-test-{binary}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

/// A scratch path as the `&str` an argument list takes.
pub fn scratch_arg(name: &str) -> String {
    scratch(name).to_string_lossy().into_owned()
}

/// The bundled preset `name` as JSON, as the core embeds it.
pub fn bundled_preset(name: &str) -> Value {
    let text = gaitlab_core::preset::bundled_json(name).expect("a bundled preset");
    serde_json::from_str(text).expect("bundled presets are JSON")
}

/// Every bundled preset's name, sorted.
pub fn bundled_names() -> Vec<String> {
    let mut names: Vec<String> = gaitlab_core::preset::bundled_names()
        .map(str::to_owned)
        .collect();
    names.sort();
    names
}
