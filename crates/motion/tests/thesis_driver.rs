//! The thesis driver on the human figure (She 2006 §5.2–5.3): tracking figures
//! per method and mode, joint limits, wounded weights, stride-matched speed,
//! reset, live changes and parameter errors.

mod common;

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::thesis::{ThesisMode, ThesisParams, WoundedJoint};
use gaitlab_core::{Pose, Skeleton};
use gaitlab_motion::{Limb, ThesisDriver};

const FPS: f64 = 60.0;

fn driver(
    skeleton: &Skeleton,
    params: ThesisParams,
    mode: ThesisMode,
    method: Method,
) -> ThesisDriver {
    let options = IkOptions {
        method,
        ..IkOptions::default()
    };
    match ThesisDriver::new(skeleton.clone(), params, mode, options) {
        Ok(driver) => driver,
        Err(error) => panic!("driver: {error}"),
    }
}

fn frames(seconds: f64) -> usize {
    (seconds * FPS).round() as usize
}

/// Mean and max error of the two feet, metres.
fn foot_errors(driver: &ThesisDriver) -> [(f64, f64); 2] {
    let Some(metrics) = driver.ik_metrics() else {
        panic!("the thesis driver reports IK metrics")
    };
    [Limb::LeftFoot, Limb::RightFoot].map(|limb| {
        let e = driver.effector_of(limb);
        (
            metrics.mean_error_m(e).unwrap_or(f64::NAN),
            metrics.max_error_m(e).unwrap_or(f64::NAN),
        )
    })
}

fn assert_pose_valid(skeleton: &Skeleton, pose: &Pose, context: &str) {
    assert!(
        pose.root.position.is_finite() && pose.root.rotation.is_finite(),
        "{context}: root"
    );
    for (joint, &value) in skeleton.joints().iter().zip(&pose.joints) {
        assert!(value.is_finite(), "{context}: {} is {value}", joint.name);
        if let Some((lo, hi)) = joint.limits {
            assert!(
                value >= lo - 1e-9 && value <= hi + 1e-9,
                "{context}: {} = {value} outside [{lo}, {hi}]",
                joint.name
            );
        }
    }
}

#[test]
fn walk_with_sdls_tracks_the_feet_within_five_millimetres() {
    let skeleton = common::human();
    let mut driver = driver(
        &skeleton,
        ThesisParams::default(),
        ThesisMode::Walk,
        Method::Sdls,
    );
    for _ in 0..frames(20.0) {
        driver.step(1.0 / FPS);
    }
    let Some(metrics) = driver.ik_metrics() else {
        panic!("metrics")
    };
    assert_eq!(metrics.frames, 1200);
    assert!((metrics.sim_seconds - 20.0).abs() < 1e-9);
    assert_eq!(
        metrics.iterations,
        1200 * ThesisParams::default().iterations_per_frame as u64
    );
    let errors = foot_errors(&driver);
    for (limb, (mean, max)) in [Limb::LeftFoot, Limb::RightFoot].iter().zip(errors) {
        println!(
            "walk sdls {limb:?}: mean {:.3} mm, max {:.3} mm",
            mean * 1e3,
            max * 1e3
        );
        assert!(mean <= 0.005, "{limb:?} mean error {mean} m > 5 mm");
    }
    // The figure walked: the root moved forward at the stride-matched speed,
    // after rising from 0 over the start ramp (a smoothstep, half its length lost).
    let ramp = ThesisParams::default().start_ramp_s;
    let expected = driver.script().speed_mps() * (20.0 - 0.5 * ramp);
    let walked = driver.pose().root.position.z;
    assert!(
        (walked - expected).abs() < 0.02,
        "walked {walked} m, expected {expected} m"
    );
    assert!(expected > 10.0, "walked only {expected} m in 20 s");
}

#[test]
fn every_method_and_mode_runs_a_minute_finite_and_within_limits() {
    let skeleton = common::human();
    for method in Method::ALL {
        for mode in ThesisMode::ALL {
            let mut driver = driver(&skeleton, ThesisParams::default(), mode, method);
            let context = format!("{} {}", method.name(), mode.name());
            for frame in 0..frames(60.0) {
                driver.step(1.0 / FPS);
                if frame % 6 == 0 {
                    assert_pose_valid(&skeleton, driver.pose(), &context);
                    assert!(
                        driver.effector_positions().iter().all(|p| p.is_finite()),
                        "{context}"
                    );
                }
            }
            assert_pose_valid(&skeleton, driver.pose(), &context);
            let Some(metrics) = driver.ik_metrics() else {
                panic!("metrics")
            };
            assert_eq!(metrics.non_finite_frames, 0, "{context}");
            assert_eq!(metrics.restored_frames, 0, "{context}");
            let [(left_mean, left_max), (right_mean, right_max)] = foot_errors(&driver);
            println!(
                "{context:>22}: feet mean {:.2} / {:.2} mm, max {:.1} / {:.1} mm",
                left_mean * 1e3,
                right_mean * 1e3,
                left_max * 1e3,
                right_max * 1e3
            );
            assert!(left_max.is_finite() && right_max.is_finite(), "{context}");
        }
    }
}

