//! Steering along a path (Raibert & Hodgins 1991, Figure 2: "the path along
//! which to travel"): the driver turns the desired heading toward each
//! waypoint in turn, and the creatures reach them all without falling.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;

fn follow(
    preset: &str,
    gait: &str,
    speed: f64,
    waypoints: &[[f64; 2]],
    seconds: f64,
) -> (PhysicsDriver, f64) {
    let preset = load_bundled(preset).expect("bundled").expect("valid");
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.gait = Some(gait.to_owned());
    params.speed_mps = speed;
    params.waypoints = waypoints.to_vec();
    let mut driver = PhysicsDriver::with_params(&preset, params).expect("driver");
    driver.reset_after_fall = false;
    let mut t = 0.0;
    while t < seconds && driver.waypoint() < waypoints.len() {
        driver.step(1.0 / 60.0);
        t += 1.0 / 60.0;
    }
    (driver, t)
}

#[test]
fn the_biped_runs_around_a_square_and_the_quadruped_trots_a_dogleg() {
    let square = [[0.0, 8.0], [8.0, 8.0], [8.0, 0.0], [0.0, 0.0]];
    for (preset, gait, speed, path) in [
        ("raibert-biped", "run", 1.5, &square[..]),
        ("raibert-biped", "gallop_alternate", 1.5, &square[..]),
        (
            "raibert-quadruped",
            "trot",
            1.5,
            &[[0.0, 8.0], [6.0, 14.0]][..],
        ),
    ] {
        let (driver, t) = follow(preset, gait, speed, path, 90.0);
        let s = driver.summary();
        eprintln!(
            "{preset} {gait}: {} of {} waypoints in {t:.1} s, heading {:.2} rad",
            driver.waypoint(),
            path.len(),
            driver.heading()
        );
        assert!(
            !s.fell && driver.resets() == 0,
            "{preset} {gait} fell: {:?}",
            driver.message()
        );
        assert_eq!(
            driver.waypoint(),
            path.len(),
            "{preset} {gait}: reached {} of {} waypoints in {t:.1} s",
            driver.waypoint(),
            path.len()
        );
    }
}
