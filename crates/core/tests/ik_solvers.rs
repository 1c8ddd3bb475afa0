//! The four IK methods of She 2006 §4.4 with limits, weights and PODA's
//! null-space term: convergence, behaviour at singular and unreachable targets,
//! limits, and agreement with the closed forms computed independently with nalgebra.

mod common;

use common::{Rng, planar_arm, random_tree};
use gaitlab_core::ik::{IkOptions, IkSolver, JointWeight, Method, Targets, TransposeAlpha};
use gaitlab_core::{Kinematics, Pose, RootTransform, Skeleton};
use glam::DVec3;
use nalgebra::{DMatrix, DVector};

fn options(method: Method) -> IkOptions {
    IkOptions {
        method,
        ..IkOptions::default()
    }
}

/// Runs `iterations` and returns the final largest effector error in metres.
fn solve(
    skeleton: &Skeleton,
    values: &mut [f64],
    targets: &Targets,
    opts: IkOptions,
    iterations: usize,
) -> f64 {
    let mut solver = IkSolver::new(skeleton, opts);
    let root = RootTransform::default();
    for _ in 0..iterations {
        solver.iterate(skeleton, &root, values, targets);
    }
    let kin = Kinematics::of(
        skeleton,
        &Pose {
            root,
            joints: values.to_vec(),
        },
    );
    targets
        .position
        .iter()
        .zip(&kin.effector_position)
        .map(|(t, s)| (*t - *s).length())
        .fold(0.0, f64::max)
}

#[test]
fn every_method_converges_on_reachable_targets() {
    let mut rng = Rng::new(3);
    for trial in 0..10 {
        let skeleton = random_tree(&mut rng, 12, 3, None, false);
        // Reachable: the targets are where a random configuration puts the effectors.
        let goal: Vec<f64> = (0..12).map(|_| rng.range(-0.6, 0.6)).collect();
        let goal_kin = Kinematics::of(
            &skeleton,
            &Pose {
                root: RootTransform::default(),
                joints: goal,
            },
        );
        let targets = Targets::at(&goal_kin);
        for method in Method::ALL {
            let mut values = vec![0.0; 12];
            let (iterations, tolerance) = match method {
                Method::Transpose | Method::Ccd => (3000, 2e-3),
                _ => (300, 1e-4),
            };
            // DLS's default λ = 0.2 m, chosen for the 1.75 m human's
            // unreachable hands, damps these small trees' small singular
            // values so much that 300 iterations leave up to 0.3 mm; the
            // convergence is what is tested here, at λ = 0.05 m.
            let opts = IkOptions {
                lambda: 0.05,
                ..options(method)
            };
            let error = solve(&skeleton, &mut values, &targets, opts, iterations);
            assert!(
                error < tolerance,
                "trial {trial}, {method:?}: error {error:e} m"
            );
        }
    }
}

#[test]
fn stretched_limb_and_unreachable_targets_give_finite_bounded_steps() {
    let arm = planar_arm(&[0.5, 0.4, 0.3]);
    let root = RootTransform::default();
    // Fully stretched along +x (a singular pose) with the target far beyond reach
    // along the same line, and another one to the side.
    for target in [
        DVec3::new(5.0, 0.0, 0.0),
        DVec3::new(1.2, 0.01, 0.0),
        DVec3::new(0.0, 0.0, 3.0),
    ] {
        let targets = Targets {
            position: vec![target],
            rotation: vec![],
        };
        for (method, clamp_every_method) in Method::ALL
            .into_iter()
            .flat_map(|m| [(m, false), (m, true)])
        {
            let opts = IkOptions {
                clamp_every_method,
                ..options(method)
            };
            // The error is at most the target's distance plus the arm's reach
            // (1.2 m), and DLS's operator has gain at most 1/(2λ); transpose
            // unclamped has no bound but finiteness.
            let error_bound = target.length() + 1.2;
            let bound = match method {
                Method::Sdls => opts.gamma_max,
                _ if opts.clamps_step() || method == Method::Ccd => opts.max_step,
                Method::Dls => error_bound / (2.0 * opts.lambda),
                _ => f64::INFINITY,
            };
            let mut solver = IkSolver::new(&arm, opts);
            let mut values = vec![0.0; 3];
            for _ in 0..200 {
                let status = solver.iterate(&arm, &root, &mut values, &targets);
                assert!(!status.failed, "{method:?}");
                assert!(
                    status.max_step <= bound + 1e-12,
                    "{method:?}: step {} > {bound}",
                    status.max_step
                );
                assert!(
                    values.iter().all(|v| v.is_finite()),
                    "{method:?}: {values:?}"
                );
            }
            // Unreachable far target: the arm ends up pointing at it, stretched.
            if target.x > 2.0 {
                let kin = Kinematics::of(
                    &arm,
                    &Pose {
                        root,
                        joints: values.clone(),
                    },
                );
                let reach = kin.effector_position[0].length();
                assert!(reach > 1.19, "{method:?}: reach {reach}");
            }
        }
    }
}

