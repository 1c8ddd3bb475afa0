//! PODA on paths tighter than the legs can follow (issue 19; Girard &
//! Maciejewski 1985, "Horizontal Control"): with `turn_within_reach` (on in
//! the bundled presets) the body cuts the corner and the planted feet stay
//! where they landed; without it, as before 2026-12-02, the body keeps to the
//! path and drags its feet. `path_error_max_m` says how far the body left
//! its path.

use gaitlab_core::driver::Driver;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::{Creature, PathSpec, load_bundled};
use gaitlab_motion::PodaDriver;

const FPS: f64 = 60.0;

fn quadruped() -> Creature {
    load_bundled("poda-quadruped")
        .expect("bundled preset")
        .expect("valid preset")
}

/// The issue's closed Catmull-Rom path, scaled.
fn tight(scale: f64) -> PathSpec {
    let points = [
        [0.0, 0.0],
        [1.0, 0.5],
        [2.0, -0.5],
        [3.0, 1.0],
        [2.0, 2.0],
        [0.0, 1.5],
    ];
    PathSpec {
        kind: Default::default(),
        points: points.iter().map(|[x, z]| [x * scale, z * scale]).collect(),
        closed: true,
        speeds_mps: None,
    }
}

/// Slip and path error, metres, of `seconds` of `gait` on `path`.
fn run(gait: &str, path: &PathSpec, within_reach: bool, seconds: f64) -> (f64, f64) {
    let creature = quadruped();
    let mut params = creature.scenario.poda_params();
    params.gait = Some(gait.to_owned());
    params.path = Some(path.clone());
    params.turn_within_reach = within_reach;
    let mut driver = PodaDriver::with_params(&creature, params).expect("driver");
    for _ in 0..(seconds * FPS).round() as usize {
        driver.step(1.0 / FPS);
    }
    (
        driver.metrics().foot_slip_max_m(),
        driver.path_error_max_m(),
    )
}

#[test]
fn the_bundled_presets_turn_within_their_legs_reach() {
    for name in ["poda-quadruped", "hexapod", "insect-14", "poda-biped"] {
        let creature = load_bundled(name).expect("bundled").expect("valid");
        assert!(creature.scenario.poda_params().turn_within_reach, "{name}");
    }
}

#[test]
fn on_the_issues_tight_path_the_body_cuts_corners_and_the_feet_stay() {
    for gait in ["walk", "trot"] {
        let (slip, departed) = run(gait, &tight(1.0), true, 12.0);
        assert!(slip <= 1e-3, "{gait}: slip {:.3} mm", slip * 1e3);
        // The bends are tighter than the legs reach: the body leaves the path.
        assert!(departed > 0.1, "{gait}: path error {departed} m");
        // As before 2026-12-02 (the force bound only), it keeps to the path
        // and drags its feet by centimetres or more.
        let (slip, departed) = run(gait, &tight(1.0), false, 12.0);
        assert!(slip > 0.02, "{gait} without the limit: slip {slip} m");
        assert!(departed < 0.02, "{gait} without the limit: {departed} m");
    }
}

#[test]
fn a_path_the_legs_can_take_is_followed_as_before() {
    // A circle of radius 3 m, well outside the quadruped's tightest turn (its
    // farthest reference foot's distance from the centre, under 1 m): the body
    // keeps to the path within centimetres, with or without the limit.
    let points = (0..16)
        .map(|k| {
            let a = f64::from(k) / 16.0 * std::f64::consts::TAU;
            [3.0 * a.pcos() - 3.0, 3.0 * a.psin()]
        })
        .collect();
    let circle = PathSpec {
        kind: Default::default(),
        points,
        closed: true,
        speeds_mps: None,
    };
    for gait in ["walk", "trot"] {
        let (slip, departed) = run(gait, &circle, true, 12.0);
        let (slip_before, departed_before) = run(gait, &circle, false, 12.0);
        assert!(
            slip <= 1e-3 && slip_before <= 1e-3,
            "{gait}: {slip} / {slip_before} m"
        );
        assert!(departed < 0.03, "{gait}: path error {departed} m");
        assert!(
            (departed - departed_before).abs() < 0.02,
            "{gait}: {departed} vs {departed_before} m"
        );
    }
}
