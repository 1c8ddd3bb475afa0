//! Shared test fixtures: the bundled human preset the thesis drivers are tuned
//! on, and `she-2006`.

#![allow(dead_code)]

use gaitlab_core::Skeleton;
use gaitlab_core::preset::thesis::ThesisParams;
use gaitlab_core::preset::{Creature, load_bundled};

/// The bundled `human` preset (presets/human.json: 20 one-DOF joints, 4 effectors).
pub fn creature() -> Creature {
    match load_bundled("human") {
        Some(Ok(creature)) => creature,
        Some(Err(error)) => panic!("human preset: {error}"),
        None => panic!("no bundled human preset"),
    }
}

/// The bundled `she-2006` preset: the human driven as She 2006 is written.
pub fn she_2006() -> Creature {
    match load_bundled("she-2006") {
        Some(Ok(creature)) => creature,
        Some(Err(error)) => panic!("she-2006 preset: {error}"),
        None => panic!("no bundled she-2006 preset"),
    }
}

/// The human's skeleton.
pub fn human() -> Skeleton {
    creature().skeleton
}

/// The lab's thesis parameters (gaitlab's target script, posture pull, start
/// ramp and step wounds: what the `human` preset ran as a `gaitlab-preset/1`
/// file until 2026-12-06) with the preset's wounded joints. The drivers'
/// tests here exercise the lab's script; the bundled human now runs §5.2.2's
/// listing alone (docs/parameters.md "Both ways").
pub fn human_params() -> ThesisParams {
    ThesisParams {
        wounded: creature().scenario.thesis.wounded,
        ..ThesisParams::lab()
    }
}

/// Knee rest and center angle of [`human_bent_knees`], radians.
pub const BENT_KNEE_RAD: f64 = 0.35;

/// The human with its knees' rest and center angles raised to at least
/// [`BENT_KNEE_RAD`].
///
/// The foot effector sits 0.1 m ahead of the ankle, so the leg is "effectively
/// straight" (hip, knee and effector in line) at a knee angle of about 0.2 rad,
/// which is the preset's rest angle: the drivers must work from both sides of
/// that line, so the figures are checked on this variant too.
pub fn human_bent_knees() -> Skeleton {
    let skeleton = human();
    let mut joints = skeleton.joints().to_vec();
    for joint in joints.iter_mut().filter(|j| j.name.ends_with("_knee")) {
        joint.rest = joint.rest.max(BENT_KNEE_RAD);
        joint.center = joint.center.max(BENT_KNEE_RAD);
    }
    match Skeleton::new(joints, skeleton.effectors().to_vec()) {
        Ok(skeleton) => skeleton,
        Err(error) => panic!("bent-knee human: {error}"),
    }
}

/// Distance between two cycle fractions on the circle, in [0, 0.5].
pub fn phase_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(1.0);
    d.min(1.0 - d)
}

/// The gait a PODA driver ran, as measured from its feet, is the gait it was
/// set: period within 5 ms, every leg's duty factor and relative phase within
/// 0.02 of the set values.
pub fn assert_gait_measured_as_set(label: &str, driver: &gaitlab_motion::PodaDriver) {
    let metrics = driver.metrics();
    let gait = driver.gait();
    let period = metrics.period_s().expect("touchdowns measured");
    assert!(
        (period - gait.period_s()).abs() < 0.005,
        "{label}: period {period} s"
    );
    for (leg, &phase) in metrics.legs.iter().zip(gait.phases()) {
        let duty = leg.duty_factor().expect("duty measured");
        assert!(
            (duty - gait.duty_factor()).abs() <= 0.02,
            "{label} {}: duty {duty} vs {}",
            leg.name,
            gait.duty_factor()
        );
        let measured = leg.relative_phase(period).expect("phase measured");
        assert!(
            phase_distance(measured, phase) <= 0.02,
            "{label} {}: phase {measured} vs {phase}",
            leg.name
        );
    }
}
