//! BVH export checked against an independent computation: a skeleton with
//! varied axes, fixed frame rotations, a prismatic joint, two roots and two
//! effectors is written for 50 random poses (plus poses at and near gimbal lock),
//! read back, and the BVH format's own forward kinematics must reproduce
//! gaitlab's `Kinematics` joint and effector positions to a micrometre.

use gaitlab_core::export::{
    BVH_ROOT_NAME, BvhChannel, BvhKinematics, BvhOptions, BvhWriter, WriteError, bvh_string,
    from_euler_zxy, parse_bvh,
};
use gaitlab_core::{Effector, Joint, Kinematics, Pose, RootTransform, Skeleton};
use glam::{DMat3, DVec3};
use std::f64::consts::{FRAC_PI_2, PI};

/// Deterministic splitmix64 stream of uniform numbers.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1_u64 << 53) as f64;
        lo + (hi - lo) * unit
    }

    fn unit_vector(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            let length = v.length();
            if (0.1..=1.0).contains(&length) {
                return v / length;
            }
        }
    }
}

fn rotated(mut joint: Joint, axis: DVec3, angle: f64) -> Joint {
    joint.frame = DMat3::from_axis_angle(axis.normalize(), angle);
    joint
}

/// Index order differs from hierarchy order (the tail root comes second), names
/// include a space, and frames are non-trivial.
fn test_skeleton() -> Skeleton {
    let joints = vec![
        // 0
        rotated(
            Joint::revolute("pelvis", None, DVec3::new(0.0, 0.05, 0.0), DVec3::Y),
            DVec3::new(0.3, 1.0, -0.2),
            0.4,
        ),
        // 1: a second joint on the root, listed before the pelvis' children
        Joint::revolute(
            "tail",
            None,
            DVec3::new(0.0, 0.0, -0.2),
            DVec3::new(1.0, 0.0, 0.0),
        ),
        // 2
        rotated(
            Joint::revolute(
                "left hip",
                Some(0),
                DVec3::new(0.1, -0.05, 0.0),
                DVec3::new(1.0, 0.3, -0.2),
            ),
            DVec3::new(0.2, 1.0, 0.5),
            0.7,
        ),
        // 3: axis X, frame identity: value ±π/2 is Euler X = ±90°
        Joint::revolute("left_knee", Some(2), DVec3::new(0.0, -0.4, 0.02), DVec3::X),
        // 4
        rotated(
            Joint::prismatic(
                "spine_slide",
                Some(0),
                DVec3::new(0.0, 0.2, 0.01),
                DVec3::new(0.1, 1.0, 0.2),
            ),
            DVec3::new(1.0, 0.0, 1.0),
            -0.5,
        ),
        // 5
        rotated(
            Joint::revolute("left_ankle", Some(3), DVec3::new(0.0, -0.42, 0.0), DVec3::Z),
            DVec3::X,
            0.3,
        ),
        // 6: leaf without an effector
        Joint::revolute(
            "neck",
            Some(4),
            DVec3::new(0.0, 0.3, 0.0),
            DVec3::new(0.0, 1.0, 1.0),
        ),
        // 7
        rotated(
            Joint::revolute("right_hip", Some(0), DVec3::new(-0.1, -0.05, 0.0), DVec3::Z),
            DVec3::new(-1.0, 2.0, 0.3),
            1.1,
        ),
        // 8
        Joint::revolute(
            "right_knee",
            Some(7),
            DVec3::new(0.0, -0.4, -0.01),
            DVec3::new(-1.0, 0.1, 0.0),
        ),
    ];
    let effectors = vec![
        Effector {
            name: "left_foot".to_owned(),
            joint: 5,
            offset: DVec3::new(0.0, -0.05, 0.12),
            orientation: false,
        },
        Effector {
            name: "right_foot".to_owned(),
            joint: 8,
            offset: DVec3::new(0.01, -0.45, 0.1),
            orientation: false,
        },
    ];
    Skeleton::new(joints, effectors).expect("test skeleton is valid")
}

fn random_poses(skeleton: &Skeleton, count: usize, seed: u64) -> Vec<Pose> {
    let mut rng = Rng(seed);
    (0..count)
        .map(|frame| {
            let t = frame as f64 / 30.0;
            let root = RootTransform {
                position: DVec3::new(
                    rng.range(-0.5, 0.5),
                    0.9 + rng.range(-0.1, 0.1),
                    1.2 * t + rng.range(-0.2, 0.2),
                ),
                rotation: DMat3::from_axis_angle(rng.unit_vector(), rng.range(0.0, PI)),
            };
            let joints = skeleton
                .joints()
                .iter()
                .map(|joint| match joint.kind {
                    gaitlab_core::JointKind::Revolute => rng.range(-PI, PI),
                    gaitlab_core::JointKind::Prismatic => rng.range(-0.1, 0.1),
                })
                .collect();
            Pose { root, joints }
        })
        .collect()
}

