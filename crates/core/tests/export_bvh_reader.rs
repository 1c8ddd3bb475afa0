//! The BVH reader on hand-written files: a conventional mocap-style file with
//! hand-computed forward kinematics, every malformed case with its line number,
//! and no panic on any prefix or corruption of a valid file.

use gaitlab_core::export::{BvhChannel, BvhKinematics, MAX_BVH_JOINTS, bvh_string, parse_bvh};
use gaitlab_core::{Effector, Joint, Pose, RootTransform, Skeleton};
use glam::{DMat3, DVec3};

/// Centimetre units, tabs, CRLF line ends, a brace on a JOINT line, a trailing blank line.
const SMALL: &str = "HIERARCHY\r\nROOT Hips\r\n{\r\n\tOFFSET 0 0 0\r\n\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\r\n\tJOINT Chest {\r\n\t\tOFFSET 0 10 0\r\n\t\tCHANNELS 3 Zrotation Xrotation Yrotation\r\n\t\tEnd Site\r\n\t\t{\r\n\t\t\tOFFSET 0 5 0\r\n\t\t}\r\n\t}\r\n\tJOINT Left Leg\r\n\t{\r\n\t\tOFFSET 3 -2 0\r\n\t\tCHANNELS 3 Xrotation Yrotation Zrotation\r\n\t}\r\n}\r\nMOTION\r\nFrames: 2\r\nFrame Time: 0.0333333\r\n0 90 0 0 0 0 0 0 0 0 0 0\r\n1 90 2 90 0 0 0 0 0 90 0 0\r\n\r\n";

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

#[test]
fn reads_a_conventional_file_and_computes_its_positions_by_hand() {
    let bvh = parse_bvh(SMALL).expect("valid file");
    assert_eq!(bvh.joints.len(), 3);
    assert_eq!(bvh.joints[1].name, "Chest");
    assert_eq!(
        bvh.joints[2].name, "Left Leg",
        "multi-word names are joined"
    );
    assert_eq!(bvh.joints[2].parent, Some(0));
    assert_eq!(bvh.channel_count, 12);
    assert_eq!(bvh.joints[2].first_channel, 9);
    assert_eq!(
        bvh.joints[2].channels,
        [
            BvhChannel::Xrotation,
            BvhChannel::Yrotation,
            BvhChannel::Zrotation
        ]
    );
    assert_eq!(bvh.frame_count, 2);
    assert!((bvh.frame_time - 0.033_333_3).abs() < 1e-15);

    let rest = BvhKinematics::of_frame(&bvh, 0).expect("frame 0");
    assert!(close(rest.joint_position[0], DVec3::new(0.0, 90.0, 0.0)));
    assert!(close(rest.joint_position[1], DVec3::new(0.0, 100.0, 0.0)));
    assert!(close(
        rest.end_site_position[1].expect("chest tip"),
        DVec3::new(0.0, 105.0, 0.0)
    ));
    assert!(close(rest.joint_position[2], DVec3::new(3.0, 88.0, 0.0)));

    // Frame 1: root at (1, 90, 2) turned 90° about z: the chest's +y offset points along -x.
    let moved = BvhKinematics::of_frame(&bvh, 1).expect("frame 1");
    assert!(close(moved.joint_position[0], DVec3::new(1.0, 90.0, 2.0)));
    assert!(close(moved.joint_position[1], DVec3::new(-9.0, 90.0, 2.0)));
    assert!(close(
        moved.end_site_position[1].expect("chest tip"),
        DVec3::new(-14.0, 90.0, 2.0)
    ));
    assert!(close(moved.joint_position[2], DVec3::new(3.0, 93.0, 2.0)));
    // The leg's own Xrotation 90° is in its world rotation: Rz(90°)·Rx(90°).
    let expected =
        DMat3::from_rotation_z(90f64.to_radians()) * DMat3::from_rotation_x(90f64.to_radians());
    assert!(
        (moved.joint_rotation[2] - expected)
            .to_cols_array()
            .iter()
            .all(|v| v.abs() < 1e-12)
    );
    assert!(bvh.world_positions(2).is_none(), "past the last frame");
}

