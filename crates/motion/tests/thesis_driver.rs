//! The thesis driver on the human figure (She 2006 §5.2–5.3): tracking figures
//! per method and mode, joint limits, wounded weights, stride-matched speed,
//! reset, live changes and parameter errors.

mod common;

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::thesis::{ThesisMode, ThesisParams, WoundedJoint};
use gaitlab_core::{Pose, Skeleton};
use gaitlab_motion::{Limb, ThesisDriver, ThesisScript};

const FPS: f64 = 60.0;

fn driver(
    skeleton: &Skeleton,
    params: ThesisParams,
    mode: ThesisMode,
    method: Method,
) -> ThesisDriver {
    // λ = 0.05 m: what the `human` preset ran as a `gaitlab-preset/1` file
    // (until 2026-12-06), with the lab's script of `common::human_params`.
    let options = IkOptions {
        method,
        lambda: 0.05,
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
        common::human_params(),
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
        1200 * common::human_params().iterations_per_frame as u64
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
    let ramp = common::human_params().start_ramp_s;
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
            let mut driver = driver(&skeleton, common::human_params(), mode, method);
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

/// Mean foot error over 20 s for `method` in `mode` on `skeleton`, metres.
fn mean_foot_errors(skeleton: &Skeleton, mode: ThesisMode, method: Method) -> [(f64, f64); 2] {
    let mut driver = driver(skeleton, common::human_params(), mode, method);
    for _ in 0..frames(20.0) {
        driver.step(1.0 / FPS);
    }
    foot_errors(&driver)
}

#[test]
fn dls_and_sdls_track_the_walking_modes_closely() {
    let skeleton = common::human();
    for method in [Method::Dls, Method::Sdls] {
        for mode in [ThesisMode::Walk, ThesisMode::WoundedWalk] {
            let bound = if mode.wounded() { 0.005 } else { 0.001 };
            for (mean, max) in mean_foot_errors(&skeleton, mode, method) {
                println!(
                    "{} {}: foot mean {:.3} mm, max {:.1} mm",
                    method.name(),
                    mode.name(),
                    mean * 1e3,
                    max * 1e3
                );
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
fn dls_and_sdls_track_the_running_modes_closely_from_either_knee_rest() {
    for (name, skeleton) in [
        ("human", common::human()),
        ("bent-knee human", common::human_bent_knees()),
    ] {
        for method in [Method::Dls, Method::Sdls] {
            for mode in [ThesisMode::Run, ThesisMode::WoundedRun] {
                let bound = if mode.wounded() { 0.01 } else { 0.001 };
                for (mean, max) in mean_foot_errors(&skeleton, mode, method) {
                    println!(
                        "{name} {} {}: foot mean {:.3} mm, max {:.1} mm",
                        method.name(),
                        mode.name(),
                        mean * 1e3,
                        max * 1e3
                    );
                    assert!(
                        mean <= bound,
                        "{name} {} {}: foot mean error {mean} m",
                        method.name(),
                        mode.name()
                    );
                }
            }
        }
    }
}

/// Range of joint `name` over `seconds` after the first second.
fn joint_range(driver: &mut ThesisDriver, name: &str, seconds: f64) -> (f64, f64) {
    let Some(j) = driver.skeleton().joint_index(name) else {
        panic!("no joint {name}")
    };
    let mut range = (f64::MAX, f64::MIN);
    for frame in 0..frames(seconds) {
        driver.step(1.0 / FPS);
        if frame >= frames(1.0) {
            let value = driver.pose().joints[j];
            range = (range.0.min(value), range.1.max(value));
        }
    }
    range
}

#[test]
fn walking_bends_the_knees_keeps_the_torso_upright_and_swings_the_arms_against_the_legs() {
    let skeleton = common::human();
    for method in [Method::Dls, Method::Sdls] {
        let make = || driver(&skeleton, common::human_params(), ThesisMode::Walk, method);
        for knee in ["left_knee", "right_knee"] {
            let (lo, hi) = joint_range(&mut make(), knee, 10.0);
            println!("{} walk {knee}: [{lo:.2}, {hi:.2}] rad", method.name());
            assert!(lo > 0.15, "{knee} straightens to {lo} rad");
            assert!(hi > 0.6 && hi < 1.4, "{knee} bends to {hi} rad in swing");
        }
        for torso in ["lumbar_flex", "lumbar_bend"] {
            let (lo, hi) = joint_range(&mut make(), torso, 10.0);
            println!("{} walk {torso}: [{lo:.2}, {hi:.2}] rad", method.name());
            assert!(
                lo > -0.15 && hi < 0.15,
                "{torso} leaves upright: [{lo}, {hi}]"
            );
        }
        // Each hand is behind the root while its own foot is ahead, and vice versa.
        let mut walker = make();
        let foot = walker.effector_of(Limb::LeftFoot);
        let hand = walker.effector_of(Limb::LeftHand);
        let mut correlation = 0.0;
        for frame in 0..frames(5.0) {
            walker.step(1.0 / FPS);
            if frame >= frames(1.0) {
                let root = walker.pose().root.position.z;
                let positions = walker.effector_positions();
                correlation += (positions[foot].z - root) * (positions[hand].z - root - 0.06);
            }
        }
        assert!(correlation < 0.0, "the left hand swings with the left foot");
    }
}

#[test]
fn running_kicks_high_and_leaves_the_ground_between_stances() {
    let skeleton = common::human();
    let mut runner = driver(
        &skeleton,
        common::human_params(),
        ThesisMode::Run,
        Method::Sdls,
    );
    let (_, knee_max) = joint_range(&mut runner, "left_knee", 5.0);
    assert!(knee_max > 1.5, "running knee bends only to {knee_max} rad");
    let feet = [
        runner.effector_of(Limb::LeftFoot),
        runner.effector_of(Limb::RightFoot),
    ];
    let mut flights = 0;
    let mut lowest_stance: f64 = f64::MAX;
    for _ in 0..frames(3.0) {
        runner.step(1.0 / FPS);
        let phase = runner.phase().rem_euclid(std::f64::consts::PI);
        let heights = feet.map(|e| runner.effector_positions()[e].y);
        if (phase - std::f64::consts::FRAC_PI_2).abs() < 0.05 {
            // Top of the bob: both feet off the ground.
            assert!(
                heights.iter().all(|&h| h > 0.01),
                "no flight: feet at {heights:?} m"
            );
            flights += 1;
        }
        lowest_stance = lowest_stance.min(heights[0].min(heights[1]));
    }
    assert!(flights >= 4, "only {flights} flight frames");
    assert!(
        lowest_stance < 0.04,
        "the feet never come down: lowest {lowest_stance} m"
    );
}

#[test]
fn planted_foot_target_is_at_rest_in_the_world_at_mid_stance() {
    let skeleton = common::human();
    for mode in [ThesisMode::Walk, ThesisMode::Run] {
        let mut driver = driver(&skeleton, common::human_params(), mode, Method::Sdls);
        let foot = driver.effector_of(Limb::LeftFoot);
        let period = driver.script().period_s();
        let mut previous = None;
        let mut checked = 0;
        for _ in 0..frames(2.0 + 4.0 * period) {
            driver.step(1.0 / FPS);
            let Some(targets) = driver.targets() else {
                panic!("targets")
            };
            let z = targets.position[foot].z;
            // Left mid-stance is phase π (half a cycle into each period); the
            // speed is full once the start ramps are over.
            let phase = driver.phase();
            // (A run starts as a walk and blends into the run over a second ramp.)
            let ramped = driver.time() > 2.0 * driver.params().start_ramp_s;
            if let Some(previous) = previous
                && ramped
                && (phase - std::f64::consts::PI).abs() < 0.1
            {
                let moved: f64 = z - previous;
                // Swinging or sliding at the stride speed would move it 25–50 mm.
                assert!(
                    moved.abs() < 1e-3,
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
    let params = common::human_params();
    assert!(
        !params.wounded.is_empty(),
        "the human preset wounds some joints"
    );
    for (skeleton, plain, wounded) in [
        (common::human(), ThesisMode::Walk, ThesisMode::WoundedWalk),
        (common::human(), ThesisMode::Run, ThesisMode::WoundedRun),
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
            assert!(mean < 0.01, "{}: foot mean error {mean} m", wounded.name());
        }
    }
}

#[test]
fn switching_modes_live_applies_and_clears_the_wounded_weights() {
    let skeleton = common::human();
    let params = common::human_params();
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
        common::human_params(),
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
    // The root stands at the script's height for phase 0, and a run starts
    // as a walk.
    let params = common::human_params();
    let expected = ThesisScript::new(&params, ThesisMode::Walk)
        .at_time(0.0)
        .root_height_m;
    assert_ne!(expected, driver.script().at_time(0.0).root_height_m);
    assert!((driver.pose().root.position.y - expected).abs() < 1e-12);
}

#[test]
fn runs_are_bit_identical() {
    let skeleton = common::human();
    let mut a = driver(
        &skeleton,
        common::human_params(),
        ThesisMode::WoundedRun,
        Method::Sdls,
    );
    let mut b = driver(
        &skeleton,
        common::human_params(),
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
        common::human_params(),
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
        &common::human_params(),
        "a refused change leaves the driver as it was"
    );
}

#[test]
fn a_driver_for_the_bundled_human_uses_its_scenario() {
    let creature = common::creature();
    let driver = match ThesisDriver::for_creature(&creature) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(driver.mode(), creature.scenario.mode);
    assert_eq!(driver.options().method, creature.scenario.method);
    assert_eq!(driver.params(), &creature.scenario.thesis);
    assert_eq!(driver.pose().joints, creature.skeleton.rest_values());
    let root = driver.pose().root.position;
    assert_eq!(
        (root.x, root.z),
        (creature.root_position.x, creature.root_position.z)
    );
}

#[test]
fn a_run_starts_as_a_walk_and_mode_changes_blend() {
    let skeleton = common::human();
    let params = common::human_params();
    let ramp = params.start_ramp_s;
    let walk = ThesisScript::new(&params, ThesisMode::Walk);
    let run = ThesisScript::new(&params, ThesisMode::Run);
    let mut runner = driver(&skeleton, params.clone(), ThesisMode::Run, Method::Sdls);
    // Walking while the start ramp lasts, running after twice its length.
    let mut previous_phase = 0.0;
    let mut largest_jump: f64 = 0.0;
    let mut previous_targets = runner.targets().cloned();
    for _ in 0..frames(3.0 * ramp) {
        runner.step(1.0 / FPS);
        let omega = (runner.phase() - previous_phase).rem_euclid(std::f64::consts::TAU) * FPS;
        previous_phase = runner.phase();
        if runner.time() < ramp {
            assert!((omega - walk.angular_frequency()).abs() < 1e-6);
        }
        if runner.time() > 2.0 * ramp + 0.02 {
            assert!((omega - run.angular_frequency()).abs() < 1e-6);
            let expected = run.at_phase(runner.phase());
            assert!((runner.sample().root_height_m - expected.root_height_m).abs() < 1e-12);
        }
        if let (Some(before), Some(now)) = (&previous_targets, runner.targets()) {
            for (a, b) in before.position.iter().zip(&now.position) {
                largest_jump = largest_jump.max(a.distance(*b) - runner.script().speed_mps() / FPS);
            }
        }
        previous_targets = runner.targets().cloned();
    }
    // No target jumps: at most a swing foot's speed (about 4·ω·stroke/2) per frame.
    assert!(
        largest_jump < 0.2,
        "a target jumped {largest_jump} m in a frame"
    );
    // Switching back to walking live blends over the ramp too.
    runner.set_mode(ThesisMode::Walk);
    let before = runner.sample().root_height_m;
    runner.step(1.0 / FPS);
    let expected_run = run.at_phase(runner.phase()).root_height_m;
    assert!((runner.sample().root_height_m - expected_run).abs() < 0.01);
    assert!((runner.sample().root_height_m - before).abs() < 0.01);
}