/// Poses whose root and left knee sit exactly at, or a hair from, Euler X = ±90°.
fn gimbal_poses(skeleton: &Skeleton) -> Vec<Pose> {
    let knee = skeleton.joint_index("left_knee").expect("knee");
    [FRAC_PI_2, -FRAC_PI_2, FRAC_PI_2 - 1e-9, -FRAC_PI_2 + 1e-12]
        .into_iter()
        .enumerate()
        .map(|(i, x)| {
            let mut joints = vec![0.3; skeleton.joint_count()];
            joints[knee] = x;
            Pose {
                root: RootTransform {
                    position: DVec3::new(0.2, 1.0, i as f64),
                    rotation: from_euler_zxy(DVec3::new(x, 0.7 + i as f64, -1.3)),
                },
                joints,
            }
        })
        .collect()
}

/// BVH joint index of each gaitlab joint, found by its written name.
fn bvh_index(bvh: &gaitlab_core::export::Bvh, name: &str) -> usize {
    let written: String = name
        .chars()
        .map(|c| if c.is_whitespace() { '_' } else { c })
        .collect();
    bvh.joint_index(&written)
        .unwrap_or_else(|| panic!("joint {written:?} missing from the BVH"))
}

#[test]
fn bvh_round_trip_reproduces_gaitlab_kinematics() {
    let skeleton = test_skeleton();
    let mut poses = random_poses(&skeleton, 50, 7);
    poses.extend(gimbal_poses(&skeleton));
    let fps = 30.0;
    let text = bvh_string(&skeleton, &poses, fps).expect("writes");
    let bvh = parse_bvh(&text).expect("reads back");

    assert_eq!(
        bvh.joints.len(),
        skeleton.joint_count() + 1,
        "gaitlab joints plus the root"
    );
    assert_eq!(bvh.frame_count, poses.len());
    assert!(
        (bvh.frame_time - 1.0 / fps).abs() < 1e-15,
        "frame time {}",
        bvh.frame_time
    );
    assert_eq!(bvh.joints[0].name, BVH_ROOT_NAME);
    assert_eq!(bvh.joints[0].parent, None);
    assert_eq!(bvh.joints[0].offset, DVec3::ZERO);
    assert_eq!(bvh.joints[0].channels.len(), 6);
    assert_eq!(
        bvh.channel_count,
        6 + 3 * (skeleton.joint_count() - 1) + 6,
        "one prismatic joint"
    );

    // Same tree, same channel layout as documented.
    for (j, joint) in skeleton.joints().iter().enumerate() {
        let b = bvh_index(&bvh, &joint.name);
        let parent = joint
            .parent
            .map_or(0, |p| bvh_index(&bvh, &skeleton.joints()[p].name));
        assert_eq!(
            bvh.joints[b].parent,
            Some(parent),
            "parent of {}",
            joint.name
        );
        assert!((bvh.joints[b].offset - joint.offset).length() < 1e-12);
        let expected: &[BvhChannel] = match joint.kind {
            gaitlab_core::JointKind::Revolute => &[
                BvhChannel::Zrotation,
                BvhChannel::Xrotation,
                BvhChannel::Yrotation,
            ],
            gaitlab_core::JointKind::Prismatic => &[
                BvhChannel::Xposition,
                BvhChannel::Yposition,
                BvhChannel::Zposition,
                BvhChannel::Zrotation,
                BvhChannel::Xrotation,
                BvhChannel::Yrotation,
            ],
        };
        assert_eq!(bvh.joints[b].channels, expected, "{}", joint.name);
        let is_leaf = skeleton.children(j).is_empty();
        assert_eq!(
            bvh.joints[b].end_site.is_some(),
            is_leaf,
            "End Site only on leaves ({})",
            joint.name
        );
    }

    // The independent check: BVH FK against gaitlab FK, every joint, every frame.
    let mut bvh_state = BvhKinematics::new(&bvh);
    let mut worst_joint = 0.0_f64;
    let mut worst_effector = 0.0_f64;
    for (f, pose) in poses.iter().enumerate() {
        bvh_state.update(&bvh, bvh.frame(f).expect("frame exists"));
        let gaitlab = Kinematics::of(&skeleton, pose);
        assert!((bvh_state.joint_position[0] - pose.root.position).length() < 1e-8);
        for (j, joint) in skeleton.joints().iter().enumerate() {
            let error = (bvh_state.joint_position[bvh_index(&bvh, &joint.name)]
                - gaitlab.joint_position[j])
                .length();
            assert!(error <= 1e-6, "frame {f} joint {}: {error} m", joint.name);
            worst_joint = worst_joint.max(error);
        }
        for (e, effector) in skeleton.effectors().iter().enumerate() {
            let b = bvh_index(&bvh, &skeleton.joints()[effector.joint].name);
            let tip = bvh_state.end_site_position[b].expect("effector leaf has an End Site");
            let error = (tip - gaitlab.effector_position[e]).length();
            assert!(
                error <= 1e-6,
                "frame {f} effector {}: {error} m",
                effector.name
            );
            worst_effector = worst_effector.max(error);
        }
    }
    // 9 decimals: the worst error is nanometres, far inside the micrometre bound.
    assert!(
        worst_joint < 1e-8 && worst_effector < 1e-8,
        "{worst_joint} {worst_effector}"
    );
}

