//! The physics driver as the app and CLI use it: every bundled creature and
//! gait builds and runs; absurd gains blow up, are caught, and the creature is
//! put back with a message; dynamic scaling (Table 1) reproduces the motion
//! with positions ×L and time ×√L; bad physics presets name the field.

use gaitlab_core::driver::Driver;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::{Creature as PresetCreature, load_bundled};
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gaits::table::gait_names;
use gaitlab_physics::engine::driver::MAX_PUT_BACKS;

fn bundled(name: &str) -> PresetCreature {
    load_bundled(name).expect("bundled").expect("valid")
}

/// Calls `f(preset, gait, driver)` with a fresh driver of every gait of every
/// bundled physics creature.
fn each_gait(mut f: impl FnMut(&str, &str, PhysicsDriver)) {
    for name in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"] {
        let preset = bundled(name);
        let species = PhysicsDriver::new(&preset)
            .expect("driver")
            .sim()
            .creature
            .species;
        for gait in gait_names(species) {
            let mut params = preset.scenario.physics.clone().expect("physics");
            params.gait = Some((*gait).to_owned());
            f(
                name,
                gait,
                PhysicsDriver::with_params(&preset, params).expect("gait builds"),
            );
        }
    }
}

#[test]
fn every_bundled_creature_runs_every_gait_with_finite_poses() {
    each_gait(|name, gait, mut driver| {
        for _ in 0..120 {
            driver.step(1.0 / 60.0);
            assert!(
                driver.pose().joints.iter().all(|q| q.is_finite()),
                "{name} {gait}"
            );
            assert!(driver.pose().root.position.is_finite(), "{name} {gait}");
        }
        assert!(
            driver.time() > 1.9,
            "{name} {gait} advanced to {}",
            driver.time()
        );
        assert!(
            driver.message().is_none_or(|m| !m.contains("blew up")),
            "{name} {gait}: {:?}",
            driver.message()
        );
    });
}

#[test]
fn an_absurd_gain_blows_up_and_the_creature_is_put_back_with_a_reason() {
    let preset = bundled("raibert-biped");
    let mut driver = PhysicsDriver::new(&preset).expect("driver");
    for _ in 0..60 {
        driver.step(1.0 / 60.0);
    }
    assert!(driver.set_gain("leg_stiffness", -1.0).is_err());
    assert!(
        driver
            .set_gain("warp_factor", 1.0)
            .expect_err("unknown")
            .contains("no such gain")
    );
    driver
        .set_gain("leg_stiffness", 1e9)
        .expect("absurd but allowed");
    let mut seconds = 0.0;
    while driver.resets() == 0 && seconds < 5.0 {
        driver.step(1.0 / 60.0);
        seconds += 1.0 / 60.0;
    }
    let message = driver.message().expect("a reason").to_owned();
    eprintln!("after {seconds:.2} s: {message}");
    assert_eq!(driver.resets(), 1);
    assert!(
        message.contains("blew up") && message.contains("put back"),
        "{message}"
    );
    assert!(driver.time() < 0.1, "restarted, t = {}", driver.time());
    assert!(driver.pose().joints.iter().all(|q| q.is_finite()));
    // The restart rebuilds the controller with the preset's gains, so the
    // creature runs again.
    for _ in 0..120 {
        driver.step(1.0 / 60.0);
    }
    assert_eq!(
        driver.resets(),
        1,
        "runs again after the reset: {:?}",
        driver.message()
    );
}

