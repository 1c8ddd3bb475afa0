//! The quadruped pace (Raibert 1990, the paper's reference 13; Raibert &
//! Hodgins 1991, "Gaits": quadruped gaits as virtual biped gaits): the
//! bundled quadruped paces by the paper's laws alone on its lateral pairs —
//! no fall, its speed within 10 %, the friction the paper reports for the
//! quadruped, and each lateral pair striking the ground as one leg while the
//! body rocks from side to side.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::{Creature as PresetCreature, load_bundled};
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gaits::pace::PACE_PAIRS;
use gaitlab_physics::engine::metrics::paper_friction_bounds;
use gaitlab_physics::engine::pair_timing::pair_timing;

fn run(gait: &str, speed: f64, seconds: f64) -> PhysicsDriver {
    let preset: PresetCreature = load_bundled("raibert-quadruped")
        .expect("bundled")
        .expect("valid");
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.gait = Some(gait.to_owned());
    params.speed_mps = speed;
    let mut driver = PhysicsDriver::with_params(&preset, params).expect("driver");
    driver.reset_after_fall = false;
    // Both by eq. 2 alone (the bundled `lab_additions_by_gait`).
    assert_eq!(
        driver.lab_additions().count(),
        0,
        "the {gait} runs by the paper's laws alone"
    );
    while driver.sim().time < seconds {
        driver.step(1.0 / 60.0);
    }
    driver
}

#[test]
fn the_pace_runs_on_the_lateral_pairs_by_the_papers_laws() {
    let speed = 1.6;
    let driver = run("pace", speed, 20.0);
    assert_eq!(driver.virtual_legs(), &PACE_PAIRS);
    let s = driver.summary();
    assert!(!s.fell && driver.resets() == 0, "the pace fell");
    let error = (s.speed_mean_mps - speed) / speed;
    assert!(error.abs() < 0.10, "mean speed {:.3} m/s", s.speed_mean_mps);
    let (mid, edges) = paper_friction_bounds(4);
    assert!(
        s.friction_needed_mid <= mid && s.friction_needed_edges <= edges,
        "friction {:.2} mid, {:.2} at the edges",
        s.friction_needed_mid,
        s.friction_needed_edges
    );
    // Each lateral pair lands as one virtual leg: touchdowns within 10 ms
    // on average (8.0 ms measured at 1.6 m/s, both by eq. 2).
    let timing = pair_timing(&s.stances, driver.virtual_legs());
    assert_eq!(timing.len(), 2);
    for t in &timing {
        assert!(t.shared > 10, "{:?}: {} shared stances", t.legs, t.shared);
        assert!(
            t.touchdown_gap_s < 0.010,
            "{:?}: {} s",
            t.legs,
            t.touchdown_gap_s
        );
    }
    // Supported on one side at a time, the body rocks: its roll swings at
    // least one and a half times as far as the trot's on its diagonals
    // (17.4° and 10.0° at 1.6 m/s, both by eq. 2; 25° and 7.5° with the
    // hop integrator's lower trot hops).
    let trot = run("trot", speed, 20.0).summary();
    assert!(
        s.roll_magnitude_deg > 1.5 * trot.roll_magnitude_deg,
        "roll {:.1}°, the trot's {:.1}°",
        s.roll_magnitude_deg,
        trot.roll_magnitude_deg
    );
}
