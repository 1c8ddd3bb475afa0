//! The hexapod with one and two more pairs of legs (8 and 10 legs) walks in the
//! n-legged named gaits (Girard & Maciejewski 1985, "Leg Coordination": gaits
//! "for figures having any number of legs"; gaitlab's alternating, ripple and
//! wave): on a straight line for 12 s its planted feet do not slip, the body
//! advances at the commanded speed, and each leg's measured duty factor and
//! relative phase are the gait's.

mod common;

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::{Creature, bundled_json};
use gaitlab_motion::PodaDriver;
use gaitlab_motion::poda::gait_names;

const FPS: f64 = 60.0;
/// Seconds walked, and seconds left out of the speed measurement while the body gets going.
const WALK_S: f64 = 12.0;
const SETTLE_S: f64 = 2.0;
/// Spacing of the hexapod's leg pairs along the body, metres (presets/hexapod.json).
const PAIR_SPACING_M: f64 = 0.2;

/// The bundled hexapod with `extra` pairs of legs added behind its last pair,
/// the way a user edits the preset: copies of the `L3`/`R3` limbs renamed
/// `L4`/`R4`, … and moved back by the pair spacing, appended to
/// `skeleton.limbs` (the legs default to the limbs in order, pairs front to
/// back, left then right).
fn hexapod_with_extra_pairs(extra: usize) -> Creature {
    let hexapod = bundled_json("hexapod").expect("bundled hexapod");
    let text = gaitlab_testkit::with_extra_leg_pairs(hexapod, 3, extra, PAIR_SPACING_M);
    Creature::from_json(&text).expect("valid preset")
}

#[test]
fn the_hexapod_preset_with_added_pairs_has_the_added_legs() {
    for (extra, legs) in [(1, 8), (2, 10)] {
        let creature = hexapod_with_extra_pairs(extra);
        let spec = creature.scenario.poda_params().legs;
        let names: Vec<&str> = spec.iter().map(|l| l.effector.as_str()).collect();
        assert_eq!(names.len(), legs);
        assert_eq!(&names[6..8], ["L4_foot", "R4_foot"]);
        // The preset's own gait is the 6-legged tripod: refused, naming the n-legged gaits.
        let error = PodaDriver::new(&creature).expect_err("no tripod for 8 or 10 legs");
        assert!(
            error.to_string().ends_with(&format!(
                "no gait \"tripod\" for {legs} legs; available: wave, alternating, ripple"
            )),
            "{error}"
        );
    }
}

/// Walks `creature` in `gait` for [`WALK_S`] at `fps`; the driver and the root's
/// ground position at [`SETTLE_S`].
fn walk(creature: &Creature, gait: &str, fps: f64) -> (PodaDriver, glam::DVec2) {
    let mut params = creature.scenario.poda_params();
    params.gait = Some(gait.to_owned());
    let mut driver = PodaDriver::with_params(creature, params).expect("driver");
    let mut settled = glam::DVec2::NAN;
    for frame in 1..=(WALK_S * fps).round() as usize {
        driver.step(1.0 / fps);
        if frame == (SETTLE_S * fps).round() as usize {
            let root = driver.pose().root.position;
            settled = glam::DVec2::new(root.x, root.z);
        }
    }
    (driver, settled)
}

#[test]
fn eight_and_ten_legs_walk_straight_in_every_named_gait_without_slipping() {
    let mut report = Vec::new();
    for extra in [1, 2] {
        let creature = hexapod_with_extra_pairs(extra);
        let legs = creature.scenario.poda_params().legs.len();
        let commanded = creature.scenario.poda_params().speed_mps;
        let gaits: Vec<&str> = gait_names(legs).collect();
        assert_eq!(gaits, ["wave", "alternating", "ripple"]);
        for gait in gaits {
            let label = format!("{legs} legs {gait}");
            // At the preset's 60 fps: planted feet stay put, the body keeps its speed and line.
            let (driver, settled) = walk(&creature, gait, FPS);
            let slip = driver.metrics().foot_slip_max_m();
            let end = driver.pose().root.position;
            let speed = (glam::DVec2::new(end.x, end.z) - settled).length() / (WALK_S - SETTLE_S);
            report.push(format!(
                "{label}: slip {:.4} mm, speed {speed:.5} m/s (commanded {commanded}), \
                 sideways {:.3} mm, duty {}",
                slip * 1e3,
                end.x.abs() * 1e3,
                driver.gait().duty_factor()
            ));
            assert!(slip <= 0.001, "{label}: foot slip {:.3} mm", slip * 1e3);
            assert!(
                (speed - commanded).abs() <= 0.02 * commanded,
                "{label}: body speed {speed} m/s for {commanded} m/s"
            );
            assert!(
                end.x.abs() < 0.01,
                "{label}: straight ahead, x = {} m",
                end.x
            );
            // At 240 fps, where a 0.08 s transfer (the 10-legged wave) spans 19 frames rather
            // than 5, so that the contact times interpolated between frames are sharp: each
            // leg's measured duty factor and relative phase are the gait's.
            let (driver, _) = walk(&creature, gait, 4.0 * FPS);
            let metrics = driver.metrics();
            assert!(metrics.foot_slip_max_m() <= 0.001, "{label} at 240 fps");
            common::assert_gait_measured_as_set(&label, &driver);
        }
    }
    println!("{}", report.join("\n"));
}