#[test]
fn every_put_back_is_listed_with_the_runs_own_time() {
    let preset = bundled("raibert-biped");
    let mut driver = PhysicsDriver::new(&preset).expect("driver");
    let frame = 1.0 / 60.0;
    // Two blow-ups, each after about a second of running: the simulation
    // clock restarts with the creature, the run's clock goes on.
    let mut frames = 0_u32;
    for _ in 0..2 {
        for _ in 0..60 {
            driver.step(frame);
            frames += 1;
        }
        let resets = driver.resets();
        driver
            .set_gain("leg_stiffness", 1e9)
            .expect("absurd but allowed");
        while driver.resets() == resets && frames < 600 {
            driver.step(frame);
            frames += 1;
        }
    }
    let put_backs = driver.put_backs().to_vec();
    assert_eq!(put_backs.len(), 2, "{put_backs:?}");
    let first = put_backs[0].run_time_s;
    let second = put_backs[1].run_time_s;
    assert!(first > 1.0 && first < 1.5, "first at {first} s");
    assert!(
        second > first + 1.0 && second < first + 1.5,
        "second at {second} s"
    );
    assert!(put_backs.iter().all(|p| p.why.contains("blew up")));
    // The run's clock is the attempts' clocks added up: the frames', less
    // what is left of a frame in which the creature was put back.
    assert!(
        driver.time() < 0.1,
        "the attempt clock restarted: {}",
        driver.time()
    );
    let run = driver.run_time_s();
    assert!((run - second - driver.time()).abs() < 1e-9, "{run}");
    let framed = f64::from(frames) * frame;
    assert!(
        run <= framed && run > framed - 2.0 * frame,
        "{run} after {frames} frames"
    );
    // The list keeps the first MAX_PUT_BACKS; the count goes on.
    while driver.resets() < 110 {
        driver
            .set_gain("leg_stiffness", 1e9)
            .expect("absurd but allowed");
        driver.step(frame);
    }
    assert_eq!(driver.put_backs().len(), MAX_PUT_BACKS);
    assert_eq!(driver.put_backs()[..2], put_backs[..]);
    // A reset begins a new run: no put-backs, the clock at zero.
    driver.reset();
    assert!(driver.put_backs().is_empty());
    assert!(driver.run_time_s() < 1e-12);
}

#[test]
fn scaling_by_l_reproduces_the_motion_with_positions_times_l_and_time_times_root_l() {
    let preset = bundled("raibert-biped");
    let drive = |l: f64| {
        let mut params = preset.scenario.physics.clone().expect("physics");
        params.scale = l;
        let mut driver = PhysicsDriver::with_params(&preset, params).expect("driver");
        // Equal step counts: the step is 0.4 ms × √L, so step k is time k·dt·√L.
        let steps = 7500; // 3 s at L = 1
        let mut trace = Vec::new();
        for k in 0..steps {
            driver.run_steps(1).expect("no blow-up");
            if k % 250 == 0 {
                let d = &driver.sim().data;
                trace.push((driver.time(), d.base_position, d.base_orientation));
            }
        }
        trace
    };
    let one = drive(1.0);
    for l in [2.0, 0.5, 3.0] {
        let scaled = drive(l);
        let mut worst = 0.0_f64;
        for ((t1, p1, r1), (tl, pl, rl)) in one.iter().zip(&scaled) {
            assert!(
                (tl - t1 * l.sqrt()).abs() < 1e-9 * l.sqrt().max(1.0),
                "time {tl} vs {t1}·√{l}"
            );
            worst = worst.max((*pl / l - *p1).length());
            // Angles do not scale (Table 1: angular displacement × 1).
            let diff = (*r1 - *rl).length().min((*r1 + *rl).length());
            assert!(
                diff < 1e-9,
                "L = {l}: orientation differs by {diff:e} at t = {t1}"
            );
        }
        eprintln!("L = {l}: worst trunk position error {worst:e} m (in L = 1 units) over 3 s");
        assert!(worst < 1e-6, "L = {l}: trunk off by {worst} m");
    }
}

