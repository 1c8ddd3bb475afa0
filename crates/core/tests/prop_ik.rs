//! Property tests of the IK solvers (She 2006 §4.4: transpose, pseudoinverse,
//! DLS, SDLS; PODA eq. 6's null-space term; CCD as the contrast) on random
//! joint trees: 1–512 one-DOF joints, revolute and prismatic, random unit axes
//! (coordinate axes and general ones), offsets (zero ones included), frames and
//! limits (wide, narrow down to 1e-9, and closed to a single value), PODA
//! center angles and gains, and the thesis' wounded weights (§5.1.1), with
//! effectors on random leaves and targets that are reachable, far beyond
//! reach (the stretched, singular pose), on the first joint's anchor (a
//! singular point for every revolute joint there) or already met.
//!
//! The contract checked after every iteration of every method, for IK options
//! drawn anywhere in the ranges presets accept ([`check_ik_options`]): every
//! joint value is finite and, with limits enforced, inside its limits exactly
//! (the solver clamps, so no tolerance is needed); the iteration does not
//! report a failed solve; and its error figures are finite.
//!
//! Case counts are fixed per test (see [`config`]); the random seed is fixed
//! too so that CI is repeatable. `PROPTEST_RNG_SEED=<u64>` picks another seed
//! and `GAITLAB_PROP_SCALE=<k>` multiplies every case count, for longer
//! explorations (docs/property-tests.md).

use std::f64::consts::PI;

use gaitlab_core::ik::{IkOptions, IkSolver, IkStatus, JointWeight, Method, Targets};
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::check_ik_options;
use gaitlab_core::{Effector, Joint, Kinematics, Pose, RootTransform, Skeleton};
use gaitlab_testkit::prop_config as config;
use glam::{DMat3, DVec3};
use proptest::prelude::*;
use proptest::sample::Index;

/// The limits of a generated joint.
#[derive(Clone, Debug)]
enum LimitSpec {
    /// No limits.
    Free,
    /// `[lo, lo + width]`, radians or metres.
    Range { lo: f64, width: f64 },
}

/// One generated joint; fractions in [0, 1] place values inside the limits.
#[derive(Clone, Debug)]
struct JointSpec {
    /// Parent: the previous joint (a chain), or `floor(fraction · (i + 1))`
    /// with `i` itself meaning "on the root".
    parent: Option<f64>,
    prismatic: bool,
    axis: DVec3,
    offset: DVec3,
    frame: DMat3,
    limits: LimitSpec,
    /// Rest value (the start of every solve) as a fraction of the range.
    rest: f64,
    /// PODA center angle as a fraction of the range, and its gain.
    center: f64,
    gain: f64,
    /// Value in the configuration the reachable targets come from, as a fraction.
    goal: f64,
    /// Wounded weight, if any (multiply in [0, 10], add in ±0.5, the preset ranges).
    weight: Option<JointWeight>,
}

/// Where an effector's target is.
#[derive(Clone, Debug)]
enum TargetSpec {
    /// Where the goal configuration puts the effector: reachable.
    Reachable,
    /// `distance` metres from the root along `direction`: far beyond reach.
    Far { direction: DVec3, distance: f64 },
    /// On the anchor of joint 0 (every revolute joint there has a zero column).
    FirstAnchor,
    /// Where the effector already is: zero error.
    Here,
}

#[derive(Clone, Debug)]
struct EffectorSpec {
    leaf: Index,
    offset: DVec3,
    orientation: bool,
    target: TargetSpec,
    /// Orientation target (used by effectors with orientation rows).
    rotation: DMat3,
}

/// A generated skeleton with its start values, targets and weights.
#[derive(Clone, Debug)]
struct Case {
    skeleton: Skeleton,
    root: RootTransform,
    start: Vec<f64>,
    targets: Targets,
    weights: Vec<Option<JointWeight>>,
}

fn unit_vector() -> impl Strategy<Value = DVec3> {
    let coordinate = prop_oneof![
        Just(DVec3::X),
        Just(DVec3::NEG_X),
        Just(DVec3::Y),
        Just(DVec3::NEG_Y),
        Just(DVec3::Z),
        Just(DVec3::NEG_Z),
    ];
    let general = (-1.0..1.0_f64, -1.0..1.0_f64, -1.0..1.0_f64).prop_filter_map(
        "a direction needs a non-zero vector",
        |(x, y, z)| {
            let v = DVec3::new(x, y, z);
            (v.length() > 1e-3).then(|| v.normalize())
        },
    );
    prop_oneof![2 => coordinate, 3 => general]
}

