//! DESIGN.md "Versions": a link and a preset made before a change that
//! altered defaults still replay with the behaviour they were made with.
//! Issue 18 added `scenario.thesis.script` (`lab` | `listing`) and
//! `scenario.thesis.wound_form` (`step` | `angle`); files without them keep
//! gaitlab's script and the step form. The link below is link version 1 with
//! a `gaitlab-preset/1` preset without those keys; its figure was recorded
//! with the lab script and the step form, the behaviour such files had before
//! issue 18 (the bundled presets' 10 s golden runs, crates/cli/tests/golden,
//! are unchanged across the change). The preset of that version is
//! `presets/human.json`, whose golden run covers it.

use gaitlab_app::{App, Settings};
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::thesis::{TargetScript, WoundForm};

/// `share_link` of a lab on an edited human (its name and one wounded weight
/// changed), wounded walking with DLS, written before issue 18.
const LINK_V1: &str = include_str!("fixtures/link_v1_human_wounded.txt");

/// Sum of |θ| over the joints after 120 frames of that link, radians,
/// recorded before issue 18.
const LINK_V1_JOINT_SUM_RAD: f64 = 3.8866359721608053;

fn open(link: &str) -> App {
    let fragment = &link[link.find('#').expect("a fragment")..];
    let mut lab = App::new(Settings::default());
    lab.open_link("", fragment);
    lab
}

#[test]
fn a_link_made_before_the_listing_and_wound_forms_replays_as_before() {
    let mut lab = open(LINK_V1.trim());
    assert_eq!(lab.last_error(), None);
    assert_eq!(lab.creature().name, "human-v1");
    let Some(thesis) = lab.driver().thesis() else {
        panic!("the link opens on the IK engine")
    };
    assert_eq!(thesis.params().script, TargetScript::Lab);
    assert_eq!(thesis.params().wound_form, WoundForm::Step);
    assert_eq!(thesis.mode().name(), "wounded-walk");
    assert_eq!(thesis.options().method.name(), "dls");
    for _ in 0..120 {
        lab.advance(lab.frame_seconds());
    }
    let sum: f64 = lab.driver().pose().joints.iter().map(|v| v.abs()).sum();
    assert!(
        (sum - LINK_V1_JOINT_SUM_RAD).abs() < 1e-9,
        "Σ|θ| after 2 s: {sum} rad, recorded {LINK_V1_JOINT_SUM_RAD} rad"
    );
}

/// The bundled `she-2006` preset as it was on 2026-12-01, before it set
/// `scenario.ik.limit_passes: 1` (the thesis' clamp-only joint limits).
const SHE_2006_2026_12_01: &str = include_str!("fixtures/preset_she_2006_2026_12_01.json");

/// A link of that day's she-2006, walking with DLS: before `limit_passes`
/// was a setting links carry, so the state has none.
fn she_2006_link_2026_12_01() -> String {
    let state = serde_json::json!({
        "mode": "walk", "method": "dls", "lambda": 0.05, "gamma_max": std::f64::consts::FRAC_PI_4,
        "max_step": 0.2, "null_space_gain": 0.0, "enforce_limits": true, "jacobian_at": "effectors",
    });
    let Some(state) = state.as_object().cloned() else {
        panic!("an object")
    };
    let link = gaitlab_app::link::FullLink {
        preset_json: SHE_2006_2026_12_01.to_owned(),
        bundled: Some("she-2006".to_owned()),
        state,
    };
    match gaitlab_app::link::encode_full(&link) {
        Ok(payload) => format!("https://example.org/#p={payload}"),
        Err(error) => panic!("{error}"),
    }
}

#[test]
fn a_she_2006_link_made_before_limit_passes_replays_with_the_re_solve() {
    // Even where the person's stored settings clamp alone.
    let mut settings = Settings::default();
    settings.ik.limit_passes = 1;
    let mut lab = App::new(settings);
    let link = she_2006_link_2026_12_01();
    lab.open_link("", &link[link.find('#').expect("a fragment")..]);
    assert_eq!(lab.last_error(), None);
    let Some(thesis) = lab.driver().thesis() else {
        panic!("the link opens on the IK engine")
    };
    assert_eq!(thesis.options().limit_passes, 4, "the re-solve it ran with");
    // The same run through the engine on that day's preset (no scenario.ik:
    // the defaults, 4 passes) gives the same angles, bit for bit.
    let creature = match gaitlab_core::preset::Creature::from_json(SHE_2006_2026_12_01) {
        Ok(creature) => creature,
        Err(error) => panic!("{error}"),
    };
    let mut reference = match gaitlab_motion::ThesisDriver::for_creature(&creature) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    reference.set_method(gaitlab_core::ik::Method::Dls);
    for _ in 0..120 {
        lab.advance(lab.frame_seconds());
        reference.step(lab.frame_seconds());
    }
    assert_eq!(lab.driver().pose().joints, reference.pose().joints);
}

/// A link to the hexapod preset as it was on 2026-12-01 (its `vertical_gain`
/// 0.3, deprecated since): it runs with the gain, and the page says so.
#[test]
fn a_link_with_the_deprecated_vertical_gain_runs_with_it_and_says_so() {
    let preset = include_str!("../../cli/tests/fixtures/hexapod_2026_12_01.json");
    let mut lab = App::new(Settings::default());
    let fragment = format!("#p={}", gaitlab_app::link::encode_preset(preset));
    lab.open_link("", &fragment);
    assert_eq!(lab.last_error(), None);
    let Some(poda) = lab.driver().poda() else {
        panic!("the link opens on the PODA engine")
    };
    assert_eq!(poda.params().vertical_gain, 0.3);
    let notice = lab.notice().unwrap_or_default();
    assert!(
        notice.starts_with("scenario.poda.vertical_gain: 0.3 is deprecated"),
        "{notice}"
    );
    let state: serde_json::Value =
        serde_json::from_str(&lab.state_json()).unwrap_or(serde_json::Value::Null);
    assert_eq!(state["notice"].as_str(), Some(notice));
    // The bundled hexapod no longer uses it: no note.
    if let Err(error) = lab.command(r#"{"preset":"hexapod"}"#) {
        panic!("{error}");
    }
    assert_eq!(lab.notice(), None);
}