#[test]
fn joint_limits_are_never_exceeded_and_a_blocked_joint_rests_on_its_limit() {
    let mut rng = Rng::new(11);
    for method in Method::ALL {
        let skeleton = random_tree(&mut rng, 15, 4, Some(0.4), false);
        let mut solver = IkSolver::new(&skeleton, options(method));
        let root = RootTransform::default();
        let mut values = vec![0.0; 15];
        for _ in 0..50 {
            let targets = Targets {
                position: (0..4).map(|_| rng.vec3(1.0)).collect(),
                rotation: vec![],
            };
            for _ in 0..5 {
                solver.iterate(&skeleton, &root, &mut values, &targets);
                for (v, joint) in values.iter().zip(skeleton.joints()) {
                    let (lo, hi) = joint.limits.expect("limited");
                    assert!(*v >= lo && *v <= hi, "{method:?}: {v} outside [{lo}, {hi}]");
                }
            }
        }
    }
    // Elbow limited to [0, 0.5] rad but the target needs ≈ 1.6 rad: the elbow must
    // sit on 0.5 every iteration once it gets there, with no flip-flop.
    let mut arm = planar_arm(&[1.0, 1.0]);
    let mut joints = arm.joints().to_vec();
    joints[1].limits = Some((0.0, 0.5));
    arm = Skeleton::new(joints, arm.effectors().to_vec()).expect("valid");
    let targets = Targets {
        position: vec![DVec3::new(0.3, 1.0, 0.0)],
        rotation: vec![],
    };
    for method in Method::ALL {
        let mut solver = IkSolver::new(&arm, options(method));
        let mut values = vec![0.0, 0.2];
        let mut elbow = Vec::new();
        for _ in 0..200 {
            solver.iterate(&arm, &RootTransform::default(), &mut values, &targets);
            elbow.push(values[1]);
        }
        let settled = &elbow[150..];
        assert!(
            settled.iter().all(|&e| (e - 0.5).abs() < 1e-12),
            "{method:?}: elbow {:?}",
            &settled[..5]
        );
    }
}

#[test]
fn pinv_step_equals_podas_full_rank_formula() {
    // PODA eq. 5: for r = m < n, J⁺ = Jᵀ(JJᵀ)⁻¹.
    let mut rng = Rng::new(8);
    // A serial chain with effectors at joints 9 and 5, so J (6×10) has full row rank.
    let tree = random_tree(&mut rng, 10, 1, None, false);
    let mut joints = tree.joints().to_vec();
    for (i, joint) in joints.iter_mut().enumerate() {
        joint.parent = i.checked_sub(1);
    }
    let mut effectors = vec![tree.effectors()[0].clone(); 2];
    effectors[0].joint = 9;
    effectors[1].joint = 5;
    effectors[1].name = "second".into();
    let skeleton = Skeleton::new(joints, effectors).expect("valid chain");
    let values: Vec<f64> = (0..10).map(|_| rng.range(-1.0, 1.0)).collect();
    let targets = Targets {
        position: vec![rng.vec3(0.05), rng.vec3(0.05)],
        rotation: vec![],
    };
    let root = RootTransform::default();
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root,
            joints: values.clone(),
        },
    );
    let targets = Targets {
        position: targets
            .position
            .iter()
            .zip(&kin.effector_position)
            .map(|(d, s)| *s + *d)
            .collect(),
        rotation: vec![],
    };
    let mut solver = IkSolver::new(
        &skeleton,
        IkOptions {
            method: Method::Pinv,
            max_step: 10.0,
            enforce_limits: false,
            ..IkOptions::default()
        },
    );
    let mut updated = values.clone();
    solver.iterate(&skeleton, &root, &mut updated, &targets);
    let j = solver.jacobian().clone();
    let e = DVector::from_iterator(
        6,
        targets
            .position
            .iter()
            .zip(&kin.effector_position)
            .flat_map(|(t, s)| (*t - *s).to_array()),
    );
    let expected = j.transpose() * (&j * j.transpose()).try_inverse().expect("full rank") * e;
    for k in 0..10 {
        assert!(
            (updated[k] - values[k] - expected[k]).abs() < 1e-9,
            "joint {k}"
        );
    }
}

