//! The figures of a run, with the timing fields (`wall_ms`, `us_per_frame`,
//! `us_per_iteration`, `steps_per_second`, `realtime_factor`) left out:
//!
//! - `gaitlab run PRESET --seconds 10 --json` for every bundled preset against
//!   the figures recorded before the engine layer (issue 17) was built, to the
//!   last bit. A deliberate change of an engine's motion re-records them:
//!   `GAITLAB_UPDATE_GOLDEN=1 cargo test -p gaitlab-cli --test run_metrics`,
//!   and the commit says why the figures moved.
//! - The page's `state().views[0].metrics` against `gaitlab run --json` for the same
//!   frames (the engine layer's one metrics type): the lab, paused and stepped
//!   exactly K frames through the command API, against the binary run for K
//!   frames at the preset's fps, for an IK, a PODA and a physics creature.

mod common;

use std::path::PathBuf;

use common::{bundled_names, gaitlab_ok, run_json, without_timing};
use gaitlab_app::{App, Settings};
use serde_json::Value;

fn golden_dir() -> PathBuf {
    [env!("CARGO_MANIFEST_DIR"), "tests", "golden", "run-10s"]
        .iter()
        .collect()
}

#[test]
fn every_bundled_preset_runs_as_recorded() {
    let update = std::env::var_os("GAITLAB_UPDATE_GOLDEN").is_some();
    let names = bundled_names();
    assert!(names.len() >= 9, "bundled presets: {names:?}");
    let mut differ = Vec::new();
    for name in &names {
        let output = gaitlab_ok(&["run", name, "--seconds", "10", "--json"]);
        let got: Value = serde_json::from_slice(&output.stdout).expect("one JSON object");
        let got = without_timing(got);
        let path = golden_dir().join(format!("{name}.json"));
        if update {
            let text = serde_json::to_string_pretty(&got).expect("serializes") + "\n";
            std::fs::write(&path, text).expect("golden file is writable");
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| {
            panic!(
                "{}: {e} (record it with GAITLAB_UPDATE_GOLDEN=1)",
                path.display()
            )
        });
        let want: Value = serde_json::from_str(&text).expect("golden file is JSON");
        if got != want {
            differ.push(format!("{name}:\n  recorded {want}\n  now      {got}"));
        }
    }
    assert!(
        differ.is_empty(),
        "the run figures moved (re-record with GAITLAB_UPDATE_GOLDEN=1 only for a deliberate change):\n{}",
        differ.join("\n")
    );
}

/// DESIGN.md "Versions": the hexapod preset as it was on 2026-12-01, with
/// its `vertical_gain` 0.3 (deprecated on 2026-12-02: eq. 12–13 have no
/// gain), runs exactly as recorded then, and says the value is deprecated.
#[test]
fn a_preset_with_the_deprecated_vertical_gain_runs_as_it_was_made() {
    let fixtures: PathBuf = [env!("CARGO_MANIFEST_DIR"), "tests", "fixtures"]
        .iter()
        .collect();
    let preset = fixtures.join("hexapod_2026_12_01.json");
    let output = gaitlab_ok(&[
        "run",
        preset.to_str().expect("utf-8 path"),
        "--seconds",
        "10",
        "--json",
    ]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.starts_with("warning: scenario.poda.vertical_gain: 0.3 is deprecated"),
        "{stderr}"
    );
    let mut got = without_timing(serde_json::from_slice(&output.stdout).expect("JSON"));
    let text = std::fs::read_to_string(fixtures.join("hexapod_2026_12_01.run-10s.json"))
        .expect("recorded figures");
    let mut want: Value = serde_json::from_str(&text).expect("JSON");
    // The gait list grows with new gaits and figures are added (the file
    // made no pitch then, `body_pitch_range_deg` is 0): the motion's figures
    // recorded then are what must not move.
    for figures in [&mut got, &mut want] {
        figures.as_object_mut().map(|o| o.remove("gaits_available"));
    }
    assert_eq!(got["body_pitch_range_deg"], serde_json::json!([0.0, 0.0]));
    if let (Some(got), Some(want)) = (got.as_object_mut(), want.as_object()) {
        got.retain(|key, _| want.contains_key(key));
    }
    assert_eq!(got, want);
}

