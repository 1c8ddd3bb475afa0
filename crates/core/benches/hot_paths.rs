//! Criterion benchmarks of the core hot paths, the parts of She 2006 §4.4's
//! per-iteration cost: forward kinematics (§3.1), the geometric Jacobian
//! (§4.3.1, PODA eq. 3) and one IK iteration of each method (§4.4; CCD for
//! contrast), on the human and on the 63-joint `ik-quadruped` preset; and
//! every effector's manipulability ellipsoid (issue 44 item 3).
//!
//! Each IK iteration starts from the rest pose towards targets a few
//! centimetres off the rest effectors, so every sample does the same work.
//! `gaitlab bench` times the same iteration over a recorded walk instead.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use gaitlab_core::ik::{IkSolver, Method, Targets};
use gaitlab_core::jacobian::fill_jacobian;
use gaitlab_core::preset::load_bundled;
use gaitlab_core::skeleton::Scope;
use gaitlab_core::{Creature, Kinematics, RootTransform};
use glam::DVec3;
use nalgebra::DMatrix;

/// The presets timed.
const PRESETS: [&str; 2] = ["human", "ik-quadruped"];

/// How far each target sits from its effector's rest position, metres.
const TARGET_OFFSET_M: DVec3 = DVec3::new(0.03, -0.02, 0.04);

fn creature(name: &str) -> Creature {
    match load_bundled(name) {
        Some(Ok(creature)) => creature,
        other => panic!("bundled preset {name}: {other:?}"),
    }
}

fn forward_kinematics(c: &mut Criterion) {
    let mut group = c.benchmark_group("fk");
    for name in PRESETS {
        let creature = creature(name);
        let skeleton = &creature.skeleton;
        let root = RootTransform::default();
        let values = skeleton.rest_values();
        let mut kinematics = Kinematics::new(skeleton);
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| kinematics.update(skeleton, black_box(&root), black_box(&values)));
        });
    }
    group.finish();
}

fn jacobian(c: &mut Criterion) {
    let mut group = c.benchmark_group("jacobian");
    for name in PRESETS {
        let creature = creature(name);
        let skeleton = &creature.skeleton;
        let mut kinematics = Kinematics::new(skeleton);
        kinematics.update(skeleton, &RootTransform::default(), &skeleton.rest_values());
        let mut matrix = DMatrix::zeros(skeleton.task_rows(), skeleton.joint_count());
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| fill_jacobian(skeleton, black_box(&kinematics), &mut matrix));
        });
    }
    group.finish();
}

/// Every effector's manipulability ellipsoid in one pose (what the 3-D view
/// computes per figure per frame with *Reach ellipsoids* on).
fn manipulability(c: &mut Criterion) {
    let mut group = c.benchmark_group("manipulability_all_effectors");
    for name in PRESETS {
        let creature = creature(name);
        let skeleton = &creature.skeleton;
        let mut kinematics = Kinematics::new(skeleton);
        kinematics.update(skeleton, &RootTransform::default(), &skeleton.rest_values());
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| {
                for e in 0..skeleton.effector_count() {
                    black_box(skeleton.manipulability(black_box(&kinematics), e, Scope::Limb));
                }
            });
        });
    }
    group.finish();
}

fn ik_iteration(c: &mut Criterion) {
    let mut group = c.benchmark_group("ik_iteration");
    for name in PRESETS {
        let creature = creature(name);
        let skeleton = &creature.skeleton;
        let root = RootTransform::default();
        let rest = skeleton.rest_values();
        let mut kinematics = Kinematics::new(skeleton);
        kinematics.update(skeleton, &root, &rest);
        let mut targets = Targets::at(&kinematics);
        for target in &mut targets.position {
            *target += TARGET_OFFSET_M;
        }
        for method in Method::ALL {
            let mut options = creature.scenario.ik_options();
            options.method = method;
            let mut solver = IkSolver::new(skeleton, options);
            let mut values = rest.clone();
            group.bench_function(BenchmarkId::new(method.name(), name), |b| {
                b.iter(|| {
                    values.copy_from_slice(&rest);
                    black_box(solver.iterate(skeleton, &root, &mut values, black_box(&targets)))
                });
            });
        }
    }
    group.finish();
}

criterion_group!(
    benches,
    forward_kinematics,
    jacobian,
    manipulability,
    ik_iteration
);
criterion_main!(benches);
