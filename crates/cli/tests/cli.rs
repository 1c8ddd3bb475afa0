//! The `gaitlab` binary end to end: the DESIGN.md CLI contract, the issue's
//! acceptance figures (walk + SDLS foot error), bad input handling, and the BVH
//! round trip through the core's reader.

mod common;

use std::path::PathBuf;

use common::{bundled_preset, gaitlab, json_of, scratch};
use gaitlab_core::export::parse_bvh;
use serde_json::Value;

fn fixture(name: &str) -> String {
    let path: PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "core",
        "tests",
        "fixtures",
        name,
    ]
    .iter()
    .collect();
    path.to_string_lossy().into_owned()
}

fn effector_mean(metrics: &Value, name: &str) -> f64 {
    metrics["effectors"]
        .as_array()
        .expect("effectors")
        .iter()
        .find(|e| e["name"] == name)
        .and_then(|e| e["mean_error_m"].as_f64())
        .expect("mean error")
}

#[test]
fn presets_lists_the_bundled_creatures() {
    let output = gaitlab(&["presets"]);
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success());
    let human = text
        .lines()
        .find(|l| l.starts_with("human "))
        .expect("human listed");
    assert!(
        human.contains("engine=ik") && human.contains("joints=20") && human.contains("legs=2"),
        "{human}"
    );
    let quad = text
        .lines()
        .find(|l| l.starts_with("ik-quadruped"))
        .expect("quadruped listed");
    assert!(
        quad.contains("joints=63") && quad.contains("legs=4"),
        "{quad}"
    );
}

#[test]
fn walk_with_sdls_keeps_mean_foot_error_under_5_mm() {
    let metrics = json_of(&gaitlab(&[
        "run",
        "human",
        "--mode",
        "walk",
        "--method",
        "sdls",
        "--seconds",
        "20",
        "--json",
    ]));
    for key in [
        "preset",
        "engine",
        "frames",
        "sim_seconds",
        "wall_ms",
        "method",
        "us_per_iteration",
        "effectors",
    ] {
        assert!(metrics.get(key).is_some(), "missing key {key}");
    }
    assert_eq!(metrics["frames"], 1200);
    assert!((metrics["sim_seconds"].as_f64().expect("seconds") - 20.0).abs() < 1e-6);
    for foot in ["left_foot", "right_foot"] {
        let mean = effector_mean(&metrics, foot);
        assert!(mean <= 0.005, "{foot}: mean error {mean} m");
    }
    assert_eq!(metrics["within_limits"], true);
    assert!(
        metrics["distance_m"].as_f64().expect("distance") > 10.0,
        "moving forward covers ground"
    );
}

#[test]
fn bad_presets_exit_2_with_the_json_path() {
    let cases = [
        (
            "bad-axis.json",
            "error: skeleton.joints[3].axis: must be a non-zero vector",
        ),
        ("bad-cycle.json", "error: skeleton.joints["),
        ("bad-nan.json", "error: "),
        ("bad-truncated.json", "error: "),
        ("bad-huge-joints.json", "error: skeleton.joints: "),
        ("bad-limits.json", "error: skeleton.joints["),
    ];
    for (file, prefix) in cases {
        let output = gaitlab(&["validate", &fixture(file)]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{file}: {stderr}");
        assert!(stderr.starts_with(prefix), "{file}: {stderr}");
        assert!(!stderr.contains("panicked"), "{file}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{file}: one line: {stderr}");
    }
}

#[test]
fn oversized_and_missing_inputs_are_refused_cleanly() {
    let big = scratch("big.json");
    std::fs::write(&big, vec![b' '; 300 * 1024]).expect("write");
    let output = gaitlab(&["validate", big.to_str().expect("utf-8 path")]);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("larger than 256 KiB"));
    let output = gaitlab(&["run", "no-such-preset"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("no such bundled preset"));
    for args in [
        &["run", "human", "--method", "magic"][..],
        &["run", "human", "--mode", "fly"][..],
        &["run", "human", "--seconds=-1"][..],
        &["run", "human", "--seconds", "NaN"][..],
        &["run", "human", "--fps", "0"][..],
        &["run", "human", "--gait", "trot"][..],
    ] {
        let output = gaitlab(args);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.starts_with("error: --"), "{args:?}: {stderr}");
    }
}

#[test]
fn validate_accepts_the_bundled_presets() {
    let path: PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "..",
        "presets",
        "human.json",
    ]
    .iter()
    .collect();
    let output = gaitlab(&["validate", path.to_str().expect("utf-8 path")]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(
        text.starts_with("ok: human") && text.contains("20 joints") && text.contains("4 effectors"),
        "{text}"
    );
}

