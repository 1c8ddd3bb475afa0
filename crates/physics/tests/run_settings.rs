//! A preset's run settings reach the simulation: the control rate, the
//! ground's springs (the rest keep the model's) and the gait controller's
//! parameters by name, which change the motion; a name the controller lacks
//! is refused with its path.

use gaitlab_core::Creature;
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::bundled_json;
use gaitlab_physics::PhysicsDriver;
use serde_json::{Value, json};

fn driver(name: &str, field: &str, value: Value) -> Result<PhysicsDriver, String> {
    let mut preset: Value =
        serde_json::from_str(bundled_json(name).expect("bundled")).expect("JSON");
    preset["scenario"]["physics"][field] = value;
    let creature = Creature::from_json(&preset.to_string()).map_err(|e| e.to_string())?;
    PhysicsDriver::new(&creature).map_err(|e| e.to_string())
}

#[test]
fn control_rate_and_ground_reach_the_simulation() {
    let d = driver("raibert-biped", "control_every", json!(4)).expect("valid");
    assert_eq!(d.sim().options.control_every, 4);
    let d = driver(
        "raibert-kangaroo",
        "ground",
        json!({"vertical_stiffness": 45000}),
    )
    .expect("valid");
    let ground = d.sim().ground;
    assert_eq!(ground.vertical_stiffness, 45000.0);
    // The kangaroo's own softer ground for what was not given.
    assert_eq!(ground.vertical_damping, 150.0);
    assert_eq!(ground.tangential_stiffness, 20000.0);
}

#[test]
fn controller_parameters_change_the_motion_and_unknown_ones_are_refused() {
    let run = |d: &mut PhysicsDriver| {
        for _ in 0..60 {
            d.step(1.0 / 60.0);
        }
        d.pose().clone()
    };
    let mut plain = driver("raibert-quadruped", "controller", json!({})).expect("valid");
    let mut changed = driver(
        "raibert-quadruped",
        "controller",
        json!({"eq2_hop_m": 0.05}),
    )
    .expect("valid");
    assert_ne!(run(&mut plain), run(&mut changed));
    let error = driver(
        "raibert-quadruped",
        "controller",
        json!({"hop_rise_m": 0.1}),
    )
    .expect_err("the trot has no hop_rise_m");
    assert!(
        error.starts_with(
            "scenario.physics.controller.hop_rise_m: the trot controller has no such parameter"
        ),
        "{error}"
    );
}
