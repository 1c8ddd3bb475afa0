//! The recording panel's motion take, driven through the command API: it
//! records exactly the frames simulated while on, and its BVH and CSV describe
//! the same motion — checked through two independent paths (the BVH reader's
//! own forward kinematics against the core's FK of the CSV rows).

use gaitlab_app::{App, Settings};
use gaitlab_core::export::{BvhKinematics, from_rotation_vector, parse_bvh};
use gaitlab_core::{Kinematics, Pose, RootTransform};
use glam::DVec3;
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).expect("state is JSON")
}

fn advance_frames(lab: &mut App, frames: usize) {
    for _ in 0..frames {
        lab.command(r#"{"step": true}"#).expect("step");
        lab.advance(0.0);
    }
}

/// A recorded lab: 90 frames of running with DLS, recording on for the middle 60.
fn recorded_lab() -> App {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"mode": "run", "method": "dls", "paused": true}"#)
        .expect("valid");
    advance_frames(&mut lab, 15);
    lab.command(r#"{"record": true}"#).expect("record");
    advance_frames(&mut lab, 60);
    lab.command(r#"{"record": false}"#).expect("stop");
    advance_frames(&mut lab, 15);
    lab
}

#[test]
fn a_take_holds_exactly_the_frames_recorded() {
    let lab = recorded_lab();
    let s = state(&lab);
    assert_eq!(s["recording"]["active"], false);
    assert_eq!(s["recording"]["frames"], 60);
    let seconds = s["recording"]["seconds"].as_f64().expect("seconds");
    assert!(
        (seconds - 1.0).abs() < 1e-9,
        "60 frames at 60 fps: {seconds} s"
    );
}

fn csv_rows(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|line| {
            line.split(',')
                .map(|x| x.parse::<f64>().expect("number"))
                .collect()
        })
        .collect();
    (header, rows)
}

#[test]
fn bvh_and_csv_of_a_take_describe_the_same_motion() {
    let mut lab = recorded_lab();
    lab.command(r#"{"save": "bvh"}"#).expect("save bvh");
    let bvh_file = lab.take_download().expect("a BVH download");
    assert!(
        bvh_file.file_name.ends_with(".bvh"),
        "{}",
        bvh_file.file_name
    );
    lab.command(r#"{"save": "csv"}"#).expect("save csv");
    let csv_file = lab.take_download().expect("a CSV download");
    assert_eq!(csv_file.file_name, "gaitlab-human-run-dls.csv");

    let bvh = parse_bvh(&bvh_file.text).expect("the BVH parses");
    assert_eq!(bvh.frame_count, 60);
    assert!((bvh.fps() - 60.0).abs() < 1e-6);
    let (header, rows) = csv_rows(&csv_file.text);
    assert_eq!(rows.len(), 60);

    let skeleton = &lab.creature().skeleton;
    let column = |name: &str| {
        header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("column {name}"))
    };
    let first_joint = column(&skeleton.joints()[0].name);
    let foot = column("left_foot_x");
    let foot_target = column("left_foot_target_x");
    let foot_index = skeleton.effector_index("left_foot").expect("left foot");
    let mut bvh_state = BvhKinematics::new(&bvh);
    let (mut worst_joint_m, mut worst_effector_m, mut worst_error_m) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut times = Vec::new();
    for (f, row) in rows.iter().enumerate() {
        times.push(row[0]);
        let pose = Pose {
            root: RootTransform {
                position: DVec3::new(row[1], row[2], row[3]),
                rotation: from_rotation_vector(DVec3::new(row[4], row[5], row[6])),
            },
            joints: row[first_joint..first_joint + skeleton.joint_count()].to_vec(),
        };
        let fk = Kinematics::of(skeleton, &pose);
        bvh_state.update(&bvh, bvh.frame(f).expect("frame"));
        for (j, joint) in skeleton.joints().iter().enumerate() {
            let b = bvh.joint_index(&joint.name).expect("joint in BVH");
            worst_joint_m =
                worst_joint_m.max((bvh_state.joint_position[b] - fk.joint_position[j]).length());
        }
        let recorded = DVec3::new(row[foot], row[foot + 1], row[foot + 2]);
        let target = DVec3::new(row[foot_target], row[foot_target + 1], row[foot_target + 2]);
        worst_effector_m =
            worst_effector_m.max((recorded - fk.effector_position[foot_index]).length());
        worst_error_m = worst_error_m.max((recorded - target).length());
    }
    assert!(
        worst_joint_m < 1e-6,
        "BVH vs CSV joint positions differ by {worst_joint_m} m"
    );
    assert!(
        worst_effector_m < 1e-9,
        "recorded foot vs FK of the recorded pose: {worst_effector_m} m (stale positions?)"
    );
    // The human runs §5.2.2's listing, whose running foot targets are out of
    // reach (She 2006 §5.3): DLS holds the foot 0.1 to 0.2 m from its target.
    assert!(
        (0.05..0.2).contains(&worst_error_m),
        "running, DLS keeps the foot near its unreachable target: {worst_error_m} m"
    );
    // One row per simulated frame, 1/60 s apart.
    assert!(
        times
            .windows(2)
            .all(|w| ((w[1] - w[0]) - 1.0 / 60.0).abs() < 1e-9)
    );
}

#[test]
fn saving_without_a_take_or_in_a_bad_format_says_why() {
    let mut lab = App::new(Settings::default());
    let error = lab
        .command(r#"{"save": "bvh"}"#)
        .expect_err("nothing recorded");
    assert!(error.starts_with("save: nothing recorded"), "{error}");
    lab.command(r#"{"record": true, "step": true}"#)
        .expect("record");
    lab.advance(0.0);
    let error = lab.command(r#"{"save": "avi"}"#).expect_err("bad format");
    assert!(error.contains("unknown format \"avi\""), "{error}");
    assert!(lab.take_download().is_none());
    let error = lab.command(r#"{"record": "yes"}"#).expect_err("bad flag");
    assert!(error.starts_with("record:"), "{error}");
}

#[test]
fn switching_preset_drops_the_take() {
    let mut lab = recorded_lab();
    lab.command(r#"{"preset": "ik-quadruped"}"#)
        .expect("preset");
    let s = state(&lab);
    assert_eq!(s["recording"]["frames"], 0);
    assert!(lab.command(r#"{"save": "csv"}"#).is_err());
}

#[test]
fn plotted_joints_follow_the_command_and_reject_unknown_names() {
    let mut lab = App::new(Settings::default());
    let s = state(&lab);
    assert_eq!(
        s["plot_joints"],
        serde_json::json!(["left_hip_flex", "left_knee", "right_hip_flex", "right_knee"])
    );
    lab.command(r#"{"plot_joints": ["neck", "left_elbow"]}"#)
        .expect("valid joints");
    assert_eq!(
        state(&lab)["plot_joints"],
        serde_json::json!(["neck", "left_elbow"])
    );
    let error = lab
        .command(r#"{"plot_joints": ["neck", "tail"]}"#)
        .expect_err("no tail");
    assert!(
        error.starts_with("plot_joints[1]:") && error.contains("tail"),
        "{error}"
    );
    assert_eq!(
        state(&lab)["plot_joints"],
        serde_json::json!(["neck", "left_elbow"])
    );
    let nine = serde_json::json!({ "plot_joints": vec!["neck"; 9] }).to_string();
    assert!(lab.command(&nine).is_err());
    // Another creature keeps the names it has, else plots its first joints.
    lab.command(r#"{"preset": "ik-quadruped"}"#)
        .expect("preset");
    let plotted = state(&lab)["plot_joints"].clone();
    let plotted = plotted.as_array().expect("array");
    assert!(!plotted.is_empty() && plotted.len() <= 4, "{plotted:?}");
    for name in plotted {
        let name = name.as_str().expect("name");
        assert!(
            lab.creature().skeleton.joint_index(name).is_some(),
            "{name}"
        );
    }
}

#[test]
fn video_commands_set_the_request_and_size() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"video_size": "p720", "record_video": true}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(s["video"]["recording"], true);
    assert_eq!(s["video"]["size"], "p720");
    // The web front end fills these in once a recorder runs.
    assert_eq!(s["video"]["encoder"], "");
    assert_eq!(s["video"]["frames"], 0);
    assert_eq!(s["video"]["skipped"], 0);
    assert_eq!(s["video"]["seconds"], 0.0);
    let error = lab
        .command(r#"{"video_size": "8k"}"#)
        .expect_err("unknown size");
    assert!(error.starts_with("video_size:"), "{error}");
}
