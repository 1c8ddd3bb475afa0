//! `window.gaitlab.bench(json)`: the benchmarks run inside the page, so the
//! browser's figures can be compared with `gaitlab bench`'s native ones for
//! the same work. One case (`{}`, `{"preset": …, "method": …}`): the per-frame
//! benchmark of [`gaitlab_bench::frame`] (or physics steps per second;
//! issue 3's wasm/native ratio). The whole suite (`{"suite": true}`): the
//! report of [`gaitlab_bench::run_suite`], the very routine behind
//! `gaitlab bench --json`, with the same rows, fields and `cases` map (issue 7's
//! native vs wasm table). Options are plain JSON data, checked field by field.

use gaitlab_bench::frame::{self as frame_bench, FrameBenchOptions, MAX_BENCH_REPEATS};
use gaitlab_bench::{DEFAULT_PRESETS, SuiteOptions, run_suite};
use gaitlab_core::ik::Method;
use gaitlab_core::preset::load_bundled;
use gaitlab_core::preset::thesis::ThesisMode;
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

/// A list of names under `key` (`default` when absent).
fn names(object: &Map<String, Value>, key: &str, default: &[&str]) -> Result<Vec<String>, String> {
    match object.get(key) {
        None => Ok(default.iter().map(|&n| n.to_owned()).collect()),
        Some(Value::Array(items)) => items
            .iter()
            .enumerate()
            .map(|(i, item)| {
                item.as_str()
                    .map(str::to_owned)
                    .ok_or_else(|| format!("bench.{key}[{i}]: expected a string"))
            })
            .collect(),
        Some(_) => Err(format!("bench.{key}: expected a list of names")),
    }
}

/// The whole suite, as `gaitlab bench --json` reports it (plus
/// `"platform": "wasm"`). Options: `suite` (true), `presets` (default: the
/// CLI's), `methods` (default: all five), `repeats` (default 15).
fn suite(object: &Map<String, Value>, clock_ms: &mut dyn FnMut() -> f64) -> Result<String, String> {
    const KNOWN: [&str; 4] = ["suite", "presets", "methods", "repeats"];
    if let Some(unknown) = object.keys().find(|k| !KNOWN.contains(&k.as_str())) {
        return Err(format!("bench.{unknown}: unknown option with \"suite\""));
    }
    if object.get("suite") != Some(&Value::Bool(true)) {
        return Err("bench.suite: expected true".to_owned());
    }
    let defaults = SuiteOptions::default();
    let repeats = count(object, "repeats", defaults.repeats).map_err(|e| format!("bench.{e}"))?;
    if repeats == 0 || repeats > MAX_BENCH_REPEATS {
        return Err(format!(
            "bench.repeats: must be between 1 and {MAX_BENCH_REPEATS}"
        ));
    }
    let all_methods: Vec<&str> = defaults.methods.iter().map(|m| m.name()).collect();
    let methods = names(object, "methods", &all_methods)?
        .iter()
        .enumerate()
        .map(|(i, name)| {
            Method::parse(name)
                .ok_or_else(|| format!("bench.methods[{i}]: unknown method {name:?}"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let creatures = names(object, "presets", &DEFAULT_PRESETS)?
        .iter()
        .enumerate()
        .map(|(i, preset)| match load_bundled(preset) {
            Some(Ok(creature)) => Ok(creature),
            Some(Err(error)) => Err(format!("bench.presets[{i}]: {preset}: {error}")),
            None => Err(format!(
                "bench.presets[{i}]: no bundled preset named {preset:?}"
            )),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let options = SuiteOptions { methods, repeats };
    let mut report = run_suite(&creatures, &options, clock_ms).map_err(|e| format!("bench.{e}"))?;
    report["platform"] = "wasm".into();
    Ok(report.to_string())
}

/// Runs the benchmark described by `json` (`{}` or empty: the human, walking,
/// SDLS, 600 frames × 15 repeats) and returns the result as JSON text:
/// `preset`, `mode`, `method`, `frames`, `repeats`, `iterations_per_frame`,
/// `us_per_frame` (median) and `us_per_frame_best`. With `"suite": true`, the
/// whole suite of `gaitlab bench --json` instead.
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
    if object.contains_key("suite") {
        return suite(object, clock_ms);
    }
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
    // A validated preset has a physical model exactly when it runs on the
    // physics engine.
    if creature.scenario.physics.is_some() {
        // Physics: integration steps per second, as `gaitlab bench` reports.
        let step_options = gaitlab_bench::step::StepBenchOptions {
            repeats: options.repeats,
            ..Default::default()
        };
        let timing = gaitlab_bench::step::time_steps(&creature, &step_options, clock_ms)
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
    fn the_suite_reports_the_cli_s_cases_and_fields() {
        let mut clock = ticking_clock();
        let text = run(
            r#"{"suite": true, "presets": ["human", "poda-biped", "raibert-biped"], "methods": ["dls"], "repeats": 3}"#,
            &mut clock,
        )
        .expect("suite runs");
        let value: Value = serde_json::from_str(&text).expect("JSON");
        assert_eq!(value["platform"], "wasm");
        let cases: Vec<&str> = value["cases"]
            .as_object()
            .map(|c| c.keys().map(String::as_str).collect())
            .unwrap_or_default();
        assert_eq!(
            cases,
            [
                "ik/human/dls/frame",
                "ik/human/dls/iteration",
                "physics/raibert-biped/step",
                "poda/poda-biped/frame",
            ]
        );
        // The fields `gaitlab bench --json` prints for each engine's rows.
        for (section, fields) in [
            (
                "ik",
                &[
                    "preset",
                    "method",
                    "us_per_iteration",
                    "us_per_frame",
                    "within_budget",
                ][..],
            ),
            (
                "poda",
                &["preset", "legs", "us_per_frame", "us_per_frame_best"][..],
            ),
            (
                "physics",
                &["preset", "steps_per_second", "realtime_factor"][..],
            ),
        ] {
            for field in fields {
                assert!(
                    value[section][0].get(*field).is_some(),
                    "{section}.{field}: {value}"
                );
            }
        }
        // One 1 ms tick per 600 frames.
        let frame = value["poda"][0]["us_per_frame"]
            .as_f64()
            .unwrap_or_default();
        assert!((frame - 1e3 / 600.0).abs() < 1e-9, "{frame}");
    }

    #[test]
    fn bad_suite_options_name_the_field() {
        let mut clock = ticking_clock();
        for (options, field) in [
            (r#"{"suite": false}"#, "bench.suite"),
            (r#"{"suite": true, "frames": 5}"#, "bench.frames"),
            (r#"{"suite": true, "presets": "human"}"#, "bench.presets"),
            (
                r#"{"suite": true, "presets": ["dragon"]}"#,
                "bench.presets[0]",
            ),
            (
                r#"{"suite": true, "methods": ["sdls", 3]}"#,
                "bench.methods[1]",
            ),
            (
                r#"{"suite": true, "methods": ["magic"]}"#,
                "bench.methods[0]",
            ),
            (r#"{"suite": true, "repeats": 0}"#, "bench.repeats"),
        ] {
            let error = run(options, &mut clock).expect_err(options);
            assert!(error.starts_with(field), "{options}: {error}");
        }
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
