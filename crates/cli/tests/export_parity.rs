//! The browser lab's motion-take downloads equal `gaitlab run`'s files for the
//! same state (issue 6 "Export": "a BVH exported from the browser and from the
//! CLI for the same state are identical"), natively: the lab (paused, reset,
//! recording on, stepped exactly K frames through the command API, as the page
//! is driven by tests/e2e/export.test.mjs) against the binary run for K frames
//! at the preset's fps — for an IK, a PODA and a physics creature, the whole
//! take and its last N seconds (`save.last_s` against `--last`).

mod common;

use common::{gaitlab_ok, scratch_arg};
use gaitlab_app::{App, Settings};

/// The CLI's BVH and CSV for `args` (preset first).
fn cli_files(tag: &str, args: &[&str]) -> (String, String) {
    let bvh = scratch_arg(&format!("{tag}.bvh"));
    let csv = scratch_arg(&format!("{tag}.csv"));
    let mut all = vec!["run"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--bvh", &bvh, "--csv", &csv]);
    gaitlab_ok(&all);
    (
        std::fs::read_to_string(bvh).expect("BVH written"),
        std::fs::read_to_string(csv).expect("CSV written"),
    )
}

/// The lab's BVH and CSV downloads after `setup`, reset, and `frames` single
/// steps with recording on; `last_s` as in the `save` command.
fn lab_files(setup: &str, frames: usize, last_s: Option<f64>) -> (String, String) {
    let mut lab = App::new(Settings::default());
    lab.command(setup).expect("setup command");
    lab.command(r#"{"paused": true, "reset": true, "record": true}"#)
        .expect("record");
    for _ in 0..frames {
        lab.command(r#"{"step": true}"#).expect("step");
        lab.advance(0.0);
    }
    let mut save = |format: &str| {
        let command = serde_json::json!({"save": {"format": format, "last_s": last_s}});
        lab.command(&command.to_string()).expect("save");
        lab.take_download().expect("a download").text
    };
    (save("bvh"), save("csv"))
}

fn frame_count(bvh: &str) -> usize {
    bvh.lines()
        .find_map(|l| l.strip_prefix("Frames:"))
        .and_then(|n| n.trim().parse().ok())
        .expect("a Frames: line")
}

fn assert_same(what: &str, lab: &str, cli: &str) {
    if lab == cli {
        return;
    }
    let line = lab
        .lines()
        .zip(cli.lines())
        .position(|(a, b)| a != b)
        .unwrap_or(lab.lines().count().min(cli.lines().count()));
    panic!(
        "{what}: lab and CLI differ first at line {} ({} vs {} lines)\nlab: {:?}\ncli: {:?}",
        line + 1,
        lab.lines().count(),
        cli.lines().count(),
        lab.lines().nth(line),
        cli.lines().nth(line)
    );
}

#[test]
fn the_human_walking_with_sdls_gives_the_same_files_in_the_lab_and_the_cli() {
    let (bvh, csv) = lab_files(
        r#"{"preset": "human", "mode": "walk", "method": "sdls"}"#,
        120,
        None,
    );
    let (cli_bvh, cli_csv) = cli_files(
        "human",
        &[
            "human",
            "--mode",
            "walk",
            "--method",
            "sdls",
            "--seconds",
            "2",
        ],
    );
    assert_eq!(frame_count(&bvh), 120);
    assert_same("human BVH", &bvh, &cli_bvh);
    assert_same("human CSV", &csv, &cli_csv);
}

#[test]
fn the_last_seconds_of_a_take_equal_the_cli_last_option() {
    let (bvh, csv) = lab_files(
        r#"{"preset": "human", "mode": "run", "method": "dls"}"#,
        150,
        Some(1.0),
    );
    let (cli_bvh, cli_csv) = cli_files(
        "human-last",
        &[
            "human",
            "--mode",
            "run",
            "--method",
            "dls",
            "--seconds",
            "2.5",
            "--last",
            "1",
        ],
    );
    assert_eq!(frame_count(&bvh), 60, "the last 1 s at 60 fps");
    assert_same("last-second BVH", &bvh, &cli_bvh);
    assert_same("last-second CSV", &csv, &cli_csv);
    // The CSV's first row is frame 91 of 150, at t = 91/60 s.
    let first_t: f64 = csv
        .lines()
        .nth(1)
        .and_then(|row| row.split(',').next())
        .and_then(|t| t.parse().ok())
        .expect("a first row");
    assert!(
        (first_t - 91.0 / 60.0).abs() < 1e-9,
        "first row at {first_t} s"
    );
}

#[test]
fn a_poda_gait_gives_the_same_files_in_the_lab_and_the_cli() {
    let (bvh, csv) = lab_files(r#"{"preset": "poda-quadruped"}"#, 90, None);
    let (cli_bvh, cli_csv) = cli_files("poda", &["poda-quadruped", "--seconds", "1.5"]);
    assert_eq!(frame_count(&bvh), 90);
    assert_same("PODA BVH", &bvh, &cli_bvh);
    assert_same("PODA CSV", &csv, &cli_csv);
}

#[test]
fn a_physics_runner_gives_the_same_files_in_the_lab_and_the_cli() {
    let (bvh, csv) = lab_files(r#"{"preset": "raibert-biped"}"#, 90, None);
    let (cli_bvh, cli_csv) = cli_files("physics", &["raibert-biped", "--seconds", "1.5"]);
    assert_eq!(frame_count(&bvh), 90);
    assert_same("physics BVH", &bvh, &cli_bvh);
    assert_same("physics CSV", &csv, &cli_csv);
}
