//! She 2006 §3.2's control way (`jacobian_at`) through the app: the command
//! key and its error, `state().ik.jacobian_at`, the solver it reaches, and
//! links with and without the key.

use gaitlab_app::{App, Settings};
use gaitlab_core::ik::JacobianAt;
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).expect("state is JSON")
}

fn way_shown(lab: &App) -> Value {
    state(lab)["ik"]["jacobian_at"].clone()
}

#[test]
fn the_default_is_the_jacobian_at_the_effectors() {
    let lab = App::new(Settings::default());
    assert_eq!(way_shown(&lab), "effectors");
    let driver = lab
        .driver()
        .thesis()
        .expect("the human runs the thesis script");
    assert_eq!(driver.options().jacobian_at, JacobianAt::Effectors);
}

#[test]
fn the_command_sets_it_and_names_the_key_on_a_bad_value() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"jacobian_at":"targets"}"#)
        .expect("targets");
    assert_eq!(way_shown(&lab), "targets");
    let driver = lab
        .driver()
        .thesis()
        .expect("the human runs the thesis script");
    assert_eq!(driver.options().jacobian_at, JacobianAt::Targets);
    let error = lab
        .command(r#"{"jacobian_at":"sideways"}"#)
        .expect_err("not a way");
    assert!(error.contains("jacobian_at"), "{error}");
    assert!(
        error.contains("effectors") && error.contains("targets"),
        "{error}"
    );
    assert_eq!(
        way_shown(&lab),
        "targets",
        "a refused command changes nothing"
    );
    lab.command(r#"{"jacobian_at":"effectors"}"#)
        .expect("effectors");
    assert_eq!(way_shown(&lab), "effectors");
}

#[test]
fn links_carry_the_way_and_old_links_open_with_the_default() {
    let mut lab = App::new(Settings::default());
    lab.command(r#"{"jacobian_at":"targets","method":"dls"}"#)
        .expect("command");
    let full = lab.full_link();
    assert_eq!(full.state.get("jacobian_at"), Some(&Value::from("targets")));
    let mut restored = App::new(Settings::default());
    assert_eq!(restored.apply_full_link(&full), Vec::<String>::new());
    assert_eq!(way_shown(&restored), "targets");

    // A link written before the key existed: everything else the same.
    let mut old = full.clone();
    old.state.remove("jacobian_at");
    let mut reopened = App::new(Settings::default());
    assert_eq!(reopened.apply_full_link(&old), Vec::<String>::new());
    assert_eq!(way_shown(&reopened), "effectors");
    let mut default_lab = App::new(Settings::default());
    default_lab.command(r#"{"method":"dls"}"#).expect("command");
    assert_eq!(state(&reopened)["ik"], state(&default_lab)["ik"]);
}