#[test]
fn dls_and_sdls_track_every_mode_closely() {
    let skeleton = common::human();
    for method in [Method::Dls, Method::Sdls] {
        for mode in ThesisMode::ALL {
            let mut driver = driver(&skeleton, ThesisParams::default(), mode, method);
            for _ in 0..frames(20.0) {
                driver.step(1.0 / FPS);
            }
            let errors = foot_errors(&driver);
            let bound = if mode.wounded() { 0.03 } else { 0.01 };
            for (mean, _) in errors {
                assert!(
                    mean <= bound,
                    "{} {}: foot mean error {mean} m",
                    method.name(),
                    mode.name()
                );
            }
        }
    }
}

#[test]
fn planted_foot_target_is_at_rest_in_the_world_at_mid_stance() {
    let skeleton = common::human();
    for mode in [ThesisMode::Walk, ThesisMode::Run] {
        let mut driver = driver(&skeleton, ThesisParams::default(), mode, Method::Sdls);
        let foot = driver.effector_of(Limb::LeftFoot);
        let period = driver.script().period_s();
        let mut previous = None;
        let mut checked = 0;
        for _ in 0..frames(3.0 * period) {
            driver.step(1.0 / FPS);
            let Some(targets) = driver.targets() else {
                panic!("targets")
            };
            let z = targets.position[foot].z;
            // Left mid-stance is phase π (half a cycle into each period).
            let phase = driver.phase();
            if let Some(previous) = previous
                && (phase - std::f64::consts::PI).abs() < 0.1
            {
                let moved: f64 = z - previous;
                assert!(
                    moved.abs() < 2e-3,
                    "{mode:?}: planted foot target moved {moved} m in a frame"
                );
                checked += 1;
            }
            previous = Some(z);
        }
        assert!(checked >= 3, "{mode:?}: only {checked} mid-stance frames");
    }
}

#[test]
fn wounded_modes_change_the_wounded_joints_and_keep_the_feet_on_target() {
    let skeleton = common::human();
    let params = ThesisParams::default();
    assert!(!params.wounded.is_empty(), "the defaults wound some joints");
    for (plain, wounded) in [
        (ThesisMode::Walk, ThesisMode::WoundedWalk),
        (ThesisMode::Run, ThesisMode::WoundedRun),
    ] {
        let mut a = driver(&skeleton, params.clone(), plain, Method::Sdls);
        let mut b = driver(&skeleton, params.clone(), wounded, Method::Sdls);
        let joints: Vec<usize> = params
            .wounded
            .iter()
            .filter_map(|w| skeleton.joint_index(&w.joint))
            .collect();
        assert_eq!(joints.len(), params.wounded.len());
        let mut squared = vec![0.0; joints.len()];
        let n = frames(10.0);
        for _ in 0..n {
            a.step(1.0 / FPS);
            b.step(1.0 / FPS);
            for (sum, &j) in squared.iter_mut().zip(&joints) {
                let d = a.pose().joints[j] - b.pose().joints[j];
                *sum += d * d;
            }
        }
        for (w, sum) in params.wounded.iter().zip(&squared) {
            let rms = (sum / n as f64).sqrt();
            println!("{}: {} RMS change {:.3} rad", wounded.name(), w.joint, rms);
            assert!(
                rms > 0.05,
                "{}: {} changed only {rms} rad RMS",
                wounded.name(),
                w.joint
            );
        }
        for (mean, max) in foot_errors(&b) {
            println!(
                "{}: foot mean {:.2} mm, max {:.1} mm",
                wounded.name(),
                mean * 1e3,
                max * 1e3
            );
            assert!(mean < 0.03, "{}: foot mean error {mean} m", wounded.name());
        }
    }
}

