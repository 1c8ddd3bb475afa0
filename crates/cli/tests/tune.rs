//! `gaitlab tune` (issue 20, item 6): a seeded tune from deliberately
//! detuned gains (fixtures/raibert-biped-detuned.json: posture damping 20
//! for 160 N·m·s/rad, eq. 3's gain 0.02 for 0.12 s, leg spring 10 for
//! 20 kN/m; it blows up within 13 s) recovers a biped that runs without
//! falling within 10 % of its speed; the same seed gives the same preset
//! on one thread or two; bad arguments are named. A small tune: the long
//! ones are commands (docs/physics.md, "The gait tuner").

mod common;

use std::path::PathBuf;

use common::{gaitlab, gaitlab_ok, run_json};

fn fixture(name: &str) -> String {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "tests", "fixtures", name]
        .iter()
        .collect();
    path.to_str().expect("utf-8 path").to_owned()
}

fn tune(out: &std::path::Path, threads: &str) -> String {
    let output = gaitlab_ok(&[
        "tune",
        &fixture("raibert-biped-detuned.json"),
        "--budget",
        "100",
        "--seconds",
        "10",
        "--seed",
        "1",
        "--threads",
        threads,
        "--out",
        out.to_str().expect("utf-8 path"),
    ]);
    String::from_utf8_lossy(&output.stdout).into_owned()
}

#[test]
fn a_seeded_tune_recovers_a_detuned_biped_and_repeats_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("gaitlab-tune-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let (one, two) = (dir.join("one.json"), dir.join("two.json"));
    let printed = tune(&one, "1");
    tune(&two, "2");
    // One line per generation with the objective, and the start's cost
    // (a blow-up: the fall weight 10 and more) lowered.
    assert!(
        printed.contains("generation   0 ·     1 runs · best 10."),
        "{printed}"
    );
    assert!(
        printed
            .lines()
            .filter(|l| l.starts_with("generation"))
            .count()
            >= 10
    );
    let detuned = run_json(&fixture("raibert-biped-detuned.json"), "20", &[]);
    assert_eq!(detuned["fell"], true, "the fixture must start detuned");
    let a = std::fs::read(&one).expect("tuned preset");
    let b = std::fs::read(&two).expect("tuned preset");
    assert_eq!(a, b, "the same seed on 1 and 2 threads");
    // The tuned preset runs 30 s without falling, within 10 % of 1.6 m/s.
    let tuned = run_json(one.to_str().expect("utf-8 path"), "30", &[]);
    assert_eq!(tuned["fell"], false);
    let speed = tuned["speed_mean_mps"].as_f64().unwrap_or(0.0);
    assert!((speed / 1.6 - 1.0).abs() < 0.10, "tuned speed {speed}");
    let preset: serde_json::Value = serde_json::from_slice(&a).expect("JSON");
    // The tuned gains are the run's own; the file's gains for every gait
    // (the detuned posture damping 20) stay as they were for the others.
    let physics = &preset["scenario"]["physics"];
    let gains = &physics["controller_by_gait"]["run"];
    assert!(
        gains["posture_kv"]
            .as_f64()
            .is_some_and(|v| v > 0.0 && v != 20.0),
        "{gains}"
    );
    assert_eq!(physics["controller"]["posture_kv"], 20.0, "{physics}");
    gaitlab_ok(&["validate", one.to_str().expect("utf-8 path")]);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_tune_arguments_are_named() {
    let out = std::env::temp_dir().join("gaitlab-tune-never-written.json");
    let out = out.to_str().expect("utf-8 path");
    for (args, want) in [
        (
            vec!["--objective", "power=1"],
            "objective: unknown term \"power\"",
        ),
        (vec!["--objective", "speed=-2"], "objective.speed"),
        (vec!["--budget", "0"], "budget:"),
        (vec!["--sigma", "0"], "sigma:"),
        (vec!["--gait", "canter"], "scenario.physics.gait"),
        (vec!["--speed", "99"], "speed"),
        (vec!["--also-at", "1,99"], "also_at[1]"),
        (
            vec!["--vary", "thrust_m,stance"],
            "vary[1]: the run controller has no parameter `stance`",
        ),
        (
            vec!["--objective", "jump=1"],
            "objective.jump: only the kangaroo",
        ),
        (
            vec!["--objective", "fall=10,switch=1"],
            "objective.switch: name the gait its runs begin in with --switch-from or change to with --switch-to",
        ),
        (
            vec!["--objective", "switch=1", "--switch-from", "run"],
            "switch_from: the runs begin in run, the tuned gait",
        ),
        (
            vec!["--objective", "switch=1", "--switch-to", "run"],
            "switch_to: the runs change to run, the tuned gait",
        ),
        (
            vec!["--objective", "switch=1", "--switch-to", "trot"],
            "switch_to: scenario.physics.gait",
        ),
        (
            vec!["--objective", "switch=1", "--switch-from", "trot"],
            "switch_from: scenario.physics.gait",
        ),
    ] {
        let mut all = vec!["tune", "raibert-biped", "--out", out];
        all.extend(args);
        let output = gaitlab(&all);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{all:?}: {stderr}");
        assert!(stderr.contains(want), "{all:?}: {stderr}");
    }
    let output = gaitlab(&["tune", "human", "--out", out]);
    assert!(String::from_utf8_lossy(&output.stderr).contains("physics"));
    assert!(!std::path::Path::new(out).exists());
}