#[test]
fn bvh_of_a_5_second_walk_parses_back_with_every_joint_and_frame() {
    let bvh = scratch("walk.bvh");
    let csv = scratch("walk.csv");
    let output = gaitlab(&[
        "run",
        "human",
        "--mode",
        "walk",
        "--seconds",
        "5",
        "--fps",
        "30",
        "--bvh",
        bvh.to_str().expect("utf-8"),
        "--csv",
        csv.to_str().expect("utf-8"),
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let text = std::fs::read_to_string(&bvh).expect("bvh written");
    let parsed = parse_bvh(&text).expect("the BVH parses");
    // 20 joints plus the BVH root node.
    assert_eq!(parsed.joints.len(), 21);
    assert_eq!(parsed.frame_count, 150);
    assert!((parsed.frame_time - 1.0 / 30.0).abs() < 1e-9);
    // The root travels forward (+z) over the walk.
    let first = parsed.world_positions(0).expect("frame 0");
    let last = parsed.world_positions(149).expect("last frame");
    assert!(
        last[0].z - first[0].z > 3.0,
        "root moved {} m",
        last[0].z - first[0].z
    );
    let rows = std::fs::read_to_string(&csv).expect("csv written");
    assert_eq!(rows.lines().count(), 151, "header + one row per frame");
    assert!(rows.lines().next().expect("header").starts_with("t,root_x"));
}

/// A target CSV for `creature`: its rest effector positions plus a 3 s
/// sinusoidal sway of a few centimetres, in world coordinates, at 30 rows a
/// second, as a marker recording would give.
fn sway_targets(creature: &gaitlab_core::Creature) -> String {
    let rest = gaitlab_core::Kinematics::of(&creature.skeleton, &creature.rest_pose());
    let mut targets = String::from("t");
    for e in creature.skeleton.effectors() {
        targets.push_str(&format!(",{0}_x,{0}_y,{0}_z", e.name));
    }
    targets.push('\n');
    for row in 0..=90 {
        let t = f64::from(row) / 30.0;
        targets.push_str(&format!("{t}"));
        for (k, p) in rest.effector_position.iter().enumerate() {
            let phase = t * 3.0 + k as f64;
            let sway = glam::DVec3::new(
                0.03 * phase.sin(),
                0.02 * phase.cos(),
                0.04 * (0.5 * phase).sin(),
            );
            let q = *p + sway;
            targets.push_str(&format!(",{},{},{}", q.x, q.y, q.z));
        }
        targets.push('\n');
    }
    targets
}

#[test]
fn track_follows_recorded_targets() {
    let creature = gaitlab_core::preset::load_bundled("human")
        .expect("bundled")
        .expect("valid");
    let targets = sway_targets(&creature);
    let target_file = scratch("targets.csv");
    std::fs::write(&target_file, targets).expect("write targets");
    let metrics = json_of(&gaitlab(&[
        "track",
        "human",
        "--targets",
        target_file.to_str().expect("utf-8"),
        "--method",
        "dls",
        "--json",
    ]));
    assert_eq!(metrics["method"], "dls");
    assert_eq!(metrics["frames"], 180, "3 s at the preset's 60 fps");
    for e in ["left_foot", "right_foot", "left_hand", "right_hand"] {
        let mean = effector_mean(&metrics, e);
        assert!(mean < 0.005, "{e}: mean error {mean} m");
    }
    // A malformed target file is refused with its line.
    std::fs::write(&target_file, "t,a,b\n0,1,2\n").expect("write");
    let output = gaitlab(&[
        "track",
        "human",
        "--targets",
        target_file.to_str().expect("utf-8"),
    ]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("line 1"),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// `track` follows targets with the skeleton only, so a four-effector `ik`
/// preset whose thesis roles name no effector tracks; `run` and `validate`,
/// which run (or vouch for) the thesis script, still refuse it at the role.
#[test]
fn track_ignores_thesis_roles_that_run_and_validate_refuse() {
    let mut value: Value =
        serde_json::from_str(gaitlab_core::preset::bundled_json("human").expect("bundled"))
            .expect("JSON");
    for effector in value["skeleton"]["effectors"]
        .as_array_mut()
        .expect("effectors")
    {
        let name = effector["name"].as_str().expect("name").to_owned();
        effector["name"] = format!("marker_{name}").into();
    }
    let text = value.to_string();
    let preset_file = scratch("renamed-markers.json");
    std::fs::write(&preset_file, &text).expect("write preset");
    let preset_path = preset_file.to_str().expect("utf-8");

    let creature =
        gaitlab_core::Creature::from_json_for(&text, gaitlab_core::preset::Purpose::Tracking)
            .expect("loads for tracking");
    assert_eq!(creature.skeleton.effector_count(), 4);
    let target_file = scratch("renamed-markers.csv");
    std::fs::write(&target_file, sway_targets(&creature)).expect("write targets");
    let metrics = json_of(&gaitlab(&[
        "track",
        preset_path,
        "--targets",
        target_file.to_str().expect("utf-8"),
        "--method",
        "dls",
        "--json",
    ]));
    assert_eq!(metrics["frames"], 180, "3 s at the preset's 60 fps");
    for e in ["left_foot", "right_foot", "left_hand", "right_hand"] {
        let mean = effector_mean(&metrics, &format!("marker_{e}"));
        assert!(mean < 0.005, "{e}: mean error {mean} m");
    }

    for args in [
        vec!["run", preset_path, "--seconds", "1"],
        vec!["validate", preset_path],
    ] {
        let output = gaitlab(&args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains(
                r#"error: scenario.thesis.roles.left_foot: no effector named "left_foot""#
            ),
            "{args:?}: {stderr}"
        );
    }
}

#[test]
fn ten_thousand_joints_and_other_nonsense_exit_2_without_panicking() {
    let chain = |count: usize| {
        let joints: Vec<String> = (0..count)
            .map(|i| {
                let parent = if i == 0 {
                    "null".to_owned()
                } else {
                    format!("\"j{}\"", i - 1)
                };
                format!(
                    r#"{{"name":"j{i}","parent":{parent},"axis":[1,0,0],"offset":[0,-0.01,0]}}"#
                )
            })
            .collect();
        format!(
            r#"{{"format":"gaitlab-preset/1","name":"chain","skeleton":{{"root":{{"position":[0,1,0]}},"joints":[{}],"effectors":[]}},"scenario":{{"engine":"ik"}}}}"#,
            joints.join(",")
        )
    };
    let cases = [
        ("ten-thousand.json", chain(10_000), "larger than 256 KiB"),
        (
            "too-many.json",
            chain(513),
            "skeleton.joints: 513 joints is more than the limit of 512",
        ),
        (
            "gain.json",
            chain(3).replace(r#""name":"j1","#, r#""name":"j1","gain":5,"#),
            "skeleton.joints[1].gain",
        ),
        (
            "size.json",
            chain(3).replace(r#""name":"j2","#, r#""name":"j2","size":-1,"#),
            "skeleton.joints[2].size",
        ),
        (
            "not-json.json",
            "🦕 definitely not a preset".to_owned(),
            "error: $:",
        ),
        ("empty.json", String::new(), "error: $:"),
    ];
    for (name, text, expected) in cases {
        let path = scratch(name);
        std::fs::write(&path, text).expect("write");
        let output = gaitlab(&["validate", path.to_str().expect("utf-8")]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{name}: {stderr}");
        assert!(stderr.contains(expected), "{name}: {stderr}");
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
    }
    // A valid small chain passes.
    let path = scratch("chain.json");
    std::fs::write(&path, chain(5)).expect("write");
    let output = gaitlab(&["validate", path.to_str().expect("utf-8")]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// A preset that validates is one that runs: `validate` asks the engine layer,
/// so the quadruped cut to three legs fails there with `run`'s own message.
#[test]
fn validate_refuses_what_run_refuses() {
    let mut preset = bundled_preset("raibert-quadruped");
    let legs = preset["scenario"]["physics"]["legs"]
        .as_array_mut()
        .expect("physics legs");
    legs.pop();
    let path = scratch("three-legs.json");
    std::fs::write(&path, preset.to_string()).expect("write");
    let file = path.to_str().expect("utf-8");
    let run = gaitlab(&["run", file, "--seconds", "0.1"]);
    let validate = gaitlab(&["validate", file]);
    let run_err = String::from_utf8_lossy(&run.stderr);
    let validate_err = String::from_utf8_lossy(&validate.stderr);
    assert_eq!(run.status.code(), Some(2), "run: {run_err}");
    assert_eq!(validate.status.code(), Some(2), "validate: {validate_err}");
    assert!(
        validate_err.contains("error: scenario.physics.legs: "),
        "{validate_err}"
    );
    assert_eq!(run_err, validate_err);
}

/// `run --set`: a dotted preset path gives the same run as the preset file
/// edited by hand (5 s: the Table-2 figures start after the settling time); a gain by name changes the motion; bad keys name themselves.
#[test]
fn set_changes_preset_values_and_gains() {
    let without_timing = |mut v: Value| {
        for key in ["wall_ms", "steps_per_second", "realtime_factor"] {
            v.as_object_mut().map(|o| o.remove(key));
        }
        v
    };
    let mut preset = bundled_preset("raibert-biped");
    preset["scenario"]["physics"]["speed_mps"] = serde_json::json!(1.5);
    let path = scratch("biped-1.5.json");
    std::fs::write(&path, preset.to_string()).expect("write");
    let file = path.to_str().expect("utf-8");
    let by_file = json_of(&gaitlab(&["run", file, "--seconds", "5", "--json"]));
    let by_set = json_of(&gaitlab(&[
        "run",
        file,
        "--seconds",
        "5",
        "--json",
        "--set",
        "scenario.physics.speed_mps=1.5",
    ]));
    let bundled_set = json_of(&gaitlab(&[
        "run",
        "raibert-biped",
        "--seconds",
        "5",
        "--json",
        "--set",
        "scenario.physics.speed_mps=1.5",
    ]));
    assert_eq!(by_file["speed_desired_mps"], serde_json::json!(1.5));
    assert_eq!(without_timing(by_set), without_timing(by_file.clone()));
    let mut bundled_set = without_timing(bundled_set);
    bundled_set["preset"] = by_file["preset"].clone();
    assert_eq!(bundled_set, without_timing(by_file.clone()));
    let stiff = json_of(&gaitlab(&[
        "run",
        file,
        "--seconds",
        "5",
        "--json",
        "--set",
        "leg_damping=0",
    ]));
    assert_ne!(
        without_timing(stiff),
        without_timing(by_file.clone()),
        "a gain changes the motion"
    );
    for (set, expected) in [
        (
            "scenario.physics.speed_mps=99",
            "error: scenario.physics.speed_mps: must be a speed within",
        ),
        (
            "scenario.nope.x=1",
            "error: scenario.nope: unknown field `nope`",
        ),
        (
            "no_such_gain=1",
            "error: --set gain.no_such_gain: no such gain",
        ),
        (
            "leg_damping=soft",
            "error: --set leg_damping: a gain is a number",
        ),
        (
            "leg_damping",
            "error: --set leg_damping: expected KEY=VALUE",
        ),
    ] {
        let output = gaitlab(&["run", "raibert-biped", "--seconds", "0.1", "--set", set]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{set}: {stderr}");
        assert!(stderr.starts_with(expected), "{set}: {stderr}");
    }
}

/// Output into a pipe whose reader has gone (`gaitlab run human --json | head -c1`)
/// ends quietly with status 0, not with a panic.
#[test]
fn a_closed_stdout_pipe_ends_quietly() {
    use std::process::{Command, Stdio};
    for args in [
        &["run", "human", "--seconds", "1", "--json"][..],
        &["presets"][..],
        &["export", "raibert-biped", "--format", "mjcf"][..],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_gaitlab"))
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("the gaitlab binary starts");
        // Close the reading end before the command writes anything.
        drop(child.stdout.take());
        let output = child.wait_with_output().expect("it ends");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(0), "{args:?}: {stderr}");
        assert!(stderr.is_empty(), "{args:?}: {stderr}");
    }
}

/// `--switch T:GAIT` and `--edit T:KEY=VALUE` change a running gait as the
/// page's commands do; a change the engine refuses is listed with its reason
/// and the run goes on; a malformed one, or one for engine ik, exits 2.
#[test]
fn switch_and_edit_change_the_gait_during_a_run() {
    let metrics = json_of(&gaitlab(&[
        "run",
        "poda-quadruped",
        "--seconds",
        "6",
        "--switch",
        "2:trot",
        "--edit",
        "4:period_s=0.8",
        "--edit",
        "5:period_s=-1",
        "--json",
    ]));
    assert_eq!(metrics["gait"], "trot", "{metrics}");
    let changes = metrics["changes"].as_array().expect("changes");
    assert_eq!(changes.len(), 3, "{metrics}");
    assert_eq!(changes[0]["change"], "2:trot");
    // Applied on the frame that starts at 2 s (60 fps: frame 120).
    let at = changes[0]["applied_at_s"].as_f64().unwrap_or(f64::NAN);
    assert!((at - 2.0).abs() < 1e-9, "{at}");
    assert_eq!(changes[1]["change"], "4:period_s=0.8");
    assert!(changes[1]["refused"].is_null(), "{}", changes[1]);
    assert!(
        changes[1]["derived"]
            .as_array()
            .is_some_and(|d| d.iter().any(|x| x == "stroke_m")),
        "a period edit keeps the speed and derives the stroke: {}",
        changes[1]
    );
    assert_eq!(changes[2]["refused"], "period_s: -1 is outside 0.1..=10");
    // The gait ends the run at the edited period; the refused edit changed nothing.
    assert_eq!(metrics["period_s_set"].as_f64(), Some(0.8), "{metrics}");

    for (args, expected) in [
        (
            &["run", "poda-quadruped", "--switch", "trot"][..],
            "error: --switch \"trot\": expected T:GAIT",
        ),
        (
            &["run", "poda-quadruped", "--edit", "1:colour=2"][..],
            "error: --edit \"1:colour=2\": \"colour\" is not a gait value",
        ),
        (
            &["run", "human", "--switch", "1:trot"][..],
            "error: --switch and --edit change gaits: engine ik has none",
        ),
    ] {
        let output = gaitlab(args);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.starts_with(expected), "{args:?}: {stderr}");
    }
}
