//! Recorded-target tracking (`gaitlab track`): the driver follows targets that a
//! known joint motion produces, reports the same IK metrics as the thesis
//! driver, and refuses a track with the wrong number of effectors.

use gaitlab_core::portable::Portable;
mod common;

use gaitlab_core::Kinematics;
use gaitlab_core::RootTransform;
use gaitlab_core::driver::Driver;
use gaitlab_core::export::TargetTrack;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_motion::{FnTargets, TargetSource, TrackDriver, TrackOptions};
use glam::DVec3;

const FPS: f64 = 60.0;

/// Joint values of a gentle reachable motion: every joint swings a little about
/// its rest value (inside its limits), 1 Hz.
fn motion(skeleton: &gaitlab_core::Skeleton, t: f64) -> Vec<f64> {
    skeleton
        .joints()
        .iter()
        .enumerate()
        .map(|(j, joint)| {
            let value = joint.rest + 0.15 * (std::f64::consts::TAU * t + j as f64).psin();
            joint.clamp(value)
        })
        .collect()
}

/// A recorded track of that motion's effector positions at 30 Hz.
fn recorded(skeleton: &gaitlab_core::Skeleton, root: RootTransform, seconds: f64) -> TargetTrack {
    let mut kinematics = Kinematics::new(skeleton);
    let mut times = Vec::new();
    let mut positions = Vec::new();
    let rows = (seconds * 30.0).round() as usize;
    for row in 0..=rows {
        let t = row as f64 / 30.0;
        kinematics.update(skeleton, &root, &motion(skeleton, t));
        times.push(t);
        positions.extend_from_slice(&kinematics.effector_position);
    }
    match TargetTrack::new(times, positions, skeleton.effector_count()) {
        Ok(track) => track,
        Err(error) => panic!("track: {error}"),
    }
}

#[test]
fn follows_a_recorded_reachable_motion_closely_with_dls_and_sdls() {
    let skeleton = common::human();
    let root = RootTransform {
        position: DVec3::new(0.3, 0.98, -1.0),
        ..RootTransform::default()
    };
    let track = recorded(&skeleton, root, 10.0);
    for method in [Method::Dls, Method::Sdls] {
        let options = TrackOptions {
            ik: IkOptions {
                method,
                ..IkOptions::default()
            },
            iterations_per_frame: 4,
            root,
        };
        let mut driver = match TrackDriver::new(skeleton.clone(), track.clone(), options) {
            Ok(driver) => driver,
            Err(error) => panic!("{error}"),
        };
        assert!((driver.duration_s() - 10.0).abs() < 1e-9);
        while driver.time() < driver.duration_s() - 1e-9 {
            driver.step(1.0 / FPS);
        }
        let Some(metrics) = driver.ik_metrics() else {
            panic!("metrics")
        };
        assert_eq!(metrics.frames, 600);
        assert_eq!(metrics.iterations, 2400);
        for (e, effector) in skeleton.effectors().iter().enumerate() {
            let mean = metrics.mean_error_m(e).unwrap_or(f64::NAN);
            let max = metrics.max_error_m(e).unwrap_or(f64::NAN);
            println!(
                "{} {}: mean {:.2} mm, max {:.2} mm",
                method.name(),
                effector.name,
                mean * 1e3,
                max * 1e3
            );
            assert!(
                mean < 0.005,
                "{} {}: mean error {mean} m",
                method.name(),
                effector.name
            );
            assert!(
                max < 0.05,
                "{} {}: max error {max} m",
                method.name(),
                effector.name
            );
        }
        // The targets drawn are the recording's, and the errors are the distances to them.
        let Some(targets) = driver.targets() else {
            panic!("targets")
        };
        let mut expected = vec![DVec3::ZERO; skeleton.effector_count()];
        track.sample(driver.time(), &mut expected);
        assert_eq!(targets.position, expected);
        let Some(report) = driver.ik_report() else {
            panic!("report")
        };
        for ((error, effector), target) in report
            .effector_error_m
            .iter()
            .zip(driver.effector_positions())
            .zip(&targets.position)
        {
            assert!((error - effector.distance(*target)).abs() < 1e-12);
        }
    }
}

#[test]
fn unreachable_targets_are_reported_as_errors() {
    let skeleton = common::human();
    let k = skeleton.effector_count();
    // Every target 5 m above the root: no pose reaches it.
    let source = FnTargets::new(k, 1.0, |_, out: &mut [DVec3]| {
        out.fill(DVec3::new(0.0, 6.0, 0.0))
    });
    let mut driver = match TrackDriver::new(skeleton.clone(), source, TrackOptions::default()) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    for _ in 0..60 {
        driver.step(1.0 / FPS);
    }
    let Some(metrics) = driver.ik_metrics() else {
        panic!("metrics")
    };
    for e in 0..k {
        assert!(metrics.mean_error_m(e).unwrap_or(0.0) > 3.0);
    }
    assert!(driver.pose().joints.iter().all(|v| v.is_finite()));
}

#[test]
fn reset_returns_to_rest_and_clears_metrics() {
    let skeleton = common::human();
    let track = recorded(&skeleton, RootTransform::default(), 2.0);
    let mut driver = match TrackDriver::new(skeleton.clone(), track, TrackOptions::default()) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    for _ in 0..30 {
        driver.step(1.0 / FPS);
    }
    assert_ne!(driver.pose().joints, skeleton.rest_values());
    driver.reset();
    assert_eq!(driver.time(), 0.0);
    assert_eq!(driver.pose().joints, skeleton.rest_values());
    assert_eq!(driver.ik_metrics().map(|m| m.frames), Some(0));
}

#[test]
fn a_track_for_another_effector_count_is_refused() {
    let skeleton = common::human();
    let source = FnTargets::new(3, 1.0, |_, out: &mut [DVec3]| out.fill(DVec3::ZERO));
    assert_eq!(source.effector_count(), 3);
    let error = TrackDriver::new(skeleton, source, TrackOptions::default()).err();
    assert_eq!(error.map(|e| e.path), Some("targets".to_owned()));
}
