//! The PODA engine in the lab (Girard & Maciejewski 1985): a PODA preset
//! switches the lab to the gait engine, `gait` and the gait values change it
//! through the same command API the browser uses, every edit keeps eq. 7–8
//! true, and bad gait commands name their key.

use gaitlab_app::{App, Settings};
use gaitlab_core::driver::Driver;
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).expect("state is JSON")
}

fn number(s: &Value, key: &str) -> f64 {
    s["poda"][key].as_f64().unwrap_or(f64::NAN)
}

/// What the last gait edit derived, as the state lists it.
fn derived_of(s: &Value) -> Vec<&str> {
    s["poda"]["derived"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_str)
        .collect()
}

/// Eq. 7 (support = stroke / speed), duty = support / P and eq. 8 (P = support + transfer).
#[track_caller]
fn assert_gait_relations(s: &Value) {
    let (p, duty, speed, stroke) = (
        number(s, "period_s"),
        number(s, "duty_factor"),
        number(s, "speed_mps"),
        number(s, "stroke_m"),
    );
    let (support, transfer) = (number(s, "support_s"), number(s, "transfer_s"));
    assert!((support - stroke / speed).abs() < 1e-9, "eq. 7: {s}");
    assert!((duty - support / p).abs() < 1e-9, "duty: {s}");
    assert!((p - support - transfer).abs() < 1e-9, "eq. 8: {s}");
}

