//! The pose CSV writer: header names and order, one row per frame, every value
//! parsing back to the exact number written (rotation vectors back to the root
//! rotation), optional effector columns, and refusals that write nothing.

use gaitlab_core::export::{PoseCsvColumns, PoseCsvWriter, WriteError, from_rotation_vector};
use gaitlab_core::{Effector, Joint, Kinematics, Pose, RootTransform, Skeleton};
use glam::{DMat3, DVec3};

fn skeleton() -> Skeleton {
    let joints = vec![
        Joint::revolute("hip", None, DVec3::new(0.0, -0.1, 0.0), DVec3::X),
        Joint::revolute("knee", Some(0), DVec3::new(0.0, -0.4, 0.0), DVec3::X),
        Joint::prismatic("slide, long", Some(1), DVec3::new(0.0, -0.4, 0.0), DVec3::Y),
    ];
    let effectors = vec![Effector {
        name: "foot".to_owned(),
        joint: 2,
        offset: DVec3::new(0.0, -0.05, 0.1),
        orientation: false,
    }];
    Skeleton::new(joints, effectors).expect("valid")
}

fn pose(frame: usize) -> Pose {
    let f = frame as f64;
    Pose {
        root: RootTransform {
            position: DVec3::new(0.01 * f, 0.9 + 1e-9 * f, -2.0 / 3.0),
            rotation: DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 2.0) / 3.0, 0.3 * f),
        },
        joints: vec![0.1 * f, -1.0 / (f + 3.0), 1e-7 * f],
    }
}

fn numbers(row: &str) -> Vec<f64> {
    row.split(',')
        .map(|v| v.parse::<f64>().expect("a number"))
        .collect()
}

#[test]
fn rows_parse_back_to_the_values_written() {
    let skeleton = skeleton();
    let columns = PoseCsvColumns {
        effector_positions: true,
        effector_targets: true,
    };
    let writer = PoseCsvWriter::new(&skeleton, columns);
    assert_eq!(writer.column_count(), 7 + 3 + 3 + 3);
    let mut out = String::new();
    writer.write_header(&mut out).expect("header");
    let frames = 10;
    let fps = 30.0;
    for frame in 0..frames {
        let pose = pose(frame);
        let effector = Kinematics::of(&skeleton, &pose).effector_position;
        let target = [effector[0] + DVec3::new(0.0, 0.0, 0.001)];
        writer
            .write_row(&mut out, frame as f64 / fps, &pose, &effector, &target)
            .expect("row");
    }

    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 1 + frames, "header plus one row per frame");
    assert_eq!(
        lines[0],
        "t,root_x,root_y,root_z,root_rx,root_ry,root_rz,hip,knee,\"slide, long\",foot_x,foot_y,foot_z,foot_target_x,foot_target_y,foot_target_z"
    );
    for (frame, line) in lines[1..].iter().enumerate() {
        let values = numbers(line);
        assert_eq!(values.len(), writer.column_count());
        let pose = pose(frame);
        assert_eq!(values[0], frame as f64 / fps);
        assert_eq!(
            DVec3::new(values[1], values[2], values[3]),
            pose.root.position,
            "bit-exact"
        );
        let rotation = from_rotation_vector(DVec3::new(values[4], values[5], values[6]));
        let error = (rotation - pose.root.rotation)
            .to_cols_array()
            .iter()
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(
            error < 1e-14,
            "frame {frame}: rotation vector off by {error}"
        );
        let angle = DVec3::new(values[4], values[5], values[6]).length();
        assert!(
            (angle - 0.3 * frame as f64).abs() < 1e-12,
            "rotation angle of frame {frame}"
        );
        assert_eq!(
            &values[7..10],
            pose.joints.as_slice(),
            "bit-exact joint values"
        );
        let effector = Kinematics::of(&skeleton, &pose).effector_position[0];
        assert_eq!(DVec3::new(values[10], values[11], values[12]), effector);
        assert_eq!(
            DVec3::new(values[13], values[14], values[15]),
            effector + DVec3::new(0.0, 0.0, 0.001)
        );
    }
}

#[test]
fn default_columns_are_time_root_and_joints() {
    let skeleton = skeleton();
    let writer = PoseCsvWriter::new(&skeleton, PoseCsvColumns::default());
    let mut out = String::new();
    writer.write_header(&mut out).expect("header");
    writer
        .write_row(&mut out, 0.5, &pose(0), &[], &[])
        .expect("row");
    assert_eq!(
        out,
        "t,root_x,root_y,root_z,root_rx,root_ry,root_rz,hip,knee,\"slide, long\"\n0.5,0,0.9,-0.6666666666666666,0,0,0,0,-0.3333333333333333,0\n"
    );
}

#[test]
fn tiny_and_huge_values_use_exponents_and_round_trip() {
    let skeleton = skeleton();
    let writer = PoseCsvWriter::new(&skeleton, PoseCsvColumns::default());
    let mut out = String::new();
    let mut tiny = pose(0);
    tiny.joints = vec![1e-300, -2.5e-8, 1e20];
    writer
        .write_row(&mut out, 1e-6, &tiny, &[], &[])
        .expect("row");
    assert!(out.len() < 120, "{out}");
    let values = numbers(out.trim_end());
    assert_eq!(values[0], 1e-6);
    assert_eq!(&values[7..], &[1e-300, -2.5e-8, 1e20]);
}

#[test]
fn wrong_lengths_are_refused_and_nothing_is_written() {
    let skeleton = skeleton();
    let writer = PoseCsvWriter::new(
        &skeleton,
        PoseCsvColumns {
            effector_positions: true,
            effector_targets: false,
        },
    );
    let mut out = String::new();
    let mut short = pose(1);
    short.joints.pop();
    assert_eq!(
        writer.write_row(&mut out, 0.0, &short, &[DVec3::ZERO], &[]),
        Err(WriteError::ValueCount {
            what: "joint values",
            expected: 3,
            found: 2
        })
    );
    assert_eq!(
        writer.write_row(&mut out, 0.0, &pose(1), &[], &[]),
        Err(WriteError::ValueCount {
            what: "effector positions",
            expected: 1,
            found: 0
        })
    );
    assert!(out.is_empty());
    // Targets are disabled, so a targets slice of any length is ignored.
    writer
        .write_row(&mut out, 0.0, &pose(1), &[DVec3::ONE], &[DVec3::ZERO; 5])
        .expect("row");
    assert_eq!(out.trim_end().split(',').count(), writer.column_count());
}
