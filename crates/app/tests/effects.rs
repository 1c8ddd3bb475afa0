//! The lab's outbox of effects (issue 17 item 2): what the web glue drains
//! once a frame instead of polling flags on the lab.

use gaitlab_app::lab::Effect;
use gaitlab_app::{App, Settings};
use gaitlab_core::ik::Method;
use gaitlab_core::preset::thesis::ThesisMode;

#[test]
fn a_preset_change_asks_for_a_history_entry_and_a_link_update_once() {
    let mut lab = App::new(Settings::default());
    assert!(lab.drain_effects().is_empty(), "a fresh lab asks nothing");
    lab.set_preset("ik-quadruped").expect("bundled");
    lab.set_mode(ThesisMode::Run);
    assert_eq!(
        lab.drain_effects(),
        vec![Effect::PresetChanged, Effect::LinkChanged]
    );
    lab.set_method(Method::Dls);
    assert_eq!(lab.drain_effects(), vec![Effect::LinkChanged]);
    assert!(lab.drain_effects().is_empty(), "drained once");
}

#[test]
fn opening_a_link_leaves_the_address_bar_as_it_is() {
    let mut lab = App::new(Settings::default());
    let query = gaitlab_app::link::query("ik-quadruped", Some("run"), Some("dls"));
    lab.open_link(&query, "");
    assert_eq!(lab.creature().name, "ik-quadruped");
    assert!(
        lab.drain_effects()
            .iter()
            .all(|e| !matches!(e, Effect::LinkChanged | Effect::PresetChanged)),
        "the address bar already shows the link"
    );
}

#[test]
fn video_file_picker_and_download_requests_reach_the_outbox() {
    let mut lab = App::new(Settings::default());
    lab.set_video_recording(true);
    lab.set_video_recording(true);
    assert_eq!(lab.drain_effects(), vec![Effect::StartVideo]);
    assert!(lab.video_recording());
    lab.set_video_recording(false);
    assert_eq!(lab.drain_effects(), vec![Effect::StopVideo]);
    lab.set_video_recording(true);
    lab.set_video_recording(false);
    assert!(
        lab.drain_effects().is_empty(),
        "a start and a stop within one frame cancel out"
    );
    assert!(!lab.video_recording());

    lab.request_file_pick();
    lab.request_file_pick();
    lab.command(r#"{"download_preset": true}"#)
        .expect("a known command");
    let effects = lab.drain_effects();
    assert_eq!(effects.len(), 2, "{effects:?}");
    assert_eq!(effects[0], Effect::PickFile);
    let Effect::Download(download) = &effects[1] else {
        panic!("a download, got {:?}", effects[1]);
    };
    assert_eq!(download.file_name, "human.json");
    assert_eq!(download.mime, "application/json");
}
