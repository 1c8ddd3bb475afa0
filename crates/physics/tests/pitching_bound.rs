//! The pitching bound experiment (`presets/experiments/
//! raibert-quadruped-pitching-bound.json`, docs/physics.md "A pitching
//! bound by the paper's laws"): the quadruped with seeded-tune bound gains
//! and no lab addition bounds as the paper's does — the trunk pitching
//! about 25°, front and rear pairs alternating with stances of 0.08–0.10 s —
//! where the bundled bound is a low skip. The figures the docs give are
//! checked here; the rows it still misses (extended flight, leg-length
//! change) are printed, not asserted.

use gaitlab_core::Creature;
use gaitlab_core::driver::Driver;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::engine::metrics::GaitSummary;
use gaitlab_physics::engine::table2::compare;

const PRESET: &str =
    include_str!("../../../presets/experiments/raibert-quadruped-pitching-bound.json");

/// The experiment's bound at `speed` (m/s) for `seconds` of simulated time.
fn bound(speed: f64, seconds: f64) -> (GaitSummary, Vec<String>) {
    let preset = match Creature::from_json(PRESET) {
        Ok(c) => c,
        Err(error) => panic!("{error}"),
    };
    let Some(mut params) = preset.scenario.physics.clone() else {
        panic!("a physics preset")
    };
    params.speed_mps = speed;
    let mut driver = match PhysicsDriver::with_params(&preset, params) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(driver.lab_additions().count(), 0, "paper-only");
    while driver.time() < seconds {
        driver.step(1.0 / 60.0);
    }
    assert_eq!(driver.resets(), 0, "bound at {speed} m/s fell");
    let legs = driver.leg_names().map(str::to_owned).collect();
    (driver.summary(), legs)
}

#[test]
fn the_experiment_bounds_with_the_papers_pitch_stride_and_stances() {
    let (s, legs) = bound(2.8, 60.0);
    let legs: Vec<&str> = legs.iter().map(String::as_str).collect();
    let off = (s.speed_mean_mps - 2.8) / 2.8;
    println!(
        "mean speed {:.3} m/s ({:+.1} %)",
        s.speed_mean_mps,
        100.0 * off
    );
    assert!(off.abs() < 0.12, "{:+.1} %", 100.0 * off);
    let mut met = Vec::new();
    for c in compare(&s, "bound", &legs) {
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
        if diff.abs() <= 35.0 {
            met.push(c.row.label);
        }
    }
    // Pitch, stride length and duration, gathered flight, both stances and
    // the running speed; not the extended flight or the leg's change of
    // length.
    assert_eq!(met.len(), 7, "rows within ±35 %: {met:?}");
    assert!(
        met.iter()
            .all(|l| !l.contains("extended") && !l.contains("leg length")),
        "{met:?}"
    );
}

#[test]
fn the_experiment_holds_a_minute_at_a_low_speed() {
    let (s, _) = bound(1.5, 60.0);
    let off = (s.speed_mean_mps - 1.5) / 1.5;
    println!(
        "1.5 m/s: mean {:.3} ({:+.1} %)",
        s.speed_mean_mps,
        100.0 * off
    );
    assert!(off.abs() < 0.12, "{:+.1} %", 100.0 * off);
}