#[test]
fn gimbal_lock_frames_write_ninety_degrees_and_stay_exact() {
    let skeleton = test_skeleton();
    let poses = gimbal_poses(&skeleton);
    let text = bvh_string(&skeleton, &poses, 60.0).expect("writes");
    let bvh = parse_bvh(&text).expect("reads back");
    let root_x = bvh.joints[0].first_channel + 4; // Xposition Yposition Zposition Zrotation [Xrotation]
    let knee = &bvh.joints[bvh_index(&bvh, "left_knee")];
    let knee_x = knee.first_channel + 1; // Zrotation [Xrotation] Yrotation
    let frame0 = bvh.frame(0).expect("frame 0");
    let frame1 = bvh.frame(1).expect("frame 1");
    assert_eq!(frame0[root_x], 90.0);
    assert_eq!(frame1[root_x], -90.0);
    assert_eq!(frame0[knee_x], 90.0);
    assert_eq!(frame1[knee_x], -90.0);
    for (f, pose) in poses.iter().enumerate() {
        let state = BvhKinematics::of_frame(&bvh, f).expect("frame exists");
        let gaitlab = Kinematics::of(&skeleton, pose);
        for (j, joint) in skeleton.joints().iter().enumerate() {
            let b = bvh_index(&bvh, &joint.name);
            let error = (state.joint_position[b] - gaitlab.joint_position[j]).length();
            assert!(error < 1e-8, "frame {f} {}: {error}", joint.name);
            let rotation_error = (state.joint_rotation[b] - gaitlab.joint_rotation[j])
                .to_cols_array()
                .iter()
                .fold(0.0_f64, |m, v| m.max(v.abs()));
            assert!(
                rotation_error < 1e-9,
                "frame {f} {} rotation off by {rotation_error}",
                joint.name
            );
        }
    }
}

#[test]
fn end_site_of_a_leaf_without_effector_points_along_its_bone() {
    let skeleton = test_skeleton();
    let rest = Pose {
        root: RootTransform::default(),
        joints: skeleton.rest_values(),
    };
    let bvh = parse_bvh(&bvh_string(&skeleton, &[rest], 30.0).expect("writes")).expect("reads");
    let neck = &bvh.joints[bvh_index(&bvh, "neck")];
    let tip = neck.end_site.expect("leaf has an End Site");
    // neck: offset (0, 0.3, 0), identity frame, rest 0 -> a quarter of the bone, straight on.
    assert!(
        (tip - DVec3::new(0.0, 0.075, 0.0)).length() < 1e-12,
        "{tip:?}"
    );
    let ankle = &bvh.joints[bvh_index(&bvh, "left_ankle")];
    assert!(
        (ankle.end_site.expect("effector leaf") - DVec3::new(0.0, -0.05, 0.12)).length() < 1e-12
    );
}

#[test]
fn scale_option_writes_centimetres() {
    let skeleton = test_skeleton();
    let poses = random_poses(&skeleton, 3, 11);
    let options = BvhOptions {
        scale: 100.0,
        decimals: 6,
    };
    let mut writer = BvhWriter::with_options(&skeleton, 24.0, options).expect("valid options");
    let mut text = String::new();
    writer.write_header(&mut text, poses.len()).expect("header");
    for pose in &poses {
        writer.write_frame(&mut text, pose).expect("frame");
    }
    writer.finish().expect("all frames written");
    let bvh = parse_bvh(&text).expect("reads back");
    for (f, pose) in poses.iter().enumerate() {
        let state = BvhKinematics::of_frame(&bvh, f).expect("frame");
        let gaitlab = Kinematics::of(&skeleton, pose);
        for (j, joint) in skeleton.joints().iter().enumerate() {
            let metres = state.joint_position[bvh_index(&bvh, &joint.name)] / 100.0;
            // 6 decimals of centimetres and degrees: well under 0.1 mm.
            assert!(
                (metres - gaitlab.joint_position[j]).length() < 1e-6,
                "{}",
                joint.name
            );
        }
    }
}

