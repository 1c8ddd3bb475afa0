//! A creature's controller takes its geometry from the creature's model, not
//! from constants (issue 20, item 1): the biped with legs 1.5 times as long
//! and a 40 kg trunk (for 23.1 kg), and the quadruped with twice its trunk's
//! mass, run from presets edited as a user would, with no code change, for
//! a minute within 10 % of the desired speed.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::{Creature, bundled_json};
use gaitlab_physics::PhysicsDriver;
use serde_json::{Value, json};

fn edited(name: &str, edit: impl Fn(&mut Value)) -> Creature {
    let mut preset: Value =
        serde_json::from_str(bundled_json(name).expect("bundled")).expect("JSON");
    edit(&mut preset);
    Creature::from_json(&preset.to_string()).expect("the edited preset is valid")
}

fn minute(preset: &Creature, gait: &str, speed: f64) -> (bool, f64) {
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.gait = Some(gait.to_owned());
    params.speed_mps = speed;
    let mut driver = PhysicsDriver::with_params(preset, params).expect("driver");
    driver.reset_after_fall = false;
    for _ in 0..3600 {
        driver.step(1.0 / 60.0);
    }
    let s = driver.summary();
    (s.fell || driver.resets() > 0, s.speed_mean_mps)
}

#[test]
fn a_biped_with_longer_legs_and_a_heavier_trunk_runs_a_minute() {
    let long = edited("raibert-biped", |p| {
        for j in p["skeleton"]["joints"].as_array_mut().expect("joints") {
            if j["name"].as_str().is_some_and(|n| n.ends_with("lower-leg")) {
                j["offset"] = json!([0.0, -0.3, 0.0]);
            }
        }
        for e in p["skeleton"]["effectors"]
            .as_array_mut()
            .expect("effectors")
        {
            e["offset"] = json!([0.0, -0.945, 0.0]);
        }
        p["skeleton"]["root"]["position"] = json!([0.0, 1.35, 0.0]);
        let physics = &mut p["scenario"]["physics"];
        physics["trunk"]["mass_kg"] = json!(40.0);
        physics["trunk"]["inertia_kgm2"] = json!([0.294, 0.519, 0.294]);
        for leg in physics["legs"].as_array_mut().expect("legs") {
            leg["foot_point_m"] = json!([0.0, -0.945, 0.0]);
        }
    });
    let physics = long.scenario.physics.as_ref().expect("physics");
    assert_eq!(physics.trunk.as_ref().map(|t| t.mass_kg), Some(40.0));
    let driver = PhysicsDriver::new(&long).expect("driver");
    for length in driver.sim().creature.leg_lengths_m() {
        assert!((length - 1.245).abs() < 1e-12, "leg {length} m");
    }
    for speed in [1.0, 1.6, 2.5] {
        let (fell, mean) = minute(&long, "run", speed);
        eprintln!("long-legged biped {speed} m/s: {mean:.3} m/s, fell {fell}");
        assert!(!fell, "fell at {speed} m/s");
        assert!((mean / speed - 1.0).abs() < 0.10, "{mean} m/s at {speed}");
    }
}

#[test]
fn a_quadruped_with_twice_the_trunk_mass_trots_a_minute() {
    let heavy = edited("raibert-quadruped", |p| {
        let trunk = &mut p["scenario"]["physics"]["trunk"];
        // Twice the mass and, as a body of the same shape, twice the inertia.
        trunk["mass_kg"] = json!(20.0);
        trunk["inertia_kgm2"] = json!([0.47, 0.478, 0.108]);
    });
    for speed in [1.0, 1.9] {
        let (fell, mean) = minute(&heavy, "trot", speed);
        eprintln!("heavy quadruped {speed} m/s: {mean:.3} m/s, fell {fell}");
        assert!(!fell, "fell at {speed} m/s");
        assert!((mean / speed - 1.0).abs() < 0.10, "{mean} m/s at {speed}");
    }
}
