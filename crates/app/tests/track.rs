//! Following a target CSV in the lab (issue 21 item 5): a recording loaded
//! as a file replaces the figure's motion and is followed by the chosen
//! method, or by four methods side by side; a bad file names its line and
//! leaves the figure as it was; stopping (or another preset) brings the
//! creature's own motion back.

use gaitlab_app::{App, Settings};
use gaitlab_core::Kinematics;
use gaitlab_core::driver::Driver;
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).unwrap_or_default()
}

fn command(lab: &mut App, json: &str) {
    if let Err(error) = lab.command(json) {
        panic!("{json}: {error}");
    }
}

/// Two seconds at 30 rows a second: each effector's rest position, the feet
/// lifted and the hands swung by up to 5 cm. The rest pose's, not the
/// figure's first frame's: a followed recording holds the root where the
/// rest pose has it, and the human's first frame is already on §5.2.2's
/// listing, with its root 8 cm lower.
fn recording(lab: &App) -> String {
    let creature = lab.creature();
    let rest = Kinematics::of(&creature.skeleton, &creature.rest_pose()).effector_position;
    let mut csv = String::from("t");
    for e in 0..rest.len() {
        csv.push_str(&format!(",e{e}_x,e{e}_y,e{e}_z"));
    }
    csv.push('\n');
    for row in 0..=60 {
        let t = f64::from(row) / 30.0;
        csv.push_str(&format!("{t}"));
        for (e, p) in rest.iter().enumerate() {
            let swing = 0.05 * (std::f64::consts::TAU * t + e as f64).sin();
            csv.push_str(&format!(
                ",{},{},{}",
                p.x,
                p.y + swing.abs() * 0.5,
                p.z + swing
            ));
        }
        csv.push('\n');
    }
    csv
}

fn run(lab: &mut App, frames: usize) {
    lab.set_paused(true);
    for _ in 0..frames {
        lab.single_step();
        lab.advance(0.0);
    }
}

#[test]
fn a_dropped_recording_is_followed_alone_and_side_by_side() {
    let mut lab = App::new(Settings::default());
    let csv = recording(&lab);
    if let Err(error) = lab.load_file("swing.csv", csv.as_bytes()) {
        panic!("{error}");
    }
    let s = state(&lab);
    assert_eq!(s["track"]["file"], "swing.csv");
    assert_eq!(s["track"]["rows"], 61);
    assert_eq!(s["track"]["effectors"], 4);
    assert!((s["track"]["duration_s"].as_f64().unwrap_or(0.0) - 2.0).abs() < 1e-9);
    assert!(lab.driver().track().is_some());

    // Followed: after 1.5 s every effector is within 2 cm of its target.
    run(&mut lab, 90);
    let Some(report) = lab.driver().ik_report() else {
        panic!("an IK report")
    };
    assert!(
        report.effector_error_m.iter().all(|&e| e < 0.02),
        "{:?}",
        report.effector_error_m
    );
    let Some(targets) = lab.driver().targets() else {
        panic!("targets")
    };
    // The target is the recording's at t = 1.5 s (row 45), exactly.
    let row45: Vec<f64> = csv
        .lines()
        .nth(46)
        .unwrap_or_default()
        .split(',')
        .filter_map(|v| v.parse().ok())
        .collect();
    assert!(
        (targets.position[0].z - row45[3]).abs() < 1e-9,
        "{} vs {}",
        targets.position[0].z,
        row45[3]
    );

    // Side by side: four methods on the same recording.
    command(
        &mut lab,
        r#"{"compare": {"views": ["transpose", "pinv", "dls", "sdls"]}}"#,
    );
    run(&mut lab, 60);
    let s = state(&lab);
    let metrics = s["compare"]["metrics"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    assert_eq!(metrics.len(), 4);
    for m in &metrics {
        assert_eq!(m["frame"], 60);
        assert!(m["mean_error_m"].as_f64().unwrap_or(1.0) < 0.05, "{m}");
    }
    let notice = s["compare"]["notice"][0].as_str().unwrap_or_default();
    assert!(notice.contains("recording"), "{notice}");
    let Some(compare) = lab.comparison() else {
        panic!("comparing")
    };
    assert!(compare.recorded());

    // Stopping brings the thesis motion back (the comparison with it).
    command(&mut lab, r#"{"track": false}"#);
    assert_eq!(state(&lab)["track"], Value::Null);
    assert!(lab.driver().thesis().is_some());
    assert!(lab.comparison().is_some_and(|c| !c.recorded()));
}

#[test]
fn a_bad_recording_names_its_line_and_leaves_the_figure() {
    let mut lab = App::new(Settings::default());
    for (name, text, want) in [
        (
            "short.csv",
            "t,x,y,z\n0,1,2,3\n".to_owned(),
            "file short.csv: ",
        ),
        (
            "nan.csv",
            format!(
                "t{}\n0{}\n1{}\n",
                ",a".repeat(12),
                ",0".repeat(12),
                ",x".repeat(12)
            ),
            "file nan.csv: line 3",
        ),
        (
            "bin.csv",
            String::from_utf8_lossy(&[0xff, 0xfe]).into_owned(),
            "file bin.csv",
        ),
    ] {
        let error = lab
            .load_file(name, text.as_bytes())
            .err()
            .unwrap_or_default();
        assert!(error.starts_with(want), "{name}: {error}");
        assert!(lab.driver().thesis().is_some(), "{name}: the figure stays");
        assert_eq!(state(&lab)["track"], Value::Null);
    }
    assert!(lab.command(r#"{"track": true}"#).is_err());
    // Another preset ends the recording.
    let csv = recording(&lab);
    if let Err(error) = lab.load_file("swing.CSV", csv.as_bytes()) {
        panic!("{error}");
    }
    if let Err(error) = lab.set_preset("she-2006") {
        panic!("{error}");
    }
    assert_eq!(state(&lab)["track"], Value::Null);
    assert_eq!(lab.driver().time(), 0.0);
}