/// The fixture preset `name`.json run 10 s: all its figures, those of them
/// the recording has, and the figures recorded then (`name`.run-10s.json).
fn replay(name: &str) -> (Value, Value, Value) {
    let fixtures: PathBuf = [env!("CARGO_MANIFEST_DIR"), "tests", "fixtures"]
        .iter()
        .collect();
    let preset = fixtures.join(format!("{name}.json"));
    let path = preset.to_str().expect("utf-8 path");
    let all = without_timing(run_json(path, "10", &[]));
    let text = std::fs::read_to_string(fixtures.join(format!("{name}.run-10s.json")))
        .expect("recorded figures");
    let mut want: Value = serde_json::from_str(&text).expect("JSON");
    let mut got = all.clone();
    if let (Some(got), Some(want)) = (got.as_object_mut(), want.as_object_mut()) {
        want.remove("gaits_available");
        // The list names the additions by today's names: the hop integrator,
        // always on until 2026-12-06, is one since (each test checks it).
        want.remove("lab_additions");
        got.retain(|key, _| want.contains_key(key));
    }
    (all, got, want)
}

/// DESIGN.md "Versions": the biped preset as it was on 2026-12-02, before
/// the lab's additions to the physics control were optional (no
/// `lab_additions`), runs exactly as recorded then: with the speed trim and
/// the earlier eq. 3 gain, where the bundled preset now runs the paper's
/// laws.
#[test]
fn a_physics_preset_made_before_the_lab_additions_runs_as_it_was_made() {
    let (all, got, want) = replay("raibert-biped_2026_12_02");
    assert_eq!(
        all["lab_additions"],
        serde_json::json!(["speed_trim", "unloading_posture", "hop_integrator"])
    );
    assert_eq!(got, want);
    // The bundled preset now runs the biped by the paper's laws alone.
    let now = run_json("raibert-biped", "10", &[]);
    assert_eq!(now["lab_additions"], serde_json::json!([]));
    assert_ne!(now["speed_mean_mps"], want["speed_mean_mps"]);
}

/// DESIGN.md "Versions": the bundled biped as it was later on 2026-12-02,
/// with `lab_additions: {}` but before control every 2 ms and its yaw
/// damping were written into the bundled preset: a file without
/// `control_every` and `controller` runs exactly as recorded then (control
/// every 0.4 ms step, the controller's own yaw damping).
#[test]
fn a_physics_preset_made_before_control_every_two_ms_runs_as_it_was_made() {
    let (all, got, want) = replay("raibert-biped_2026_12_02b");
    assert_eq!(
        all["lab_additions"],
        serde_json::json!(["unloading_posture", "hop_integrator"])
    );
    assert_eq!(got, want);
}

/// DESIGN.md "Versions": the bundled quadruped as it was on 2026-12-03,
/// before its trot carried gains of its own (`controller_by_gait.trot`):
/// the file runs exactly as recorded then, with the trot controller's own
/// gains, and the bundled quadruped now trots differently.
#[test]
fn the_quadruped_preset_from_before_its_trot_gains_runs_as_it_was_made() {
    let (_, got, want) = replay("raibert-quadruped_2026_12_03");
    assert_eq!(got, want);
    let now = run_json("raibert-quadruped", "10", &[]);
    assert_ne!(now["pitch_magnitude_deg"], want["pitch_magnitude_deg"]);
}

/// DESIGN.md "Versions": the bundled quadruped as it was on 2026-12-04,
/// before it took the pitching bound's body and gains (Table 3's trunk
/// inertia read as [0.054 0.235 0.239] kg·m²), saved bounding at 2.8 m/s:
/// the file runs exactly as recorded then (the low skip with the speed
/// trim), and the bundled quadruped now bounds pitching by the paper's laws.
#[test]
fn the_quadruped_preset_from_before_the_pitching_bound_runs_as_it_was_made() {
    let (all, got, want) = replay("raibert-quadruped_2026_12_04");
    assert_eq!(
        all["lab_additions"],
        serde_json::json!(["speed_trim", "hop_integrator"])
    );
    assert_eq!(got, want);
    let now = run_json(
        "raibert-quadruped",
        "10",
        &["--gait", "bound", "--speed", "2.8"],
    );
    // By eq. 2 alone since the night of 2026-12-06, and changing gait by
    // the paper's take-over since the take-over tune: no addition.
    assert_eq!(now["lab_additions"], serde_json::json!([]));
    let (was, is) = (&want["pitch_magnitude_deg"], &now["pitch_magnitude_deg"]);
    assert!(
        was.as_f64() < Some(5.0) && is.as_f64() > Some(20.0),
        "{was} → {is}"
    );
}

