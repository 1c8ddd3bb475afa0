//! The lab's command and state API (what `window.gaitlab.command` / `state()`
//! expose): commands change what the panels change, bad commands name the key
//! and change nothing after it, and the state reports figures.

use gaitlab_app::{App, Settings};
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).expect("state is JSON")
}

#[test]
fn defaults_show_the_human_walking_with_sdls() {
    let lab = App::new(Settings::default());
    let s = state(&lab);
    assert_eq!(s["preset"], "human");
    assert_eq!(s["engine"], "ik");
    assert_eq!(s["mode"], "walk");
    assert_eq!(s["method"], "sdls");
    assert_eq!(s["paused"], false);
    assert_eq!(s["joints"], 20);
    assert!(s["last_error"].is_null());
}

#[test]
fn commands_switch_mode_method_and_pause() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"mode":"run","method":"dls"}"#)
        .expect("valid");
    let s = state(&lab);
    assert_eq!(
        (s["mode"].as_str(), s["method"].as_str()),
        (Some("run"), Some("dls"))
    );
    for _ in 0..30 {
        lab.advance(1.0 / 60.0);
    }
    let frames = lab.frame();
    assert!(
        (29..=31).contains(&frames),
        "half a second at 60 fps advances ~30 frames, got {frames}"
    );
    // A long stall (a hidden tab) advances at most 0.1 s.
    lab.advance(5.0);
    assert!(
        lab.frame() - frames <= 7,
        "stall advanced {} frames",
        lab.frame() - frames
    );
    let frames = lab.frame();
    lab.command(r#"{"paused":true}"#).expect("valid");
    lab.advance(0.5);
    assert_eq!(lab.frame(), frames, "paused: no frames advance");
    lab.command(r#"{"step":true}"#).expect("valid");
    lab.advance(0.0);
    assert_eq!(lab.frame(), frames + 1, "a single step advances one frame");
    lab.command(r#"{"reset":true}"#).expect("valid");
    assert_eq!(lab.frame(), 0);
}

#[test]
fn walking_in_the_lab_tracks_the_feet() {
    let mut lab = App::new(Settings::default());
    for _ in 0..120 {
        lab.advance(1.0 / 60.0);
    }
    let s = state(&lab);
    let effectors = s["views"][0]["effectors"].as_array().expect("effectors");
    for foot in effectors
        .iter()
        .filter(|e| e["name"].as_str().is_some_and(|n| n.ends_with("foot")))
    {
        let mean = foot["mean_error_m"].as_f64().expect("mean");
        assert!(mean < 0.005, "{foot}");
    }
}

#[test]
fn bad_commands_name_the_key_and_keep_the_state() {
    let mut lab = App::new(Settings::default());
    for (command, expected) in [
        ("not json", "command is not JSON"),
        ("[1]", "command must be a JSON object"),
        (r#"{"mode":"fly"}"#, "mode: unknown mode"),
        (r#"{"method":7}"#, "method: expected a string"),
        (r#"{"lambda":-1}"#, "lambda: -1 is outside"),
        (r#"{"lambda":1e999}"#, "command is not JSON"),
        (
            r#"{"preset":"dragon"}"#,
            "no bundled preset named \"dragon\"",
        ),
        (
            r#"{"views":{"sparkles":true}}"#,
            "views.sparkles: unknown view option",
        ),
        (r#"{"launch":"missiles"}"#, "launch: unknown command"),
        (
            r#"{"preset_json":"{\"format\":\"gaitlab-preset/1\"}"}"#,
            "preset: ",
        ),
    ] {
        let error = lab.command(command).expect_err(command);
        assert!(error.contains(expected), "{command}: {error}");
    }
    let s = state(&lab);
    assert_eq!(
        (
            s["preset"].as_str(),
            s["mode"].as_str(),
            s["method"].as_str()
        ),
        (Some("human"), Some("walk"), Some("sdls"))
    );
}

#[test]
fn unknown_stored_preset_falls_back_with_a_message() {
    let settings = Settings {
        preset: "no-such".into(),
        ..Settings::default()
    };
    let lab = App::new(settings);
    let s = state(&lab);
    assert_eq!(s["preset"], "human");
    assert!(
        s["last_error"]
            .as_str()
            .is_some_and(|e| e.contains("no-such"))
    );
}

#[test]
fn presets_switch_and_custom_presets_load() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"preset":"ik-quadruped"}"#)
        .expect("bundled");
    assert_eq!(state(&lab)["joints"], 63);
    let json = gaitlab_core::preset::bundled_json("human").expect("bundled");
    let command = serde_json::json!({ "preset_json": json }).to_string();
    lab.command(&command).expect("custom preset");
    let s = state(&lab);
    assert_eq!(s["joints"], 20);
    assert_eq!(s["custom_preset"], true);
}

/// Saved settings that load a preset but cannot drive it fall back to the
/// default preset and settings as one figure: the creature shown is the one
/// the driver animates, and the reason is shown.
#[test]
fn settings_that_cannot_drive_fall_back_to_the_default_creature_and_driver() {
    use gaitlab_core::driver::Driver;
    let mut settings = Settings {
        preset: "ik-quadruped".to_owned(),
        ..Settings::default()
    };
    settings.ik.lambda = -1.0;
    let lab = App::new(settings);
    assert_eq!(lab.creature().name, gaitlab_core::preset::DEFAULT_PRESET);
    assert_eq!(
        lab.creature().skeleton.joint_count(),
        lab.driver().skeleton().joint_count(),
        "the creature and its driver are the same figure"
    );
    let error = lab.last_error().unwrap_or_default();
    assert!(error.starts_with("settings.ik.lambda"), "{error}");
}

/// Issue 43 item 5: the address bar says only what is on screen — the IK
/// method while one view runs, not while a comparison runs several, and no
/// mode or method for a physics or PODA creature.
#[test]
fn the_address_bar_describes_what_is_on_screen() {
    let mut lab = gaitlab_app::App::new(gaitlab_app::Settings::default());
    for (command, query) in [
        (
            r#"{"preset":"she-2006","mode":"walk","method":"sdls"}"#,
            "?preset=she-2006&mode=walk&method=sdls",
        ),
        (
            r#"{"compare":{"views":["transpose","pinv","dls","sdls"]}}"#,
            "?preset=she-2006&mode=walk",
        ),
        (
            r#"{"compare":false}"#,
            "?preset=she-2006&mode=walk&method=sdls",
        ),
        (
            r#"{"preset":"raibert-quadruped"}"#,
            "?preset=raibert-quadruped",
        ),
        (r#"{"preset":"hexapod"}"#, "?preset=hexapod"),
    ] {
        if let Err(error) = lab.command(command) {
            panic!("{command}: {error}");
        }
        assert_eq!(lab.address_query(), query, "after {command}");
    }
}
