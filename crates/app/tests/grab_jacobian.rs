//! Grab and pull and the Jacobian panel through the JS API (issue 44):
//! `drag_target` moves a target in every figure on screen and the effector
//! follows; the one-iteration step (`iterate`) is the frame's iterations one
//! by one; `state().jacobian` carries each view's singular values and gains;
//! bad input names its field and changes nothing.

use gaitlab_app::{App, Settings};
use serde_json::{Value, json};

fn lab(preset: &str) -> App {
    let mut lab = App::new(Settings::default());
    if let Err(error) = lab.set_preset(preset) {
        panic!("{preset}: {error}");
    }
    lab.set_paused(true);
    lab
}

fn state(lab: &App) -> Value {
    match serde_json::from_str(&lab.state_json()) {
        Ok(value) => value,
        Err(error) => panic!("{error}"),
    }
}

fn command(lab: &mut App, c: &Value) {
    if let Err(error) = lab.command(&c.to_string()) {
        panic!("{c}: {error}");
    }
}

fn frames(lab: &mut App, n: usize) {
    for _ in 0..n {
        lab.single_step();
        lab.advance(0.0);
    }
}

fn effector<'a>(s: &'a Value, name: &str) -> &'a Value {
    match s["views"][0]["effectors"]
        .as_array()
        .and_then(|a| a.iter().find(|e| e["name"] == name))
    {
        Some(e) => e,
        None => panic!("no effector {name}"),
    }
}