/// DESIGN.md "Versions": the bundled kangaroo as it was on 2026-12-03,
/// before it started on its hopping cycle with the tuner's gains and the
/// tail only stepped: the file runs exactly as recorded then (from the
/// gait's own start at 2 m/s, the speed ramp and the tail feedback on), and
/// the bundled kangaroo now starts at speed by the paper's laws.
#[test]
fn the_kangaroo_preset_from_before_its_start_on_the_cycle_runs_as_it_was_made() {
    let (all, got, want) = replay("raibert-kangaroo_2026_12_03");
    assert_eq!(all["start"], "gait");
    assert_eq!(
        all["lab_additions"],
        serde_json::json!(["speed_ramp", "tail_feedback", "hop_integrator"])
    );
    assert_eq!(got, want);
    let now = run_json("raibert-kangaroo", "10", &[]);
    assert_eq!(now["start"], "on_cycle");
    assert_eq!(
        now["lab_additions"],
        serde_json::json!(["speed_ramp", "hop_integrator"])
    );
    let (was, is) = (&want["speed_mean_mps"], &now["speed_mean_mps"]);
    assert!(
        was.as_f64() < Some(4.0) && is.as_f64() > Some(4.5),
        "{was} → {is}"
    );
}

/// DESIGN.md "Versions": the bundled biped as it was on 2026-12-03, before
/// its gallops carried gains of their own (`controller_by_gait.gallop`,
/// `.gallop_alternate`) and turned the speed trim off, saved galloping: the
/// file runs exactly as recorded then (the trim on, the controller's own
/// gains), and the bundled biped now gallops by the paper's laws alone
/// (eq. 2 too, since 2026-12-06).
#[test]
fn the_biped_preset_from_before_its_gallop_gains_runs_as_it_was_made() {
    let (all, got, want) = replay("raibert-biped_2026_12_03");
    assert_eq!(
        all["lab_additions"],
        serde_json::json!(["speed_trim", "hop_integrator"])
    );
    assert_eq!(got, want);
    let now = run_json(
        "raibert-biped",
        "10",
        &["--gait", "gallop", "--speed", "1.5"],
    );
    assert_eq!(now["lab_additions"], serde_json::json!([]));
    assert_ne!(now["pitch_magnitude_deg"], want["pitch_magnitude_deg"]);
}

/// DESIGN.md "Versions": the she-2006 preset as it was on 2026-12-04 (a
/// `gaitlab-preset/1` file), saved with DLS, before She 2006's step clamp
/// became pinv's alone, the transpose took §4.4.1's α and λ its measured
/// 0.2 m: the file runs exactly as recorded then (the clamp on DLS, λ =
/// 0.05 m; the walking feet 45.6 mm off), and the bundled she-2006 now
/// tracks them to 2 mm with nothing of the lab's.
#[test]
fn the_she_2006_preset_from_before_the_thesis_solver_runs_as_it_was_made() {
    let (all, got, want) = replay("she-2006_2026_12_04");
    assert_eq!(
        all["lab_additions"],
        serde_json::json!(["clamp_every_method"])
    );
    assert_eq!(got, want);
    let now = run_json("she-2006", "10", &["--method", "dls"]);
    assert_eq!(now["lab_additions"], serde_json::json!([]));
    let feet = |run: &Value| run["effectors"][0]["mean_error_m"].as_f64();
    let (was, is) = (feet(&want), feet(&now));
    assert!(
        was > Some(0.04) && is < Some(0.003),
        "left foot {was:?} → {is:?} m"
    );
}

