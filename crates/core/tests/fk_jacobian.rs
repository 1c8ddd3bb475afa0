//! Forward kinematics against hand-computed poses, and the geometric Jacobian
//! against central finite differences of forward kinematics.

use gaitlab_core::portable::Portable;
mod common;

use std::f64::consts::FRAC_PI_2;

use common::{Rng, planar_arm, random_tree};
use gaitlab_core::jacobian::fill_jacobian;
use gaitlab_core::{Effector, Joint, Kinematics, Pose, RootTransform, Skeleton};
use glam::{DMat3, DQuat, DVec3};
use nalgebra::DMatrix;

fn close(a: DVec3, b: DVec3, tol: f64) {
    assert!((a - b).length() <= tol, "{a} vs {b}");
}

#[test]
fn planar_arm_matches_hand_computed_positions() {
    let arm = planar_arm(&[1.0, 0.5]);
    // θ1 = 90°, θ2 = −90°: the first link points up, the second along +x again.
    let pose = Pose {
        root: RootTransform::default(),
        joints: vec![FRAC_PI_2, -FRAC_PI_2],
    };
    let kin = Kinematics::of(&arm, &pose);
    close(kin.joint_position[0], DVec3::ZERO, 1e-12);
    close(kin.joint_position[1], DVec3::new(0.0, 1.0, 0.0), 1e-12);
    close(kin.effector_position[0], DVec3::new(0.5, 1.0, 0.0), 1e-12);
    // θ1 = 30°, θ2 = 60°: tip at (cos30 + 0.5·cos90, sin30 + 0.5·sin90).
    let pose = Pose {
        root: RootTransform::default(),
        joints: vec![30f64.to_radians(), 60f64.to_radians()],
    };
    let kin = Kinematics::of(&arm, &pose);
    let expected = DVec3::new(30f64.to_radians().pcos(), 0.5 + 0.5, 0.0);
    close(kin.effector_position[0], expected, 1e-12);
}

#[test]
fn root_transform_moves_and_turns_the_whole_figure() {
    let arm = planar_arm(&[1.0, 0.5]);
    let root = RootTransform {
        position: DVec3::new(2.0, 1.0, -3.0),
        rotation: DMat3::from_rotation_y(FRAC_PI_2),
    };
    let pose = Pose {
        root,
        joints: vec![0.0, 0.0],
    };
    let kin = Kinematics::of(&arm, &pose);
    // The straight arm along +x turned 90° about y points along −z.
    close(kin.effector_position[0], DVec3::new(2.0, 1.0, -4.5), 1e-12);
}

#[test]
fn prismatic_joint_slides_along_its_axis_and_frames_rotate_axes() {
    let mut slider = Joint::prismatic("slide", None, DVec3::new(0.0, 1.0, 0.0), DVec3::X);
    slider.frame = DMat3::from_rotation_z(FRAC_PI_2); // the slide axis now points along +y
    let elbow = Joint::revolute("elbow", Some(0), DVec3::ZERO, DVec3::Z);
    let tip = Effector {
        name: "tip".into(),
        joint: 1,
        offset: DVec3::new(1.0, 0.0, 0.0),
        orientation: false,
    };
    let skeleton = Skeleton::new(vec![slider, elbow], vec![tip]).expect("valid");
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root: RootTransform::default(),
            joints: vec![0.25, 0.0],
        },
    );
    close(kin.joint_position[0], DVec3::new(0.0, 1.25, 0.0), 1e-12);
    // The elbow inherits the 90° frame: its zero-angle link points along +y.
    close(kin.effector_position[0], DVec3::new(0.0, 2.25, 0.0), 1e-12);
}

fn finite_difference_jacobian(skeleton: &Skeleton, pose: &Pose, h: f64) -> DMatrix<f64> {
    let rows = skeleton.task_rows();
    let mut jac = DMatrix::zeros(rows, skeleton.joint_count());
    for j in 0..skeleton.joint_count() {
        let mut plus = pose.clone();
        plus.joints[j] += h;
        let mut minus = pose.clone();
        minus.joints[j] -= h;
        let kp = Kinematics::of(skeleton, &plus);
        let km = Kinematics::of(skeleton, &minus);
        let mut row = 0;
        for (e, effector) in skeleton.effectors().iter().enumerate() {
            let d = (kp.effector_position[e] - km.effector_position[e]) / (2.0 * h);
            jac[(row, j)] = d.x;
            jac[(row + 1, j)] = d.y;
            jac[(row + 2, j)] = d.z;
            if effector.orientation {
                let turn = DQuat::from_mat3(
                    &(kp.effector_rotation[e] * km.effector_rotation[e].transpose()),
                )
                .to_scaled_axis()
                    / (2.0 * h);
                jac[(row + 3, j)] = turn.x;
                jac[(row + 4, j)] = turn.y;
                jac[(row + 5, j)] = turn.z;
                row += 6;
            } else {
                row += 3;
            }
        }
    }
    jac
}

#[test]
fn jacobian_matches_finite_differences() {
    let mut rng = Rng::new(42);
    for trial in 0..20 {
        let skeleton = random_tree(&mut rng, 3 + trial, 1 + trial % 4, None, trial % 2 == 0);
        let root = RootTransform {
            position: rng.vec3(1.0),
            rotation: DMat3::from_axis_angle(rng.unit_vec3(), rng.range(-3.0, 3.0)),
        };
        let joints = (0..skeleton.joint_count())
            .map(|_| rng.range(-2.0, 2.0))
            .collect();
        let pose = Pose { root, joints };
        let kin = Kinematics::of(&skeleton, &pose);
        let mut analytic = DMatrix::zeros(0, 0);
        fill_jacobian(&skeleton, &kin, &mut analytic);
        let numeric = finite_difference_jacobian(&skeleton, &pose, 1e-6);
        let worst = (&analytic - &numeric).abs().max();
        assert!(worst <= 1e-6, "trial {trial}: max |J − J_fd| = {worst:e}");
    }
}

#[test]
fn jacobian_columns_are_zero_off_each_effectors_chain() {
    let mut rng = Rng::new(5);
    let skeleton = random_tree(&mut rng, 30, 3, None, false);
    let kin = Kinematics::of(
        &skeleton,
        &Pose {
            root: RootTransform::default(),
            joints: vec![0.3; 30],
        },
    );
    let mut jac = DMatrix::zeros(0, 0);
    fill_jacobian(&skeleton, &kin, &mut jac);
    for e in 0..skeleton.effector_count() {
        let chain = skeleton.chain(e);
        for j in 0..skeleton.joint_count() {
            if !chain.contains(&j) {
                for r in 0..3 {
                    assert_eq!(jac[(3 * e + r, j)], 0.0);
                }
            }
        }
    }
}