/// (text, expected line, words the reason must contain)
fn malformed_cases() -> Vec<(String, usize, &'static str)> {
    let head =
        "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n}\nMOTION\n";
    let mut cases: Vec<(String, usize, &'static str)> = vec![
        (String::new(), 1, "empty file"),
        ("   \n\n".into(), 1, "empty file"),
        ("HIERARCH\n".into(), 1, "expected \"HIERARCHY\""),
        ("HIERARCHY\nROOT\n{\n".into(), 2, "needs a name"),
        (
            "HIERARCHY\nROOT r\nOFFSET 0 0 0\n".into(),
            3,
            "expected \"{\"",
        ),
        ("HIERARCHY\nJOINT j\n{\n".into(), 2, "outside any ROOT"),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nROOT s\n".into(),
            5,
            "ROOT inside",
        ),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 abc\n".into(),
            4,
            "not a finite number \"abc\"",
        ),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 inf\n".into(),
            4,
            "not a finite number",
        ),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nOFFSET 1 1 1\n".into(),
            5,
            "second OFFSET",
        ),
        (
            "HIERARCHY\nROOT r\n{\nCHANNELS 7 Xposition\n".into(),
            4,
            "at most 6",
        ),
        (
            "HIERARCHY\nROOT r\n{\nCHANNELS -1\n".into(),
            4,
            "not a channel count",
        ),
        (
            "HIERARCHY\nROOT r\n{\nCHANNELS 2 Xrotation\nWrotation\n".into(),
            5,
            "unknown channel \"Wrotation\"",
        ),
        (
            "HIERARCHY\nROOT r\n{\nCHANNELS 1 Xrotation\n}\n".into(),
            5,
            "has no OFFSET",
        ),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nEnd Site\n{\nOFFSET 1 2 3\n}\nEnd Site\n".into(),
            9,
            "second End Site",
        ),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nEnd Sight\n".into(),
            5,
            "expected \"Site\"",
        ),
        ("HIERARCHY\n}\n".into(), 2, "without a matching"),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\n".into(),
            4,
            "file ends inside the block of \"r\"",
        ),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nMOTION\n".into(),
            5,
            "MOTION inside the unclosed block",
        ),
        ("HIERARCHY\nMOTION\n".into(), 2, "MOTION before any ROOT"),
        (
            "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\n}\nbanana\n".into(),
            6,
            "unexpected \"banana\"",
        ),
        (head.to_string(), 7, "\"Frames: N\""),
        (format!("{head}Frames 2\n"), 8, "expected \"Frames: N\""),
        (format!("{head}Frames: -2\n"), 8, "not a whole number"),
        (
            format!("{head}Frames: 1\nFrame Time: 0\n0 0 0\n"),
            9,
            "not a positive number",
        ),
        (
            format!("{head}Frames: 1\nFrame Tim: 0.1\n0 0 0\n"),
            9,
            "expected \"Frame Time: T\"",
        ),
        (
            format!("{head}Frames: 1\nFrame Time: 0.1\n0 0\n"),
            10,
            "expected 3 values (one per channel), found 2",
        ),
        (
            format!("{head}Frames: 1\nFrame Time: 0.1\n0 0 0 0\n"),
            10,
            "found 4",
        ),
        (
            format!("{head}Frames: 1\nFrame Time: 0.1\n0 nan 0\n"),
            10,
            "value 2 of 3: not a finite number \"nan\"",
        ),
        (
            format!("{head}Frames: 3\nFrame Time: 0.1\n0 0 0\n\n1 1 1\n"),
            12,
            "only 2 frame lines",
        ),
        (
            format!("{head}Frames: 1\nFrame Time: 0.1\n0 0 0\n1 1 1\n"),
            11,
            "more frame lines than the 1",
        ),
    ];
    // One joint past the limit: a flat root with MAX_BVH_JOINTS children.
    let mut many = String::from("HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\n");
    for i in 1..=MAX_BVH_JOINTS {
        many.push_str(&format!("JOINT j{i}\n{{\nOFFSET 0 1 0\n}}\n"));
    }
    let line = 4 + 4 * (MAX_BVH_JOINTS - 1) + 1;
    cases.push((many, line, "more than 4096 joints"));
    cases
}

#[test]
fn malformed_files_are_refused_with_the_right_line() {
    for (text, line, words) in malformed_cases() {
        let error = parse_bvh(&text)
            .expect_err(&format!("should refuse {:?}", &text[..text.len().min(80)]));
        assert_eq!(
            error.line,
            line,
            "{error} for {:?}",
            &text[..text.len().min(80)]
        );
        assert!(
            error.reason.contains(words),
            "{error:?} should mention {words:?}"
        );
        assert!(error.to_string().starts_with(&format!("line {line}: ")));
    }
}

