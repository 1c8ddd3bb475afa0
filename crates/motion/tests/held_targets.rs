//! Grab and pull on the thesis driver (issue 44): a held target moves at
//! once and the effector follows; on release the script takes over without a
//! jump; a pinned target stays; and the one-iteration step is bit-identical
//! to the iterations inside a normal frame.

use gaitlab_core::Kinematics;
use gaitlab_core::driver::Driver;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::load_bundled;
use gaitlab_motion::{Limb, ThesisDriver};
use glam::DVec3;

const DT: f64 = 1.0 / 60.0;

fn she_2006(method: Method) -> ThesisDriver {
    let creature = load_bundled("she-2006").expect("bundled").expect("valid");
    let mut driver = ThesisDriver::for_creature(&creature).expect("driver");
    driver.set_method(method);
    driver
}

fn target(driver: &ThesisDriver, e: usize) -> DVec3 {
    driver.targets().expect("targets").position[e]
}

#[test]
fn one_iteration_steps_are_bit_identical_to_a_frame() {
    for method in [Method::Transpose, Method::Pinv, Method::Dls, Method::Sdls] {
        let mut whole = she_2006(method);
        let mut by_iteration = she_2006(method);
        let of = whole.params().iterations_per_frame;
        assert!(of > 1, "the preset runs {of} iterations a frame");
        for _ in 0..37 {
            whole.step(DT);
            by_iteration.step(DT);
        }
        whole.step(DT);
        let mut before = by_iteration.pose().joints.clone();
        for k in 1..=of {
            let step = by_iteration.step_iteration(DT).expect("a step");
            assert_eq!((step.done, step.of), (k, of));
            assert_eq!(by_iteration.frame_open(), k < of);
            // Each iteration shows its own angles.
            assert_ne!(by_iteration.pose().joints, before, "iteration {k}");
            before = by_iteration.pose().joints.clone();
        }
        assert_eq!(whole.time().to_bits(), by_iteration.time().to_bits());
        let bits = |d: &ThesisDriver| -> Vec<u64> {
            d.pose().joints.iter().map(|x| x.to_bits()).collect()
        };
        assert_eq!(bits(&whole), bits(&by_iteration), "{method:?}");
        assert_eq!(whole.targets(), by_iteration.targets());
        let metrics = |d: &ThesisDriver| {
            let m = d.ik_metrics().expect("metrics");
            (0..4).map(|e| m.mean_error_m(e)).collect::<Vec<_>>()
        };
        assert_eq!(metrics(&whole), metrics(&by_iteration));
        // Pressing play inside an open frame finishes that frame.
        let mut partly = by_iteration.clone();
        partly.step_iteration(DT);
        partly.step(DT);
        whole.step(DT);
        assert_eq!(bits(&whole), bits(&partly), "{method:?} finished by play");
        assert_eq!(whole.time().to_bits(), partly.time().to_bits());
    }
}

