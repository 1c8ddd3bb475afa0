//! She 2006 §5.1.1 / §5.2.3 on the `she-2006` preset: the wounded weights'
//! two forms measured as the stiffened joints' range of motion against the
//! unwounded motion. The thesis' form (`angle`, θ_shown = w·θ) must leave a
//! weight-0.2 joint w × its range; the lab's form (`step`) is reported beside it.
//!
//! Figures: `cargo test -p gaitlab-motion --test she_2006_wounds -- --nocapture`.

mod common;

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::Creature;
use gaitlab_core::preset::thesis::{ThesisMode, WoundForm};
use gaitlab_motion::ThesisDriver;

const FPS: f64 = 60.0;
/// Seconds left out at the start (the IK settles from the rest pose).
const SETTLE_S: f64 = 2.0;
/// Seconds measured.
const MEASURE_S: f64 = 8.0;

/// Range (max − min) of each of `joints` over the measured seconds, radians.
fn ranges(
    creature: &Creature,
    mode: ThesisMode,
    form: WoundForm,
    method: Method,
    joints: &[usize],
) -> Vec<f64> {
    let mut creature = creature.clone();
    creature.scenario.mode = mode;
    creature.scenario.method = method;
    creature.scenario.thesis.wound_form = form;
    let mut driver = match ThesisDriver::for_creature(&creature) {
        Ok(driver) => driver,
        Err(error) => panic!("driver: {error}"),
    };
    let mut low = vec![f64::INFINITY; joints.len()];
    let mut high = vec![f64::NEG_INFINITY; joints.len()];
    let frames = ((SETTLE_S + MEASURE_S) * FPS).round() as usize;
    for frame in 0..frames {
        driver.step(1.0 / FPS);
        if (frame as f64) < SETTLE_S * FPS {
            continue;
        }
        for (k, &j) in joints.iter().enumerate() {
            let value = driver.pose().joints[j];
            low[k] = low[k].min(value);
            high[k] = high[k].max(value);
        }
    }
    high.iter().zip(&low).map(|(h, l)| h - l).collect()
}

#[test]
fn thesis_angle_form_leaves_the_weight_times_the_range() {
    let creature = common::she_2006();
    let wounded: Vec<(usize, f64, String)> = creature
        .scenario
        .thesis
        .wounded
        .iter()
        .map(|w| match creature.skeleton.joint_index(&w.joint) {
            Some(j) => (j, w.multiply, w.joint.clone()),
            None => panic!("no joint {}", w.joint),
        })
        .collect();
    let joints: Vec<usize> = wounded.iter().map(|(j, _, _)| *j).collect();
    for (plain, hurt) in [
        (ThesisMode::Walk, ThesisMode::WoundedWalk),
        (ThesisMode::Run, ThesisMode::WoundedRun),
    ] {
        for method in [Method::Transpose, Method::Pinv, Method::Dls, Method::Sdls] {
            let base = ranges(&creature, plain, WoundForm::Angle, method, &joints);
            let angle = ranges(&creature, hurt, WoundForm::Angle, method, &joints);
            let step = ranges(&creature, hurt, WoundForm::Step, method, &joints);
            for (k, (_, weight, name)) in wounded.iter().enumerate() {
                let angle_ratio = angle[k] / base[k];
                let step_ratio = step[k] / base[k];
                println!(
                    "{:<12} {:<9} {name:<20} w={weight:.1} range {:.3} rad; angle form {:.3} rad ({:.0} %), step form {:.3} rad ({:.0} %)",
                    hurt.name(),
                    method.name(),
                    base[k],
                    angle[k],
                    100.0 * angle_ratio,
                    step[k],
                    100.0 * step_ratio,
                );
                if base[k] > 0.05 {
                    assert!(
                        (angle_ratio - weight).abs() < 0.02,
                        "{} {} {name}: the angle form leaves {:.1} % of the range, expected {:.0} %",
                        hurt.name(),
                        method.name(),
                        100.0 * angle_ratio,
                        100.0 * weight
                    );
                }
            }
        }
    }
}