#[test]
fn the_quadruped_trots_then_gallops() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"poda-quadruped","gait":"trot"}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(s["engine"], "poda");
    assert_eq!(s["gait"], "trot");
    assert_eq!(s["joints"], 63);
    assert_eq!(s["poda"]["legs"].as_array().map(Vec::len), Some(4));
    for _ in 0..60 {
        lab.advance(1.0 / 60.0);
    }
    lab.command(r#"{"gait":"transverse_gallop"}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(s["gait"], "transverse_gallop");
    assert_eq!(s["poda"]["blending"], true);
    // Each leg takes the gallop on at its mid-stance, a fifth of the way a
    // cycle at most (docs/poda.md, "Leg by leg").
    for _ in 0..900 {
        lab.advance(1.0 / 60.0);
    }
    let s = state(&lab);
    assert_eq!(s["poda"]["blending"], false);
    assert!((number(&s, "duty_factor") - 0.3).abs() < 1e-12);
    assert!(number(&s, "foot_slip_max_m") <= 0.001, "{s}");
    // The feet track their targets: the effector error plot has data.
    let errors = s["views"][0]["effectors"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    assert!(errors.iter().any(|e| e["error_m"].is_number()));
    assert!(s["last_error"].is_null());
}

#[test]
fn every_gait_edit_keeps_eq_7_and_8_and_says_what_it_derived() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"hexapod"}"#).expect("valid");
    assert_gait_relations(&state(&lab));
    for (command, derived) in [
        (r#"{"period_s": 1.2}"#, "stroke_m"),
        (r#"{"duty_factor": 0.6}"#, "support_s"),
        (r#"{"speed_mps": 0.3}"#, "period_s"),
        (r#"{"stroke_m": 0.12}"#, "period_s"),
    ] {
        lab.command(command).expect("valid edit");
        let s = state(&lab);
        assert_gait_relations(&s);
        let said = derived_of(&s);
        assert!(said.contains(&derived), "{command} derived {said:?}");
    }
    // Speed 0.3 m/s at stroke 0.12 m: support 0.4 s.
    let s = state(&lab);
    assert!((number(&s, "support_s") - 0.4).abs() < 1e-9);
}

#[test]
fn bad_gait_commands_name_their_key_and_change_nothing() {
    let mut lab = App::new(Settings::default());
    let error = lab
        .command(r#"{"gait":"trot"}"#)
        .expect_err("no gaits on ik");
    assert!(error.starts_with("gait:"), "{error}");
    lab.command(r#"{"preset":"hexapod"}"#).expect("valid");
    let error = lab
        .command(r#"{"gait":"gallop"}"#)
        .expect_err("unknown gait");
    assert!(
        error.starts_with("gait:") && error.contains("tripod"),
        "{error}"
    );
    let before = state(&lab);
    let error = lab
        .command(r#"{"duty_factor": 1.5}"#)
        .expect_err("out of range");
    assert!(error.starts_with("duty_factor"), "{error}");
    let error = lab
        .command(r#"{"speed_mps": "fast"}"#)
        .expect_err("not a number");
    assert!(error.starts_with("speed_mps"), "{error}");
    let after = state(&lab);
    assert_eq!(before["poda"], after["poda"]);
    // Back to the IK engine: the thesis panels' state returns.
    lab.command(r#"{"preset":"human","mode":"run"}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(s["engine"], "ik");
    assert!(s["gait"].is_null());
}

#[test]
fn phases_step_height_and_transfer_keys_are_editable() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"poda-quadruped","gait":"trot"}"#)
        .expect("valid");
    lab.command(
        r#"{"phases":[0.1,0.6,0.6,0.1],"step_height_m":0.12,"transfer_keys":[[0.2,0.9],[0.8,0.7]]}"#,
    )
    .expect("valid shape edits");
    let s = state(&lab);
    let phases: Vec<f64> = s["poda"]["phases"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_f64)
        .collect();
    assert_eq!(phases, [0.1, 0.6, 0.6, 0.1]);
    assert!((number(&s, "step_height_m") - 0.12).abs() < 1e-12);
    assert_eq!(
        s["poda"]["transfer_keys"],
        serde_json::json!([[0.2, 0.9], [0.8, 0.7]])
    );
    // The feet now rise to 12 cm: the highest foot target over a cycle.
    let mut highest: f64 = 0.0;
    for _ in 0..72 {
        lab.advance(1.0 / 60.0);
        highest = highest.max(
            lab.driver()
                .poda()
                .map(|d| d.foot_targets().map(|(t, _)| t.y).fold(0.0, f64::max))
                .unwrap_or(0.0),
        );
    }
    assert!(
        (0.10..=0.13).contains(&highest),
        "highest foot target {highest} m"
    );
    for (command, key) in [
        (
            r#"{"transfer_keys":[[0.6,0.9],[0.4,0.7]]}"#,
            "transfer_keys[1]",
        ),
        (r#"{"transfer_keys":"up"}"#, "transfer_keys"),
        (r#"{"step_height_m":-1}"#, "step_height_m"),
        (r#"{"phases":[0.1,"x"]}"#, "phases[1]"),
    ] {
        let error = lab.command(command).expect_err(command);
        assert!(error.starts_with(key), "{command}: {error}");
    }
}

#[test]
fn a_leg_joints_center_pulls_it_without_moving_the_planted_feet() {
    let mut lab = App::new(Settings::default());
    // The feet's positions alone: a foot that holds its orientation too
    // (eq. 2's six rows, the bundled default) leaves the knee no freedom
    // in the null space, so eq. 6's pull on it would have nothing to move.
    let json = gaitlab_core::preset::bundled_json("poda-quadruped").expect("bundled");
    let mut preset: Value = serde_json::from_str(json).expect("JSON");
    preset["scenario"]["poda"]["foot_orientation"] = Value::Bool(false);
    let command = serde_json::json!({ "preset_json": preset.to_string() }).to_string();
    lab.command(&command).expect("custom preset");
    lab.command(r#"{"gait":"walk"}"#).expect("valid");
    let joint = "left_hind_knee_x";
    let value = |lab: &App| {
        let driver = lab.driver().poda().expect("PODA");
        let j = driver.skeleton().joint_index(joint).expect("joint");
        driver.pose().joints[j]
    };
    // The knee's mean bend over two cycles, before and after pulling it to 1.2 rad.
    let mean_over = |lab: &mut App| -> f64 {
        let mut sum = 0.0;
        for _ in 0..72 {
            lab.advance(1.0 / 60.0);
            sum += value(lab);
        }
        sum / 72.0
    };
    let before = mean_over(&mut lab);
    lab.command(r#"{"center":{"joint":"left_hind_knee_x","center":1.2,"gain":1.0}}"#)
        .expect("valid center");
    mean_over(&mut lab);
    let after = mean_over(&mut lab);
    assert!(
        (after - 1.2).abs() < (before - 1.2).abs(),
        "knee pulled toward 1.2 rad: {before} → {after}"
    );
    let s = state(&lab);
    assert!(number(&s, "foot_slip_max_m") <= 0.001, "{s}");
    for (command, key) in [
        (
            r#"{"center":{"joint":"spine_03","center":0,"gain":0.5}}"#,
            "center.joint",
        ),
        (
            r#"{"center":{"joint":"nope","center":0,"gain":0.5}}"#,
            "center.joint",
        ),
        (
            r#"{"center":{"joint":"left_hind_knee_x","center":9,"gain":0.5}}"#,
            "center.center",
        ),
        (
            r#"{"center":{"joint":"left_hind_knee_x","center":0.5,"gain":2}}"#,
            "center.gain",
        ),
        (
            r#"{"center":{"joint":"left_hind_knee_x"}}"#,
            "center.center",
        ),
    ] {
        let error = lab.command(command).expect_err(command);
        assert!(error.starts_with(key), "{command}: {error}");
    }
}

#[test]
fn a_new_body_path_is_joined_where_the_body_is_and_followed() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"hexapod"}"#).expect("valid");
    for _ in 0..60 {
        lab.advance(1.0 / 60.0);
    }
    // A left turn of radius 1.5 m starting beside the body.
    lab.command(
        r#"{"path":{"kind":"catmull_rom","closed":true,"points":[[0,0],[1.5,1.5],[0,3],[-1.5,1.5]]}}"#,
    )
    .expect("valid path");
    let s = state(&lab);
    assert_eq!(s["poda"]["path"]["closed"], true);
    let driver = || lab.driver().poda().expect("PODA");
    let path = driver().path().clone();
    let (mut worst, mut worst_joined): (f64, f64) = (0.0, 0.0);
    for frame in 0..600 {
        lab.advance(1.0 / 60.0);
        let root = lab.driver().poda().map(|d| {
            let p = gaitlab_core::driver::Driver::pose(d).root.position;
            glam::DVec2::new(p.x, p.z)
        });
        if let Some(at) = root {
            let nearest = path.sample(path.closest_distance(at)).position;
            worst = worst.max((nearest - at).length());
            if frame >= 300 {
                worst_joined = worst_joined.max((nearest - at).length());
            }
        }
    }
    // The path starts across the body's heading: it turns onto it no tighter
    // than its legs reach (turn_within_reach), then stays on it.
    assert!(worst < 0.6, "body up to {worst} m off the path");
    assert!(
        worst_joined < 0.1,
        "body up to {worst_joined} m off the path after 3 s"
    );
    let s = state(&lab);
    assert!(number(&s, "foot_slip_max_m") <= 0.001, "{s}");
    // The state's figure is the same distance, measured by the driver.
    let reported = number(&s, "path_error_max_m");
    assert!((reported - worst).abs() < 1e-6, "{reported} vs {worst} m");
    let error = lab
        .command(r#"{"path":{"points":[[0,0]]}}"#)
        .expect_err("one point");
    assert!(error.starts_with("path.points"), "{error}");
}

#[test]
fn the_engine_selector_swaps_matching_creatures_and_leg_force_lengthens_flights() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"engine":"poda"}"#).expect("valid");
    let s = state(&lab);
    assert_eq!(
        (s["engine"].as_str(), s["preset"].as_str()),
        (Some("poda"), Some("poda-biped"))
    );
    lab.command(r#"{"engine":"ik"}"#).expect("valid");
    assert_eq!(state(&lab)["preset"], "human");
    lab.command(r#"{"engine":"physics"}"#).expect("valid");
    assert_eq!(state(&lab)["preset"], "raibert-biped");
    lab.command(r#"{"engine":"ik"}"#).expect("valid");
    assert_eq!(state(&lab)["preset"], "human");
    let error = lab.command(r#"{"engine":"quantum"}"#).expect_err("unknown");
    assert!(error.starts_with("engine:"), "{error}");

    lab.command(r#"{"engine":"poda","preset":"poda-quadruped","gait":"pronk"}"#)
        .expect("valid");
    let s = state(&lab);
    let balance = number(&s, "leg_force_n");
    let duty = number(&s, "duty_factor");
    lab.command(&format!(r#"{{"leg_force_n": {}}}"#, 2.0 * balance))
        .expect("stronger legs");
    let s = state(&lab);
    assert_gait_relations(&s);
    assert!(
        number(&s, "duty_factor") < duty,
        "more force, less time on the ground"
    );
    assert!((number(&s, "leg_force_n") - 2.0 * balance).abs() < 1e-6 * balance);
    let said = derived_of(&s);
    assert!(said.contains(&"transfer_s"), "{said:?}");
    let error = lab
        .command(r#"{"leg_force_n": 1.0}"#)
        .expect_err("below the weight share");
    assert!(error.starts_with("leg_force_n"), "{error}");
}

/// Issue 45 item 4: the page walks the hexapod up stairs from its preset
/// and draws them (a tread and a riser per step), with the footholds moved
/// off the risers' edges on the treads; an IK figure on stairs is refused
/// with the field named, and the running creature carries on.
#[test]
fn the_page_draws_stairs_and_the_hexapod_climbs_them() {
    let mut lab = App::new(Settings {
        preset: "hexapod".into(),
        ..Settings::default()
    });
    let text = gaitlab_core::preset::bundled_json("hexapod").expect("bundled hexapod");
    let mut preset: Value = serde_json::from_str(text).expect("JSON");
    preset["scenario"]["terrain"] = serde_json::json!({"kind": "stairs", "rise_m": 0.05,
        "run_m": 0.3, "count": 4, "direction_deg": 90, "start_m": 0.4});
    lab.set_custom_preset(&preset.to_string())
        .expect("stairs in the page");
    let mesh = lab
        .stage()
        .scene()
        .frame()
        .terrain
        .clone()
        .expect("the stairs are drawn");
    assert_eq!(
        mesh.triangles(),
        2 * (1 + 2 * 4),
        "floor, then riser and tread"
    );
    let start_y = lab.driver().pose().root.position.y;
    lab.set_paused(false);
    let mut moved_drawn = 0;
    for _ in 0..100 {
        lab.advance(0.1);
        moved_drawn = moved_drawn.max(lab.driver().moved_footholds().count());
    }
    let root = lab.driver().pose().root.position;
    assert!(root.z > 1.8, "walked up the flight: at z = {:.2} m", root.z);
    let climbed = root.y - start_y;
    assert!(
        (climbed - 0.2).abs() < 0.03,
        "four 5 cm steps: the body rose {climbed:.3} m"
    );
    assert!(moved_drawn > 0, "a foothold moved off an edge while drawn");
    // Every drawn foothold cross lies on the tread under it.
    let scene = lab.stage().scene();
    for hold in lab.driver().footholds() {
        let ground = scene.ground_height_m(hold.x, hold.z);
        assert!(
            (hold.y - ground).abs() < 1e-6,
            "foothold {hold} on ground {ground}"
        );
    }

    // Bad ground through the command key: refused naming the field, the
    // stairs and the walk on them kept.
    let time = lab.driver().time();
    for (command, field) in [
        (
            r#"{"terrain": {"kind": "stairs", "rise_m": 0.05, "run_m": 0.3, "count": 0}}"#,
            "terrain.count",
        ),
        (
            r#"{"terrain": {"kind": "stairs", "rise_m": 0.2, "run_m": 0.3, "count": 3}}"#,
            "scenario.terrain.rise_m: a 0.200 m step is as high as hexapod's hips",
        ),
        (
            r#"{"terrain": {"kind": "height_field", "cell_m": 0.1, "cols": 0, "rows": 4, "heights_m": []}}"#,
            "terrain.cols",
        ),
        (
            r#"{"terrain": {"kind": "plane", "slope_deg": 45}}"#,
            "scenario.terrain.slope_deg: 45° is steeper than a foot may stand",
        ),
        (r#"{"terrain": {"kind": "cliff"}}"#, "terrain"),
    ] {
        let error = lab.command(command).expect_err(command);
        assert!(
            error.starts_with("terrain") && error.contains(field),
            "{command}: {error}"
        );
        assert_eq!(lab.terrain().kind_name(), "stairs", "{command}");
        assert_eq!(lab.driver().time(), time, "{command}: the walk carries on");
    }

    let human = gaitlab_core::preset::bundled_json("human").expect("bundled human");
    let mut human: Value = serde_json::from_str(human).expect("JSON");
    human["scenario"]["terrain"] = serde_json::json!({"kind": "plane", "slope_deg": 5});
    let error = lab
        .set_custom_preset(&human.to_string())
        .expect_err("IK walks on the floor only");
    assert!(error.contains("scenario.terrain"), "{error}");
    assert_eq!(lab.creature().name, "hexapod");
    let before = lab.driver().time();
    lab.advance(0.5);
    assert!(lab.driver().time() > before, "the hexapod carries on");
}
