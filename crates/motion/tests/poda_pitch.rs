//! Body pitch from the front and rear legs' vertical motion (Girard &
//! Maciejewski 1985, Figure 2 and "Rotational Control";
//! `scenario.poda.body_pitch`): the bundled quadruped's bound pitches, nose
//! up when its front section is higher, with planted feet still; a trot and
//! a pronk, whose front and rear push together, do not pitch; gait changes
//! into and out of the pitching gaits keep planted feet still.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_core::{Kinematics, preset::Creature};
use gaitlab_motion::PodaDriver;

const FPS: f64 = 60.0;

/// The bundled quadruped (`body_pitch` on by default).
fn quadruped() -> Creature {
    match load_bundled("poda-quadruped") {
        Some(Ok(creature)) => creature,
        other => panic!("poda-quadruped: {other:?}"),
    }
}

/// Runs `gait` for `seconds`; returns the pitch range (radians) and, over
/// the frames, the largest disagreement between the pitch's sign and the
/// front-minus-rear hip heights' sign (metres of the wrong sign).
fn run(creature: &Creature, gait: &str, seconds: f64) -> ((f64, f64), f64, f64) {
    let mut creature = creature.clone();
    if let Some(poda) = creature.scenario.poda.as_mut() {
        poda.gait = Some(gait.to_owned());
    }
    let mut driver = match PodaDriver::new(&creature) {
        Ok(driver) => driver,
        Err(error) => panic!("{gait}: {error}"),
    };
    let skeleton = creature.skeleton.clone();
    let joint = |name: &str| match skeleton.joint_index(name) {
        Some(j) => j,
        None => panic!("no joint {name}"),
    };
    let front = [
        joint("left_front_shoulder_x"),
        joint("right_front_shoulder_x"),
    ];
    let rear = [joint("left_hind_hip_x"), joint("right_hind_hip_x")];
    let mut wrong_sign_m: f64 = 0.0;
    for _ in 0..(seconds * FPS) as usize {
        driver.step(1.0 / FPS);
        let kin = Kinematics::of(&skeleton, driver.pose());
        let height =
            |js: [usize; 2]| (kin.joint_position[js[0]].y + kin.joint_position[js[1]].y) / 2.0;
        let lift = height(front) - height(rear);
        // The frame's pitch: the root's forward axis (+z) rises by sin(pitch).
        let forward_y = (driver.pose().root.rotation * glam::DVec3::Z).y;
        if forward_y * lift < 0.0 {
            wrong_sign_m = wrong_sign_m.max(lift.abs());
        }
    }
    let range = driver.metrics().body_pitch_range_rad;
    (range, wrong_sign_m, driver.metrics().foot_slip_max_m())
}

#[test]
fn the_bound_pitches_nose_up_when_its_front_is_higher_and_feet_stay_planted() {
    let creature = quadruped();
    let ((low, high), wrong_sign_m, slip_m) = run(&creature, "bound", 10.0);
    println!(
        "bound: pitch {:.2}° to {:.2}°, slip {:.4} mm",
        low.to_degrees(),
        high.to_degrees(),
        slip_m * 1e3
    );
    // Front and rear push half a cycle apart: the body rocks both ways.
    assert!(
        high.to_degrees() > 5.0 && low.to_degrees() < -5.0,
        "{low} {high}"
    );
    // Symmetric about level (the front and rear legs are alike).
    assert!((high + low).abs() < 1e-3, "{low} {high}");
    // Nose up exactly when the front hips are higher than the rear (1 mm slack).
    assert!(
        wrong_sign_m < 1e-3,
        "pitch and hip heights disagree by {wrong_sign_m} m"
    );
    assert!(slip_m < 1e-6, "planted feet slip {slip_m} m");
}

#[test]
fn a_trot_and_a_pronk_do_not_pitch_and_the_option_turns_it_off() {
    let creature = quadruped();
    for gait in ["trot", "pronk"] {
        let ((low, high), _, _) = run(&creature, gait, 5.0);
        assert!(
            low.abs() < 1e-9 && high.abs() < 1e-9,
            "{gait}: {low} {high}"
        );
    }
    let mut level = creature;
    if let Some(poda) = level.scenario.poda.as_mut() {
        poda.body_pitch = false;
    }
    let ((low, high), _, _) = run(&level, "bound", 5.0);
    assert_eq!(
        (low, high),
        (0.0, 0.0),
        "body_pitch off keeps the body level"
    );
    // The bundled preset pitches (Figure 2 by default).
    assert!(quadruped().scenario.poda_params().body_pitch);
}

/// A sample of `tools/poda_change_sweep.py --set
/// scenario.poda.body_pitch=true` (docs/poda.md, "Body pitch"): the
/// switches that slipped most before the IK stage pitched less where a
/// planted foot could not be held (walk → bound 30.8 mm, bound → walk
/// 18.1 mm, canter → bound 12.6 mm), and the worst left after it (pace →
/// bound at 2.0667 s, 0.16 mm): 12 s after each, no planted foot slipped
/// more than 1 mm, and the body pitched more than 10° either way.
#[test]
fn gait_changes_with_the_pitch_keep_planted_feet_still() {
    let creature = quadruped();
    for (from, to, frame) in [
        ("walk", "bound", 120),
        ("bound", "walk", 120),
        ("canter", "bound", 120),
        ("pace", "bound", 124),
    ] {
        let mut creature = creature.clone();
        if let Some(poda) = creature.scenario.poda.as_mut() {
            poda.gait = Some(from.to_owned());
        }
        let mut driver = match PodaDriver::new(&creature) {
            Ok(driver) => driver,
            Err(error) => panic!("{from}: {error}"),
        };
        for _ in 0..frame {
            driver.step(1.0 / FPS);
        }
        if let Err(error) = driver.set_gait(to) {
            panic!("{to}: {error}");
        }
        for _ in 0..(12.0 * FPS) as usize {
            driver.step(1.0 / FPS);
        }
        let slip_m = driver.metrics().foot_slip_max_m();
        let (low, high) = driver.metrics().body_pitch_range_rad;
        println!(
            "{from} → {to} at frame {frame}: slip {:.3} mm, pitch {:.1}° to {:.1}°",
            slip_m * 1e3,
            low.to_degrees(),
            high.to_degrees()
        );
        assert!(slip_m <= 1e-3, "{from} → {to}: slip {} mm", slip_m * 1e3);
        assert!(!driver.is_shifting(), "{from} → {to}: still shifting");
        assert!(
            high.to_degrees() > 10.0 && low.to_degrees() < -10.0,
            "{from} → {to}: pitch {low} to {high} rad"
        );
    }
}
