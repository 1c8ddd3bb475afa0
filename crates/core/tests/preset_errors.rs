//! Bad presets are rejected with the JSON path of the offending value and a
//! reason a person can act on (DESIGN.md input limits), and no input panics.

use gaitlab_core::preset::{self, Preset, PresetError};
use serde_json::{Value, json};

fn human_json() -> &'static str {
    preset::bundled_json("human").expect("human is bundled")
}

/// The human preset as a JSON value, changed by `change`, as text.
fn human_with(change: impl FnOnce(&mut Value)) -> String {
    let mut value: Value = serde_json::from_str(human_json()).expect("human.json is JSON");
    change(&mut value);
    serde_json::to_string_pretty(&value).expect("serialises")
}

fn at<'a>(value: &'a mut Value, pointer: &str) -> &'a mut Value {
    value
        .pointer_mut(pointer)
        .unwrap_or_else(|| panic!("{pointer} exists"))
}

fn set(pointer: &'static str, new: Value) -> impl FnOnce(&mut Value) {
    move |value| *at(value, pointer) = new
}

/// Asserts that `json` is rejected at exactly `path` with a reason containing `reason`.
#[track_caller]
fn assert_rejected(json: &str, path: &str, reason: &str) -> PresetError {
    let error = match Preset::from_json(json) {
        Ok(_) => panic!("accepted, expected `{path}: …{reason}…`"),
        Err(error) => error,
    };
    assert_eq!(error.path, path, "path of `{error}`");
    assert!(
        error.reason.contains(reason),
        "reason of `{error}` should contain {reason:?}"
    );
    assert_eq!(
        error.to_string(),
        format!("{}: {}", error.path, error.reason)
    );
    error
}

/// A chain of `count` small joints (each on the previous) with one effector.
fn chain_preset(count: usize) -> String {
    let joints: Vec<Value> = (0..count)
        .map(|i| {
            let parent = if i == 0 { Value::Null } else { json!(format!("j{}", i - 1)) };
            json!({"name": format!("j{i}"), "parent": parent, "axis": [1, 0, 0], "offset": [0, 0.01, 0]})
        })
        .collect();
    json!({
        "format": "gaitlab-preset/1",
        "name": "chain",
        "skeleton": {"root": {"position": [0, 0, 0]}, "joints": joints,
                     "effectors": [{"name": "tip", "joint": format!("j{}", count - 1)}]},
        "scenario": {"engine": "ik"}
    })
    .to_string()
}

#[test]
fn the_untouched_human_is_accepted() {
    Preset::from_json(&human_with(|_| {})).expect("a re-serialised human.json is still valid");
}

#[test]
fn malformed_json_names_the_path_reached_and_the_line() {
    let error = assert_rejected(
        "{\"format\": \"gaitlab-preset/1\", \"name\": }",
        "name",
        "expected value at line 1 column",
    );
    assert!(error.reason.contains("column 40"), "{error}");
    assert_rejected("", "$", "EOF while parsing a value at line 1 column 0");
    assert_rejected("\"a preset\"", "$", "a preset must be a JSON object");
    assert_rejected("[1, 2]", "$", "a preset must be a JSON object");
    assert_rejected(
        &format!("{} {{}}", human_json()),
        "$",
        "trailing characters at line",
    );
}

#[test]
fn a_truncated_file_names_where_it_stopped() {
    let text = human_json();
    let cut = text.find("\"left_knee\", \"parent\"").expect("marker") + 5;
    assert_rejected(
        &text[..cut],
        "skeleton.joints[2].name",
        "EOF while parsing a string at line 10",
    );
    assert_rejected(&text[..text.len() - 3], "$", "EOF while parsing an object");
}

#[test]
fn a_preset_over_256_kib_is_rejected_before_parsing() {
    let padded =
        human_with(|v| *at(v, "/description") = json!("x".repeat(preset::MAX_PRESET_BYTES)));
    let error = assert_rejected(&padded, "$", "more than the limit of 262144 bytes");
    assert!(error.reason.contains(&padded.len().to_string()));
    // Even text that is not JSON at all is refused on size alone.
    assert_rejected(
        &"{".repeat(preset::MAX_PRESET_BYTES + 1),
        "$",
        "262145 bytes",
    );
    // Exactly at the limit the size is fine (the padding is then a JSON matter).
    let body = human_with(|v| *at(v, "/description") = json!(""));
    let exact = format!(
        "{body}{}",
        " ".repeat(preset::MAX_PRESET_BYTES - body.len())
    );
    Preset::from_json(&exact).expect("256 KiB exactly is accepted");
}