fn point(v: &Value) -> [f64; 3] {
    let a = |k: usize| v[k].as_f64().unwrap_or(f64::NAN);
    [a(0), a(1), a(2)]
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[test]
fn a_dragged_target_moves_and_the_hand_follows_alone_and_side_by_side() {
    let mut lab = lab("she-2006");
    frames(&mut lab, 60);
    let s = state(&lab);
    let hand = effector(&s, "left_hand");
    // Grab where the hand is, then pull it 0.3 m toward the shoulder.
    let at = point(&hand["position_m"]);
    let anchor = point(&hand["reach_anchor_m"]);
    command(
        &mut lab,
        &json!({"drag_target": {"name": "left_hand", "position": at}}),
    );
    let length = distance(anchor, at);
    let to: [f64; 3] = std::array::from_fn(|k| at[k] + (anchor[k] - at[k]) * 0.3 / length);
    command(
        &mut lab,
        &json!({"drag_target": {"name": "left_hand", "position": to}}),
    );
    let s = state(&lab);
    let hand = effector(&s, "left_hand");
    assert_eq!(hand["held"], true);
    let moved = distance(point(&hand["target_m"]), at);
    assert!((moved - 0.3).abs() < 0.01, "target moved {moved} m");
    // Paused, the figure reaches for it over the next UI frames.
    let error = |lab: &App| {
        effector(&state(lab), "left_hand")["error_m"]
            .as_f64()
            .unwrap_or(f64::NAN)
    };
    let first = error(&lab);
    for _ in 0..30 {
        command(
            &mut lab,
            &json!({"drag_target": {"name": "left_hand", "position": to}}),
        );
    }
    let paused = error(&lab);
    // Running, the held target rides with the body; within a second SDLS has it.
    let mut frames_to_1cm = None;
    for frame in 1..=60 {
        frames(&mut lab, 1);
        if frames_to_1cm.is_none() && error(&lab) < 0.01 {
            frames_to_1cm = Some(frame);
        }
    }
    let s = state(&lab);
    let hand = effector(&s, "left_hand");
    assert!(
        hand["out_of_reach_m"].as_f64().unwrap_or(1.0) < 0.0,
        "{hand}"
    );
    println!(
        "left hand: {:.1} mm at the pull, {:.1} mm after 30 paused settles, under 1 cm after {frames_to_1cm:?} frames running, {:.1} mm at 1 s",
        first * 1e3,
        paused * 1e3,
        error(&lab) * 1e3
    );
    assert!(paused < first, "paused, it reaches");
    assert!(error(&lab) < 0.01, "{hand}");
    // Side by side: every view's target moves with the drag.
    command(
        &mut lab,
        &json!({"compare": {"views": ["transpose", "pinv", "dls", "sdls"]}}),
    );
    frames(&mut lab, 30);
    let to = [to[0], to[1], to[2] + 0.05];
    command(
        &mut lab,
        &json!({"drag_target": {"name": "left_hand", "position": to}}),
    );
    let Some(compare) = lab.comparison() else {
        panic!("a comparison")
    };
    let e = lab
        .creature()
        .skeleton
        .effector_index("left_hand")
        .unwrap_or(0);
    for view in compare.views() {
        let target = gaitlab_core::driver::Driver::targets(view.driver())
            .map(|t| t.position[e].to_array())
            .unwrap_or([f64::NAN; 3]);
        assert!(
            distance(target, to) < 1e-9,
            "{}: {target:?}",
            view.method.name()
        );
    }
}

#[test]
fn one_iteration_at_a_time_is_the_frame() {
    let mut whole = lab("she-2006");
    let mut stepped = lab("she-2006");
    frames(&mut whole, 21);
    frames(&mut stepped, 20);
    let of = stepped
        .driver()
        .thesis()
        .map_or(0, |d| d.params().iterations_per_frame);
    for k in 1..=of {
        command(&mut stepped, &json!({"iterate": true}));
        let s = state(&stepped);
        assert_eq!(
            s["jacobian"]["iterations"].as_array().map(Vec::len),
            Some(k),
            "the panel shows the frame's iterations so far"
        );
    }
    let (a, b) = (state(&whole), state(&stepped));
    assert_eq!(a["frame"], b["frame"]);
    assert_eq!(a["time_s"], b["time_s"]);
    let joints = |lab: &App| -> Vec<u64> {
        gaitlab_core::driver::Driver::pose(lab.driver())
            .joints
            .iter()
            .map(|x| x.to_bits())
            .collect()
    };
    assert_eq!(joints(&whole), joints(&stepped), "bit-identical");
    assert_eq!(a["views"][0]["metrics"], b["views"][0]["metrics"]);
    assert_eq!(a["jacobian"], b["jacobian"]);
    // Each iteration's error after is the next one's before.
    let iterations = b["jacobian"]["iterations"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    for pair in iterations.windows(2) {
        assert_eq!(pair[0]["error_after_m"], pair[1]["error_before_m"]);
    }
}

#[test]
fn the_state_carries_each_views_singular_values_and_gains() {
    let mut lab = lab("she-2006");
    command(
        &mut lab,
        &json!({"compare": {"views": ["pinv", "dls"], "scenario": "singularity"}}),
    );
    frames(&mut lab, 90);
    let s = state(&lab);
    let views = s["jacobian"]["views"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    assert_eq!(views.len(), 2);
    for (view, law) in views.iter().zip(["pinv", "dls"]) {
        assert_eq!(view["law"]["law"], law);
        let sigma: Vec<f64> = view["sigma"]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default();
        let formula: Vec<f64> = view["formula_gain"]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default();
        let actual: Vec<Option<f64>> = view["actual_gain"]
            .as_array()
            .map(|a| a.iter().map(Value::as_f64).collect())
            .unwrap_or_default();
        assert!(sigma.len() >= 3 && sigma.len() == formula.len(), "{view}");
        assert_eq!(actual.len(), sigma.len());
        assert!(sigma.windows(2).all(|w| w[0] >= w[1]), "largest first");
        let measured = actual.iter().flatten().count();
        assert!(
            measured * 2 >= actual.len(),
            "most directions measured: {view}"
        );
        if law == "dls" {
            let lambda = view["law"]["lambda"].as_f64().unwrap_or(f64::NAN);
            for (s, g) in sigma.iter().zip(&formula) {
                let expected = s / (s * s + lambda * lambda);
                assert!(
                    (g - expected).abs() <= 1e-12 * expected,
                    "{g} against {expected}"
                );
            }
        }
        let ratios: Vec<String> = actual
            .iter()
            .zip(&formula)
            .map(|(a, f)| a.map_or("—".to_owned(), |a| format!("{:.2}", a / f)))
            .collect();
        println!(
            "{law}: σ {:.4} … {:.4}, condition {}, actual/formula per direction {}",
            sigma[0],
            sigma[sigma.len() - 1],
            view["condition"],
            ratios.join(" ")
        );
    }
}

#[test]
fn bad_drags_name_their_field_and_change_nothing() {
    let mut lab = lab("she-2006");
    frames(&mut lab, 5);
    let before = state(&lab)["views"][0]["effectors"].clone();
    for (c, field) in [
        (
            json!({"drag_target": {"name": "tail", "position": [0, 1, 0]}}),
            "drag_target.name",
        ),
        (
            json!({"drag_target": {"name": "left_hand", "position": [0, 1e6, 0]}}),
            "drag_target.position",
        ),
        (
            json!({"drag_target": {"name": "left_hand", "position": [0, 1]}}),
            "drag_target.position",
        ),
        (
            json!({"drag_target": {"name": "left_hand", "where": 1}}),
            "drag_target",
        ),
    ] {
        let error = lab.command(&c.to_string()).err().unwrap_or_default();
        assert!(error.starts_with(field), "{c}: {error}");
    }
    assert_eq!(state(&lab)["views"][0]["effectors"], before);
    let mut physics = self::lab("raibert-biped");
    let error = physics
        .command(&json!({"drag_target": {"name": "foot", "position": null}}).to_string())
        .err()
        .unwrap_or_default();
    assert!(error.starts_with("drag_target"), "{error}");
    let error = physics
        .command(&json!({"iterate": true}).to_string())
        .err()
        .unwrap_or_default();
    assert!(error.starts_with("iterate"), "{error}");
}

#[test]
fn pinned_targets_ride_in_links_and_bad_pins_change_nothing() {
    let mut lab = lab("she-2006");
    frames(&mut lab, 30);
    let s = state(&lab);
    let at = point(&effector(&s, "right_foot")["position_m"]);
    let to = [at[0], at[1] + 0.15, at[2] + 0.1];
    command(
        &mut lab,
        &json!({"drag_target": {"name": "right_foot", "position": to, "pin": true}}),
    );
    command(
        &mut lab,
        &json!({"drag_target": {"name": "right_foot", "position": null}}),
    );
    let pins = state(&lab)["pinned_targets"].clone();
    assert_eq!(pins.as_object().map(|m| m.len()), Some(1), "{pins}");
    let link = lab.full_link();
    assert_eq!(link.state.get("pinned_targets"), Some(&pins));
    let mut opened = App::new(Settings::default());
    let errors = opened.apply_full_link(&link);
    assert!(errors.is_empty(), "{errors:?}");
    let s = state(&opened);
    assert_eq!(s["pinned_targets"], pins);
    let foot = effector(&s, "right_foot");
    assert_eq!(foot["pinned"], true);
    // Where the link says, relative to the restored root.
    let body = point(&pins["right_foot"]);
    let root = gaitlab_core::driver::Driver::pose(opened.driver()).root;
    let world = root.position + root.rotation * glam::DVec3::from_array(body);
    assert!(distance(point(&foot["target_m"]), world.to_array()) < 1e-9);
    // Bad pins name their field and leave the pins as they were.
    for (c, field) in [
        (
            json!({"pinned_targets": {"tail": [0, 0, 0]}}),
            "pinned_targets.tail",
        ),
        (
            json!({"pinned_targets": {"left_hand": [0, 500, 0]}}),
            "pinned_targets.left_hand",
        ),
    ] {
        let error = opened.command(&c.to_string()).err().unwrap_or_default();
        assert!(error.starts_with(field), "{c}: {error}");
        assert_eq!(state(&opened)["pinned_targets"], pins);
    }
    command(&mut opened, &json!({"pinned_targets": {}}));
    assert_eq!(state(&opened)["pinned_targets"], json!({}));
}

/// A lesson starts from a pinned pose (issue 44 item 5): the right foot's
/// target pinned 0.1 m beyond its leg's reach, the reach shells and
/// ellipsoids on and the Jacobian panel named; the link brings all of it
/// back, and playing, the leg straightens toward the target and its
/// ellipsoid flattens to a disc (σ₃ of the foot's limb falls). The
/// she-2006 hands are no example: their targets lie beyond reach by design
/// and the trunk follows them, so their arms are straight (σ₃ ≈ 0) all along.
#[test]
fn a_lesson_link_starts_from_a_pinned_pose_and_the_leg_flattens() {
    let mut lab = lab("she-2006");
    command(&mut lab, &json!({"method": "dls"}));
    frames(&mut lab, 10);
    let s = state(&lab);
    let sigma = |s: &Value, name: &str, i: usize| {
        effector(s, name)["manipulability_m_per_rad"][i]
            .as_f64()
            .unwrap_or(f64::NAN)
    };
    let bent = sigma(&s, "right_foot", 2);
    let hand = sigma(&s, "right_hand", 2);
    let foot = effector(&s, "right_foot");
    let anchor = point(&foot["reach_anchor_m"]);
    let at = point(&foot["position_m"]);
    let out = distance(at, anchor);
    let leg_m = 0.987;
    let to: Vec<f64> = (0..3)
        .map(|k| anchor[k] + (at[k] - anchor[k]) / out * (leg_m + 0.1))
        .collect();
    command(
        &mut lab,
        &json!({"drag_target": {"name": "right_foot", "position": to, "pin": true}}),
    );
    command(
        &mut lab,
        &json!({"drag_target": {"name": "right_foot", "position": null},
                "views": {"reach_shells": true, "ellipsoids": true},
                "lesson": {"note": "Drag the right foot past its reach and watch σ₃.",
                           "open_panels": ["Jacobian"], "pin_plots": ["errors"]}}),
    );
    let link = lab.full_link();
    let mut opened = App::new(Settings::default());
    let errors = opened.apply_full_link(&link);
    assert!(errors.is_empty(), "{errors:?}");
    let s = state(&opened);
    assert_eq!(s["lesson"]["open_panels"], json!(["Jacobian"]));
    assert_eq!(s["view_options"]["reach_shells"], true);
    assert_eq!(s["view_options"]["ellipsoids"], true);
    assert_eq!(effector(&s, "right_foot")["pinned"], true);
    frames(&mut opened, 60);
    let s = state(&opened);
    let foot = effector(&s, "right_foot");
    assert!(
        foot["out_of_reach_m"].as_f64().is_some_and(|d| d > 0.05),
        "{foot}"
    );
    let stretched = sigma(&s, "right_foot", 2);
    eprintln!(
        "right foot σ₃ {bent:.4} → {stretched:.4} m/rad pinned beyond reach (σ₁ {:.3}); right hand σ₃ {hand:.5}",
        sigma(&s, "right_foot", 0)
    );
    assert!(bent > 0.05, "the walking leg is bent: σ₃ {bent}");
    assert!(
        stretched < 0.25 * bent,
        "σ₃ {bent} → {stretched}: the leg straightens toward the target"
    );
    assert!(hand < 0.01, "the she-2006 arm is straight: σ₃ {hand}");
}

/// The hand following a pinned target on a reachable spot (issue 44's
/// acceptance, "error under 1 cm within 1 s for SDLS"), on the she-2006
/// walk at 60 frames a second: the left hand's target pinned 0.35 m and
/// 0.45 m from the shoulder along the arm. With joint limits off SDLS is
/// within 1 cm inside a second and stays within 5 mm for 2 s; under She
/// 2006's own limit rule (clamp after each iteration, §6.1.1.1), and with
/// the lab's re-solve (`limit_passes: 4`), clamped joints lose the target
/// again for part of each step — a finding, printed, not asserted.
#[test]
fn a_pinned_reachable_target_is_followed_and_the_paper_clamp_loses_it() {
    for (label, extra) in [
        ("paper's clamp", json!({"method": "sdls"})),
        (
            "limits off",
            json!({"method": "sdls", "enforce_limits": false}),
        ),
        (
            "lab's re-solve",
            json!({"method": "sdls", "limit_passes": 4}),
        ),
    ] {
        for from_shoulder_m in [0.35, 0.45] {
            let mut lab = lab("she-2006");
            command(&mut lab, &extra);
            frames(&mut lab, 30);
            let s = state(&lab);
            let hand = effector(&s, "left_hand");
            let anchor = point(&hand["reach_anchor_m"]);
            let at = point(&hand["position_m"]);
            let out = distance(at, anchor);
            let to: Vec<f64> = (0..3)
                .map(|k| anchor[k] + (at[k] - anchor[k]) / out * from_shoulder_m)
                .collect();
            command(
                &mut lab,
                &json!({"drag_target": {"name": "left_hand", "position": to, "pin": true}}),
            );
            command(
                &mut lab,
                &json!({"drag_target": {"name": "left_hand", "position": null}}),
            );
            let mut reached = None;
            let mut worst_after = 0.0_f64;
            let mut deepest = 0.0_f64;
            for k in 1..=120 {
                frames(&mut lab, 1);
                let s = state(&lab);
                let hand = effector(&s, "left_hand");
                let error = hand["error_m"].as_f64().unwrap_or(f64::NAN);
                deepest = deepest.min(hand["out_of_reach_m"].as_f64().unwrap_or(f64::NAN));
                match reached {
                    None if error < 0.01 => reached = Some(k),
                    Some(_) => worst_after = worst_after.max(error),
                    None => {}
                }
            }
            eprintln!(
                "{label}, {from_shoulder_m} m from the shoulder: within 1 cm after {} frames, \
                 then at most {:.1} mm over 2 s (target {:.0} mm inside the reach at most)",
                reached.map_or("—".to_owned(), |k| k.to_string()),
                worst_after * 1e3,
                -deepest * 1e3
            );
            if label == "limits off" {
                assert!(
                    reached.is_some_and(|k| k <= 60),
                    "{label} {from_shoulder_m}: reached after {reached:?} frames"
                );
                assert!(
                    worst_after < 0.005,
                    "{label} {from_shoulder_m}: lost by {worst_after} m"
                );
            }
        }
    }
}