#[test]
fn a_held_target_moves_at_once_and_sdls_reaches_it_within_a_second() {
    let mut driver = she_2006(Method::Sdls);
    for _ in 0..120 {
        driver.step(DT);
    }
    let hand = driver.effector_of(Limb::LeftHand);
    // Grab the target where the hand is (the script's hand targets lie
    // beyond reach, §5.3), then pull it 0.3 m toward the limb's anchor: a
    // spot well within reach.
    let from = driver.effector_positions()[hand];
    assert!(driver.hold_target(hand, Some(from)));
    let kinematics = Kinematics::of(driver.skeleton(), driver.pose());
    let anchor = driver
        .skeleton()
        .limb(hand)
        .anchor(&kinematics.joint_anchor, &kinematics.joint_position);
    let to = from + (anchor - from).normalize() * 0.3;
    assert!(driver.hold_target(hand, Some(to)));
    let moved = target(&driver, hand).distance(from);
    assert!((moved - 0.3).abs() < 0.01, "moved {moved:.4} m");
    let mut reached_at = None;
    for frame in 1..=60 {
        driver.step(DT);
        let report = driver.ik_report().expect("report");
        assert!(
            report.out_of_reach_m[hand] <= 0.0,
            "a reachable spot: {:?}",
            report.out_of_reach_m
        );
        if reached_at.is_none() && report.effector_error_m[hand] < 0.01 {
            reached_at = Some(frame);
        }
    }
    let error = driver.ik_report().expect("report").effector_error_m[hand];
    println!("SDLS reaches the held target in {reached_at:?} frames; error after 1 s {error:.4} m");
    assert!(error < 0.01, "error {error} m after 1 s");
    // Held in the root's frame: the walking figure carries it along.
    let root = driver.pose().root.position;
    let held = driver.held().held_at(hand).expect("held");
    assert!((target(&driver, hand) - (root + held)).length() < 1e-12);
    // Paused: settling reaches for a moved target without advancing time.
    let time = driver.time();
    driver.hold_target(
        hand,
        Some(target(&driver, hand) + DVec3::new(0.0, 0.0, 0.05)),
    );
    for _ in 0..30 {
        driver.settle();
    }
    assert_eq!(driver.time(), time);
    let error = driver.ik_report().expect("report").effector_error_m[hand];
    assert!(error < 0.01, "settled error {error} m");
}

#[test]
fn a_released_target_rejoins_the_script_without_a_jump() {
    let mut held = she_2006(Method::Sdls);
    let mut free = she_2006(Method::Sdls);
    for _ in 0..90 {
        held.step(DT);
        free.step(DT);
    }
    let hand = held.effector_of(Limb::RightHand);
    let away = target(&held, hand) + DVec3::new(0.3, 0.4, -0.2);
    held.hold_target(hand, Some(away));
    for _ in 0..30 {
        held.step(DT);
        free.step(DT);
    }
    held.hold_target(hand, None);
    let offset = |h: &ThesisDriver, f: &ThesisDriver| target(h, hand) - target(f, hand);
    let mut last = offset(&held, &free);
    let mut largest: f64 = 0.0;
    let mut frames_to_script = None;
    for frame in 1..=600 {
        held.step(DT);
        free.step(DT);
        let now = offset(&held, &free);
        largest = largest.max((now - last).length());
        last = now;
        if frames_to_script.is_none() && now.length() < 1e-12 {
            frames_to_script = Some(frame);
        }
    }
    println!(
        "released {:.3} m from the script: largest extra move {:.2} mm/frame, back on the script after {frames_to_script:?} frames",
        (away - target(&free, hand)).length(),
        largest * 1e3
    );
    assert!(largest < 0.005, "{largest} m in a frame");
    assert!(frames_to_script.is_some(), "the script takes over");
}

#[test]
fn a_pinned_target_stays_after_release_and_unpinning_lets_it_go() {
    let mut driver = she_2006(Method::Dls);
    for _ in 0..30 {
        driver.step(DT);
    }
    let foot = driver.effector_of(Limb::LeftFoot);
    let spot = target(&driver, foot) + DVec3::new(0.0, 0.2, 0.1);
    driver.hold_target(foot, Some(spot));
    driver.pin_target(foot, true);
    driver.hold_target(foot, None);
    for _ in 0..120 {
        driver.step(DT);
    }
    let body = driver.held().held_at(foot).expect("still held");
    assert!(driver.held().is_pinned(foot));
    let root = driver.pose().root.position;
    assert!((target(&driver, foot) - (root + body)).length() < 1e-12);
    driver.pin_target(foot, false);
    for _ in 0..240 {
        driver.step(DT);
    }
    assert_eq!(driver.held().held_at(foot), None);
    assert!(!driver.held().any(), "back on the script");
    // Bad input is refused, not a panic.
    assert!(!driver.hold_target(99, Some(spot)));
    assert!(!driver.hold_target(foot, Some(DVec3::NAN)));
}
