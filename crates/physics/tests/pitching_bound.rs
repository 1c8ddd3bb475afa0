//! The pitching bound experiment (`presets/experiments/
//! raibert-quadruped-pitching-bound.json`, docs/physics.md "A pitching
//! bound by the paper's laws"): the quadruped with seeded-tune bound gains
//! and no lab addition bounds as the paper's does — the trunk pitching
//! about 25°, front and rear pairs alternating with stances of 0.08–0.10 s —
//! where the bundled bound is a low skip. The figures the docs give are
//! checked here; the rows it still misses (extended flight, leg-length
//! change) are printed, not asserted.

mod common;

use common::{paper_only_run, run, speed_error, table2_diffs};
use gaitlab_core::Creature;
use gaitlab_core::preset::physics::PhysicsParams;
use gaitlab_physics::engine::metrics::GaitSummary;

const PRESET: &str =
    include_str!("../../../presets/experiments/raibert-quadruped-pitching-bound.json");

/// The experiment's bound at `speed` (m/s) for `seconds` of simulated time.
fn bound(speed: f64, seconds: f64) -> (GaitSummary, Vec<String>) {
    match Creature::from_json(PRESET) {
        Ok(preset) => paper_only_run(&preset, None, speed, seconds),
        Err(error) => panic!("{error}"),
    }
}

#[test]
fn the_experiment_bounds_with_the_papers_pitch_stride_and_stances() {
    let (s, legs) = bound(2.8, 60.0);
    let off = speed_error(&s, "bound", 2.8);
    assert!(off.abs() < 0.12, "{:+.1} %", 100.0 * off);
    let met: Vec<&str> = table2_diffs(&s, "bound", &legs)
        .into_iter()
        .filter(|(_, diff)| diff.abs() <= 35.0)
        .map(|(label, _)| label)
        .collect();
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
    let off = speed_error(&s, "bound", 1.5);
    assert!(off.abs() < 0.12, "{:+.1} %", 100.0 * off);
}

/// With the lab's speed trim turned on at the experiment's own trim gain
/// (`speed_integral_gain` 0.05; at the bound's default 0.11 it falls at
/// 2.0 and 2.3 m/s) the experiment holds its speed there within 2 %.
#[test]
fn with_the_labs_trim_at_its_gain_the_experiment_holds_its_speed() {
    let preset = match Creature::from_json(PRESET) {
        Ok(preset) => preset,
        Err(error) => panic!("{error}"),
    };
    for speed in [2.0, 2.3] {
        let trim_on = |p: &mut PhysicsParams| {
            p.lab_additions.get_or_insert_default().speed_trim = Some(true);
        };
        let (s, _) = run(&preset, None, speed, 60.0, trim_on, &["speed_trim"]);
        let off = speed_error(&s, "bound, trim on", speed);
        assert!(off.abs() < 0.02, "{:+.1} %", 100.0 * off);
    }
}