#[test]
fn non_finite_numbers_are_path_errors() {
    let text = human_json();
    let nan = text.replacen("\"rest\": 0.2", "\"rest\": NaN", 1);
    assert_rejected(
        &nan,
        "skeleton.joints[2].rest",
        "NaN and Infinity are not JSON numbers",
    );
    let huge = text.replacen("\"rest\": 0.2", "\"rest\": 1e999", 1);
    assert_rejected(
        &huge,
        "skeleton.joints[2].rest",
        "number out of range at line",
    );
    let inf_axis = text.replacen("\"axis\": [0, 0, 1]", "\"axis\": [0, 0, -1e400]", 1);
    assert_rejected(
        &inf_axis,
        "skeleton.joints[1].axis[2]",
        "number out of range",
    );
    let infinity = text.replacen("[0, 0.98, 0]", "[0, Infinity, 0]", 1);
    assert_rejected(
        &infinity,
        "skeleton.root.position[1]",
        "every number must be finite",
    );
}

#[test]
fn a_zero_axis_names_the_joint_axis() {
    let json = human_with(set("/skeleton/joints/3/axis", json!([0, 0, 0])));
    let error = assert_rejected(
        &json,
        "skeleton.joints[3].axis",
        "must be a non-zero vector",
    );
    assert_eq!(
        error.to_string(),
        "skeleton.joints[3].axis: must be a non-zero vector"
    );
    // Axes need not be unit: tiny and huge ones are normalised.
    let tiny = human_with(set("/skeleton/joints/3/axis", json!([1e-200, 0, 0])));
    let creature = gaitlab_core::preset::Creature::from_json(&tiny).expect("tiny axis is fine");
    assert!((creature.skeleton.joints()[3].axis - glam::DVec3::X).length() < 1e-15);
    let huge = human_with(set("/skeleton/joints/3/axis", json!([0, 3e200, 4e200])));
    let creature = gaitlab_core::preset::Creature::from_json(&huge).expect("huge axis is fine");
    assert!(
        (creature.skeleton.joints()[3].axis - glam::DVec3::new(0.0, 0.6, 0.8)).length() < 1e-15
    );
    let short = human_with(set("/skeleton/joints/3/axis", json!([1, 0])));
    assert_rejected(
        &short,
        "skeleton.joints[3].axis",
        "invalid length 2, expected a sequence of 3",
    );
}

#[test]
fn ten_thousand_joints_are_rejected() {
    let huge = chain_preset(10_000);
    assert!(
        huge.len() > preset::MAX_PRESET_BYTES,
        "10 000 joints do not fit in 256 KiB"
    );
    assert_rejected(&huge, "$", "more than the limit of 262144 bytes");
    let many = chain_preset(600);
    assert!(many.len() < preset::MAX_PRESET_BYTES);
    assert_rejected(
        &many,
        "skeleton.joints",
        "600 joints is more than the limit of 512",
    );
    assert_rejected(
        &chain_preset(513),
        "skeleton.joints",
        "513 joints is more than the limit of 512",
    );
    let creature = gaitlab_core::preset::Creature::from_json(&chain_preset(512))
        .expect("512 joints is the limit");
    assert_eq!(creature.skeleton.joint_count(), 512);
}

#[test]
fn more_than_32_effectors_are_rejected() {
    let json = human_with(|v| {
        let effectors: Vec<Value> = (0..33)
            .map(|i| json!({"name": format!("e{i}"), "joint": "neck"}))
            .collect();
        *at(v, "/skeleton/effectors") = Value::Array(effectors);
    });
    assert_rejected(
        &json,
        "skeleton.effectors",
        "33 effectors is more than the limit of 32",
    );
    let none = human_with(set("/skeleton/joints", json!([])));
    assert_rejected(&none, "skeleton.joints", "at least one joint");
}