fn vector(scale: f64) -> impl Strategy<Value = DVec3> {
    (-scale..=scale, -scale..=scale, -scale..=scale).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn rotation() -> impl Strategy<Value = DMat3> {
    prop_oneof![
        1 => Just(DMat3::IDENTITY),
        3 => (unit_vector(), -PI..PI).prop_map(|(axis, angle)| DMat3::from_axis_angle(axis, angle)),
    ]
}

fn limits() -> impl Strategy<Value = LimitSpec> {
    prop_oneof![
        2 => Just(LimitSpec::Free),
        // Wide: up to the two turns a preset allows (less a rounding margin).
        3 => (-PI..PI, 0.01..=4.0 * PI - 1e-9).prop_map(|(lo, width)| LimitSpec::Range { lo, width }),
        // Narrow: 1e-9 to 1e-3 wide (log-uniform).
        2 => (-PI..PI, -9.0..=-3.0_f64)
            .prop_map(|(lo, e)| LimitSpec::Range { lo, width: 10.0_f64.ppowf(e) }),
        // Closed: a single allowed value.
        1 => (-PI..PI).prop_map(|lo| LimitSpec::Range { lo, width: 0.0 }),
    ]
}

fn weight() -> impl Strategy<Value = Option<JointWeight>> {
    prop_oneof![
        6 => Just(None),
        1 => (0.0..=10.0_f64, -0.5..=0.5_f64)
            .prop_map(|(multiply, add)| Some(JointWeight { multiply, add })),
        1 => Just(Some(JointWeight { multiply: 0.0, add: 0.0 })),
    ]
}

fn joint() -> impl Strategy<Value = JointSpec> {
    (
        prop_oneof![1 => Just(None), 1 => (0.0..1.0_f64).prop_map(Some)],
        prop::bool::weighted(0.2),
        unit_vector(),
        prop_oneof![1 => Just(DVec3::ZERO), 4 => vector(0.4)],
        rotation(),
        limits(),
        (0.0..=1.0_f64, 0.0..=1.0_f64, 0.0..=1.0_f64, 0.0..=1.0_f64),
        weight(),
    )
        .prop_map(
            |(
                parent,
                prismatic,
                axis,
                offset,
                frame,
                limits,
                (rest, center, gain, goal),
                weight,
            )| {
                JointSpec {
                    parent,
                    prismatic,
                    axis,
                    offset,
                    frame,
                    limits,
                    rest,
                    center,
                    gain,
                    goal,
                    weight,
                }
            },
        )
}

fn target() -> impl Strategy<Value = TargetSpec> {
    prop_oneof![
        4 => Just(TargetSpec::Reachable),
        // 10 m to 1000 km away (log-uniform).
        3 => (unit_vector(), 1.0..=6.0_f64).prop_map(|(direction, e)| TargetSpec::Far {
            direction,
            distance: 10.0_f64.ppowf(e),
        }),
        1 => Just(TargetSpec::FirstAnchor),
        1 => Just(TargetSpec::Here),
    ]
}

fn effector() -> impl Strategy<Value = EffectorSpec> {
    (
        any::<Index>(),
        prop_oneof![1 => Just(DVec3::ZERO), 4 => vector(0.3)],
        prop::bool::weighted(0.2),
        target(),
        rotation(),
    )
        .prop_map(
            |(leaf, offset, orientation, target, rotation)| EffectorSpec {
                leaf,
                offset,
                orientation,
                target,
                rotation,
            },
        )
}

/// The value at `fraction` of a joint's range (free joints: ±1 rad or m).
fn place(limits: &LimitSpec, fraction: f64) -> f64 {
    match *limits {
        LimitSpec::Free => 2.0 * fraction - 1.0,
        LimitSpec::Range { lo, width } => lo + width * fraction,
    }
}

/// Builds the skeleton, start values and targets a generated case describes.
fn build(joints: &[JointSpec], effectors: &[EffectorSpec], root: RootTransform) -> Case {
    let mut built = Vec::with_capacity(joints.len());
    let mut has_child = vec![false; joints.len()];
    for (i, spec) in joints.iter().enumerate() {
        let parent = match spec.parent {
            None => i.checked_sub(1),
            Some(fraction) => {
                let p = ((fraction * (i + 1) as f64) as usize).min(i);
                (p < i).then_some(p)
            }
        };
        if let Some(p) = parent {
            has_child[p] = true;
        }
        let name = format!("j{i}");
        let mut joint = if spec.prismatic {
            Joint::prismatic(&name, parent, spec.offset, spec.axis)
        } else {
            Joint::revolute(&name, parent, spec.offset, spec.axis)
        };
        joint.frame = spec.frame;
        if let LimitSpec::Range { lo, width } = spec.limits {
            joint.limits = Some((lo, lo + width));
        }
        joint.rest = place(&spec.limits, spec.rest);
        joint.center = place(&spec.limits, spec.center);
        joint.gain = spec.gain;
        built.push(joint);
    }
    let leaves: Vec<usize> = (0..joints.len()).filter(|&j| !has_child[j]).collect();
    let placed: Vec<Effector> = effectors
        .iter()
        .enumerate()
        .map(|(e, spec)| Effector {
            name: format!("e{e}"),
            joint: leaves[spec.leaf.index(leaves.len())],
            offset: spec.offset,
            orientation: spec.orientation,
        })
        .collect();
    let skeleton = match Skeleton::new(built, placed) {
        Ok(skeleton) => skeleton,
        Err(error) => panic!("the generator made an invalid skeleton: {error}"),
    };
    let start = skeleton.rest_values();
    let goal: Vec<f64> = joints.iter().map(|s| place(&s.limits, s.goal)).collect();
    let at_goal = Kinematics::of(&skeleton, &Pose { root, joints: goal });
    let at_start = Kinematics::of(
        &skeleton,
        &Pose {
            root,
            joints: start.clone(),
        },
    );
    let position = effectors
        .iter()
        .enumerate()
        .map(|(e, spec)| match spec.target {
            TargetSpec::Reachable => at_goal.effector_position[e],
            TargetSpec::Far {
                direction,
                distance,
            } => root.position + direction * distance,
            TargetSpec::FirstAnchor => at_start.joint_anchor[0],
            TargetSpec::Here => at_start.effector_position[e],
        })
        .collect();
    let rotation = effectors.iter().map(|spec| spec.rotation).collect();
    Case {
        skeleton,
        root,
        start,
        targets: Targets { position, rotation },
        weights: joints.iter().map(|s| s.weight).collect(),
    }
}

/// A random case with `joints` joints and `effectors` effectors.
fn case(
    joints: std::ops::RangeInclusive<usize>,
    effectors: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = Case> {
    (
        prop::collection::vec(joint(), joints),
        prop::collection::vec(effector(), effectors),
        vector(10.0),
        rotation(),
    )
        .prop_map(|(joints, effectors, position, rotation)| {
            build(&joints, &effectors, RootTransform { position, rotation })
        })
}

/// IK options anywhere in the ranges [`check_ik_options`] accepts: half the
/// time the defaults, otherwise every field drawn (λ and the rank tolerance
/// log-uniform). The method is set per run.
fn options() -> impl Strategy<Value = IkOptions> {
    let drawn = (
        (-4.0..=1.0_f64),
        (1e-3..=PI),
        (1e-3..=PI),
        (-12.0..=-0.5_f64),
        (0.0..=10.0_f64),
        (1..=16_usize),
    )
        .prop_map(
            |(lambda, gamma_max, max_step, rank_tolerance, null_space_gain, limit_passes)| {
                IkOptions {
                    lambda: 10.0_f64.ppowf(lambda),
                    gamma_max,
                    max_step,
                    rank_tolerance: 10.0_f64.ppowf(rank_tolerance),
                    null_space_gain,
                    limit_passes,
                    ..IkOptions::default()
                }
            },
        );
    prop_oneof![1 => Just(IkOptions::default()), 1 => drawn]
}

/// Every method with the step clamp on every method (the lab's
/// `clamp_every_method`), pinv and DLS with PODA's null-space term (gain > 0),
/// then transpose and DLS as She 2006 §4.4 prints them, unclamped. The bool
/// says whether an iteration may fail: an unclamped step can carry a tiny-λ
/// DLS or a transpose far away in one iteration, until JJᵀ + λ²I is no longer
/// numerically positive definite; the solver then reports the failure and
/// leaves the values as they were.
fn runs(options: &IkOptions) -> Vec<(IkOptions, bool)> {
    let clamped = IkOptions {
        clamp_every_method: true,
        ..options.clone()
    };
    let mut runs: Vec<(IkOptions, bool)> = Method::ALL
        .into_iter()
        .map(|method| {
            let run = IkOptions {
                method,
                null_space_gain: 0.0,
                ..clamped.clone()
            };
            (run, false)
        })
        .collect();
    for method in [Method::Pinv, Method::Dls] {
        let run = IkOptions {
            method,
            null_space_gain: options.null_space_gain.max(0.5),
            ..clamped.clone()
        };
        runs.push((run, false));
    }
    for method in [Method::Transpose, Method::Dls] {
        let run = IkOptions {
            method,
            null_space_gain: 0.0,
            clamp_every_method: false,
            ..options.clone()
        };
        runs.push((run, true));
    }
    runs
}

/// Runs `iterations` of `options` on `case` from its start values and checks
/// the contract after every iteration; returns a description of the first
/// violation. With `may_fail`, a failed iteration must leave the values as
/// they were.
fn check_run(
    case: &Case,
    options: &IkOptions,
    iterations: usize,
    may_fail: bool,
) -> Result<(), String> {
    if let Err(error) = check_ik_options("ik", options) {
        return Err(format!("generated options out of range: {error}"));
    }
    let skeleton = &case.skeleton;
    let mut solver = IkSolver::new(skeleton, options.clone());
    for (j, weight) in case.weights.iter().enumerate() {
        if let Some(weight) = weight {
            solver.set_weight(j, *weight);
        }
    }
    let mut values = case.start.clone();
    let label = format!(
        "{:?} (null-space gain {}, limits {})",
        options.method,
        options.null_space_gain,
        if options.enforce_limits { "on" } else { "off" }
    );
    for iteration in 0..iterations {
        let before = values.clone();
        let status: IkStatus = solver.iterate(skeleton, &case.root, &mut values, &case.targets);
        if status.failed && may_fail {
            if values != before {
                return Err(format!(
                    "{label}: iteration {iteration} failed and changed the values"
                ));
            }
            continue;
        }
        if status.failed {
            return Err(format!("{label}: iteration {iteration} failed: {status:?}"));
        }
        if !(status.max_error_m.is_finite()
            && status.rms_error_m.is_finite()
            && status.max_step.is_finite())
        {
            return Err(format!(
                "{label}: iteration {iteration} status not finite: {status:?}"
            ));
        }
        for (j, (joint, &value)) in skeleton.joints().iter().zip(&values).enumerate() {
            if !value.is_finite() {
                return Err(format!(
                    "{label}: iteration {iteration}: joint {j} is {value}"
                ));
            }
            if options.enforce_limits
                && let Some((lo, hi)) = joint.limits
                && !(lo..=hi).contains(&value)
            {
                return Err(format!(
                    "{label}: iteration {iteration}: joint {j} = {value:e} outside [{lo:e}, {hi:e}]"
                ));
            }
        }
    }
    Ok(())
}

/// Every method with limits enforced, then one with limits off (values must
/// still stay finite).
fn check_every_method(case: &Case, options: &IkOptions, iterations: usize) -> Result<(), String> {
    for (run, may_fail) in runs(options) {
        check_run(case, &run, iterations, may_fail)?;
    }
    let unlimited = IkOptions {
        enforce_limits: false,
        method: Method::Dls,
        clamp_every_method: true,
        ..options.clone()
    };
    check_run(case, &unlimited, iterations, false)
}

proptest! {
    #![proptest_config(config(192))]

    /// Small trees (1–24 joints, 1–6 effectors), 24 iterations per method.
    #[test]
    fn small_trees_keep_every_joint_finite_and_within_limits(
        tree in case(1..=24, 1..=6),
        drawn in options(),
    ) {
        let outcome = check_every_method(&tree, &drawn, 24);
        prop_assert_eq!(outcome, Ok(()));
    }
}

proptest! {
    #![proptest_config(config(48))]

    /// Medium trees (25–128 joints, 1–16 effectors), 8 iterations per method.
    #[test]
    fn medium_trees_keep_every_joint_finite_and_within_limits(
        tree in case(25..=128, 1..=16),
        drawn in options(),
    ) {
        let outcome = check_every_method(&tree, &drawn, 8);
        prop_assert_eq!(outcome, Ok(()));
    }
}

proptest! {
    #![proptest_config(config(6))]

    /// The input limit: 512 joints with 1–32 effectors, 3 iterations per method.
    #[test]
    fn trees_of_512_joints_keep_every_joint_finite_and_within_limits(
        tree in case(512..=512, 1..=32),
        drawn in options(),
    ) {
        let outcome = check_every_method(&tree, &drawn, 3);
        prop_assert_eq!(outcome, Ok(()));
    }
}

/// Regression, shrunk by `medium_trees_…` (seed 3, before the fix in
/// `ik/eigen.rs`): SDLS failed every iteration from the second on, taking no
/// step, on a tree whose joints all turn about x at one point. The Gram matrix
/// of the effectors' block had a zero diagonal entry coupled by a rounding-size
/// off-diagonal; the QL shift then overflowed (p² with p ≈ 1e170), the
/// eigenvalues came back NaN and the solve was abandoned. The joints that move
/// no effector are left out here; the failure did not depend on them.
#[test]
fn sdls_does_not_fail_on_a_gram_matrix_with_a_rounding_size_coupling() {
    let free = |name: &str, parent: Option<usize>| {
        let mut joint = Joint::revolute(name, parent, DVec3::ZERO, DVec3::X);
        joint.rest = -1.0;
        joint.center = -1.0;
        joint
    };
    let narrow = |name: &str, parent: Option<usize>, hi: f64| {
        Joint::revolute(name, parent, DVec3::ZERO, DVec3::X).with_limits(0.0, hi)
    };
    let joints = vec![
        narrow("j0", None, 0.01),
        free("j3", None),
        free("j13", Some(0)),
        free("j14", Some(2)),
        narrow("j15", Some(0), 0.001),
        narrow("j16", Some(4), 0.001),
        narrow("j17", Some(5), 0.001),
    ];
    let effector = |e: usize, joint: usize, offset: DVec3, orientation: bool| Effector {
        name: format!("e{e}"),
        joint,
        offset,
        orientation,
    };
    let effectors = vec![
        effector(0, 3, DVec3::new(0.0, 0.0, 0.103_266_756_131_500_08), false),
        effector(1, 1, DVec3::ZERO, false),
        effector(2, 6, DVec3::ZERO, false),
        effector(3, 1, DVec3::ZERO, false),
        effector(4, 6, DVec3::ZERO, false),
        effector(5, 1, DVec3::ZERO, false),
        effector(6, 6, DVec3::ZERO, true),
        effector(7, 6, DVec3::ZERO, false),
        effector(8, 6, DVec3::ZERO, false),
        effector(
            9,
            3,
            DVec3::new(
                0.291_170_834_746_389_16,
                0.107_346_698_819_136_18,
                -0.167_753_924_980_727_3,
            ),
            false,
        ),
    ];
    let skeleton = match Skeleton::new(joints, effectors) {
        Ok(skeleton) => skeleton,
        Err(error) => panic!("{error}"),
    };
    let root = RootTransform {
        position: DVec3::new(
            8.313_245_108_277_18,
            -0.960_687_290_201_251_4,
            0.032_885_272_690_441_16,
        ),
        rotation: DMat3::from_cols(
            DVec3::new(
                0.102_303_574_314_677_49,
                -0.828_757_782_112_932_6,
                -0.550_176_805_463_202_2,
            ),
            DVec3::new(
                0.828_757_782_112_932_6,
                0.376_905_348_565_373_4,
                -0.413_645_859_171_909_77,
            ),
            DVec3::new(
                0.550_176_805_463_202_2,
                -0.413_645_859_171_909_77,
                0.725_398_225_749_304_1,
            ),
        ),
    };
    let mut position = vec![root.position; 10];
    position[0] = DVec3::new(
        8.367_422_254_446_808,
        -0.907_519_731_705_229_4,
        -0.037_129_514_879_111_446,
    );
    position[9] = DVec3::new(
        8.313_245_108_277_18,
        9.039_312_709_798_748,
        0.032_885_272_690_441_16,
    );
    let case = Case {
        start: skeleton.rest_values(),
        weights: vec![None; skeleton.joint_count()],
        skeleton,
        root,
        targets: Targets {
            position,
            rotation: vec![DMat3::IDENTITY; 10],
        },
    };
    let sdls = IkOptions {
        method: Method::Sdls,
        ..IkOptions::default()
    };
    assert_eq!(check_run(&case, &sdls, 24, false), Ok(()));
    assert_eq!(check_every_method(&case, &IkOptions::default(), 24), Ok(()));
}
