//! The preset editor's model (issue 6 item 3): the current preset's JSON as
//! editable text and the last problem. The lab's side (`lab/editor.rs`) fills
//! it and runs Apply / Revert, files loaded by picker or drag-and-drop, and
//! "Download preset". Validation is the core's (DESIGN.md "Input limits"):
//! errors read `preset: json.path: reason`, syntax errors name the line and
//! column, and a bad edit leaves the running creature alone. The editor shows
//! the problem in the user's terms ([`crate::editor_message`]) at its line,
//! confirms a good Apply, and can undo it.

use crate::editor_message::{EditorProblem, explain};

/// The preset that ran before an Apply.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BeforeApply {
    /// A bundled preset, by name (Undo reloads it as bundled).
    Bundled(String),
    /// An edited or loaded preset's text.
    Custom(String),
}

/// The editor's state.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PresetEditor {
    /// Whether the editor window is shown.
    pub open: bool,
    /// The text being edited.
    pub text: String,
    /// The last Apply's or file load's problem, shown under the editor.
    pub error: Option<String>,
    /// `error` in the user's terms, with the line it stands on.
    pub problem: Option<EditorProblem>,
    /// What the last good Apply did ("Applied: NAME, 20 joints"), until the
    /// text changes again.
    pub applied_note: Option<String>,
    /// The running preset before the last good Apply, for Undo.
    pub before_apply: Option<BeforeApply>,
    /// The text of the running preset the editor was filled from; `None`
    /// until it is filled (and after the preset changes).
    source: Option<String>,
}

impl PresetEditor {
    /// Whether the text differs from the running preset.
    #[must_use]
    pub fn dirty(&self) -> bool {
        self.source.as_ref().is_some_and(|s| *s != self.text)
    }

    /// Forgets the filled text so the next [`App::editor_sync`](crate::App::editor_sync) refills it
    /// (called when the running preset changes). Unapplied edits are kept.
    pub(crate) fn preset_changed(&mut self) {
        if !self.dirty() {
            self.source = None;
        }
    }

    /// Whether the editor has not been filled from the running preset yet.
    pub(crate) fn needs_fill(&self) -> bool {
        self.source.is_none()
    }

    /// Fills the editor with the running preset's `text`, replacing what it holds.
    pub(crate) fn fill(&mut self, text: String) {
        self.text.clone_from(&text);
        self.source = Some(text);
    }

    /// Forgets the filled text and the error, so the next fill replaces unapplied edits.
    pub(crate) fn clear(&mut self) {
        self.source = None;
        self.set_error(None);
        self.applied_note = None;
    }

    /// Records that `text` was applied: it is now the running preset's, with
    /// no error; `note` says what changed.
    pub(crate) fn applied(&mut self, text: String, note: String) {
        self.set_error(None);
        self.applied_note = Some(note);
        self.source = Some(text);
    }

    /// Records the last problem (or none), explained against the text.
    pub(crate) fn set_error(&mut self, error: Option<String>) {
        self.problem = error.as_deref().map(|e| explain(e, &self.text));
        self.error = error;
        if self.error.is_some() {
            self.applied_note = None;
        }
    }
}

/// Indented JSON for the editor: text that already has line breaks stays as
/// it is; a one-line preset (from a link or a minified file) is spread out.
#[must_use]
pub fn readable_json(text: &str) -> String {
    if text.contains('\n') {
        return text.to_owned();
    }
    serde_json::from_str::<serde_json::Value>(text)
        .ok()
        .and_then(|value| serde_json::to_string_pretty(&value).ok())
        .unwrap_or_else(|| text.to_owned())
}
