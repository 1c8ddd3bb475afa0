//! `window.gaitlab.bench(json)`: the per-frame benchmark of
//! [`gaitlab_motion::frame_bench`] run inside the page, so the browser's
//! simulation + IK cost per frame can be compared with `gaitlab bench`'s
//! native figure for the same work (issue 3's wasm/native ratio). Options are
//! plain JSON data, checked field by field.

use gaitlab_core::ik::Method;
use gaitlab_core::preset::load_bundled;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_motion::frame_bench::{self, FrameBenchOptions};
use serde_json::{Map, Value, json};

/// Longest options text accepted, bytes.
const MAX_OPTIONS_BYTES: usize = 4096;

fn count(object: &Map<String, Value>, key: &str, default: usize) -> Result<usize, String> {
    match object.get(key) {
        None => Ok(default),
        Some(value) => value
            .as_u64()
            .and_then(|n| usize::try_from(n).ok())
            .ok_or_else(|| format!("{key}: expected a whole number")),
    }
}

fn name<'a>(
    object: &'a Map<String, Value>,
    key: &str,
    default: &'a str,
) -> Result<&'a str, String> {
    match object.get(key) {
        None => Ok(default),
        Some(value) => value
            .as_str()
            .ok_or_else(|| format!("{key}: expected a string")),
    }
}

/// Runs the benchmark described by `json` (`{}` or empty: the human, walking,
/// SDLS, 600 frames × 15 repeats) and returns the result as JSON text:
/// `preset`, `mode`, `method`, `frames`, `repeats`, `iterations_per_frame`,
/// `us_per_frame` (median) and `us_per_frame_best`.
///
/// # Errors
/// A readable `field: reason`.
pub fn run(json: &str, clock_ms: &mut dyn FnMut() -> f64) -> Result<String, String> {
    if json.len() > MAX_OPTIONS_BYTES {
        return Err(format!(
            "bench: options longer than {MAX_OPTIONS_BYTES} bytes"
        ));
    }
    let value: Value = if json.trim().is_empty() {
        Value::Object(Map::new())
    } else {
        serde_json::from_str(json).map_err(|e| format!("bench: not JSON: {e}"))?
    };
    let object = value
        .as_object()
        .ok_or("bench: options must be a JSON object")?;
    const KNOWN: [&str; 6] = [
        "preset",
        "mode",
        "method",
        "frames",
        "repeats",
        "warmup_frames",
    ];
    if let Some(unknown) = object.keys().find(|k| !KNOWN.contains(&k.as_str())) {
        return Err(format!("bench.{unknown}: unknown option"));
    }
    let defaults = FrameBenchOptions::default();
    let preset = name(object, "preset", "human")?;
    let mode_name = name(object, "mode", defaults.mode.name())?;
    let method_name = name(object, "method", defaults.method.name())?;
    let options = FrameBenchOptions {
        mode: ThesisMode::parse(mode_name)
            .ok_or_else(|| format!("bench.mode: unknown mode {mode_name:?}"))?,
        method: Method::parse(method_name)
            .ok_or_else(|| format!("bench.method: unknown method {method_name:?}"))?,
        frames: count(object, "frames", defaults.frames)?,
        repeats: count(object, "repeats", defaults.repeats)?,
        warmup_frames: count(object, "warmup_frames", defaults.warmup_frames)?,
        ..defaults
    };
    let creature = match load_bundled(preset) {
        Some(Ok(creature)) => creature,
        Some(Err(error)) => return Err(format!("bench.preset: {preset}: {error}")),
        None => return Err(format!("bench.preset: no bundled preset named {preset:?}")),
    };
    if creature.scenario.engine == gaitlab_core::preset::Engine::Physics {
        // Physics: integration steps per second, as `gaitlab bench` reports.
        let step_options = gaitlab_physics::step_bench::StepBenchOptions {
            repeats: options.repeats,
            ..Default::default()
        };
        let timing = gaitlab_physics::step_bench::time_steps(&creature, &step_options, clock_ms)
            .map_err(|e| format!("bench.{e}"))?;
        return Ok(json!({
            "preset": creature.name,
            "engine": "physics",
            "repeats": step_options.repeats,
            "dt_s": timing.dt_s,
            "steps_per_second": timing.steps_per_second,
            "steps_per_second_best": timing.steps_per_second_best,
            "realtime_factor": timing.realtime_factor,
        })
        .to_string());
    }
    let timing = frame_bench::time_frames(&creature, &options, clock_ms)
        .map_err(|e| format!("bench.{e}"))?;
    Ok(json!({
        "preset": creature.name,
        "engine": creature.scenario.engine.name(),
        "mode": options.mode.name(),
        "method": options.method.name(),
        "frames": options.frames,
        "repeats": options.repeats,
        "iterations_per_frame": timing.iterations_per_frame,
        "us_per_frame": timing.median_us,
        "us_per_frame_best": timing.best_us,
    })
    .to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ticking_clock() -> impl FnMut() -> f64 {
        let mut now = 0.0;
        move || {
            now += 1.0;
            now
        }
    }

    #[test]
    fn defaults_time_the_walking_human_with_sdls() {
        let mut clock = ticking_clock();
        let text = run(
            r#"{"frames": 10, "repeats": 3, "warmup_frames": 0}"#,
            &mut clock,
        )
        .expect("bench runs");
        let value: Value = serde_json::from_str(&text).expect("JSON");
        assert_eq!(value["preset"], "human");
        assert_eq!(value["mode"], "walk");
        assert_eq!(value["method"], "sdls");
        // One clock tick (1 ms) per 10 frames: 100 µs per frame.
        assert!((value["us_per_frame"].as_f64().unwrap_or(0.0) - 100.0).abs() < 1e-9);
    }

    #[test]
    fn a_poda_preset_times_the_gait_engine() {
        let mut clock = ticking_clock();
        let text = run(
            r#"{"preset": "poda-quadruped", "frames": 20, "repeats": 3, "warmup_frames": 5}"#,
            &mut clock,
        )
        .expect("bench runs");
        let value: Value = serde_json::from_str(&text).expect("JSON");
        assert_eq!(value["engine"], "poda");
        // One tick (1 ms) per 20 frames: 50 µs per frame.
        assert!((value["us_per_frame"].as_f64().unwrap_or(0.0) - 50.0).abs() < 1e-9);
    }

    #[test]
    fn a_physics_preset_times_integration_steps() {
        let mut clock = ticking_clock();
        let text = run(r#"{"preset": "raibert-biped", "repeats": 3}"#, &mut clock).expect("runs");
        let value: Value = serde_json::from_str(&text).expect("JSON");
        assert_eq!(value["engine"], "physics");
        assert!(
            value["steps_per_second"].as_f64().is_some_and(|s| s > 0.0),
            "{value}"
        );
        assert!((value["dt_s"].as_f64().unwrap_or_default() - 0.0004).abs() < 1e-12);
    }

    #[test]
    fn bad_options_name_the_field() {
        let mut clock = ticking_clock();
        for (options, field) in [
            (r#"{"method": "magic"}"#, "bench.method"),
            (r#"{"frames": -1}"#, "frames"),
            (r#"{"frames": 0}"#, "bench.frames"),
            (r#"{"preset": "dragon"}"#, "bench.preset"),
            (r#"{"speed": 1}"#, "bench.speed"),
            ("[1]", "bench: options"),
        ] {
            let error = run(options, &mut clock).expect_err(options);
            assert!(error.starts_with(field), "{options}: {error}");
        }
    }
}
