//! The typed command API (docs/app.md "The JS API"): a command is read whole,
//! so a wrong type, an unknown key or an unknown name anywhere refuses it
//! before any key applies; errors name the key path in the API's words.

use gaitlab_app::api::Command;
use gaitlab_app::{App, Settings};
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).expect("state is JSON")
}

#[test]
fn a_type_error_anywhere_refuses_the_whole_command() {
    let mut lab = App::new(Settings::default());
    for (command, expected) in [
        (
            r#"{"mode":"run","gain":{"name":"leg_stiffness","value":"x"}}"#,
            "gain.value: expected a number",
        ),
        (
            r#"{"mode":"run","phases":[0.1,0.2,"x"]}"#,
            "phases[2]: expected a number",
        ),
        (
            r#"{"mode":"run","paused":"yes"}"#,
            "paused: expected true or false",
        ),
        (r#"{"mode":"run","launch":1}"#, "launch: unknown command"),
        (
            r#"{"mode":"run","camera":{"zoom":2}}"#,
            "camera.zoom: unknown camera field",
        ),
        (r#"{"mode":"run","gain":{"value":1}}"#, "gain.name: missing"),
        (
            r#"{"mode":"run","theme":"sepia"}"#,
            r#"theme: unknown theme "sepia" (system, light, dark)"#,
        ),
        (
            r#"{"mode":"run","compare":{"views":["pinv","warp"]}}"#,
            r#"compare.views[1]: unknown method "warp""#,
        ),
        (
            r#"{"mode":"run","compare":{"options":[{"lambda":"x"}]}}"#,
            "compare.options[0].lambda: expected a number",
        ),
        (
            r#"{"mode":"run","compare":true}"#,
            "compare: expected an object or false",
        ),
        (
            r#"{"mode":"run","save":{"format":"bvh","when":1}}"#,
            "save.when: unknown key",
        ),
        (
            r#"{"mode":"run","views":[true]}"#,
            "views: expected an object",
        ),
    ] {
        let error = lab.command(command).expect_err(command);
        assert!(error.starts_with(expected), "{command}: {error}");
        assert_eq!(state(&lab)["mode"], "walk", "{command}: nothing applied");
    }
}

#[test]
fn a_range_error_stops_in_order_and_keeps_what_came_before() {
    let mut lab = App::new(Settings::default());
    let error = lab
        .command(r#"{"mode":"run","lambda":-1,"plots":false}"#)
        .expect_err("lambda out of range");
    assert!(error.starts_with("lambda: -1 is outside"), "{error}");
    let s = state(&lab);
    assert_eq!(s["mode"], "run", "mode applies before lambda");
    assert_eq!(s["plots"], true, "plots applies after lambda");
}

#[test]
fn null_is_absent_except_for_compare_and_narrow() {
    let parsed = Command::parse(r#"{"mode":null,"compare":null,"narrow":null}"#).expect("valid");
    assert!(parsed.mode.is_none());
    assert!(parsed.compare.is_some());
    assert_eq!(parsed.narrow, Some(None));
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"compare":{"views":["pinv","dls"]}}"#)
        .expect("starts");
    lab.command(r#"{"compare":null}"#).expect("leaves");
    assert!(lab.comparison().is_none());
}

#[test]
fn the_playback_rate_is_set_within_its_range() {
    let mut lab = App::new(Settings::default());
    assert_eq!(state(&lab)["playback_rate"], 1.0);
    assert!(lab.command(r#"{"playback_rate": 0.25}"#).is_ok());
    assert_eq!(state(&lab)["playback_rate"], 0.25);
    let error = lab
        .command(r#"{"playback_rate": 5}"#)
        .expect_err("out of range");
    assert!(error.starts_with("playback_rate: 5 is outside"), "{error}");
    assert_eq!(state(&lab)["playback_rate"], 0.25, "kept");
}
