//! Full-state links through the lab (issue 6 item 2): a lab changed in many
//! ways, written by `share_link` and opened in a fresh lab, has the same
//! `state()` field by field (live counters aside); broken links leave a message
//! and the default preset.

use gaitlab_app::{App, Settings};
use serde_json::Value;

/// `state()` fields that count live time, not settings: the frame counter,
/// simulated time, frame rate and timing, the per-frame effector errors, and
/// the physics body's live readings.
const LIVE: [&str; 6] = [
    "frame",
    "time_s",
    "fps",
    "sim_us_per_frame",
    "views",
    "rewind",
];

fn settled_state(lab: &App) -> Value {
    let mut state: Value = serde_json::from_str(&lab.state_json()).expect("state is JSON");
    let object = state.as_object_mut().expect("object");
    for key in LIVE {
        object.remove(key);
    }
    if let Some(physics) = object.get_mut("physics").and_then(Value::as_object_mut) {
        for key in [
            "phase",
            "waypoint",
            "speed_mean_mps",
            "fell",
            "resets",
            "height_m",
            "pitch_deg",
            "roll_deg",
            "stride_length_m",
            "stride_duration_s",
            "flight_duration_s",
            "stance_duration_s",
            "friction_needed_max",
            "steps",
        ] {
            physics.remove(key);
        }
    }
    if let Some(poda) = object.get_mut("poda").and_then(Value::as_object_mut) {
        poda.remove("foot_slip_max_m");
        poda.remove("derived");
    }
    state
}

fn fresh_lab() -> App {
    App::new(Settings::default())
}

/// Opens `link` (`…#p=…`) in a fresh lab.
fn open(link: &str) -> App {
    let fragment = &link[link.find('#').expect("a fragment")..];
    let mut lab = fresh_lab();
    lab.open_link("", fragment);
    lab
}

fn assert_same_state(original: &App, restored: &App) {
    let a = settled_state(original);
    let b = settled_state(restored);
    for (key, value) in a.as_object().expect("object") {
        assert_eq!(Some(value), b.get(key), "state field {key}");
    }
    assert_eq!(a, b);
}

fn run(lab: &mut App, frames: usize) {
    for _ in 0..frames {
        lab.advance(lab.frame_seconds());
    }
}

#[test]
fn an_edited_ik_lab_comes_back_exactly() {
    let mut lab = fresh_lab();
    lab.page_url = "http://127.0.0.1:8080/".to_owned();
    let edited = gaitlab_core::preset::bundled_json("human")
        .expect("bundled")
        .replacen("\"name\": \"human\"", "\"name\": \"human-edited\"", 1);
    lab.set_editor_text(&edited);
    lab.editor_apply().expect("the edit is valid");
    for command in [
        r#"{"mode":"wounded-run","method":"dls","lambda":0.2,"gamma_max":0.5,"max_step":0.1}"#,
        r#"{"null_space_gain":0.3,"enforce_limits":false,"heading_deg":30}"#,
        r#"{"views":{"follow":false,"grid":false,"world_axes":true},"plots":false}"#,
        r#"{"plot_joints":["left_knee","right_knee"],"video_size":"p720"}"#,
        r#"{"camera":{"yaw_deg":-40,"pitch_deg":25,"distance_m":5.5,"target_m":[0.2,0.8,1.5]}}"#,
        r#"{"paused":true}"#,
    ] {
        lab.command(command).expect(command);
    }
    run(&mut lab, 3);
    let link = lab.share_link().expect("a link");
    assert!(link.starts_with("http://127.0.0.1:8080/#p="), "{link:.60}");
    assert!(link.len() < 8000, "{} characters", link.len());
    let restored = open(&link);
    assert_eq!(restored.last_error(), None);
    assert_eq!(restored.creature().name, "human-edited");
    assert_same_state(&lab, &restored);
    // The restored lab writes the same link again.
    let mut again = restored;
    again.page_url = lab.page_url.clone();
    assert_eq!(again.share_link(), Ok(link));
}

