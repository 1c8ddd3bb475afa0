//! She 2006 §3.2's two ways to drive the Jacobian formulation
//! ([`JacobianAt`]): the Jacobian at the end effectors (Buss's `Jend`) or at
//! the targets (Buss's `Jtarget`), with the error e = t − s in both. Figures on
//! a planar 3-link arm (links 0.5, 0.4, 0.3 m; reach 1.2 m).

mod common;

use common::{Rng, planar_arm, random_tree, tip};
use gaitlab_core::ik::{IkOptions, IkSolver, JacobianAt, Method, Targets};
use gaitlab_core::jacobian::{fill_jacobian, fill_jacobian_at};
use gaitlab_core::portable::Portable;
use gaitlab_core::{JointKind, Kinematics, Pose, RootTransform};
use glam::DVec3;
use nalgebra::DMatrix;

const LINKS: [f64; 3] = [0.5, 0.4, 0.3];
const START: [f64; 3] = [0.3, 0.5, 0.4];
const JACOBIAN_METHODS: [Method; 4] = [Method::Transpose, Method::Pinv, Method::Dls, Method::Sdls];

fn options(method: Method, jacobian_at: JacobianAt) -> IkOptions {
    IkOptions {
        method,
        jacobian_at,
        // The arm has no limits; keep the solve unconstrained either way.
        enforce_limits: false,
        ..IkOptions::default()
    }
}

fn one_target(position: DVec3) -> Targets {
    Targets {
        position: vec![position],
        rotation: Vec::new(),
    }
}

/// What a run from [`START`] towards `target` did.
struct Run {
    /// Effector error after the last iteration, metres.
    final_error_m: f64,
    /// First iteration after which the error is under 1 mm (None: never).
    under_1mm_at: Option<usize>,
    /// Joint values after each iteration, radians.
    path: Vec<Vec<f64>>,
    /// Largest |Δθ| of the last iteration, radians.
    last_step_rad: f64,
    /// Final joint values, radians.
    values: Vec<f64>,
}

fn run(method: Method, way: JacobianAt, target: DVec3, iterations: usize) -> Run {
    let skeleton = planar_arm(&LINKS);
    let mut solver = IkSolver::new(&skeleton, options(method, way));
    let targets = one_target(target);
    let root = RootTransform::default();
    let mut values = START.to_vec();
    let mut under_1mm_at = None;
    let mut path = Vec::with_capacity(iterations);
    let mut last_step_rad = 0.0;
    for i in 0..iterations {
        let status = solver.iterate(&skeleton, &root, &mut values, &targets);
        assert!(!status.failed, "{method:?} {way:?}: the solve failed");
        path.push(values.clone());
        last_step_rad = solver
            .last_step()
            .iter()
            .fold(0.0_f64, |m, x| m.max(x.abs()));
        if under_1mm_at.is_none() && (tip(&skeleton, &values) - target).length() < 1e-3 {
            under_1mm_at = Some(i + 1);
        }
    }
    Run {
        final_error_m: (tip(&skeleton, &values) - target).length(),
        under_1mm_at,
        path,
        last_step_rad,
        values,
    }
}

#[test]
fn target_jacobian_columns_are_v_cross_t_minus_p() {
    // Independent of the library's FK: a random tree's columns checked
    // against vⱼ × (point − pⱼ) from the joint anchors and axes.
    let mut rng = Rng::new(18);
    let skeleton = random_tree(&mut rng, 10, 3, None, true);
    let values: Vec<f64> = (0..10).map(|_| rng.range(-0.8, 0.8)).collect();
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root: RootTransform::default(),
            joints: values,
        },
    );
    let points: Vec<DVec3> = (0..3).map(|_| rng.vec3(1.0)).collect();
    let mut at_effectors = DMatrix::zeros(0, 0);
    let mut at_effectors_explicit = DMatrix::zeros(0, 0);
    let mut at_targets = DMatrix::zeros(0, 0);
    fill_jacobian(&skeleton, &kin, &mut at_effectors);
    fill_jacobian_at(
        &skeleton,
        &kin,
        &kin.effector_position,
        &mut at_effectors_explicit,
    );
    fill_jacobian_at(&skeleton, &kin, &points, &mut at_targets);
    assert_eq!(at_effectors, at_effectors_explicit);
    let mut row = 0;
    for (e, eff) in skeleton.effectors().iter().enumerate() {
        for &j in skeleton.chain(e) {
            let v = kin.joint_axis[j];
            let (expected, shift) = match skeleton.joints()[j].kind {
                JointKind::Revolute => (
                    v.cross(points[e] - kin.joint_anchor[j]),
                    // Jtarget − Jend = vⱼ × (tᵢ − sᵢ), whatever the joint's place.
                    v.cross(points[e] - kin.effector_position[e]),
                ),
                JointKind::Prismatic => (v, DVec3::ZERO),
            };
            for k in 0..3 {
                let got = at_targets[(row + k, j)];
                assert!((got - expected[k]).abs() < 1e-12, "J[{},{j}]", row + k);
                let diff = got - at_effectors[(row + k, j)];
                assert!((diff - shift[k]).abs() < 1e-12, "ΔJ[{},{j}]", row + k);
            }
            if eff.orientation {
                for k in 3..6 {
                    // Orientation rows do not depend on the point.
                    assert_eq!(at_targets[(row + k, j)], at_effectors[(row + k, j)]);
                }
            }
        }
        row += if eff.orientation { 6 } else { 3 };
    }
}

