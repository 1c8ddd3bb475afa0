//! Limbs and reach (She 2006 §3.1 figure, §5.3 reachable targets): a 2-link arm
//! whose reach is the sum of its links, a shared trunk that belongs to neither
//! arm, and the bundled human: each leg hangs from the root at `*_hip_flex` and
//! reaches 0.44 + 0.43 + |(0, −0.06, 0.1)| ≈ 0.987 m; both hands share
//! `thorax_twist`, so each arm starts at `*_shoulder_flex` and reaches 0.64 m.

use gaitlab_core::preset;
use glam::DVec3;

use gaitlab_core::{Effector, Joint, Kinematics, RootTransform, Skeleton};

fn effector(name: &str, joint: usize, offset: DVec3) -> Effector {
    Effector {
        name: name.to_owned(),
        joint,
        offset,
        orientation: false,
    }
}

/// A 2-link planar arm hanging from the root at (0, 1, 0): links 0.5 m and
/// 0.3 m, reach 0.8 m from the shoulder.
fn two_link() -> Skeleton {
    let joints = vec![
        Joint::revolute("shoulder", None, DVec3::new(0.0, 1.0, 0.0), DVec3::Z),
        Joint::revolute("elbow", Some(0), DVec3::new(0.5, 0.0, 0.0), DVec3::Z),
    ];
    Skeleton::new(joints, vec![effector("hand", 1, DVec3::new(0.3, 0.0, 0.0))])
        .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_two_link_arm_reaches_the_sum_of_its_links() {
    let skeleton = two_link();
    let limb = skeleton.limb(0);
    assert_eq!(limb.shared_root, None);
    assert_eq!(limb.joints, vec![0, 1]);
    assert!((limb.length_m - 0.8).abs() < 1e-12);
    let mut kinematics = Kinematics::new(&skeleton);
    kinematics.update(&skeleton, &RootTransform::default(), &[0.7, -1.2]);
    let anchor = limb.anchor(&kinematics.joint_anchor, &kinematics.joint_position);
    assert!(anchor.distance(DVec3::new(0.0, 1.0, 0.0)) < 1e-12);
    // 1 m to the right of the shoulder: 0.2 m out of reach, whatever the pose.
    let beyond = limb.out_of_reach_m(
        &kinematics.joint_anchor,
        &kinematics.joint_position,
        DVec3::new(1.0, 1.0, 0.0),
    );
    assert!((beyond - 0.2).abs() < 1e-12);
    // 0.6 m below it: 0.2 m inside.
    let inside = limb.out_of_reach_m(
        &kinematics.joint_anchor,
        &kinematics.joint_position,
        DVec3::new(0.0, 0.4, 0.0),
    );
    assert!((inside + 0.2).abs() < 1e-12);
}

#[test]
fn a_shared_trunk_is_not_part_of_either_limb() {
    // trunk → two arms of 0.4 + 0.1 m; a third effector on the trunk itself.
    let joints = vec![
        Joint::revolute("trunk", None, DVec3::ZERO, DVec3::Y),
        Joint::revolute("left", Some(0), DVec3::new(0.2, 0.5, 0.0), DVec3::X),
        Joint::revolute("left_elbow", Some(1), DVec3::new(0.0, -0.4, 0.0), DVec3::X),
        Joint::revolute("right", Some(0), DVec3::new(-0.2, 0.5, 0.0), DVec3::X),
    ];
    let effectors = vec![
        effector("left_hand", 2, DVec3::new(0.0, -0.1, 0.0)),
        effector("right_hand", 3, DVec3::new(0.0, -0.3, 0.0)),
        effector("head", 0, DVec3::new(0.0, 0.7, 0.0)),
    ];
    let skeleton = Skeleton::new(joints, effectors).unwrap_or_else(|e| panic!("{e}"));
    let left = skeleton.limb(0);
    assert_eq!(left.shared_root, Some(0));
    assert_eq!(left.joints, vec![1, 2]);
    assert!((left.length_m - 0.5).abs() < 1e-12);
    let right = skeleton.limb(1);
    assert_eq!(right.joints, vec![3]);
    assert!((right.length_m - 0.3).abs() < 1e-12);
    // The head's joint is shared: no limb joints, measured from the trunk's origin.
    let head = skeleton.limb(2);
    assert_eq!(head.shared_root, Some(0));
    assert!(head.joints.is_empty());
    assert!((head.length_m - 0.7).abs() < 1e-12);
    let mut kinematics = Kinematics::new(&skeleton);
    kinematics.update(&skeleton, &RootTransform::default(), &[0.3, 0.0, 0.0, 0.0]);
    assert!(
        head.anchor(&kinematics.joint_anchor, &kinematics.joint_position)
            .length()
            < 1e-12
    );
}

#[test]
fn the_human_limbs_start_below_the_shared_root_and_have_their_link_lengths() {
    let creature = preset::load_bundled("human")
        .expect("human is bundled")
        .expect("human.json is valid");
    let skeleton = &creature.skeleton;
    let leg_m = 0.44 + 0.43 + (0.06_f64.powi(2) + 0.1_f64.powi(2)).sqrt();
    for (effector, first, shared_root, length_m) in [
        ("left_foot", "left_hip_flex", None, leg_m),
        ("right_foot", "right_hip_flex", None, leg_m),
        (
            "left_hand",
            "left_shoulder_flex",
            Some("thorax_twist"),
            0.64,
        ),
        (
            "right_hand",
            "right_shoulder_flex",
            Some("thorax_twist"),
            0.64,
        ),
    ] {
        let e = skeleton.effector_index(effector).expect("effector exists");
        let limb = skeleton.limb(e);
        let names: Vec<&str> = limb
            .joints
            .iter()
            .map(|&j| skeleton.joints()[j].name.as_str())
            .collect();
        assert_eq!(names.first().copied(), Some(first), "{effector}: {names:?}");
        assert_eq!(names.len(), 4, "{effector}: {names:?}");
        assert_eq!(
            limb.shared_root.map(|j| skeleton.joints()[j].name.as_str()),
            shared_root,
            "{effector}"
        );
        assert!(
            (limb.length_m - length_m).abs() < 1e-3,
            "{effector}: {} m, want {length_m} m",
            limb.length_m
        );
    }
    assert!((leg_m - 0.987).abs() < 1e-3);
}