#[test]
fn dls_and_transpose_steps_match_their_closed_forms() {
    let mut rng = Rng::new(21);
    let skeleton = random_tree(&mut rng, 9, 3, None, false);
    let values: Vec<f64> = (0..9).map(|_| rng.range(-1.0, 1.0)).collect();
    let root = RootTransform::default();
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root,
            joints: values.clone(),
        },
    );
    let targets = Targets {
        position: kin
            .effector_position
            .iter()
            .map(|s| *s + rng.vec3(0.02))
            .collect(),
        rotation: vec![],
    };
    let e = DVector::from_iterator(
        9,
        targets
            .position
            .iter()
            .zip(&kin.effector_position)
            .flat_map(|(t, s)| (*t - *s).to_array()),
    );
    let lambda = 0.3;
    for (method, alpha) in [
        (Method::Dls, TransposeAlpha::Thesis),
        (Method::Transpose, TransposeAlpha::Thesis),
        (Method::Transpose, TransposeAlpha::Buss),
    ] {
        let opts = IkOptions {
            method,
            lambda,
            max_step: 10.0,
            transpose_alpha: alpha,
            enforce_limits: false,
            ..IkOptions::default()
        };
        let mut solver = IkSolver::new(&skeleton, opts);
        let mut updated = values.clone();
        solver.iterate(&skeleton, &root, &mut updated, &targets);
        let j: DMatrix<f64> = solver.jacobian().clone();
        let expected = match method {
            Method::Dls => {
                j.transpose()
                    * (&j * j.transpose() + DMatrix::identity(9, 9) * lambda * lambda)
                        .try_inverse()
                        .expect("spd")
                    * &e
            }
            _ => {
                // §4.4.1: α = Δs·Δt / (2|Δt|²) with Δs = e, Δt = JJᵀe; Buss's
                // α is twice that.
                let jjte = &j * j.transpose() * &e;
                let thesis = e.dot(&jjte) / (2.0 * jjte.dot(&jjte));
                let alpha_value = match alpha {
                    TransposeAlpha::Thesis => thesis,
                    TransposeAlpha::Buss => 2.0 * thesis,
                };
                j.transpose() * &e * alpha_value
            }
        };
        for k in 0..9 {
            assert!(
                (updated[k] - values[k] - expected[k]).abs() < 1e-9,
                "{method:?} {alpha:?} joint {k}"
            );
        }
    }
}

#[test]
fn sdls_without_clamping_is_the_pseudoinverse_and_with_clamping_respects_gamma_max() {
    let mut rng = Rng::new(2);
    let skeleton = random_tree(&mut rng, 8, 2, None, false);
    let values: Vec<f64> = (0..8).map(|_| rng.range(-1.0, 1.0)).collect();
    let root = RootTransform::default();
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root,
            joints: values.clone(),
        },
    );
    let small = Targets {
        position: kin
            .effector_position
            .iter()
            .map(|s| *s + rng.vec3(1e-4))
            .collect(),
        rotation: vec![],
    };
    let run = |method, gamma_max, targets: &Targets| {
        let mut solver = IkSolver::new(
            &skeleton,
            IkOptions {
                method,
                gamma_max,
                max_step: 1e9,
                enforce_limits: false,
                ..IkOptions::default()
            },
        );
        let mut v = values.clone();
        solver.iterate(&skeleton, &root, &mut v, targets);
        v
    };
    let sdls = run(Method::Sdls, 1e9, &small);
    let pinv = run(Method::Pinv, 1e9, &small);
    for k in 0..8 {
        assert!((sdls[k] - pinv[k]).abs() < 1e-12, "joint {k}");
    }
    let far = Targets {
        position: vec![DVec3::new(9.0, 0.0, 0.0), DVec3::new(0.0, -9.0, 0.0)],
        rotation: vec![],
    };
    let clamped = run(Method::Sdls, 0.1, &far);
    let largest = clamped
        .iter()
        .zip(&values)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(
        largest <= 0.1 + 1e-12 && largest > 0.05,
        "largest step {largest}"
    );
}

