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

use gaitlab_app::{Lab, Settings};
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::thesis::{TargetScript, WoundForm};

/// `share_link` of a lab on an edited human (its name and one wounded weight
/// changed), wounded walking with DLS, written before issue 18.
const LINK_V1: &str = include_str!("fixtures/link_v1_human_wounded.txt");

/// Sum of |θ| over the joints after 120 frames of that link, radians,
/// recorded before issue 18.
const LINK_V1_JOINT_SUM_RAD: f64 = 3.8866359721608053;

fn open(link: &str) -> Lab {
    let fragment = &link[link.find('#').expect("a fragment")..];
    let mut lab = Lab::new(Settings::default());
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