#[test]
fn switching_modes_live_applies_and_clears_the_wounded_weights() {
    let skeleton = common::human();
    let params = ThesisParams::default();
    let mut plain = driver(&skeleton, params.clone(), ThesisMode::Walk, Method::Sdls);
    let mut switched = driver(
        &skeleton,
        params.clone(),
        ThesisMode::WoundedWalk,
        Method::Sdls,
    );
    switched.set_mode(ThesisMode::Walk);
    for _ in 0..frames(2.0) {
        plain.step(1.0 / FPS);
        switched.step(1.0 / FPS);
    }
    assert_eq!(
        plain.pose().joints,
        switched.pose().joints,
        "clearing the weights restores the plain walk"
    );
    switched.set_mode(ThesisMode::WoundedWalk);
    for _ in 0..frames(1.0) {
        plain.step(1.0 / FPS);
        switched.step(1.0 / FPS);
    }
    assert_ne!(plain.pose().joints, switched.pose().joints);
}

#[test]
fn reset_returns_to_the_rest_pose_at_time_zero() {
    let skeleton = common::human();
    let mut driver = driver(
        &skeleton,
        ThesisParams::default(),
        ThesisMode::Run,
        Method::Dls,
    );
    let fresh_targets = driver.targets().cloned();
    let fresh_root = driver.pose().root;
    assert_eq!(driver.pose().joints, skeleton.rest_values());
    for _ in 0..frames(2.5) {
        driver.step(1.0 / FPS);
    }
    assert!(driver.time() > 2.4);
    assert_ne!(driver.pose().joints, skeleton.rest_values());
    driver.reset();
    assert_eq!(driver.time(), 0.0);
    assert_eq!(driver.phase(), 0.0);
    assert_eq!(driver.distance_m(), 0.0);
    assert_eq!(driver.pose().joints, skeleton.rest_values());
    assert_eq!(driver.pose().root, fresh_root);
    assert_eq!(driver.targets().cloned(), fresh_targets);
    let Some(metrics) = driver.ik_metrics() else {
        panic!("metrics")
    };
    assert_eq!(metrics.frames, 0);
    // The root stands at the script's height for phase 0.
    let expected = driver.script().at_time(0.0).root_height_m;
    assert!((driver.pose().root.position.y - expected).abs() < 1e-12);
}

#[test]
fn runs_are_bit_identical() {
    let skeleton = common::human();
    let mut a = driver(
        &skeleton,
        ThesisParams::default(),
        ThesisMode::WoundedRun,
        Method::Sdls,
    );
    let mut b = driver(
        &skeleton,
        ThesisParams::default(),
        ThesisMode::WoundedRun,
        Method::Sdls,
    );
    for _ in 0..frames(3.0) {
        a.step(1.0 / FPS);
        b.step(1.0 / FPS);
    }
    assert_eq!(a.pose(), b.pose());
}

#[test]
fn not_moving_forward_keeps_the_root_in_place() {
    let skeleton = common::human();
    let params = ThesisParams {
        moving_forward: false,
        ..ThesisParams::default()
    };
    let mut driver = driver(&skeleton, params, ThesisMode::Walk, Method::Sdls);
    for _ in 0..frames(2.0) {
        driver.step(1.0 / FPS);
    }
    assert_eq!(driver.pose().root.position.z, 0.0);
    assert_eq!(driver.pose().root.position.x, 0.0);
}

#[test]
fn bad_parameters_are_refused_with_a_path() {
    let skeleton = common::human();
    let bad_role = ThesisParams {
        roles: gaitlab_core::preset::thesis::EffectorRoles {
            left_foot: "left_paw".into(),
            ..Default::default()
        },
        ..ThesisParams::default()
    };
    let error = ThesisDriver::new(
        skeleton.clone(),
        bad_role,
        ThesisMode::Walk,
        IkOptions::default(),
    )
    .err();
    assert_eq!(error.map(|e| e.path), Some("roles.left_foot".to_owned()));

    let bad_joint = ThesisParams {
        wounded: vec![WoundedJoint {
            joint: "tail".into(),
            multiply: 0.5,
            add: 0.0,
        }],
        ..ThesisParams::default()
    };
    let error = ThesisDriver::new(
        skeleton.clone(),
        bad_joint.clone(),
        ThesisMode::Walk,
        IkOptions::default(),
    )
    .err();
    assert_eq!(error.map(|e| e.path), Some("wounded[0].joint".to_owned()));

    let mut driver = driver(
        &skeleton,
        ThesisParams::default(),
        ThesisMode::Walk,
        Method::Sdls,
    );
    let zero_slowdown = ThesisParams {
        slowdown: 0.0,
        ..ThesisParams::default()
    };
    let error = driver.set_params(zero_slowdown).err();
    assert_eq!(
        error.map(|e| e.to_string().starts_with("slowdown: ")),
        Some(true)
    );
    assert!(driver.set_params(bad_joint).is_err());
    assert_eq!(
        driver.params(),
        &ThesisParams::default(),
        "a refused change leaves the driver as it was"
    );
}
