//! The physics engine in the lab (Raibert & Hodgins 1991): a physics preset
//! runs under its controller, the gait, desired speed, hop height and gains
//! change through the browser's command API, `state()` reports the running
//! figures, and an absurd gain blows up, is caught, and the lab says why
//! while the creature starts again.

use gaitlab_app::{App, Settings};
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).expect("state is JSON")
}

fn run(lab: &mut App, seconds: f64) {
    for _ in 0..(seconds * 60.0) as usize {
        lab.advance(1.0 / 60.0);
    }
}

#[test]
fn a_physics_preset_runs_and_answers_commands() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"raibert-biped","speed_mps":2.0}"#)
        .expect("valid");
    run(&mut lab, 8.0);
    let s = state(&lab);
    assert_eq!(s["engine"], "physics");
    assert_eq!(s["gait"], "run");
    let physics = &s["physics"];
    assert_eq!(physics["speed_desired_mps"], 2.0);
    let mean = physics["speed_mean_mps"].as_f64().expect("mean speed");
    assert!((mean - 2.0).abs() < 0.2, "mean speed {mean}: {s}");
    assert_eq!(physics["fell"], false);
    assert!(physics["height_m"].as_f64().expect("height") > 0.6);
    assert!(s["last_error"].is_null(), "{s}");

    lab.command(r#"{"gait":"gallop_alternate","hop_height_m":0.1}"#)
        .expect("valid");
    run(&mut lab, 4.0);
    let s = state(&lab);
    assert_eq!(s["gait"], "gallop_alternate");
    assert_eq!(s["physics"]["resets"], 0, "{s}");

    for (bad, key) in [
        (r#"{"gait":"trot"}"#, "gait"),
        (r#"{"speed_mps":99}"#, "speed_mps"),
        (r#"{"hop_height_m":-1}"#, "hop_height_m"),
        (
            r#"{"gain":{"name":"posture_kp","value":-5}}"#,
            "gain.posture_kp",
        ),
        (r#"{"gain":{"name":"flux","value":1}}"#, "gain.flux"),
        (r#"{"gain":{"value":1}}"#, "gain.name"),
    ] {
        let error = lab.command(bad).expect_err(bad);
        assert!(error.starts_with(key), "{bad}: {error}");
    }
}

#[test]
fn an_absurd_gain_is_caught_and_the_lab_says_why() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"raibert-biped"}"#).expect("valid");
    run(&mut lab, 2.0);
    lab.command(r#"{"gain":{"name":"leg_stiffness","value":1e9}}"#)
        .expect("allowed");
    run(&mut lab, 2.0);
    let s = state(&lab);
    let error = s["last_error"].as_str().unwrap_or_default();
    assert!(
        error.contains("blew up") && error.contains("put back"),
        "{s}"
    );
    assert_eq!(s["physics"]["resets"], 1);
    // Running again from the start, with finite figures.
    assert!(
        s["physics"]["height_m"]
            .as_f64()
            .is_some_and(f64::is_finite),
        "{s}"
    );
    assert!(s["time_s"].as_f64().expect("time") < 2.0, "{s}");
    // A preset that does not load leaves the biped running.
    assert!(lab.command(r#"{"preset":"no-such-creature"}"#).is_err());
    assert_eq!(state(&lab)["preset"], "raibert-biped");
    // The next preset is a new run: the biped's put-back is not its message,
    // nor, after it, an IK preset's.
    lab.command(r#"{"preset":"raibert-kangaroo"}"#)
        .expect("valid");
    run(&mut lab, 1.0);
    let s = state(&lab);
    assert!(s["last_error"].is_null(), "{s}");
    assert_eq!(s["physics"]["resets"], 0);
    lab.command(r#"{"preset":"she-2006"}"#).expect("valid");
    assert!(state(&lab)["last_error"].is_null());
}

#[test]
fn the_engine_selector_reaches_the_physics_creatures() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"engine":"poda","preset":"poda-quadruped"}"#)
        .expect("valid");
    lab.command(r#"{"engine":"physics"}"#).expect("valid");
    assert_eq!(state(&lab)["preset"], "raibert-quadruped");
    lab.command(r#"{"engine":"ik"}"#).expect("valid");
    assert_eq!(state(&lab)["preset"], "ik-quadruped");
    lab.command(r#"{"preset":"raibert-kangaroo"}"#)
        .expect("valid");
    run(&mut lab, 3.0);
    let s = state(&lab);
    assert_eq!(s["gait"], "hop");
    assert_eq!(s["physics"]["fell"], false, "{s}");
    let error = lab.command(r#"{"mode":"run","gain":{"name":"tail_stiffness","value":2}}"#);
    assert!(error.is_ok(), "{error:?}");
}

#[test]
fn gaits_change_on_command_while_running() {
    // The biped changes between all three gaits mid-run; the quadruped from
    // trot to bound and back (bound to quadruped gallop still falls: see
    // docs/physics.md).
    // The change waits for the next flight, so it holds whenever it is asked for.
    for (preset, gaits, hold_s) in [
        (
            "raibert-biped",
            &["run", "gallop", "gallop_alternate", "run"][..],
            4.0,
        ),
        (
            "raibert-biped",
            &["gallop", "run", "gallop_alternate"][..],
            2.55,
        ),
        (
            "raibert-biped",
            &["run", "gallop_alternate", "gallop"][..],
            3.1,
        ),
        ("raibert-quadruped", &["trot", "bound", "trot"][..], 4.0),
    ] {
        let mut lab = App::new(Settings::default());
        lab.command(&format!(r#"{{"preset":"{preset}"}}"#))
            .expect("valid");
        for gait in gaits {
            lab.command(&format!(r#"{{"gait":"{gait}"}}"#))
                .expect("gait");
            run(&mut lab, hold_s);
            let s = state(&lab);
            assert_eq!(s["gait"], *gait);
            assert_eq!(s["physics"]["fell"], false, "{preset} fell in {gait}: {s}");
            assert_eq!(s["physics"]["resets"], 0, "{preset} {gait}: {s}");
        }
    }
}

/// Table 1 from the panel's "Scale L" slider (`Lab::set_physics_scale`):
/// at L = 2 the creature keeps its gait and desired speed, integrates at
/// 0.4 ms × √2, and its strides last √2 times as long as at L = 1.
#[test]
fn the_dynamic_scale_from_the_panel_stretches_steps_by_root_l() {
    let stride = |scale: f64| {
        let mut lab = App::new(Settings::default());
        lab.command(r#"{"preset":"raibert-biped","gait":"gallop","speed_mps":1.5}"#)
            .expect("valid");
        if scale != 1.0 {
            lab.set_physics_scale(scale).expect("in range");
        }
        let Some(driver) = lab.driver().physics() else {
            panic!("still physics")
        };
        assert_eq!(driver.gait(), "gallop");
        assert_eq!(driver.params().speed_mps, 1.5);
        assert!((driver.sim().options.dt - 0.0004 * scale.sqrt()).abs() < 1e-15);
        run(&mut lab, 12.0 * scale.sqrt());
        let s = state(&lab);
        assert_eq!(s["physics"]["fell"], false, "{s}");
        s["physics"]["stride_duration_s"].as_f64().expect("stride")
    };
    let (one, two) = (stride(1.0), stride(2.0));
    // Within 1 %: the page's 60 Hz frames do not scale, so the two runs
    // end a fraction of a stride apart (measured: 0.17 %).
    assert!(
        (two / one / 2.0_f64.sqrt() - 1.0).abs() < 0.01,
        "strides {one} s and {two} s"
    );
    let mut lab = App::new(Settings::default());
    assert!(
        lab.set_physics_scale(2.0)
            .is_err_and(|e| e.starts_with("scale: engine"))
    );
    lab.command(r#"{"preset":"raibert-kangaroo"}"#)
        .expect("valid");
    assert!(
        lab.set_physics_scale(100.0)
            .is_err_and(|e| e.contains("scale"))
    );
    assert_eq!(lab.driver().physics().map(|d| d.params().scale), Some(1.0));
}

/// Two boxes, the second placed 10 m ahead while the kangaroo is in the air
/// over the first (at the bundled 5 m/s): each is jumped in turn.
/// Before the jumps were queued the second box replaced the first's jump
/// and the kangaroo ran into one of them.
#[test]
fn a_second_box_placed_mid_jump_is_jumped_too() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"raibert-kangaroo"}"#)
        .expect("valid");
    run(&mut lab, 2.0);
    lab.place_obstacle(3.0).expect("the kangaroo jumps");
    let phase = |lab: &App| lab.driver().physics().map_or("", |d| d.phase_name());
    let mut frames = 0;
    while phase(&lab) != "jump flight" {
        lab.advance(1.0 / 60.0);
        frames += 1;
        assert!(frames < 3 * 60, "no jump within 3 s");
    }
    lab.place_obstacle(10.0).expect("a second box");
    let Some(driver) = lab.driver().physics() else {
        panic!("physics")
    };
    let boxes = driver.sim().terrain.obstacles.clone();
    assert_eq!(boxes.len(), 2);
    let mut clearance = f64::INFINITY;
    let mut jumps = 0;
    let mut was = phase(&lab);
    for _ in 0..(8 * 60) {
        lab.advance(1.0 / 60.0);
        let Some(driver) = lab.driver().physics() else {
            panic!("physics")
        };
        let toe = driver.sim().contacts[0].position;
        for b in &boxes {
            if b.covers(toe.x, toe.z) {
                clearance = clearance.min(toe.y - b.height_m);
            }
        }
        let now = phase(&lab);
        if now == "jump flight" && was != "jump flight" {
            jumps += 1;
        }
        was = now;
    }
    let s = state(&lab);
    assert_eq!(s["physics"]["fell"], false, "{s}");
    assert_eq!(jumps, 1, "one more jump after the first");
    assert!(clearance > 0.0, "the toe entered a box ({clearance} m)");
    let com_z = lab.driver().physics().map(|d| {
        gaitlab_physics::dynamics::energy::center_of_mass(&d.sim().creature.model, &d.sim().data).z
    });
    assert!(
        com_z.is_some_and(|z| z > boxes[1].max_xz[1] + 1.0),
        "{com_z:?}"
    );
}

/// The kangaroo's jump from the panel ("Place a box 3 m ahead",
/// `Lab::place_obstacle`): the box appears in its path and the jump states
/// carry it over without the toe entering it; the other gaits have no jump.
#[test]
fn a_box_placed_from_the_panel_is_jumped_by_the_kangaroo() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"raibert-kangaroo","speed_mps":2.0}"#)
        .expect("valid");
    // It starts on its cycle at the preset's 5 m/s and its speed ramp
    // brings it down to 2 m/s at 0.25 m/s² (12 s).
    run(&mut lab, 16.0);
    let at = lab.place_obstacle(3.0).expect("the kangaroo jumps");
    let Some(driver) = lab.driver().physics() else {
        panic!("physics")
    };
    let obstacle = *driver.sim().terrain.obstacles.last().expect("a box");
    assert!((obstacle.min_xz[1] - at).abs() < 1e-12 && obstacle.height_m == 0.25);
    let mut clearance = f64::INFINITY;
    for _ in 0..(6 * 60) {
        lab.advance(1.0 / 60.0);
        let Some(driver) = lab.driver().physics() else {
            panic!("physics")
        };
        let toe = driver.sim().contacts[0].position;
        if obstacle.covers(toe.x, toe.z) {
            clearance = clearance.min(toe.y - obstacle.height_m);
        }
    }
    let s = state(&lab);
    assert_eq!(s["physics"]["fell"], false, "{s}");
    assert!(s["last_error"].is_null(), "{s}");
    assert!(clearance > 0.0, "the toe entered the box ({clearance} m)");
    let com_z = lab.driver().physics().map(|d| {
        gaitlab_physics::dynamics::energy::center_of_mass(&d.sim().creature.model, &d.sim().data).z
    });
    assert!(
        com_z.is_some_and(|z| z > obstacle.max_xz[1] + 1.0),
        "{com_z:?}"
    );
    // The biped has no jump states.
    lab.command(r#"{"preset":"raibert-biped"}"#).expect("valid");
    assert!(
        lab.place_obstacle(3.0)
            .is_err_and(|e| e.contains("no jump"))
    );
}

/// tan 5°: the slope's rise per metre.
const TAN_5_DEG: f64 = 0.087_488_663_525_924;

/// Issue 45: the Terrain panel's command puts the running biped on a 5°
/// slope (drawn, and run by its controller with the ground under it); stairs
/// are refused with the engine's reason and the slope run carries on.
#[test]
fn the_biped_runs_up_a_slope_from_the_page_and_stairs_are_refused() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"raibert-biped"}"#).expect("valid");
    lab.command(r#"{"terrain":{"kind":"plane","slope_deg":5,"direction_deg":90}}"#)
        .expect("a slope for the biped");
    run(&mut lab, 6.0);
    let s = state(&lab);
    assert_eq!(s["terrain"]["kind"], "plane");
    assert_eq!(s["terrain"]["triangles_drawn"], 2);
    assert!(s["last_error"].is_null(), "{}", s["last_error"]);
    let root = &s["terrain"]["root_m"];
    let (z, y) = (
        root[2].as_f64().unwrap_or(0.0),
        root[1].as_f64().unwrap_or(0.0),
    );
    let ground = s["terrain"]["ground_under_root_m"]
        .as_f64()
        .unwrap_or(f64::NAN);
    assert!(z > 3.0, "ran up the slope: z = {z:.2} m");
    assert!(
        (ground - z * TAN_5_DEG).abs() < 0.01,
        "ground {ground:.3} m at z = {z:.2}"
    );
    assert!(
        y - ground > 0.5,
        "the trunk above the slope: {y:.3} m over {ground:.3} m"
    );
    let error = lab
        .command(r#"{"terrain":{"kind":"stairs","rise_m":0.1,"run_m":0.4,"count":5}}"#)
        .expect_err("stairs are not climbed by the physics engine yet");
    assert!(error.contains("does not climb stairs"), "{error}");
    assert_eq!(state(&lab)["terrain"]["kind"], "plane");
}