#[test]
fn null_space_term_moves_joints_to_centers_without_moving_effectors() {
    let mut rng = Rng::new(17);
    let base = random_tree(&mut rng, 14, 1, None, false);
    let mut joints = base.joints().to_vec();
    for joint in &mut joints {
        joint.center = rng.range(-0.5, 0.5);
        joint.gain = 0.5;
    }
    let skeleton = Skeleton::new(joints, base.effectors().to_vec()).expect("valid");
    let h = |v: &[f64]| {
        skeleton
            .joints()
            .iter()
            .zip(v)
            .map(|(j, x)| j.gain * (x - j.center).powi(2))
            .sum::<f64>()
    };
    for method in [Method::Pinv, Method::Dls] {
        let values: Vec<f64> = (0..14).map(|_| rng.range(-1.0, 1.0)).collect();
        let root = RootTransform::default();
        let kin = Kinematics::of(
            &skeleton,
            &Pose {
                root,
                joints: values.clone(),
            },
        );
        let targets = Targets::at(&kin); // zero task error: only the null-space term acts
        for gain in [0.01, 0.02] {
            let opts = IkOptions {
                method,
                null_space_gain: gain,
                enforce_limits: false,
                max_step: 10.0,
                ..IkOptions::default()
            };
            let mut solver = IkSolver::new(&skeleton, opts);
            let mut moved = values.clone();
            solver.iterate(&skeleton, &root, &mut moved, &targets);
            let step: f64 = moved
                .iter()
                .zip(&values)
                .map(|(a, b)| (a - b).powi(2))
                .sum::<f64>()
                .sqrt();
            let after = Kinematics::of(
                &skeleton,
                &Pose {
                    root,
                    joints: moved.clone(),
                },
            );
            let drift = (after.effector_position[0] - kin.effector_position[0]).length();
            assert!(
                step > 1e-3,
                "{method:?}: the term must move joints (step {step})"
            );
            assert!(h(&moved) < h(&values), "{method:?}: H must decrease");
            // First order: the effector drift is O(step²), far below the step itself.
            assert!(
                drift < 0.5 * step * step + 1e-12,
                "{method:?}: drift {drift:e} for step {step:e}"
            );
        }
    }
}

#[test]
fn multiply_weight_zero_freezes_a_joint_and_others_still_reach_the_target() {
    let arm = planar_arm(&[0.5, 0.4, 0.3, 0.2]);
    let targets = Targets {
        position: vec![DVec3::new(0.6, 0.6, 0.0)],
        rotation: vec![],
    };
    for method in [Method::Pinv, Method::Dls, Method::Sdls, Method::Transpose] {
        let mut solver = IkSolver::new(&arm, options(method));
        solver.set_weight(
            1,
            JointWeight {
                multiply: 0.0,
                add: 0.0,
            },
        );
        let mut values = vec![0.1, 0.3, 0.1, 0.1];
        let iterations = if method == Method::Transpose {
            4000
        } else {
            200
        };
        for _ in 0..iterations {
            solver.iterate(&arm, &RootTransform::default(), &mut values, &targets);
        }
        assert_eq!(values[1], 0.3, "{method:?}: frozen joint moved");
        let kin = Kinematics::of(
            &arm,
            &Pose {
                root: RootTransform::default(),
                joints: values,
            },
        );
        let error = (kin.effector_position[0] - targets.position[0]).length();
        assert!(error < 1e-3, "{method:?}: error {error}");
    }
}

#[test]
fn add_weight_biases_the_joint_and_the_rest_compensates() {
    let arm = planar_arm(&[0.5, 0.4, 0.3]);
    let targets = Targets {
        position: vec![DVec3::new(0.7, 0.4, 0.0)],
        rotation: vec![],
    };
    let settle = |add: f64| {
        let mut solver = IkSolver::new(&arm, options(Method::Dls));
        solver.set_weight(2, JointWeight { multiply: 1.0, add });
        let mut values = vec![0.0; 3];
        for _ in 0..300 {
            solver.iterate(&arm, &RootTransform::default(), &mut values, &targets);
        }
        values
    };
    let plain = settle(0.0);
    let biased = settle(0.01);
    assert!(
        biased[2] - plain[2] > 0.05,
        "the pushed joint bends further: {plain:?} vs {biased:?}"
    );
}

#[test]
fn orientation_rows_align_the_effector_frame() {
    let mut rng = Rng::new(4);
    let skeleton = random_tree(&mut rng, 10, 1, None, true);
    let goal: Vec<f64> = (0..10).map(|_| rng.range(-0.5, 0.5)).collect();
    let goal_kin = Kinematics::of(
        &skeleton,
        &Pose {
            root: RootTransform::default(),
            joints: goal,
        },
    );
    let targets = Targets::at(&goal_kin);
    let mut values = vec![0.0; 10];
    let error = solve(&skeleton, &mut values, &targets, options(Method::Dls), 400);
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root: RootTransform::default(),
            joints: values,
        },
    );
    let turn =
        glam::DQuat::from_mat3(&(targets.rotation[0] * kin.effector_rotation[0].transpose()))
            .to_scaled_axis()
            .length();
    assert!(
        error < 1e-4 && turn < 1e-4,
        "position {error:e} m, orientation {turn:e} rad"
    );
}

