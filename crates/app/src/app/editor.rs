//! The app's side of the preset editor ([`crate::editor`]): filling it from the
//! running preset, Apply / Revert, preset files loaded by picker or
//! drag-and-drop, and "Download preset".

use gaitlab_core::preset::MAX_PRESET_BYTES;

use super::App;
use crate::editor::{BeforeApply, PresetEditor, readable_json};
use crate::lab::{Download, Effect};

impl App {
    /// The running preset's JSON: the custom text, or the bundled file.
    #[must_use]
    pub fn preset_text(&self) -> String {
        self.session.preset_text()
    }

    /// The preset editor.
    #[must_use]
    pub fn editor(&self) -> &PresetEditor {
        &self.editor
    }

    /// Fills the editor from the running preset unless it already holds it
    /// (or unapplied edits).
    pub fn editor_sync(&mut self) {
        if self.editor.needs_fill() {
            let text = readable_json(&self.preset_text());
            self.editor.fill(text);
        }
    }

    /// Shows or hides the editor.
    pub fn set_editor_open(&mut self, open: bool) {
        self.editor.open = open;
        if open {
            self.editor_sync();
        }
    }

    /// Replaces the editor's text (not applied yet).
    pub fn set_editor_text(&mut self, text: &str) {
        self.editor_sync();
        text.clone_into(&mut self.editor.text);
    }

    /// Puts the running preset's text back in the editor.
    pub fn editor_revert(&mut self) {
        self.editor.clear();
        self.editor_sync();
    }

    /// Runs the editor's text as the preset. On a problem the error is shown
    /// under the editor and the running creature stays.
    ///
    /// # Errors
    /// `preset: json.path: reason` (or the line and column of a syntax error).
    pub fn editor_apply(&mut self) -> Result<(), String> {
        self.editor_sync();
        let text = self.editor.text.clone();
        let before = match &self.session.custom_preset {
            Some(text) => BeforeApply::Custom(text.clone()),
            None => BeforeApply::Bundled(self.session.creature.name.clone()),
        };
        match self.set_custom_preset(&text) {
            Ok(()) => {
                let creature = &self.session.creature;
                let note = format!(
                    "Applied: {}, {} joints",
                    creature.name,
                    creature.skeleton.joint_count()
                );
                self.editor.before_apply = Some(before);
                self.editor.applied(text, note);
                Ok(())
            }
            Err(error) => {
                self.editor.set_error(Some(error.clone()));
                Err(error)
            }
        }
    }

    /// Runs the preset as it was before the last good Apply again, and puts
    /// its text in the editor.
    ///
    /// # Errors
    /// When there is nothing to undo, or the old text no longer runs.
    pub fn editor_undo_apply(&mut self) -> Result<(), String> {
        let Some(before) = self.editor.before_apply.take() else {
            return Err("editor: nothing applied to undo".to_owned());
        };
        match &before {
            BeforeApply::Bundled(name) => self.set_preset(name)?,
            BeforeApply::Custom(text) => self.set_custom_preset(text)?,
        }
        self.editor.clear();
        self.editor_sync();
        self.editor.applied_note = Some(format!("Undone: back to {}", self.session.creature.name));
        Ok(())
    }

    /// Loads a preset file (picked or dropped): at most the preset size limit,
    /// UTF-8, then validated like any preset. A file that does not load stays
    /// in the editor, opened, with its problem under it.
    ///
    /// # Errors
    /// `file NAME: reason`; the running creature stays.
    pub fn load_preset_file(&mut self, name: &str, bytes: &[u8]) -> Result<(), String> {
        let result = if bytes.len() > MAX_PRESET_BYTES {
            Err(format!(
                "file {name}: {} bytes, more than the {} KiB preset limit",
                bytes.len(),
                MAX_PRESET_BYTES / 1024
            ))
        } else {
            match std::str::from_utf8(bytes) {
                Err(_) => Err(format!("file {name}: not UTF-8 text")),
                Ok(text) => match self.set_custom_preset(text) {
                    Ok(()) => {
                        self.editor.clear();
                        self.editor_sync();
                        Ok(())
                    }
                    Err(error) => {
                        self.editor_sync();
                        text.clone_into(&mut self.editor.text);
                        self.editor.open = true;
                        Err(format!("file {name}: {error}"))
                    }
                },
            }
        };
        if let Err(error) = &result {
            self.editor.set_error(Some(error.clone()));
            self.report_error(error.clone());
        }
        result
    }