#[test]
fn lenient_forms_are_accepted() {
    let text = "\u{feff}hierarchy\nroot r\n{\noffset 0 0 0\nchannels 1 xrotation\n}\nROOT second {\nOFFSET 1 0 0\n}\nmotion\nFrames:2\nFrame  Time :0.5\n\n10\n\n20\n";
    let bvh = parse_bvh(text).expect("lenient forms");
    assert_eq!(bvh.joints.len(), 2);
    assert_eq!(bvh.joints[1].parent, None, "a second ROOT");
    assert_eq!(bvh.motion, [10.0, 20.0]);
    assert_eq!(bvh.frame(1), Some(&[20.0][..]));
}

fn valid_written_file() -> String {
    let joints = vec![
        Joint::revolute("hip", None, DVec3::new(0.0, -0.1, 0.0), DVec3::X),
        Joint::prismatic("slide", Some(0), DVec3::new(0.0, -0.4, 0.0), DVec3::Y),
        Joint::revolute("ankle", Some(1), DVec3::new(0.0, -0.4, 0.0), DVec3::Z),
    ];
    let effectors = vec![Effector {
        name: "foot".to_owned(),
        joint: 2,
        offset: DVec3::new(0.0, -0.1, 0.1),
        orientation: false,
    }];
    let skeleton = Skeleton::new(joints, effectors).expect("valid");
    let poses: Vec<Pose> = (0..3)
        .map(|i| Pose {
            root: RootTransform {
                position: DVec3::new(0.1 * f64::from(i), 0.9, -0.3),
                rotation: DMat3::from_rotation_y(0.2 * f64::from(i)),
            },
            joints: vec![0.1, -0.02 * f64::from(i), 1.5],
        })
        .collect();
    bvh_string(&skeleton, &poses, 30.0).expect("writes")
}

#[test]
fn no_prefix_of_a_valid_file_panics_and_only_whole_files_parse() {
    let text = valid_written_file();
    let full = parse_bvh(&text).expect("valid");
    let mut accepted = 0;
    for end in 0..=text.len() {
        if let Ok(bvh) = parse_bvh(&text[..end]) {
            // Only a cut inside the last number (or its newline) still parses.
            assert_eq!(bvh.frame_count, full.frame_count, "prefix of {end} bytes");
            assert_eq!(bvh.joints.len(), full.joints.len());
            accepted += 1;
        }
    }
    let last_number = text.trim_end().rsplit(' ').next().expect("a number").len();
    assert!(accepted <= last_number + 1, "{accepted} prefixes parsed");
}

#[test]
fn corrupted_files_never_panic() {
    let text = valid_written_file();
    let bytes = text.as_bytes();
    let replacements = [
        "{",
        "}",
        " ",
        "\n",
        "x",
        "-",
        "9999999999999999999999",
        "End Site",
        "JOINT",
        "CHANNELS 6",
        "é",
        "\0",
    ];
    let mut refused = 0;
    for (i, replacement) in (0..bytes.len())
        .step_by(3)
        .flat_map(|i| replacements.iter().map(move |r| (i, r)))
    {
        if !text.is_char_boundary(i) || !text.is_char_boundary(i + 1) {
            continue;
        }
        let corrupted = format!("{}{}{}", &text[..i], replacement, &text[i + 1..]);
        if parse_bvh(&corrupted).is_err() {
            refused += 1;
        }
    }
    assert!(refused > 0);
    // Token soup.
    let words = [
        "HIERARCHY",
        "ROOT",
        "JOINT",
        "End",
        "Site",
        "{",
        "}",
        "OFFSET",
        "CHANNELS",
        "3",
        "Xrotation",
        "MOTION",
        "Frames:",
        "Frame",
        "Time:",
        "1",
        "0.5",
        "\n",
    ];
    let mut state = 0x1234_5678_u64;
    for _ in 0..2000 {
        let mut soup = String::new();
        for _ in 0..40 {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            soup.push_str(words[(state >> 33) as usize % words.len()]);
            soup.push(' ');
        }
        let _ = parse_bvh(&soup);
    }
}