#[test]
fn writer_refuses_bad_input_without_writing_half_a_line() {
    let skeleton = test_skeleton();
    let good = random_poses(&skeleton, 1, 3).remove(0);
    assert!(matches!(
        BvhWriter::new(&skeleton, 0.0),
        Err(WriteError::InvalidOption { name: "fps", .. })
    ));
    assert!(matches!(
        BvhWriter::new(&skeleton, f64::NAN),
        Err(WriteError::InvalidOption { .. })
    ));
    let bad_scale = BvhOptions {
        scale: -1.0,
        ..BvhOptions::default()
    };
    assert!(matches!(
        BvhWriter::with_options(&skeleton, 30.0, bad_scale),
        Err(WriteError::InvalidOption { name: "scale", .. })
    ));

    let mut writer = BvhWriter::new(&skeleton, 30.0).expect("writer");
    let mut out = String::new();
    assert!(matches!(
        writer.write_frame(&mut out, &good),
        Err(WriteError::Order(_))
    ));
    writer.write_header(&mut out, 2).expect("header");
    assert!(matches!(
        writer.write_header(&mut out, 2),
        Err(WriteError::Order(_))
    ));
    let header_len = out.len();

    let short = Pose {
        root: good.root,
        joints: vec![0.0; 3],
    };
    assert_eq!(
        writer.write_frame(&mut out, &short),
        Err(WriteError::ValueCount {
            what: "joint values",
            expected: skeleton.joint_count(),
            found: 3
        })
    );
    let mut not_finite = good.clone();
    not_finite.joints[4] = f64::NAN;
    assert_eq!(
        writer.write_frame(&mut out, &not_finite),
        Err(WriteError::NonFinite {
            what: "pose",
            row: 0
        })
    );
    assert_eq!(out.len(), header_len, "a refused frame writes nothing");

    writer.write_frame(&mut out, &good).expect("frame 1");
    assert_eq!(
        writer.finish(),
        Err(WriteError::FrameCount {
            declared: 2,
            written: 1
        })
    );
    writer.write_frame(&mut out, &good).expect("frame 2");
    assert!(matches!(
        writer.write_frame(&mut out, &good),
        Err(WriteError::Order(_))
    ));
    writer.finish().expect("declared count reached");
    assert_eq!(parse_bvh(&out).expect("valid file").frame_count, 2);
}

#[test]
fn header_layout_matches_the_bvh_conventions() {
    let joints = vec![
        Joint::revolute("hip", None, DVec3::new(0.0, -0.1, 0.0), DVec3::X),
        Joint::revolute("knee", Some(0), DVec3::new(0.0, -0.4, 0.0), DVec3::X),
    ];
    let effectors = vec![Effector {
        name: "foot".to_owned(),
        joint: 1,
        offset: DVec3::new(0.0, -0.4, 0.0),
        orientation: false,
    }];
    let skeleton = Skeleton::new(joints, effectors).expect("valid");
    let pose = Pose {
        root: RootTransform {
            position: DVec3::new(0.0, 0.9, 0.0),
            rotation: DMat3::IDENTITY,
        },
        joints: vec![0.5, -0.25],
    };
    let text = bvh_string(&skeleton, &[pose], 25.0).expect("writes");
    let expected = "HIERARCHY
ROOT root
{
\tOFFSET 0.000000000 0.000000000 0.000000000
\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
\tJOINT hip
\t{
\t\tOFFSET 0.000000000 -0.100000000 0.000000000
\t\tCHANNELS 3 Zrotation Xrotation Yrotation
\t\tJOINT knee
\t\t{
\t\t\tOFFSET 0.000000000 -0.400000000 0.000000000
\t\t\tCHANNELS 3 Zrotation Xrotation Yrotation
\t\t\tEnd Site
\t\t\t{
\t\t\t\tOFFSET 0.000000000 -0.400000000 0.000000000
\t\t\t}
\t\t}
\t}
}
MOTION
Frames: 1
Frame Time: 0.04
0.000000000 0.900000000 0.000000000 0.000000000 0.000000000 0.000000000 0.000000000 28.647889757 0.000000000 0.000000000 -14.323944878 0.000000000
";
    assert_eq!(text, expected);
}
