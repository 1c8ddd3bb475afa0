//! Lessons as links (issue 21 item 6): a teacher's note, hidden panels and
//! pinned plots travel in a link and come back with the note open; bad names
//! are refused with the entry named; leaving the lesson shows everything again.

use gaitlab_app::{App, Settings};
use serde_json::Value;

fn state(lab: &App) -> Value {
    serde_json::from_str(&lab.state_json()).unwrap_or_default()
}

const LESSON: &str = r#"{"lesson": {"note": "Watch the hands: the pseudoinverse shakes where targets are out of reach.", "hide_panels": ["Method", "Recording"], "pin_plots": ["errors"]}}"#;

#[test]
fn a_lesson_link_opens_with_its_note_hidden_panels_and_pinned_plots() {
    let mut teacher = App::new(Settings::default());
    if let Err(error) = teacher.command(LESSON) {
        panic!("{error}");
    }
    let s = state(&teacher);
    assert_eq!(
        s["lesson"]["hide_panels"],
        serde_json::json!(["Method", "Recording"])
    );
    assert_eq!(s["layout"]["lesson_note_open"], true);
    assert!(teacher.lesson_hides("Method") && !teacher.lesson_hides("Motion"));
    assert_eq!(teacher.plots_shown().collect::<Vec<_>>(), ["errors"]);

    let link = match teacher.share_link() {
        Ok(link) => link,
        Err(error) => panic!("{error}"),
    };
    let mut student = App::new(Settings::default());
    student.open_link("", &link[link.find('#').unwrap_or(0)..]);
    let s = state(&student);
    assert_eq!(s["last_error"], Value::Null);
    assert_eq!(s["lesson"], state(&teacher)["lesson"]);
    assert_eq!(
        s["layout"]["lesson_note_open"], true,
        "the note shows first"
    );

    // Leaving it.
    if let Err(error) = student.command(r#"{"lesson": false}"#) {
        panic!("{error}");
    }
    assert_eq!(state(&student)["lesson"], Value::Null);
    assert!(!student.lesson_hides("Method"));
    assert_eq!(state(&student)["layout"]["lesson_note_open"], false);
}

#[test]
fn bad_lessons_are_refused_with_the_entry_named() {
    let mut lab = App::new(Settings::default());
    for (command, want) in [
        (
            r#"{"lesson": {"hide_panels": ["Method", "Warp"]}}"#,
            "lesson.hide_panels[1]: no panel \"Warp\"",
        ),
        (
            r#"{"lesson": {"pin_plots": ["joy"]}}"#,
            "lesson.pin_plots[0]",
        ),
        (r#"{"lesson": {"notes": "x"}}"#, "lesson"),
        (r#"{"lesson": true}"#, "lesson"),
    ] {
        let error = lab.command(command).err().unwrap_or_default();
        assert!(error.contains(want), "{command}: {error}");
        assert_eq!(state(&lab)["lesson"], Value::Null, "{command}");
    }
}

#[test]
fn pins_of_another_engines_plots_hide_none() {
    let mut lab = App::new(Settings::default());
    for command in [r#"{"preset": "raibert-biped"}"#, LESSON] {
        if let Err(error) = lab.command(command) {
            panic!("{command}: {error}");
        }
    }
    assert!(lab.lesson().is_some());
    assert_eq!(
        lab.plots_shown().collect::<Vec<_>>(),
        ["lengths", "force", "attitude", "state"]
    );
    if let Err(error) = lab.command(r#"{"lesson": {"pin_plots": ["force"]}}"#) {
        panic!("{error}");
    }
    assert_eq!(lab.plots_shown().collect::<Vec<_>>(), ["force"]);
}
