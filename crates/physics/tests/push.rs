//! Pushes (`PhysicsDriver::push`): the whole creature's velocity changes
//! by the push at once — checked against its centre of mass's velocity
//! computed from every body's — the recovery is judged five seconds later,
//! and a planar creature refuses a sideways push.

mod common;

use common::{bundled, driver_with};
use gaitlab_core::driver::Driver;
use gaitlab_physics::control::laws::attitude::com_velocity;
use gaitlab_physics::dynamics::kinematics::kinematics;
use glam::DVec3;

fn com_velocity_now(driver: &gaitlab_physics::PhysicsDriver) -> DVec3 {
    let mut sim = driver.sim().clone();
    kinematics(&sim.creature.model, &mut sim.data);
    com_velocity(&sim.creature, &sim.data)
}

#[test]
fn a_push_changes_the_whole_creatures_velocity_by_its_amount() {
    let mut driver = driver_with(&bundled("raibert-quadruped"), |p| {
        p.gait = Some("trot".to_owned());
    });
    while driver.time() < 3.0 {
        driver.step(1.0 / 60.0);
    }
    let before = com_velocity_now(&driver);
    driver.push([0.3, -0.2]).expect("pushed");
    let change = com_velocity_now(&driver) - before;
    assert!(
        (change - DVec3::new(0.3, 0.0, -0.2)).length() < 1e-9,
        "{change}"
    );
}

#[test]
fn the_papers_trot_recovers_a_forward_push_judged_five_seconds_on() {
    let mut driver = driver_with(&bundled("raibert-quadruped"), |p| {
        p.gait = Some("trot".to_owned());
        if let Some(a) = p.lab_additions.as_mut() {
            a.speed_trim = Some(false);
        }
    });
    driver.reset_after_fall = false;
    while driver.time() < 6.0 {
        driver.step(1.0 / 60.0);
    }
    driver.push([0.0, 0.3]).expect("pushed");
    while driver.time() < 10.5 {
        driver.step(1.0 / 60.0);
    }
    assert_eq!(driver.pushes()[0].recovered(), None, "not yet five seconds");
    while driver.time() < 11.2 {
        driver.step(1.0 / 60.0);
    }
    let push = &driver.pushes()[0];
    let speed = push.speed_after_mps.expect("measured");
    assert!((speed - 2.3).abs() < 0.23, "{speed} m/s");
    assert_eq!(push.recovered(), Some(true));
}

#[test]
fn pushes_out_of_range_or_sideways_on_the_planar_kangaroo_are_refused() {
    let mut kangaroo = driver_with(&bundled("raibert-kangaroo"), |_| {});
    let error = kangaroo.push([0.3, 0.0]).err().unwrap_or_default();
    assert!(
        error.starts_with("push: this creature is planar"),
        "{error}"
    );
    assert!(kangaroo.push([0.0, f64::NAN]).is_err());
    assert!(kangaroo.push([0.0, 10.5]).is_err());
    assert!(kangaroo.pushes().is_empty(), "nothing recorded");
    let forward = kangaroo.sim().data.qd[0];
    kangaroo.push([0.0, -0.3]).expect("pushed");
    assert!((kangaroo.sim().data.qd[0] - (forward - 0.3)).abs() < 1e-12);
}