#[test]
fn target_on_the_effector_gives_no_step_either_way() {
    let skeleton = planar_arm(&LINKS);
    let here = tip(&skeleton, &START);
    for method in JACOBIAN_METHODS {
        for way in JacobianAt::ALL {
            let mut solver = IkSolver::new(&skeleton, options(method, way));
            let mut values = START.to_vec();
            solver.iterate(
                &skeleton,
                &RootTransform::default(),
                &mut values,
                &one_target(here),
            );
            let largest = solver
                .last_step()
                .iter()
                .fold(0.0_f64, |m, x| m.max(x.abs()));
            assert!(largest < 1e-12, "{method:?} {way:?}: |Δθ| {largest:e} rad");
        }
    }
}

/// A reachable target: the pose (1.3, −0.9, 1.1) rad puts the tip there.
fn reachable_target() -> DVec3 {
    tip(&planar_arm(&LINKS), &[1.3, -0.9, 1.1])
}

#[test]
fn both_ways_reach_a_reachable_target_within_1_mm() {
    let target = reachable_target();
    let start = tip(&planar_arm(&LINKS), &START);
    eprintln!(
        "reachable target {target:.3} m, start error {:.3} m",
        (target - start).length()
    );
    for method in JACOBIAN_METHODS {
        let iterations = if method == Method::Transpose {
            2000
        } else {
            200
        };
        let effectors = run(method, JacobianAt::Effectors, target, iterations);
        let targets = run(method, JacobianAt::Targets, target, iterations);
        // The two ways take different paths: the lever arms differ by t − s.
        let path_difference = effectors
            .path
            .iter()
            .zip(&targets.path)
            .flat_map(|(a, b)| a.iter().zip(b))
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        eprintln!(
            "{method:?}: effectors way under 1 mm after {:?} iterations (final {:.2e} m); \
             targets way after {:?} (final {:.2e} m); paths differ by up to {path_difference:.3} rad",
            effectors.under_1mm_at,
            effectors.final_error_m,
            targets.under_1mm_at,
            targets.final_error_m,
        );
        assert!(
            path_difference > 1e-4,
            "{method:?}: the ways took the same path"
        );
        for (way, r) in [("effectors", &effectors), ("targets", &targets)] {
            assert!(
                r.final_error_m < 1e-3,
                "{method:?} {way}: final error {:e} m after {iterations} iterations",
                r.final_error_m
            );
        }
    }
}

#[test]
fn both_ways_stretch_towards_an_unreachable_target() {
    // 2.06 m from the base, 0.86 m past the 1.2 m reach: the best any pose can
    // do is the arm straight along the base→target line.
    let target = DVec3::new(2.0, 0.5, 0.0);
    let reach: f64 = LINKS.iter().sum();
    let gap = target.length() - reach;
    let heading = target.y.patan2(target.x);
    for method in [Method::Dls, Method::Sdls, Method::Pinv] {
        for way in JacobianAt::ALL {
            let r = run(method, way, target, 400);
            let bend = r.values[1].abs().max(r.values[2].abs());
            eprintln!(
                "{method:?} {way:?}: final error {:.4} m (gap {gap:.4} m), base angle {:.4} rad \
                 (line {heading:.4}), largest bend {bend:.2e} rad, last |Δθ| {:.2e} rad",
                r.final_error_m, r.values[0], r.last_step_rad
            );
            assert!(r.final_error_m >= gap - 1e-9);
            if method == Method::Sdls {
                assert!(
                    r.final_error_m < gap + 1e-3,
                    "{method:?} {way:?}: {:.4} m from the target, the gap is {gap:.4} m",
                    r.final_error_m
                );
            }
        }
    }
}

#[test]
fn the_preset_key_is_read_and_checked() {
    use gaitlab_core::preset::{self, Preset};
    let human = preset::bundled_json("human").expect("human is bundled");
    let parsed = Preset::from_json(human).expect("human parses");
    assert_eq!(parsed.scenario.ik.jacobian_at, JacobianAt::Effectors);
    let with = |way: &str| {
        let mut value: serde_json::Value = serde_json::from_str(human).expect("JSON");
        value["scenario"]["ik"]["jacobian_at"] = way.into();
        Preset::from_json(&value.to_string())
    };
    let targets = with("targets").expect("targets is a way");
    assert_eq!(targets.scenario.ik.jacobian_at, JacobianAt::Targets);
    assert_eq!(
        targets.scenario.ik_options().jacobian_at,
        JacobianAt::Targets
    );
    let error = with("sideways").expect_err("not a way");
    assert_eq!(error.path, "scenario.ik.jacobian_at", "{error}");
    assert!(
        error.reason.contains("effectors") && error.reason.contains("targets"),
        "{error}"
    );
}
