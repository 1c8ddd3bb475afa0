//! The panels' controls drawn from the parameter table (issue 41 item 1): a
//! value the table calls the lab's addition carries a small "lab" tag on its
//! row, and a value of the paper, or one the paper leaves open, does not.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use gaitlab_app::{App, Settings};

/// A paused lab on `preset` in a tall window (every control laid out).
fn harness(preset: &str) -> Harness<'static, App> {
    let mut lab = App::new(Settings::default());
    lab.set_paused(true);
    lab.set_preset(preset).expect("bundled");
    Harness::builder()
        .with_size(egui::vec2(1200.0, 1600.0))
        .build_ui_state(|ui, lab: &mut App| lab.ui(ui), lab)
}

/// The vertical centres of every "lab" tag on screen.
fn tag_rows(harness: &Harness<'static, App>) -> Vec<f32> {
    harness
        .query_all_by_label("lab")
        .map(|node| node.rect().center().y)
        .collect()
}

/// Whether a "lab" tag sits on the row of the control labelled `label` (a
/// slider's first node: it has one for the handle and one for its text).
fn tagged(harness: &Harness<'static, App>, label: &str) -> bool {
    let row = harness
        .query_all_by_label(label)
        .next()
        .unwrap_or_else(|| panic!("no control {label}"))
        .rect();
    tag_rows(harness)
        .into_iter()
        .any(|y| y > row.top() && y < row.bottom())
}

#[test]
fn the_method_panel_tags_the_labs_additions_and_not_the_papers_values() {
    let mut harness = harness("human");
    harness.run();
    assert!(tag_rows(&harness).is_empty(), "the Method panel is folded");
    harness.get_by_label("Method").click();
    harness.run();
    // scenario.ik.clamp_every_method and limit_passes are the lab's.
    assert!(tagged(&harness, "Clamp transpose and DLS too"));
    assert!(tagged(&harness, "Limit passes"));
    assert!(tagged(&harness, "Buss"), "Buss's α is the lab's choice");
    // λ is open (the lab's pick of a value the paper needs), γmax the
    // paper's; the units come from the table.
    for other in ["DLS λ (m)", "SDLS γmax (°)", "Joint limits"] {
        assert!(!tagged(&harness, other), "{other}");
    }
}

#[test]
fn the_posture_pull_is_tagged_as_the_labs() {
    let mut harness = harness("human");
    harness.run();
    harness.get_by_label("Motion").click();
    harness.run();
    assert!(
        tagged(&harness, "Posture pull"),
        "scenario.thesis.posture_gain is the lab's"
    );
    assert!(!tagged(&harness, "Moving forward"), "the thesis' effect");
}