#[test]
fn bad_physics_presets_name_the_field() {
    let json = gaitlab_core::preset::bundled_json("raibert-biped").expect("bundled");
    let cases = [
        (
            "/scenario/physics/bodies/0/mass_kg",
            serde_json::json!(-1.0),
            "scenario.physics.bodies[0].mass_kg",
        ),
        (
            "/scenario/physics/legs/0/spring",
            serde_json::json!("nowhere"),
            "scenario.physics.legs[0].spring",
        ),
        (
            "/scenario/physics/scale",
            serde_json::json!(0.0),
            "scenario.physics.scale",
        ),
        (
            "/scenario/physics/dt_s",
            serde_json::json!(1.0),
            "scenario.physics.dt_s",
        ),
        (
            "/scenario/physics/trunk/inertia_kgm2",
            serde_json::json!([1.0, -2.0, 1.0]),
            "scenario.physics.trunk.inertia_kgm2",
        ),
    ];
    for (pointer, value, path) in cases {
        let mut v: serde_json::Value = serde_json::from_str(json).expect("json");
        *v.pointer_mut(pointer).expect(pointer) = value;
        let error = PresetCreature::from_json(&v.to_string()).expect_err(pointer);
        assert_eq!(error.path, path, "{error}");
    }
    let mut v: serde_json::Value = serde_json::from_str(json).expect("json");
    *v.pointer_mut("/scenario/physics/gait").expect("gait") = serde_json::json!("moonwalk");
    let preset =
        PresetCreature::from_json(&v.to_string()).expect("gait names are the driver's to check");
    let error = PhysicsDriver::new(&preset).expect_err("unknown gait");
    assert_eq!(error.path, "scenario.physics.gait");
    assert!(
        error.reason.contains("run, gallop, gallop_alternate"),
        "{error}"
    );
    let mut v: serde_json::Value = serde_json::from_str(json).expect("json");
    v["scenario"]["physics"]["switch_to_start"] = serde_json::json!(["gallop", "bound"]);
    let preset = PresetCreature::from_json(&v.to_string()).expect("names are the driver's");
    let error = PhysicsDriver::new(&preset).expect_err("the biped has no bound");
    assert_eq!(error.path, "scenario.physics.switch_to_start[1]", "{error}");
}

/// The lab's entry at a gait's own start (`switch_to_start`, the bundled
/// quadruped's for every gait until the take-over held 66 of 72 switches;
/// named here): asked for the bound mid-trot, the bound
/// runs at once from its own start, over the ground point the trunk was
/// over and turned to the heading, and holds; the trot, asked for again,
/// comes back the same way.
#[test]
fn a_gait_in_switch_to_start_is_entered_at_its_own_start_where_the_creature_is() {
    let preset = bundled("raibert-quadruped");
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.speed_mps = 2.3;
    params.switch_to_start = ["trot", "bound", "gallop"].map(str::to_owned).to_vec();
    // A path that turns the heading away from +z before the switch.
    params.waypoints = vec![[20.0, 20.0]];
    let mut driver = PhysicsDriver::with_params(&preset, params).expect("driver");
    let run = |driver: &mut PhysicsDriver, seconds: u32| {
        for _ in 0..seconds * 60 {
            driver.step(1.0 / 60.0);
        }
    };
    run(&mut driver, 10);
    assert_eq!(driver.running_gait(), "trot");
    let before = driver.sim().data.base_position;
    let heading = driver.heading();
    assert!(heading > 0.3, "turned toward the waypoint: {heading} rad");
    driver.set_gait("bound").expect("a quadruped gait");
    assert_eq!(driver.running_gait(), "bound", "entered at once");
    let data = &driver.sim().data;
    let after = data.base_position;
    assert_eq!([after.x, after.z], [before.x, before.z]);
    // The bound's start: level, its rear legs out, moving along the heading
    // at the desired speed.
    let forward = data.base_orientation * glam::DVec3::Z;
    let (sin, cos) = (heading.psin(), heading.pcos());
    assert!((forward.x - sin).abs() < 1e-12 && (forward.z - cos).abs() < 1e-12);
    assert_eq!(data.base_velocity.linear, glam::DVec3::new(0.0, 0.0, 2.3));
    assert!(driver.sim().contacts.iter().all(|c| !c.touching));
    run(&mut driver, 20);
    assert!(!driver.fell() && driver.resets() == 0, "the bound held");
    driver.set_gait("trot").expect("a quadruped gait");
    assert_eq!(driver.running_gait(), "trot");
    run(&mut driver, 10);
    assert!(!driver.fell() && driver.resets() == 0, "the trot held");
}

