//! Static stability of PODA walks (issue 21 item 3): the hexapod's wave at
//! duty factor 0.83 keeps about five feet down and its body's centre inside
//! their support polygon all the time; the same wave at duty 0.46 (2.76 feet
//! down on average) leaves it for a large share of every period, which is
//! what the app warns about. Independent check: the feet down counted here
//! average six times the duty factor.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::{Creature, bundled_json};
use gaitlab_motion::PodaDriver;

const FPS: f64 = 60.0;

/// Walks the hexapod's wave at `duty` for 8 s; returns the largest unstable
/// share over the last 4 s and the mean number of feet down.
fn wave(duty: f64) -> (f64, f64) {
    let creature = Creature::from_json(bundled_json("hexapod").expect("bundled")).expect("valid");
    let mut driver = PodaDriver::new(&creature).expect("driver");
    driver.set_gait("wave").expect("wave");
    driver.gait_mut().set_duty_factor(duty).expect("duty");
    driver.reset();
    let (mut worst, mut feet, mut frames) = (0.0f64, 0.0, 0.0);
    for frame in 0..(8.0 * FPS) as usize {
        driver.step(1.0 / FPS);
        if frame as f64 >= 4.0 * FPS {
            let report = driver.stability();
            worst = worst.max(report.unstable_share);
            feet += report.feet_down as f64;
            frames += 1.0;
        }
    }
    (worst, feet / frames)
}

#[test]
fn a_slow_wave_is_statically_stable_and_a_fast_one_is_not() {
    let (stable, feet_stable) = wave(0.83);
    let (unstable, feet_unstable) = wave(0.46);
    println!("wave 0.83: unstable share {stable:.2}, feet down {feet_stable:.2}");
    println!("wave 0.46: unstable share {unstable:.2}, feet down {feet_unstable:.2}");
    assert!((feet_stable - 6.0 * 0.83).abs() < 0.3, "{feet_stable}");
    assert!((feet_unstable - 6.0 * 0.46).abs() < 0.3, "{feet_unstable}");
    assert_eq!(
        stable, 0.0,
        "the slow wave never leaves its support polygon"
    );
    assert!(
        unstable > 0.2,
        "the fast wave is statically unstable {unstable:.2} of a period"
    );
}