    /// Asks the front end to open the preset file picker.
    pub fn request_file_pick(&mut self) {
        self.outbox.push(Effect::PickFile);
    }

    /// Queues the running preset's JSON as a download (`NAME.json`).
    pub fn download_preset(&mut self) {
        let clean: String = self
            .session
            .creature
            .name
            .chars()
            .filter(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_'))
            .collect();
        let file_name = if clean.is_empty() {
            "preset.json".to_owned()
        } else {
            format!("{clean}.json")
        };
        let text = self.preset_text();
        self.outbox.push(Effect::Download(Download {
            file_name,
            mime: "application/json",
            text,
        }));
    }

    /// Loads the first file dropped on the window this frame, if any (natively;
    /// on the web the glue reads dropped files, which only arrive asynchronously).
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn take_dropped_file(&mut self, ui: &egui::Ui) {
        let Some(file) = ui.input(|i| i.raw.dropped_files.first().cloned()) else {
            return;
        };
        let name = file.path().file_name().map_or_else(
            || "dropped file".to_owned(),
            |n| n.to_string_lossy().into_owned(),
        );
        match file.bytes() {
            // The error is shown by load_file.
            Ok(bytes) => drop(self.load_file(&name, &bytes)),
            Err(error) => self.report_error(format!("file {name}: {error}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Settings;

    #[test]
    fn a_bad_edit_names_the_path_and_keeps_the_creature() {
        let mut lab = App::new(Settings::default());
        lab.set_editor_open(true);
        let good = lab.editor().text.clone();
        assert!(!good.is_empty() && !lab.editor().dirty());
        let bad = good.replacen("\"name\": \"human\"", "\"name\": \"\"", 1);
        assert_ne!(bad, good, "the human preset has a name field");
        lab.set_editor_text(&bad);
        assert!(lab.editor().dirty());
        let error = lab.editor_apply().expect_err("an empty name is invalid");
        assert!(error.starts_with("preset: name"), "{error}");
        assert_eq!(lab.editor().error.as_deref(), Some(error.as_str()));
        assert_eq!(lab.creature().name, "human");
        let error = {
            lab.set_editor_text("{\n  \"name\": \"x\",\n  oops\n}");
            lab.editor_apply().expect_err("syntax")
        };
        assert!(error.contains("line 3"), "{error}");
        lab.editor_revert();
        assert_eq!(lab.editor().text, good);
        assert!(lab.editor().error.is_none());
    }

    #[test]
    fn files_over_the_limit_or_not_text_are_refused_before_parsing() {
        let mut lab = App::new(Settings::default());
        let big = vec![b' '; MAX_PRESET_BYTES + 1];
        let error = lab.load_preset_file("big.json", &big).expect_err("too big");
        assert!(error.contains("256 KiB"), "{error}");
        let error = lab
            .load_preset_file("bin.json", &[0xff, 0xfe, 0x00])
            .expect_err("binary");
        assert!(error.contains("UTF-8"), "{error}");
        assert_eq!(lab.creature().name, "human");
        let quadruped = gaitlab_core::preset::bundled_json("ik-quadruped").expect("bundled");
        lab.load_preset_file("q.json", quadruped.as_bytes())
            .expect("loads");
        assert_eq!(lab.creature().name, "ik-quadruped");
        assert_eq!(lab.editor().text, quadruped);
        lab.download_preset();
        let download = lab.take_download().expect("queued");
        assert_eq!(download.file_name, "ik-quadruped.json");
        assert_eq!(download.text, quadruped);
    }
}
