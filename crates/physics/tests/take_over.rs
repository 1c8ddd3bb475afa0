//! Gait changes by the paper's take-over at the next flight (Raibert &
//! Hodgins 1991, "Gaits"; issue 42 item 3), by the paper's laws alone and
//! without the lab's entry at a gait's own start: the new gait's controller
//! takes over from the state it finds in a flight it can start in, and the
//! quadruped runs on in it.

use gaitlab_core::Creature;
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::{bundled_json, paper_alone};
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::engine::gait_change::Entry;
use serde_json::Value;

/// The bundled quadruped, paper alone (every lab addition off, no
/// `switch_to_start`; every gait by eq. 2 alone, as bundled since the night
/// of 2026-12-06: docs/physics.md, "Eq. 2 as written"), `from` at `speed`
/// m/s.
fn quadruped(from: &str, speed: f64) -> PhysicsDriver {
    let json = bundled_json("raibert-quadruped").expect("bundled");
    let mut preset: Value = serde_json::from_str(json).expect("json");
    paper_alone(&mut preset).expect("paper alone");
    let creature = Creature::from_json(&preset.to_string()).expect("preset");
    let mut params = creature.scenario.physics.clone().expect("physics");
    assert!(
        params.switch_to_start.is_empty(),
        "paper alone: no own-start entry"
    );
    params.gait = Some(from.to_owned());
    params.speed_mps = speed;
    let mut driver = PhysicsDriver::with_params(&creature, params).expect("driver");
    driver.reset_after_fall = false;
    driver
}

/// `from` for `at_s`, then `to` asked for, on to `seconds`: asserts the
/// take-over happened within `within_s` after `at_s` and the quadruped ran
/// on without a fall or a put-back.
fn takes_over(from: &str, to: &str, speed: f64, at_s: f64, within_s: f64, seconds: f64) {
    let mut driver = quadruped(from, speed);
    while driver.sim().time < at_s {
        driver.step(1.0 / 60.0);
    }
    driver.set_gait(to).expect("a gait of the quadruped");
    while driver.sim().time < seconds {
        driver.step(1.0 / 60.0);
    }
    let took = driver
        .gait_changes()
        .iter()
        .find(|c| c.to == to && c.entry == Entry::TakeOver && c.from == from)
        .map(|c| c.at_s)
        .unwrap_or_else(|| panic!("{from} → {to}: the {to} never took over"));
    assert_eq!(driver.running_gait(), to);
    assert!(
        (at_s..at_s + within_s).contains(&took),
        "{from} → {to}: took over at {took} s"
    );
    assert!(
        !driver.summary().fell && driver.resets() == 0,
        "{from} → {to}: fell after taking over at {took} s"
    );
}

/// The example, which blew up at 13.96 s before the take-over
/// started from the state it finds: trot to bound at 2.3 m/s at 10 s.
#[test]
fn the_trot_hands_over_to_the_bound_at_the_next_flight_and_it_bounds_on() {
    takes_over("trot", "bound", 2.3, 10.0, 0.5, 30.0);
}

/// Out of the gallop into the trot: the trot waits for a flight long
/// enough for its landing pair (the gallop's short extended flight is
/// not), then runs on.
#[test]
fn the_gallop_hands_over_to_the_trot_in_a_flight_long_enough() {
    takes_over("gallop", "trot", 1.5, 7.0, 1.0, 27.0);
}

/// Bound and gallop change by the same take-over, each style's controller
/// with its own gains.
#[test]
fn the_bound_hands_over_to_the_gallop_by_the_same_take_over() {
    takes_over("bound", "gallop", 1.5, 10.0, 0.5, 30.0);
}

/// Out of the bound into the trot at 1.5 m/s, the case the bound tuned
/// without it lost at every switch time (its trunk 14–15° nose up or down
/// at the end of every flight, too steep for a diagonal pair to land
/// together): the bound tuned with the switch out of it in the objective
/// pitches less, and the trot takes over and trots on.
#[test]
fn the_bound_hands_over_to_the_trot_at_its_slowest_speed() {
    takes_over("bound", "trot", 1.5, 10.0, 0.5, 30.0);
}