#[test]
fn a_bundled_preset_stays_bundled_and_poda_gait_values_come_back() {
    let mut lab = fresh_lab();
    lab.command(r#"{"preset":"poda-quadruped"}"#)
        .expect("preset");
    for command in [
        r#"{"speed_mps":0.6}"#,
        r#"{"duty_factor":0.7}"#,
        r#"{"period_s":1.3}"#,
        r#"{"step_height_m":0.09}"#,
        r#"{"views":{"follow":false}}"#,
    ] {
        lab.command(command).expect(command);
    }
    let link = lab.share_link().expect("a link");
    let restored = open(&link);
    assert_eq!(restored.last_error(), None);
    let state: Value = serde_json::from_str(&restored.state_json()).expect("json");
    assert_eq!(
        state["custom_preset"], false,
        "loaded as the bundled preset"
    );
    assert_eq!(state["poda"]["period_s"], 1.3);
    assert_eq!(state["poda"]["duty_factor"], 0.7);
    assert_eq!(state["poda"]["speed_mps"], 0.6);
    assert_same_state(&lab, &restored);
}

#[test]
fn physics_speed_hop_height_and_gains_come_back() {
    let mut lab = fresh_lab();
    lab.command(r#"{"engine":"physics"}"#).expect("engine");
    let state: Value = serde_json::from_str(&lab.state_json()).expect("json");
    let gains = state["physics"]["gains"]
        .as_object()
        .expect("gains")
        .clone();
    let (name, value) = gains.iter().next().expect("a gain");
    let doubled = value.as_f64().expect("number") * 2.0 + 0.5;
    lab.command(&serde_json::json!({"gain": {"name": name, "value": doubled}}).to_string())
        .expect("gain");
    lab.command(r#"{"speed_mps":1.1,"views":{"follow":false}}"#)
        .expect("speed");
    let link = lab.share_link().expect("a link");
    let restored = open(&link);
    assert_eq!(restored.last_error(), None);
    let state: Value = serde_json::from_str(&restored.state_json()).expect("json");
    assert_eq!(state["physics"]["gains"][name], doubled);
    assert_eq!(state["physics"]["speed_desired_mps"], 1.1);
    assert_same_state(&lab, &restored);
}

#[test]
fn broken_links_show_a_message_and_load_the_default_preset() {
    let mut lab = fresh_lab();
    lab.command(r#"{"preset":"hexapod","paused":true}"#)
        .expect("preset");
    let link = lab.share_link().expect("a link");
    let payload = &link[link.find("#p=").expect("payload") + 3..];
    let mut flipped = payload.as_bytes().to_vec();
    for at in [5, 6, 7] {
        flipped[at] = if flipped[at] == b'Q' { b'w' } else { b'Q' };
    }
    let flipped = String::from_utf8(flipped).expect("ascii");
    let cases = [
        ("truncated", payload[..payload.len() / 2].to_owned()),
        ("flipped", flipped),
        ("10 MB", "x".repeat(10 << 20)),
        ("not base64", "%%%".to_owned()),
    ];
    for (what, payload) in cases {
        let mut lab = App::new(Settings {
            preset: "ik-quadruped".to_owned(),
            ..Settings::default()
        });
        lab.open_link("?preset=hexapod", &format!("#p={payload}"));
        let error = lab
            .last_error()
            .unwrap_or_else(|| panic!("{what}: a message"));
        assert!(error.starts_with("link: "), "{what}: {error}");
        assert_eq!(
            lab.creature().name,
            gaitlab_core::preset::DEFAULT_PRESET,
            "{what}"
        );
    }
    // A link whose preset is invalid, and one with a bad setting.
    let mut bad = lab.full_link();
    bad.preset_json = bad.preset_json.replacen("\"hexapod\"", "\"\"", 1);
    bad.bundled = None;
    let payload = gaitlab_app::link::encode_full(&bad).expect("encodes");
    let mut restored = App::new(Settings {
        preset: "ik-quadruped".to_owned(),
        ..Settings::default()
    });
    restored.open_link("", &format!("#p={payload}"));
    let error = restored.last_error().expect("a message");
    assert!(error.contains("link: preset: name"), "{error}");
    assert_eq!(
        restored.creature().name,
        gaitlab_core::preset::DEFAULT_PRESET
    );
    let mut odd = lab.full_link();
    odd.state.insert("lambda".into(), Value::from(-1.0));
    odd.state.insert("eval".into(), Value::from("alert(1)"));
    let payload = gaitlab_app::link::encode_full(&odd).expect("encodes");
    let mut restored = fresh_lab();
    restored.open_link("", &format!("#p={payload}"));
    let error = restored.last_error().expect("a message");
    assert!(error.contains("state.lambda"), "{error}");
    assert!(error.contains("state.eval"), "{error}");
    assert_eq!(restored.creature().name, "hexapod", "the rest applied");
    assert!(restored.paused());
}