/// DESIGN.md "Versions": the poda-quadruped preset as it was on 2026-12-06
/// (a `gaitlab-preset/1` file), saved bounding, before Figure 2's body
/// pitch and eq. 2's foot orientation were on by default: the file runs
/// exactly as recorded then (level, `without_body_pitch` and
/// `without_foot_orientation` listed), and the bundled quadruped now pitches
/// as it bounds, with nothing left out.
#[test]
fn the_poda_quadruped_from_before_the_body_pitch_runs_as_it_was_made() {
    let (all, got, want) = replay("poda-quadruped_2026_12_06");
    assert_eq!(
        all["lab_additions"],
        serde_json::json!([
            "turn_within_reach",
            "yaw_toward_actual",
            "fore_aft_surge",
            "without_body_pitch",
            "without_foot_orientation"
        ])
    );
    assert_eq!(got, want);
    assert_eq!(want["body_pitch_range_deg"], serde_json::json!([0.0, 0.0]));
    let now = run_json("poda-quadruped", "10", &["--gait", "bound"]);
    assert_eq!(
        now["lab_additions"],
        serde_json::json!(["turn_within_reach", "yaw_toward_actual", "fore_aft_surge"])
    );
    let pitch = &now["body_pitch_range_deg"];
    assert!(
        pitch[0].as_f64() < Some(-10.0) && pitch[1].as_f64() > Some(10.0),
        "{pitch}"
    );
}

/// Raibert & Hodgins 1991, "Modeling", read as the paper reads it: the
/// friction needed in the middle of each support apart from its first and
/// last 10 ms, and the peak vertical force on each leg (issue 42's
/// baseline, docs/physics.md "Friction and force"). The paper-only trot
/// needs far more at the edges than in the middle (12.4 against 3.7 on
/// 2026-12-06); every figure is within the whole-support one, and no leg
/// carries more than all of them together.
#[test]
fn the_friction_needed_is_read_apart_at_the_supports_edges() {
    let run = run_json("raibert-quadruped", "8", &["--paper-alone"]);
    let figure = |key: &str| run[key].as_f64().unwrap_or(f64::NAN);
    let (max, mid, edges) = (
        figure("friction_needed_max"),
        figure("friction_needed_mid"),
        figure("friction_needed_edges"),
    );
    assert!(
        mid > 0.0 && mid <= max && edges <= max,
        "{mid} {edges} {max}"
    );
    assert!(
        edges > 2.0 * mid,
        "edges {edges} against the middle's {mid}"
    );
    let legs: Vec<f64> = run["peak_leg_force_bw"]
        .as_array()
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default();
    let total = figure("peak_vertical_force_bw");
    assert_eq!(legs.len(), 4, "{run}");
    assert!(
        legs.iter().all(|&leg| leg > 1.0 && leg <= total + 1e-9),
        "{legs:?} against {total}"
    );
}

fn cli_metrics(preset: &str, seconds: &str) -> Value {
    run_json(preset, seconds, &[])
}

