//! Cyclic coordinate descent (core `ik::ccd`): convergence on a planar arm,
//! the exact single-joint turn, limits and step clamps on unreachable targets,
//! and frozen joints.

mod common;

use common::{planar_arm, tip};
use gaitlab_core::ik::{IkOptions, IkSolver, JointWeight, Method, Targets};
use gaitlab_core::{RootTransform, Skeleton};
use glam::DVec3;

fn ccd() -> IkOptions {
    IkOptions {
        method: Method::Ccd,
        ..IkOptions::default()
    }
}

#[test]
fn reaches_a_reachable_planar_target_within_a_millimetre() {
    let arm = planar_arm(&[0.5, 0.4, 0.3]);
    let target = DVec3::new(0.3, 0.6, 0.0);
    let targets = Targets {
        position: vec![target],
        rotation: vec![],
    };
    let mut solver = IkSolver::new(&arm, ccd());
    let mut values = vec![0.1, 0.1, 0.1];
    let mut errors = Vec::new();
    for _ in 0..60 {
        let status = solver.iterate(&arm, &RootTransform::default(), &mut values, &targets);
        errors.push(status.max_error_m);
    }
    let error = tip(&arm, &values).distance(target);
    println!(
        "CCD planar: error after 1/10/60 sweeps {:.4} / {:.5} / {error:.2e} m",
        errors[0], errors[9]
    );
    assert!(error < 1e-3, "error {error} m");
    assert!(errors[0] > 0.3, "started {} m away", errors[0]);
}

#[test]
fn one_sweep_turns_a_single_joint_exactly_onto_the_target_direction() {
    let arm = planar_arm(&[1.0]);
    let target = DVec3::new(0.0, 2.0, 0.0);
    let targets = Targets {
        position: vec![target],
        rotation: vec![],
    };
    let options = IkOptions {
        max_step: 10.0,
        ..ccd()
    };
    let mut solver = IkSolver::new(&arm, options);
    let mut values = vec![0.0];
    solver.iterate(&arm, &RootTransform::default(), &mut values, &targets);
    assert!(
        (values[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-12,
        "{values:?}"
    );
}

#[test]
fn stays_finite_bounded_and_inside_limits_on_unreachable_targets() {
    let mut arm = planar_arm(&[0.5, 0.4, 0.3]);
    let mut joints = arm.joints().to_vec();
    for joint in &mut joints {
        joint.limits = Some((-0.7, 0.9));
    }
    arm = match Skeleton::new(joints, arm.effectors().to_vec()) {
        Ok(skeleton) => skeleton,
        Err(error) => panic!("{error}"),
    };
    let options = ccd();
    let mut solver = IkSolver::new(&arm, options.clone());
    let mut values = vec![0.0; 3];
    for target in [
        DVec3::new(5.0, 0.0, 0.0),
        DVec3::new(-2.0, -0.5, 0.0),
        DVec3::new(0.0, 0.0, 3.0),
    ] {
        let targets = Targets {
            position: vec![target],
            rotation: vec![],
        };
        for _ in 0..100 {
            let status = solver.iterate(&arm, &RootTransform::default(), &mut values, &targets);
            assert!(!status.failed);
            assert!(
                status.max_step <= options.max_step + 1e-12,
                "{}",
                status.max_step
            );
            for v in &values {
                assert!(v.is_finite() && (-0.7..=0.9).contains(v), "{values:?}");
            }
        }
    }
    // Behind the arm: the joints sit on their limits.
    assert!(values.iter().any(|v| *v == -0.7 || *v == 0.9), "{values:?}");
}

#[test]
fn a_frozen_joint_does_not_move() {
    let arm = planar_arm(&[0.5, 0.4]);
    let targets = Targets {
        position: vec![DVec3::new(0.2, 0.5, 0.0)],
        rotation: vec![],
    };
    let mut solver = IkSolver::new(&arm, ccd());
    solver.set_weight(
        0,
        JointWeight {
            multiply: 0.0,
            add: 0.0,
        },
    );
    let mut values = vec![0.25, 0.0];
    for _ in 0..20 {
        solver.iterate(&arm, &RootTransform::default(), &mut values, &targets);
    }
    assert_eq!(values[0], 0.25);
    assert!(values[1] != 0.0);
}
