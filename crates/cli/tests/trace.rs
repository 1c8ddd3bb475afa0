//! `gaitlab run … --trace FILE.csv`: one row per integration step of a physics
//! run whose figures agree with `--json`'s, refused for the kinematic engines
//! and for a file that cannot be written.

mod common;

use common::{gaitlab, run_json, scratch_arg, without_timing};

/// The integration step of the bundled physics presets at scale 1 (s).
const STEP_S: f64 = 0.0004;

/// The trace's header and rows, each split at commas.
fn read_trace(path: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).expect("trace written");
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("a header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    (header, rows)
}

fn column(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

fn number(row: &[String], at: usize) -> f64 {
    row[at].parse().expect("a number")
}

#[test]
fn a_short_run_has_a_header_and_one_row_per_step() {
    let path = scratch_arg("biped-short.csv");
    let metrics = run_json("raibert-biped", "0.5", &["--trace", &path]);
    let (header, rows) = read_trace(&path);
    for name in [
        "time_s",
        "state",
        "state_index",
        "speed_desired_mps",
        "trunk_x_m",
        "trunk_y_m",
        "trunk_z_m",
        "com_vz_mps",
        "pitch_deg",
        "roll_deg",
        "yaw_deg",
        "ground_force_bw",
    ] {
        column(&header, name);
    }
    for leg in ["left", "right"] {
        for field in ["state", "touching", "length_m", "spring_rest", "force_y_n"] {
            column(&header, &format!("{leg}.{field}"));
        }
    }
    assert!(
        header.iter().any(|h| h.ends_with(".length_m")),
        "{header:?}"
    );
    assert!(
        header.iter().any(|h| h.ends_with(".force_y_n")),
        "{header:?}"
    );
    assert!(rows.iter().all(|r| r.len() == header.len()));
    let sim_seconds = metrics["sim_seconds"].as_f64().expect("sim_seconds");
    let steps = (sim_seconds / STEP_S).round() as usize;
    assert_eq!(rows.len(), steps, "{sim_seconds} s");
    let time = column(&header, "time_s");
    let last = rows.last().expect("rows");
    assert!((number(last, time) - sim_seconds).abs() < 1e-6);
    assert!((number(&rows[0], time) - STEP_S).abs() < 1e-9);
    let state = column(&header, "state");
    let states = ["flight", "loading", "compression", "thrust", "unloading"];
    assert!(rows.iter().all(|r| states.contains(&r[state].as_str())));
    let desired = column(&header, "speed_desired_mps");
    assert!(rows.iter().all(|r| {
        (number(r, desired) - metrics["speed_desired_mps"].as_f64().unwrap_or(f64::NAN)).abs()
            < 1e-9
    }));
}

/// The trace is the recorder's view: the mean speed over the settled part
/// (after 3 s) recomputed from the centre of mass equals `speed_mean_mps`,
/// and tracing changes none of the figures.
#[test]
fn the_mean_speed_from_the_trace_is_the_json_figure() {
    let path = scratch_arg("quadruped-6s.csv");
    let traced = run_json("raibert-quadruped", "6", &["--trace", &path]);
    let plain = run_json("raibert-quadruped", "6", &[]);
    assert_eq!(without_timing(traced.clone()), without_timing(plain));
    let (header, rows) = read_trace(&path);
    let (time, com_z) = (column(&header, "time_s"), column(&header, "com_z_m"));
    let first = rows
        .iter()
        .find(|r| number(r, time) >= 3.0 - 1e-9)
        .expect("a settled row");
    let last = rows.last().expect("rows");
    let speed =
        (number(last, com_z) - number(first, com_z)) / (number(last, time) - number(first, time));
    let want = traced["speed_mean_mps"].as_f64().expect("speed_mean_mps");
    assert!(
        (speed - want).abs() < 1e-4,
        "trace {speed} vs --json {want}"
    );
    assert!(want > 1.0, "the quadruped trots forward: {want}");
}

#[test]
fn the_kinematic_engines_and_unwritable_files_are_refused() {
    let path = scratch_arg("never.csv");
    for (preset, engine) in [("human", "ik"), ("poda-quadruped", "poda")] {
        let output = gaitlab(&["run", preset, "--seconds", "0.1", "--trace", &path]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{preset}: {stderr}");
        assert!(
            stderr.starts_with(&format!("error: --trace: engine {engine} has no")),
            "{stderr}"
        );
    }
    assert!(!std::path::Path::new(&path).exists());
    let missing = "/nonexistent-gaitlab-dir/trace.csv";
    let output = gaitlab(&[
        "run",
        "raibert-biped",
        "--seconds",
        "0.1",
        "--trace",
        missing,
    ]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.starts_with(&format!("error: --trace {missing}: ")),
        "{stderr}"
    );
}
