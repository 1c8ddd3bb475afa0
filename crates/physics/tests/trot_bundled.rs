//! The bundled quadruped's trot by the paper's laws alone (the trot has none
//! of the lab's additions), with the gains its preset carries
//! (`controller_by_gait.trot`, tuned toward Table 2 at three speeds;
//! docs/physics.md, "Trot toward Table 2"): every Table-2 row of the
//! animation column within ±35 % at 2.3 m/s, and a minute at each of the
//! issue's three speeds within 10 % of the desired one.

mod common;

use common::{assert_table2_within, bundled, paper_only_run, speed_error};
use gaitlab_physics::engine::metrics::GaitSummary;

/// The bundled trot at `speed` (m/s) for `seconds` of simulated time.
fn trot(speed: f64, seconds: f64) -> (GaitSummary, Vec<String>) {
    paper_only_run(&bundled("raibert-quadruped"), Some("trot"), speed, seconds)
}

#[test]
fn every_table_2_row_of_the_trot_is_within_35_percent() {
    let (s, legs) = trot(2.3, 20.0);
    // Pitch, stride, stride time, flight, stance, leg-length change.
    assert_eq!(assert_table2_within(&s, "trot", &legs, 35.0), 6);
}

#[test]
fn the_trot_holds_its_speed_a_minute_at_three_speeds() {
    for speed in [1.0, 1.9, 2.3] {
        let (s, _) = trot(speed, 60.0);
        let off = speed_error(&s, "trot", speed);
        assert!(
            !s.fell && off.abs() < 0.10,
            "{speed} m/s: {:+.1} %",
            100.0 * off
        );
    }
}
