//! Foot slip after a live PODA gait change (`PodaDriver::set_gait`, the
//! one-period phase and duty-factor blend of `GaitParams::blend_to`), for every
//! ordered pair of the quadruped's gaits, switched at each of 72 frames after
//! one second of the first gait. Prints the pairs where a planted foot slips
//! more than 1 mm, with the worst slip.
//!
//! `cargo run --release -p gaitlab-motion --example gait_switch_slip`

use std::collections::BTreeMap;
use std::process::ExitCode;

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_motion::PodaDriver;

const FPS: f64 = 60.0;
const GAITS: [&str; 8] = [
    "walk",
    "trot",
    "pace",
    "canter",
    "transverse_gallop",
    "rotary_gallop",
    "bound",
    "pronk",
];

fn main() -> ExitCode {
    let creature = match load_bundled("poda-quadruped") {
        Some(Ok(creature)) => creature,
        other => {
            eprintln!("poda-quadruped: {other:?}");
            return ExitCode::FAILURE;
        }
    };
    let mut over: BTreeMap<String, (usize, f64)> = BTreeMap::new();
    let mut cases = 0;
    for from in GAITS {
        for to in GAITS.iter().filter(|&&g| g != from) {
            for start in 0..72 {
                let Ok(mut driver) = PodaDriver::new(&creature) else {
                    eprintln!("poda-quadruped: no PODA driver");
                    return ExitCode::FAILURE;
                };
                let switched = driver.set_gait(from).and_then(|()| {
                    for _ in 0..60 + start {
                        driver.step(1.0 / FPS);
                    }
                    driver.set_gait(to)
                });
                if let Err(error) = switched {
                    eprintln!("{from} → {to}: {error}");
                    return ExitCode::FAILURE;
                }
                for _ in 0..150 {
                    driver.step(1.0 / FPS);
                }
                cases += 1;
                let slip_m = driver.metrics().foot_slip_max_m();
                if slip_m > 0.001 {
                    let entry = over.entry(format!("{from} → {to}")).or_default();
                    entry.0 += 1;
                    entry.1 = entry.1.max(slip_m);
                }
            }
        }
    }
    for (pair, (count, worst_m)) in &over {
        println!(
            "{pair}: {count} of 72 switch frames over 1 mm, worst {:.3} mm",
            worst_m * 1e3
        );
    }
    let total: usize = over.values().map(|v| v.0).sum();
    println!("{total} of {cases} switches slip more than 1 mm");
    ExitCode::SUCCESS
}
