//! Shared by the tests of the gains the presets carry: a preset's gait run
//! by the paper's laws alone for a while, its summary and leg names.

#![allow(dead_code, reason = "each test binary uses a part of this")]

use gaitlab_core::Creature;
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::physics::PhysicsParams;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::engine::metrics::GaitSummary;

/// The additions a gait keeps by default where the paper's law alone misses
/// (docs/physics.md, "Eq. 2 as written"): the kangaroo's hop integrator
/// (every other bundled gait runs by eq. 2 alone).
pub const KEPT: &[&str] = &["hop_integrator"];

/// `preset`'s `gait` (its own when `None`) at `speed` (m/s) for `seconds`
/// of simulated time, asserting it runs with none of the lab's additions
/// but those in [`KEPT`] and does not fall; its summary and leg names.
pub fn paper_only_run(
    preset: &Creature,
    gait: Option<&str>,
    speed: f64,
    seconds: f64,
) -> (GaitSummary, Vec<String>) {
    run_where(
        preset,
        gait,
        speed,
        seconds,
        |_| {},
        |got| {
            assert!(
                got.iter().all(|name| KEPT.contains(name)),
                "the lab's additions: {got:?}"
            );
        },
    )
}

/// `preset`'s `gait` (its own when `None`) at `speed` (m/s) for `seconds`
/// of simulated time, after `edit` has changed its physics parameters,
/// asserting it runs with exactly the lab's additions `additions` and does
/// not fall (the run stops at a fall's restart, which would otherwise start
/// the clock again); its summary and leg names.
pub fn run(
    preset: &Creature,
    gait: Option<&str>,
    speed: f64,
    seconds: f64,
    edit: impl FnOnce(&mut PhysicsParams),
    additions: &[&str],
) -> (GaitSummary, Vec<String>) {
    run_where(preset, gait, speed, seconds, edit, |got| {
        assert_eq!(got, additions, "the lab's additions");
    })
}

/// [`run`], the additions the driver runs with checked by `check`.
fn run_where(
    preset: &Creature,
    gait: Option<&str>,
    speed: f64,
    seconds: f64,
    edit: impl FnOnce(&mut PhysicsParams),
    check: impl FnOnce(&[&str]),
) -> (GaitSummary, Vec<String>) {
    let mut driver = driver_with(preset, |params| {
        if let Some(gait) = gait {
            params.gait = Some(gait.to_owned());
        }
        params.speed_mps = speed;
        edit(params);
    });
    check(&driver.lab_additions().collect::<Vec<_>>());
    while driver.time() < seconds && driver.resets() == 0 {
        driver.step(1.0 / 60.0);
    }
    assert_eq!(driver.resets(), 0, "{gait:?} at {speed} m/s fell");
    let legs = driver.leg_names().map(str::to_owned).collect();
    (driver.summary(), legs)
}

/// A driver for `preset` with its physics parameters changed by `edit`.
pub fn driver_with(preset: &Creature, edit: impl FnOnce(&mut PhysicsParams)) -> PhysicsDriver {
    let Some(mut params) = preset.scenario.physics.clone() else {
        panic!("a physics preset")
    };
    edit(&mut params);
    match PhysicsDriver::with_params(preset, params) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    }
}

/// The bundled preset `name`.
pub fn bundled(name: &str) -> Creature {
    let Some(Ok(preset)) = gaitlab_core::preset::load_bundled(name) else {
        panic!("{name} is bundled")
    };
    preset
}

/// Each measured Table-2 row of `gait` (inputs and speed-error rows left
/// out) with its difference from the paper's animation column (%), printed
/// as it goes; a row not measured fails.
pub fn table2_diffs(s: &GaitSummary, gait: &str, legs: &[String]) -> Vec<(&'static str, f64)> {
    let legs: Vec<&str> = legs.iter().map(String::as_str).collect();
    let mut rows = Vec::new();
    for c in gaitlab_physics::engine::table2::compare(s, gait, &legs) {
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
        rows.push((c.row.label, diff));
    }
    rows
}

/// Asserts every measured Table-2 row of `gait` ([`table2_diffs`]) lies
/// within ±`pct` % of the paper's animation column; the number of rows.
pub fn assert_table2_within(s: &GaitSummary, gait: &str, legs: &[String], pct: f64) -> usize {
    let rows = table2_diffs(s, gait, legs);
    for (label, diff) in &rows {
        assert!(diff.abs() <= pct, "{label}: {diff:+.1} %");
    }
    rows.len()
}

/// The mean speed's error from `speed` (a fraction), printed.
pub fn speed_error(s: &GaitSummary, what: &str, speed: f64) -> f64 {
    let off = (s.speed_mean_mps - speed) / speed;
    println!(
        "{what} at {speed} m/s: mean {:.3} ({:+.1} %), pitch {:.1}°",
        s.speed_mean_mps,
        100.0 * off,
        s.pitch_magnitude_deg
    );
    off
}
