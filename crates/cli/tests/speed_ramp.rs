//! Issue 19's speed ramp with gait by speed (`tools/poda_speed_ramp.py`,
//! docs/poda.md "Gait by speed"): the PODA quadruped raised from 0.2 to
//! 5 m/s by `--edit T:speed_mps=V` walks, trots and gallops, the gait
//! changing where the Froude number v²/(g·h) passes 0.5 and 2.5, with no
//! planted foot slipping more than 1 mm.

mod common;

use common::run_json;

#[test]
fn a_speed_ramp_walks_trots_and_gallops_without_slipping() {
    // One edit every half second over 20 s (the tool's ramp edits every 0.25 s).
    let edits: Vec<String> = (0..=40)
        .map(|k| {
            let t = f64::from(k) * 0.5;
            let v = 0.2 + 4.8 * f64::from(k) / 40.0;
            format!("{t}:speed_mps={v}")
        })
        .collect();
    let mut args = vec!["--set", "scenario.poda.gait_by_speed=true"];
    for edit in &edits {
        args.extend(["--edit", edit.as_str()]);
    }
    let metrics = run_json("poda-quadruped", "24", &args);
    let changes = metrics["changes"].as_array().expect("changes");
    assert_eq!(changes.len(), edits.len(), "{metrics}");
    let mut gaits: Vec<(&str, f64)> = Vec::new();
    for change in changes {
        assert!(change["refused"].is_null(), "{change}");
        let gait = change["gait"].as_str().expect("a PODA gait");
        let speed: f64 = change["change"]
            .as_str()
            .and_then(|c| c.split('=').nth(1))
            .and_then(|v| v.parse().ok())
            .expect("speed");
        if gaits.last().is_none_or(|(last, _)| *last != gait) {
            gaits.push((gait, speed));
        }
    }
    let names: Vec<&str> = gaits.iter().map(|(g, _)| *g).collect();
    assert_eq!(names, ["walk", "trot", "rotary_gallop"], "{gaits:?}");
    // Fr = 0.5 at √(0.5·9.81·0.5) = 1.566 m/s, Fr = 2.5 at 3.502 m/s; the
    // ramp's edits are 0.12 m/s apart.
    assert!((1.566..1.566 + 0.121).contains(&gaits[1].1), "{gaits:?}");
    assert!((3.502..3.502 + 0.121).contains(&gaits[2].1), "{gaits:?}");
    let slip = metrics["foot_slip_max_m"].as_f64().expect("slip");
    assert!(slip <= 0.001, "slip {} mm", slip * 1e3);
    assert_eq!(metrics["speed_mps_set"].as_f64(), Some(5.0), "{metrics}");
}