#[test]
fn independent_limbs_are_solved_block_by_block_with_the_same_result() {
    // Two chains hanging from the root share no joint: J is block diagonal and
    // the solver decomposes each block alone. The steps must equal the closed
    // forms computed on the whole matrix with nalgebra.
    use gaitlab_core::{Effector, Joint};
    let mut rng = Rng::new(99);
    let mut joints = Vec::new();
    for limb in 0..2 {
        for i in 0..5 {
            let parent = if i == 0 { None } else { Some(joints.len() - 1) };
            joints.push(Joint::revolute(
                &format!("l{limb}j{i}"),
                parent,
                rng.vec3(0.3),
                rng.unit_vec3(),
            ));
        }
    }
    let effectors = vec![
        Effector {
            name: "a".into(),
            joint: 4,
            offset: DVec3::new(0.0, -0.1, 0.0),
            orientation: false,
        },
        Effector {
            name: "b".into(),
            joint: 9,
            offset: DVec3::new(0.0, -0.1, 0.0),
            orientation: true,
        },
    ];
    let skeleton = Skeleton::new(joints, effectors).expect("valid");
    assert_eq!(skeleton.task_blocks().len(), 2);
    let values: Vec<f64> = (0..10).map(|_| rng.range(-1.0, 1.0)).collect();
    let root = RootTransform::default();
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root,
            joints: values.clone(),
        },
    );
    let mut targets = Targets::at(&kin);
    targets.position[0] += DVec3::new(0.01, -0.02, 0.005);
    targets.position[1] += DVec3::new(-0.01, 0.01, 0.02);
    let lambda: f64 = 0.2;
    for method in [Method::Pinv, Method::Dls] {
        let opts = IkOptions {
            method,
            lambda,
            max_step: 10.0,
            enforce_limits: false,
            ..IkOptions::default()
        };
        let mut solver = IkSolver::new(&skeleton, opts);
        let mut updated = values.clone();
        solver.iterate(&skeleton, &root, &mut updated, &targets);
        let j = solver.jacobian().clone();
        let mut e = DVector::zeros(9);
        for (r, x) in (targets.position[0] - kin.effector_position[0])
            .to_array()
            .into_iter()
            .enumerate()
        {
            e[r] = x;
        }
        for (r, x) in (targets.position[1] - kin.effector_position[1])
            .to_array()
            .into_iter()
            .enumerate()
        {
            e[3 + r] = x;
        }
        let expected = match method {
            Method::Pinv => j.clone().pseudo_inverse(1e-12).expect("svd") * &e,
            _ => {
                j.transpose()
                    * (&j * j.transpose() + DMatrix::identity(9, 9) * lambda * lambda)
                        .try_inverse()
                        .expect("spd")
                    * &e
            }
        };
        for k in 0..10 {
            assert!(
                (updated[k] - values[k] - expected[k]).abs() < 1e-9,
                "{method:?} joint {k}: {} vs {}",
                updated[k] - values[k],
                expected[k]
            );
        }
    }
}

/// She 2006 §4.4.2 clamps the pseudoinverse's step; transpose and DLS are
/// clamped only with the lab's `clamp_every_method`.
#[test]
fn the_step_clamp_acts_on_pinv_alone_unless_every_method_is_asked() {
    let arm = planar_arm(&[0.5, 0.4, 0.3]);
    let root = RootTransform::default();
    // A target across the arm's reach asks for a large first step.
    let targets = Targets {
        position: vec![DVec3::new(-0.6, 0.5, 0.0)],
        rotation: vec![],
    };
    let max_step = 0.05;
    for method in [Method::Transpose, Method::Pinv, Method::Dls] {
        for clamp_every_method in [false, true] {
            let opts = IkOptions {
                method,
                max_step,
                clamp_every_method,
                enforce_limits: false,
                ..IkOptions::default()
            };
            let mut solver = IkSolver::new(&arm, opts);
            let mut values = vec![0.3, 0.3, 0.3];
            let status = solver.iterate(&arm, &root, &mut values, &targets);
            let clamped = method == Method::Pinv || clamp_every_method;
            if clamped {
                assert!(
                    (status.max_step - max_step).abs() < 1e-12,
                    "{method:?} {clamp_every_method}: step {}",
                    status.max_step
                );
            } else {
                assert!(
                    status.max_step > 2.0 * max_step,
                    "{method:?} {clamp_every_method}: step {} should be unclamped",
                    status.max_step
                );
            }
        }
    }
}