#[test]
fn parent_cycles_are_found_wherever_they_are_listed() {
    let json = human_with(|v| {
        *at(v, "/skeleton/joints/8/parent") = json!("thorax_twist"); // lumbar_flex under its own grandchild
    });
    let error = assert_rejected(&json, "skeleton.joints[8].parent", "parents form a cycle");
    assert!(
        error
            .reason
            .contains(r#""lumbar_flex" → "thorax_twist" → "lumbar_bend" → "lumbar_flex""#),
        "{error}"
    );
    let own = human_with(set("/skeleton/joints/19/parent", json!("neck")));
    assert_rejected(
        &own,
        "skeleton.joints[19].parent",
        r#""neck" is its own parent"#,
    );
    // A joint hanging off a cycle is not blamed: the cycle member listed first is.
    let hanging = human_with(|v| {
        *at(v, "/skeleton/joints/0/parent") = json!("left_knee");
    });
    assert_rejected(&hanging, "skeleton.joints[0].parent", "cycle");
}

#[test]
fn unknown_parents_and_effector_joints_are_named() {
    let json = human_with(set("/skeleton/joints/2/parent", json!("left_hip")));
    assert_rejected(
        &json,
        "skeleton.joints[2].parent",
        r#"no joint named "left_hip""#,
    );
    let json = human_with(set("/skeleton/effectors/1/joint", json!("right_toe")));
    assert_rejected(
        &json,
        "skeleton.effectors[1].joint",
        r#"no joint named "right_toe""#,
    );
}

#[test]
fn duplicate_names_point_at_the_second_occurrence() {
    let json = human_with(set("/skeleton/joints/6/name", json!("left_knee")));
    assert_rejected(
        &json,
        "skeleton.joints[6].name",
        r#"duplicate joint name "left_knee" (first at skeleton.joints[2].name)"#,
    );
    let json = human_with(set("/skeleton/effectors/3/name", json!("left_hand")));
    assert_rejected(
        &json,
        "skeleton.effectors[3].name",
        r#"duplicate effector name "left_hand""#,
    );
    let json = human_with(set("/skeleton/joints/6/name", json!("right knee")));
    assert_rejected(&json, "skeleton.joints[6].name", "must not contain spaces");
    let json = human_with(set("/name", json!("")));
    assert_rejected(&json, "name", "must not be empty");
}

#[test]
fn limits_must_be_ordered_and_hold_rest_and_center() {
    let json = human_with(set("/skeleton/joints/2/limits", json!([2.4, 0.0])));
    assert_rejected(
        &json,
        "skeleton.joints[2].limits",
        "minimum 2.4 is greater than maximum 0",
    );
    let json = human_with(set("/skeleton/joints/2/rest", json!(3.0)));
    assert_rejected(
        &json,
        "skeleton.joints[2].rest",
        "3 is outside the limits [0, 2.4]",
    );
    let json = human_with(set("/skeleton/joints/2/center", json!(-0.5)));
    assert_rejected(
        &json,
        "skeleton.joints[2].center",
        "-0.5 is outside the limits [0, 2.4]",
    );
    let json = human_with(set("/skeleton/joints/2/limits", json!([-10, 10])));
    assert_rejected(&json, "skeleton.joints[2].limits", "wider than two turns");
    // Without an explicit center, the center is the rest value and must be inside too.
    let json = human_with(|v| {
        at(v, "/skeleton/joints/2")
            .as_object_mut()
            .expect("object")
            .remove("center");
        *at(v, "/skeleton/joints/2/rest") = json!(2.5);
    });
    assert_rejected(&json, "skeleton.joints[2].rest", "outside the limits");
}

#[test]
fn gains_sizes_and_frames_are_checked() {
    let json = human_with(set("/skeleton/joints/4/gain", json!(1.5)));
    assert_rejected(&json, "skeleton.joints[4].gain", "between 0 and 1");
    let json = human_with(set("/skeleton/joints/4/size", json!(0)));
    assert_rejected(&json, "skeleton.joints[4].size", "positive");
    let json = human_with(|v| {
        at(v, "/skeleton/joints/4")
            .as_object_mut()
            .expect("object")
            .insert("frame_rotation".into(), json!([0, 90, 0]));
    });
    assert_rejected(
        &json,
        "skeleton.joints[4].frame_rotation",
        "angles are in radians",
    );
}

#[test]
fn unknown_missing_and_mistyped_fields_are_named() {
    let json = human_with(|v| {
        at(v, "/skeleton/joints/5")
            .as_object_mut()
            .expect("object")
            .insert("stiffness".into(), json!(3));
    });
    assert_rejected(
        &json,
        "skeleton.joints[5].stiffness",
        "unknown field `stiffness`, expected one of",
    );
    let json = human_with(|v| {
        at(v, "/skeleton/joints/5")
            .as_object_mut()
            .expect("object")
            .remove("axis");
    });
    assert_rejected(&json, "skeleton.joints[5].axis", "missing field `axis`");
    let json = human_with(set("/skeleton/joints/5/rest", json!("bent")));
    assert_rejected(
        &json,
        "skeleton.joints[5].rest",
        r#"invalid type: string "bent", expected f64"#,
    );
    let json = human_with(set("/skeleton/joints/5/type", json!("spherical")));
    assert_rejected(
        &json,
        "skeleton.joints[5].type",
        "unknown variant `spherical`, expected `revolute` or `prismatic`",
    );
    let json = human_with(|v| {
        at(v, "")
            .as_object_mut()
            .expect("object")
            .insert("physics".into(), json!({}));
    });
    assert_rejected(&json, "physics", "unknown field `physics`");
    let json = human_with(set("/format", json!("gaitlab-preset/3")));
    assert_rejected(
        &json,
        "format",
        "unknown variant `gaitlab-preset/3`, expected `gaitlab-preset/1` or `gaitlab-preset/2`",
    );
    let json = human_with(set("/scenario/engine", json!("quantum")));
    assert_rejected(
        &json,
        "scenario.engine",
        "unknown variant `quantum`, expected one of `ik`, `poda`, `physics`",
    );
    // Engine physics without its model, and a physics section on engine ik.
    let json = human_with(set("/scenario/engine", json!("physics")));
    assert_rejected(
        &json,
        "scenario.physics",
        "engine \"physics\" needs the creature's physical model",
    );
    let json = human_with(set("/scenario/mode", json!("jog")));
    assert_rejected(&json, "scenario.mode", "unknown variant `jog`");
    let json = human_with(set("/scenario/method", json!("newton")));
    assert_rejected(&json, "scenario.method", "unknown variant `newton`");
    let json = human_with(|v| {
        at(v, "/scenario/thesis")
            .as_object_mut()
            .expect("object")
            .insert("walk".into(), json!({"frequency": 1.0}));
    });
    assert_rejected(
        &json,
        "scenario.thesis.walk.frequency",
        "unknown field `frequency`",
    );
}

#[test]
fn ik_options_are_range_checked() {
    for (field, value, reason) in [
        ("lambda", json!(0.0), "(0, 10]"),
        ("lambda", json!(11.0), "(0, 10]"),
        ("gamma_max", json!(4.0), "(0, π]"),
        ("max_step", json!(0.0), "(0, π]"),
        ("rank_tolerance", json!(1.0), "(0, 1)"),
        ("null_space_gain", json!(-0.1), "between 0 and 10"),
        ("limit_passes", json!(0), "between 1 and 16"),
        ("limit_passes", json!(17), "between 1 and 16"),
    ] {
        let json = human_with(|v| {
            at(v, "/scenario")
                .as_object_mut()
                .expect("object")
                .insert("ik".into(), json!({field: value}));
        });
        assert_rejected(&json, &format!("scenario.ik.{field}"), reason);
    }
    let json = human_with(|v| {
        at(v, "/scenario")
            .as_object_mut()
            .expect("object")
            .insert("ik".into(), json!({"method": "dls"}));
    });
    assert_rejected(
        &json,
        "scenario.ik.method",
        "set the method with scenario.method",
    );
    let json = human_with(|v| {
        at(v, "/scenario")
            .as_object_mut()
            .expect("object")
            .insert("ik".into(), json!({"lambda": 0.2}));
        *at(v, "/scenario/method") = json!("dls");
    });
    let parsed = Preset::from_json(&json).expect("valid ik section");
    assert_eq!(parsed.scenario.ik.lambda, 0.2);
    assert_eq!(parsed.scenario.ik.method, gaitlab_core::ik::Method::Dls);
    let json = human_with(set("/scenario/fps", json!(0)));
    assert_rejected(&json, "scenario.fps", "between 1 and 1000");
}

#[test]
fn thesis_parameters_are_range_checked() {
    for (pointer, value, path, reason) in [
        (
            "/scenario/thesis/walk",
            json!({"frequency_hz": 0.0}),
            "scenario.thesis.walk.frequency_hz",
            "(0, 10] Hz",
        ),
        (
            "/scenario/thesis/run",
            json!({"frequency_hz": 12.0}),
            "scenario.thesis.run.frequency_hz",
            "(0, 10] Hz",
        ),
        (
            "/scenario/thesis/walk",
            json!({"root_height_m": 0.0}),
            "scenario.thesis.walk.root_height_m",
            "positive",
        ),
        (
            "/scenario/thesis/walk",
            json!({"step_height_m": -0.1}),
            "scenario.thesis.walk.step_height_m",
            "≥ 0",
        ),
        (
            "/scenario/thesis/slowdown",
            json!(0.5),
            "scenario.thesis.slowdown",
            "between 1 and 100",
        ),
        (
            "/scenario/thesis/slowdown",
            json!(101),
            "scenario.thesis.slowdown",
            "between 1 and 100",
        ),
        (
            "/scenario/thesis/speed_mps",
            json!(-1),
            "scenario.thesis.speed_mps",
            "between 0 and 20",
        ),
        (
            "/scenario/thesis/speed_mps",
            json!(21),
            "scenario.thesis.speed_mps",
            "between 0 and 20",
        ),
        (
            "/scenario/thesis/iterations_per_frame",
            json!(0),
            "scenario.thesis.iterations_per_frame",
            "between 1 and 100",
        ),
        (
            "/scenario/thesis/iterations_per_frame",
            json!(101),
            "scenario.thesis.iterations_per_frame",
            "between 1 and 100",
        ),
        (
            "/scenario/thesis/posture_gain",
            json!(1.5),
            "scenario.thesis.posture_gain",
            "between 0 and 1",
        ),
        (
            "/scenario/thesis/start_ramp_s",
            json!(-0.1),
            "scenario.thesis.start_ramp_s",
            "between 0 and 10",
        ),
        (
            "/scenario/thesis/start_ramp_s",
            json!(11),
            "scenario.thesis.start_ramp_s",
            "between 0 and 10",
        ),
        (
            "/scenario/thesis/wounded/1/joint",
            json!("left_shin"),
            "scenario.thesis.wounded[1].joint",
            r#"no joint named "left_shin""#,
        ),
        (
            "/scenario/thesis/wounded/1/joint",
            json!("left_hip_flex"),
            "scenario.thesis.wounded[1].joint",
            "already listed at scenario.thesis.wounded[0]",
        ),
        (
            "/scenario/thesis/wounded/1/multiply",
            json!(11),
            "scenario.thesis.wounded[1].multiply",
            "between 0 and 10",
        ),
        (
            "/scenario/thesis/wounded/1/multiply",
            json!(-0.1),
            "scenario.thesis.wounded[1].multiply",
            "between 0 and 10",
        ),
        (
            "/scenario/thesis/roles",
            json!({"left_hand": "left_paw"}),
            "scenario.thesis.roles.left_hand",
            r#"no effector named "left_paw""#,
        ),
        (
            "/scenario/thesis/roles",
            json!({"right_hand": "left_hand"}),
            "scenario.thesis.roles.right_hand",
            "already plays left_hand",
        ),
    ] {
        let json = human_with(|v| {
            let (parent, key) = pointer.rsplit_once('/').expect("pointer has a parent");
            at(v, parent)
                .as_object_mut()
                .expect("object")
                .insert(key.to_owned(), value);
        });
        assert_rejected(&json, path, reason);
    }
    let json = human_with(set(
        "/scenario/thesis/wounded/1",
        json!({"joint": "left_knee", "add": 0.6}),
    ));
    assert_rejected(
        &json,
        "scenario.thesis.wounded[1].add",
        "between -0.5 and 0.5",
    );
}

#[test]
fn roles_are_only_checked_when_the_skeleton_has_four_effectors() {
    // A two-effector arm cannot run the thesis script; its default roles are not an error.
    let json = json!({
        "format": "gaitlab-preset/1", "name": "arm",
        "skeleton": {"root": {"position": [0, 1, 0]},
            "joints": [{"name": "shoulder", "axis": [1, 0, 0], "offset": [0, 0, 0]},
                       {"name": "elbow", "parent": "shoulder", "axis": [1, 0, 0], "offset": [0, -0.3, 0]}],
            "effectors": [{"name": "hand", "joint": "elbow", "offset": [0, -0.3, 0]},
                          {"name": "elbow_tip", "joint": "elbow"}]},
        "scenario": {"engine": "ik"}
    });
    let creature = gaitlab_core::preset::Creature::from_json(&json.to_string()).expect("valid arm");
    assert_eq!(creature.skeleton.effector_count(), 2);
}

/// The thesis roles are checked where the thesis script uses them: engine `ik`,
/// loaded to run its scenario. A PODA or physics preset with four or more
/// effectors and roles that name none of them is valid; the same preset with
/// engine `ik` is not, unless it is loaded only to track recorded targets.
#[test]
fn roles_are_checked_only_where_the_thesis_script_runs() {
    let roles = json!({"left_foot": "nowhere", "right_foot": "nowhere_else",
                       "left_hand": "no_hand", "right_hand": "no_other_hand"});
    for (name, engine_section, effectors) in [
        ("poda-quadruped", "poda", 5),
        ("raibert-quadruped", "physics", 4),
    ] {
        let mut value: Value =
            serde_json::from_str(preset::bundled_json(name).expect("bundled")).expect("JSON");
        let scenario = at(&mut value, "/scenario").as_object_mut().expect("object");
        scenario
            .entry("thesis")
            .or_insert_with(|| json!({}))
            .as_object_mut()
            .expect("thesis object")
            .insert("roles".to_owned(), roles.clone());
        let creature = preset::Creature::from_json(&value.to_string())
            .unwrap_or_else(|e| panic!("{name} with unused roles: {e}"));
        assert_eq!(creature.skeleton.effector_count(), effectors, "{name}");

        let scenario = at(&mut value, "/scenario").as_object_mut().expect("object");
        scenario.remove(engine_section);
        scenario.insert("engine".to_owned(), json!("ik"));
        let as_ik = value.to_string();
        assert_rejected(
            &as_ik,
            "scenario.thesis.roles.left_foot",
            r#"no effector named "nowhere""#,
        );
        // Tracking recorded targets never runs the script: the roles are not checked.
        let tracked = preset::Creature::from_json_for(&as_ik, preset::Purpose::Tracking)
            .unwrap_or_else(|e| panic!("{name} as ik, for tracking: {e}"));
        assert_eq!(tracked.skeleton.effector_count(), effectors, "{name}");
        let preset = Preset::from_json_for(&as_ik, preset::Purpose::Tracking).expect("parses");
        assert_eq!(
            preset.validate().map_err(|e| e.path),
            Err("scenario.thesis.roles.left_foot".to_owned())
        );
    }
}

/// No prefix of a valid preset and no single-byte corruption of it panics, and every
/// rejection names a path.
#[test]
fn no_truncation_or_corruption_panics() {
    let text = human_json();
    for cut in (0..text.trim_end().len()).filter(|&i| text.is_char_boundary(i)) {
        let error =
            Preset::from_json(&text[..cut]).expect_err("a strict prefix is never a whole preset");
        assert!(!error.path.is_empty() && !error.reason.is_empty());
    }
    let bytes = text.as_bytes();
    let replacements = b"0-9.e\",:[]{}nNaxyz ";
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    for _ in 0..4000 {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let position = (state >> 33) as usize % bytes.len();
        let replacement = replacements[(state >> 13) as usize % replacements.len()];
        let mut corrupted = bytes.to_vec();
        corrupted[position] = replacement;
        if let Ok(candidate) = String::from_utf8(corrupted)
            && let Err(error) = Preset::from_json(&candidate)
        {
            assert!(!error.path.is_empty() && !error.reason.is_empty());
        }
    }
    // Deep nesting is refused at the first level that has a type, without recursing.
    let deep = format!(
        "{{\"format\": \"gaitlab-preset/1\", \"name\": {}",
        "[".repeat(100_000)
    );
    assert_rejected(&deep, "name", "invalid type: sequence, expected a string");
    let deep = format!("{{\"skeleton\": {{\"joints\": {}", "[".repeat(100_000));
    assert_rejected(
        &deep,
        "skeleton.joints[0][0]",
        "invalid type: sequence, expected a string",
    );
}
