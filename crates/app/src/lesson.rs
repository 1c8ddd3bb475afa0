//! Lessons as links (issue 21 item 6): a teacher's note and a lesson view —
//! control panels hidden and plots pinned — carried by a link (`lesson` in
//! [`crate::link_state::LINK_KEYS`]). Opening such a link shows the note
//! first, in a window over the lab; the hidden panels stay out of the
//! controls, and the pinned plots are the ones the plot area shows, always
//! shown, until the student leaves the lesson.
//!
//! # The `lesson` command and state
//! `{"lesson": {"note": TEXT, "hide_panels": [TITLE, …], "pin_plots": [NAME, …],
//! "open_panels": [TITLE, …]}}` sets a lesson (each key optional) and opens its
//! note when it has one; `{"lesson": false}` leaves it. `TITLE` is a control
//! panel's title as the panel shows it (`ui::panels::hideable_titles`); `NAME`
//! one of [`PLOT_NAMES`]; `open_panels` names panels whose closed sections the
//! lesson opens ([`OPENABLE_PANELS`]: the Jacobian panel). `state().lesson` is
//! that object, or `null`.
//!
//! A lesson starts from a pinned pose with the link's `pinned_targets` (the
//! link applies them before the lesson): "drag the right hand past its reach
//! and watch σ₃" is a link with the hand's target pinned near its reach, the
//! Jacobian panel open and the reach shells drawn (`views`).

use serde::{Deserialize, Serialize};

/// Longest note, characters.
pub const MAX_NOTE_CHARS: usize = 2000;

/// The plots a lesson can pin: the IK and PODA engines' effector errors and
/// joint angles, the physics engine's lengths, ground force, trunk attitude
/// and Figure 4's state.
pub const PLOT_NAMES: [&str; 6] = ["errors", "joints", "lengths", "force", "attitude", "state"];

/// The panels whose sections a lesson can open (`open_panels`): the Jacobian
/// panel (issue 44 item 5). The other panels show their controls open.
pub const OPENABLE_PANELS: [&str; 1] = ["Jacobian"];

/// The panel that shows the lesson and leaves it, never hidden.
pub const LESSON_PANEL: &str = "Lesson";

/// A teacher's note and lesson view.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Lesson {
    /// What the student reads first (plain text, at most 2000 characters).
    #[serde(default)]
    pub note: String,
    /// Control panels to hide, by title.
    #[serde(default)]
    pub hide_panels: Vec<String>,
    /// Plots to pin, by name ([`PLOT_NAMES`]).
    #[serde(default)]
    pub pin_plots: Vec<String>,
    /// Panels whose sections open when the lesson starts, by title
    /// ([`OPENABLE_PANELS`]).
    #[serde(default)]
    pub open_panels: Vec<String>,
}

impl Lesson {
    /// Checks the note's length and every name; `panels` are the titles a
    /// lesson may hide.
    ///
    /// # Errors
    /// `lesson.FIELD: reason`, naming the entry and the names allowed.
    pub fn check(&self, panels: &[&str]) -> Result<(), String> {
        let chars = self.note.chars().count();
        if chars > MAX_NOTE_CHARS {
            return Err(format!(
                "lesson.note: {chars} characters, at most {MAX_NOTE_CHARS}"
            ));
        }
        for (i, title) in self.hide_panels.iter().enumerate() {
            if !panels.contains(&title.as_str()) || title == LESSON_PANEL {
                return Err(format!(
                    "lesson.hide_panels[{i}]: no panel {title:?} to hide (panels: {})",
                    panels.join(", ")
                ));
            }
        }
        for (i, title) in self.open_panels.iter().enumerate() {
            if !OPENABLE_PANELS.contains(&title.as_str()) {
                return Err(format!(
                    "lesson.open_panels[{i}]: no panel {title:?} to open (panels a lesson opens: {})",
                    OPENABLE_PANELS.join(", ")
                ));
            }
            if self.hides(title) {
                return Err(format!(
                    "lesson.open_panels[{i}]: {title:?} is also in hide_panels; a lesson opens a \
                     panel or hides it"
                ));
            }
        }
        for (i, name) in self.pin_plots.iter().enumerate() {
            if !PLOT_NAMES.contains(&name.as_str()) {
                return Err(format!(
                    "lesson.pin_plots[{i}]: no plot {name:?} (plots: {})",
                    PLOT_NAMES.join(", ")
                ));
            }
        }
        Ok(())
    }

    /// Whether the panel titled `title` is hidden.
    #[must_use]
    pub fn hides(&self, title: &str) -> bool {
        self.hide_panels.iter().any(|t| t == title)
    }

    /// Whether the lesson opens the panel titled `title`.
    #[must_use]
    pub fn opens(&self, title: &str) -> bool {
        self.open_panels.iter().any(|t| t == title)
    }

    /// Whether the plot `name` is pinned.
    #[must_use]
    pub fn pins(&self, name: &str) -> bool {
        self.pin_plots.iter().any(|p| p == name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PANELS: &[&str] = &["Method", "Motion", "Recording", LESSON_PANEL];

    #[test]
    fn names_are_checked_and_errors_name_the_entry() {
        let ok = Lesson {
            note: "Watch pinv's hands.".to_owned(),
            hide_panels: vec!["Method".to_owned(), "Recording".to_owned()],
            pin_plots: vec!["errors".to_owned()],
            open_panels: vec!["Jacobian".to_owned()],
        };
        assert_eq!(ok.check(PANELS), Ok(()));
        assert!(ok.opens("Jacobian") && !ok.opens("Method"));
        assert!(ok.hides("Method") && !ok.hides("Motion"));
        assert!(ok.pins("errors") && !ok.pins("joints"));

        let bad_panel = Lesson {
            hide_panels: vec!["Method".to_owned(), "Warp drive".to_owned()],
            ..Lesson::default()
        };
        let error = bad_panel.check(PANELS).err().unwrap_or_default();
        assert!(
            error.starts_with("lesson.hide_panels[1]: no panel \"Warp drive\""),
            "{error}"
        );
        assert!(error.contains("Method"), "{error}");
        let own = Lesson {
            hide_panels: vec![LESSON_PANEL.to_owned()],
            ..Lesson::default()
        };
        assert!(own.check(PANELS).is_err(), "the lesson's own panel stays");
        let bad_plot = Lesson {
            pin_plots: vec!["joy".to_owned()],
            ..Lesson::default()
        };
        assert!(
            bad_plot
                .check(PANELS)
                .err()
                .unwrap_or_default()
                .starts_with("lesson.pin_plots[0]")
        );
        let bad_open = Lesson {
            open_panels: vec!["Method".to_owned()],
            ..Lesson::default()
        };
        let error = bad_open.check(PANELS).err().unwrap_or_default();
        assert!(
            error.starts_with("lesson.open_panels[0]: no panel \"Method\" to open")
                && error.contains("Jacobian"),
            "{error}"
        );
        let both = Lesson {
            hide_panels: vec!["Jacobian".to_owned()],
            open_panels: vec!["Jacobian".to_owned()],
            ..Lesson::default()
        };
        let panels = [PANELS, &["Jacobian"]].concat();
        assert!(
            both.check(&panels)
                .err()
                .unwrap_or_default()
                .contains("also in hide_panels")
        );
        let long = Lesson {
            note: "x".repeat(MAX_NOTE_CHARS + 1),
            ..Lesson::default()
        };
        assert!(
            long.check(PANELS)
                .err()
                .unwrap_or_default()
                .starts_with("lesson.note")
        );
    }
}
