//! The bundled quadruped's trot by the paper's laws alone (the trot has none
//! of the lab's additions), with the gains its preset carries
//! (`controller_by_gait.trot`, tuned toward Table 2 at three speeds;
//! docs/physics.md, "Trot toward Table 2"): every Table-2 row of the
//! animation column within ±35 % at 2.3 m/s, and a minute at each of the
//! issue's three speeds within 10 % of the desired one.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::engine::metrics::GaitSummary;
use gaitlab_physics::engine::table2::compare;

/// The bundled trot at `speed` (m/s) for `seconds` of simulated time.
fn trot(speed: f64, seconds: f64) -> (GaitSummary, Vec<String>) {
    let Some(Ok(preset)) = load_bundled("raibert-quadruped") else {
        panic!("the quadruped is bundled")
    };
    let Some(mut params) = preset.scenario.physics.clone() else {
        panic!("a physics preset")
    };
    params.gait = Some("trot".to_owned());
    params.speed_mps = speed;
    let mut driver = match PhysicsDriver::with_params(&preset, params) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(driver.lab_additions().count(), 0, "paper-only");
    while driver.time() < seconds {
        driver.step(1.0 / 60.0);
    }
    assert_eq!(driver.resets(), 0, "trot at {speed} m/s fell");
    let legs = driver.leg_names().map(str::to_owned).collect();
    (driver.summary(), legs)
}

#[test]
fn every_table_2_row_of_the_trot_is_within_35_percent() {
    let (s, legs) = trot(2.3, 20.0);
    let legs: Vec<&str> = legs.iter().map(String::as_str).collect();
    let mut checked = 0;
    for c in compare(&s, "trot", &legs) {
        if c.row.quantity.is_input() || c.row.quantity.is_speed_error() {
            continue;
        }
        let Some(diff) = c.diff_pct() else {
            panic!("{}: not measured", c.row.label)
        };
        println!(
            "{:40} paper {:7.3} {diff:+.0} %",
            c.row.label, c.row.animation
        );
        assert!(diff.abs() <= 35.0, "{}: {diff:+.1} %", c.row.label);
        checked += 1;
    }
    // Pitch, stride, stride time, flight, stance, leg-length change.
    assert_eq!(checked, 6);
}

#[test]
fn the_trot_holds_its_speed_a_minute_at_three_speeds() {
    for speed in [1.0, 1.9, 2.3] {
        let (s, _) = trot(speed, 60.0);
        let off = (s.speed_mean_mps - speed) / speed;
        println!(
            "trot at {speed} m/s: mean {:.3} ({:+.1} %)",
            s.speed_mean_mps,
            100.0 * off
        );
        assert!(
            !s.fell && off.abs() < 0.10,
            "{speed} m/s: {:+.1} %",
            100.0 * off
        );
    }
}