/// The live setters check the preset's own ranges (one source of range truth:
/// `gaitlab_core::preset::physics`), and a refused value changes nothing.
#[test]
fn live_speed_and_hop_height_take_the_preset_ranges() {
    let preset = match gaitlab_core::preset::load_bundled("raibert-kangaroo") {
        Some(Ok(preset)) => preset,
        other => panic!("bundled kangaroo: {other:?}"),
    };
    let mut driver = gaitlab_physics::PhysicsDriver::new(&preset).expect("drives");
    let (lo, hi) = gaitlab_core::preset::physics::HOP_HEIGHT_RANGE_M;
    assert_eq!((lo, hi), (0.0, 2.0));
    driver
        .set_hop_height(hi)
        .expect("the top of the range is a height");
    assert_eq!(driver.params().hop_height_m, Some(hi));
    for bad in [-0.01, hi + 0.01, f64::NAN] {
        let error = driver.set_hop_height(bad).expect_err("outside the range");
        assert_eq!(
            error.to_string(),
            "hop_height_m: must be a height in [0, 2] m"
        );
        assert_eq!(driver.params().hop_height_m, Some(hi));
    }
    driver.set_speed(-15.0).expect("the top speed backwards");
    let error = driver.set_speed(15.5).expect_err("too fast");
    assert_eq!(
        error.to_string(),
        "speed_mps: must be a speed within ±15 m/s"
    );
    assert_eq!(driver.params().speed_mps, -15.0);
    // A preset says the same at its own path.
    let mut json: serde_json::Value =
        serde_json::from_str(gaitlab_core::preset::bundled_json("raibert-kangaroo").expect("json"))
            .expect("JSON");
    json["scenario"]["physics"]["hop_height_m"] = serde_json::json!(2.5);
    let error = gaitlab_core::Creature::from_json(&json.to_string()).expect_err("too high");
    assert_eq!(error.path, "scenario.physics.hop_height_m");
    assert_eq!(error.reason, "must be a height in [0, 2] m");
}

/// Every tunable gain of every gait has words for people (the panel's label),
/// with its unit; its wire key stays the parameter's name.
#[test]
fn every_tunable_gain_is_named_in_words() {
    each_gait(|name, gait, driver| {
        for gain in driver.gains() {
            assert_ne!(
                gain.label, gain.name,
                "{name} {gait}: {} has no words",
                gain.name
            );
            assert!(gain.label.contains(' '), "{}: words, not a key", gain.label);
            assert!(!gain.unit.is_empty(), "{name} {gait}: {}", gain.name);
        }
    });
}

/// The trunk's position after `steps` steps, and whether it fell or was put
/// back, with `between(driver)` called after the first `at` steps; gait
/// switches by the paper's take-over.
fn run_with(
    preset: &str,
    gait: &str,
    at: u32,
    steps: u32,
    between: impl FnOnce(&mut PhysicsDriver),
) -> ([f64; 3], bool) {
    let preset = bundled(preset);
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.gait = Some(gait.to_owned());
    // The paper's switch: a take-over at the next flight.
    params.switch_to_start.clear();
    let mut driver = PhysicsDriver::with_params(&preset, params).expect("driver");
    driver.run_steps(at).expect("runs to the call");
    between(&mut driver);
    let blew_up = driver.run_steps(steps - at).is_err();
    let p = driver.sim().data.base_position;
    (
        p.to_array(),
        blew_up || driver.fell() || driver.resets() > 0,
    )
}

#[test]
fn the_running_gait_asked_for_again_runs_on_with_its_state() {
    // The kangaroo holds 5 m/s on its cycle with what its controller has
    // learned. Asked for "hop" again (the app's {"preset", "gait"} command
    // does this), a fresh controller used to take over at the next flight
    // and tumble within 3–6 s; now the running one runs on, to the bit.
    let steps = 20 * 2500; // 20 s at 0.4 ms
    let alone = run_with("raibert-kangaroo", "hop", 2500, steps, |_| {});
    let again = run_with("raibert-kangaroo", "hop", 2500, steps, |d| {
        d.set_gait("hop").expect("its gait");
    });
    assert!(!alone.1, "the kangaroo hops 20 s");
    assert_eq!(again, alone, "asked again, the hop runs on unchanged");
    // A switch still waiting for its flight is dropped when the running gait
    // is asked for again: the trot runs on as if the bound had not been asked.
    let steps = 5 * 2500;
    let trot = run_with("raibert-quadruped", "trot", 1000, steps, |_| {});
    let back = run_with("raibert-quadruped", "trot", 1000, steps, |d| {
        d.set_gait("bound").expect("a quadruped gait");
        assert_eq!(d.gait(), "bound");
        d.set_gait("trot").expect("a quadruped gait");
        assert_eq!(d.gait(), "trot");
    });
    assert_eq!(back, trot, "the waiting bound never took over");
}