fn lab_metrics(preset: &str, frames: usize) -> Value {
    let mut lab = App::new(Settings::default());
    lab.command(&serde_json::json!({"preset": preset}).to_string())
        .expect("preset");
    lab.command(r#"{"paused": true, "reset": true}"#)
        .expect("pause");
    for _ in 0..frames {
        lab.command(r#"{"step": true}"#).expect("step");
        lab.advance(0.0);
    }
    let state: Value = serde_json::from_str(&lab.state_json()).expect("state is JSON");
    state["views"][0]["metrics"].clone()
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

#[test]
fn a_physics_run_carries_table_2_for_its_gait() {
    // The bound: all ten animation rows, the pairs' flights and stances too.
    let bound = run_json(
        "raibert-quadruped",
        "6",
        &["--gait", "bound", "--speed", "2.8"],
    );
    let rows = bound["table2"].as_array().expect("table2 array");
    let names: Vec<&str> = rows.iter().filter_map(|r| r["quantity"].as_str()).collect();
    assert_eq!(rows.len(), 10, "{names:?}");
    for want in [
        "gathered flight (s)",
        "extended flight (s)",
        "stance, front legs (s)",
        "stance, rear legs (s)",
        "error in running speed (m/s)",
    ] {
        assert!(names.contains(&want), "{want} missing from {names:?}");
    }
    // Each difference is the measured figure against the paper's.
    for r in rows {
        if let (Some(m), Some(p), Some(d)) = (
            r["measured"].as_f64(),
            r["paper"].as_f64(),
            r["diff_pct"].as_f64(),
        ) {
            assert!((d - (m / p - 1.0) * 100.0).abs() < 1e-9, "{r}");
        }
    }
    let speed = rows
        .iter()
        .find(|r| r["quantity"] == "running speed (m/s)")
        .and_then(|r| r["measured"].as_f64());
    assert_eq!(speed, bound["speed_mean_mps"].as_f64());
    // The kangaroo: the tail wag, the desired speed as an input, and the
    // peak acceleration as ground force over weight less 1 g.
    let hop = run_json("raibert-kangaroo", "6", &[]);
    let rows = hop["table2"].as_array().expect("table2 array");
    assert_eq!(rows.len(), 8);
    let row = |q: &str| rows.iter().find(|r| r["quantity"] == q).cloned();
    let tail = row("tail wag relative to trunk (deg)").expect("tail row");
    assert!(tail["measured"].as_f64().is_some_and(|w| w > 5.0), "{tail}");
    let desired = row("desired running speed (m/s)").expect("desired row");
    assert_eq!(desired["input"], true);
    assert_eq!(desired["measured"], hop["speed_desired_mps"]);
    let accel = hop["peak_vertical_accel_g"].as_f64().unwrap_or(f64::NAN);
    let force = hop["peak_vertical_force_bw"].as_f64().unwrap_or(f64::NAN);
    assert!(
        (force - accel - 1.0).abs() < 1e-12 && accel > 1.0,
        "{accel} g, {force} × weight"
    );
    // A gait the paper does not tabulate: no rows.
    let gallop = run_json("raibert-biped", "2", &["--gait", "gallop"]);
    assert_eq!(gallop["table2"].as_array().map(Vec::len), Some(0));
}

/// DESIGN.md "Versions", issue 41 item 2: the human and ik-quadruped presets
/// as they were on 2026-12-06 (`gaitlab-preset/1` files, so with the lab's
/// old defaults written in: its script, the posture pull, the start ramp and
/// the limit re-solve) run exactly as recorded then. The bundled files are
/// now `gaitlab-preset/2` and keep only the additions without which they
/// fail a claim of She 2006 (docs/parameters.md "Both ways",
/// `tools/ik_additions_both_ways.py`): the human none, so it runs §5.2.2's
/// listing with its hands out of reach (§5.3); ik-quadruped the lab's script
/// alone, without which its walking feet are out of reach (§5.3, Figure 5.10).
#[test]
fn the_ik_presets_from_before_the_rule_on_additions_run_as_they_were_made() {
    let old_lab = serde_json::json!(["limit_re_solve", "lab_script", "posture_pull", "start_ramp"]);
    let error = |run: &Value, i: usize| run["effectors"][i]["mean_error_m"].as_f64();
    let reach = |run: &Value, i: usize| run["effectors"][i]["reachable"].as_f64();

    let (all, got, want) = replay("human_2026_12_06");
    assert_eq!(all["lab_additions"], old_lab);
    assert_eq!(got, want);
    let now = run_json("human", "10", &[]);
    assert_eq!(now["lab_additions"], serde_json::json!([]));
    assert_eq!(now["within_limits"], true);
    // Feet 0, 1 on their reachable targets both ways; the hands (2, 3) were
    // on the lab's targets in front and are now out of reach of the listing's.
    for i in [0, 1] {
        assert!(
            error(&want, i) < Some(1e-6) && error(&now, i) < Some(1e-6),
            "foot {i}"
        );
        assert_eq!(reach(&now, i), Some(1.0), "foot {i}");
    }
    for i in [2, 3] {
        let (was, is) = (error(&want, i), error(&now, i));
        assert!(
            was < Some(1e-6) && is > Some(0.2),
            "hand {i}: {was:?} → {is:?} m"
        );
        assert_eq!(reach(&now, i), Some(0.0), "hand {i}");
    }

    let (all, got, want) = replay("ik-quadruped_2026_12_06");
    assert_eq!(all["lab_additions"], old_lab);
    assert_eq!(got, want);
    let now = run_json("ik-quadruped", "10", &[]);
    assert_eq!(now["lab_additions"], serde_json::json!(["lab_script"]));
    assert_eq!(now["within_limits"], true);
    let paper = run_json("ik-quadruped", "10", &["--paper-alone"]);
    // The hind feet (2, 3) play the thesis' feet: on their targets with the
    // lab's script, as before; out of reach of the listing's by 0.3 m.
    for i in [2, 3] {
        assert!(
            error(&want, i) < Some(1e-6) && error(&now, i) < Some(1e-3),
            "hind foot {i}"
        );
        assert_eq!(reach(&now, i), Some(1.0), "hind foot {i}");
        assert!(error(&paper, i) > Some(0.3), "hind foot {i}");
        assert_eq!(reach(&paper, i), Some(0.0), "hind foot {i}");
    }
}
