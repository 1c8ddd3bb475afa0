//! The Share panel and the preset editor window (issue 6 items 2–3): "Copy
//! link" (the full-state link of [`crate::link_state`], copied and shown for
//! copying by hand), and a monospace JSON editor of the running preset with
//! Apply / Revert, file loading and download, its validation message (the
//! core's `json.path: reason`) under the text.

use super::panel::Panel;
use crate::app::App;

/// The Share row.
pub struct SharePanel;

impl Panel for SharePanel {
    fn title(&self) -> &'static str {
        "Share"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        share(ui, lab);
    }
}

/// Colour of problem messages.
use crate::theme::PROBLEM_COLOR as PROBLEM;

/// The Share row: Copy link, Edit preset, Load preset file, Download preset.
fn share(ui: &mut egui::Ui, lab: &mut App) {
    ui.horizontal_wrapped(|ui| {
        if ui
            .button("Copy link")
            .on_hover_text(
                "Copy a link that opens this lab exactly as it is now: preset, engine, \
                 settings and camera",
            )
            .clicked()
        {
            match lab.share_link() {
                Ok(link) => {
                    ui.ctx().copy_text(link.clone());
                    lab.shown_link = Some(link);
                }
                Err(error) => lab.report_error(error),
            }
        }
        let label = if lab.editor.open {
            "Close editor"
        } else {
            "Edit preset…"
        };
        if ui
            .button(label)
            .on_hover_text("Edit the creature's preset JSON and apply it")
            .clicked()
        {
            lab.set_editor_open(!lab.editor.open);
        }
        if ui
            .button("Load file…")
            .on_hover_text(
                "Load a preset JSON file (at most 256 KiB), or a target CSV to follow (header t, \
                 then x,y,z per effector, as gaitlab track reads); or drop one onto the page",
            )
            .clicked()
        {
            lab.request_file_pick();
        }
        if ui
            .button("Download preset")
            .on_hover_text("Save the running preset as a JSON file")
            .clicked()
        {
            lab.download_preset();
        }
    });
    let mut close = false;
    if let Some(link) = &lab.shown_link {
        // The row must end at the panel's edge: the side panel grows to fit
        // what it holds, and a row wider than the room left would widen it a
        // little every frame (a field sized from `available_width` minus a
        // guess at the button's width did, 4.6 px a second). Laid out right to
        // left, the button comes first and the field takes exactly what is
        // left; a single-line field clips its text, so the link's length
        // never counts.
        ui.horizontal(|ui| {
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                close = ui
                    .small_button("×")
                    .on_hover_text("Hide the link")
                    .clicked();
                let mut shown = link.as_str();
                ui.add(
                    egui::TextEdit::singleline(&mut shown)
                        .desired_width(ui.available_width())
                        .font(egui::TextStyle::Monospace),
                )
                .on_hover_text("The link, copied to the clipboard; select it to copy it by hand");
            });
        });
    }
    if close {
        lab.shown_link = None;
    }
}

impl App {
    /// Shows the full-state link under the Share row, as "Copy link" does but
    /// without touching the clipboard (the `show_link` command), or hides it.
    ///
    /// # Errors
    /// Why the link could not be made.
    pub fn show_link(&mut self, show: bool) -> Result<(), String> {
        self.shown_link = if show { Some(self.share_link()?) } else { None };
        Ok(())
    }
}

/// The preset editor window, when open.
pub fn editor_window(ctx: &egui::Context, lab: &mut App) {
    if !lab.editor.open {
        return;
    }
    lab.editor_sync();
    let mut open = true;
    let mut apply = false;
    let mut revert = false;
    let mut undo = false;
    // Within the screen on a phone too.
    let narrow = lab.narrow();
    let placement = crate::ui::window::Placement {
        width_pt: 520.0,
        height_pt: Some(520.0),
        height_share: 0.8,
        centred: false,
        scrolls: false,
    };
    crate::ui::window::show(ctx, "Preset editor", narrow, &mut open, placement, |ui| {
        ui.horizontal_wrapped(|ui| {
            apply = ui
                .button("Apply")
                .on_hover_text("Validate the JSON and run it (a bad preset changes nothing)")
                .clicked();
            revert = ui
                .add_enabled(lab.editor.dirty(), egui::Button::new("Revert"))
                .on_hover_text("Put the running preset's JSON back")
                .clicked();
            if ui
                .button("Load file…")
                .on_hover_text(
                    "Load a preset JSON file or a target CSV (or drop one onto the page)",
                )
                .clicked()
            {
                lab.request_file_pick();
            }
            if ui
                .button("Download")
                .on_hover_text("Save the running preset as a JSON file")
                .clicked()
            {
                lab.download_preset();
            }
            if lab.editor.dirty() {
                ui.label("edited, not applied");
            }
        });
        // Room under the text for the message.
        let text_height = (ui.available_height() - 56.0).max(120.0);
        let error_line = lab.editor.problem.as_ref().and_then(|p| p.line);
        egui::ScrollArea::both()
            .scroll_bar_visibility(crate::ui::window::scroll_bars(narrow))
            .max_height(text_height)
            .show(ui, |ui| {
                ui.horizontal_top(|ui| {
                    line_numbers(ui, &lab.editor.text, error_line);
                    let mut layouter = |ui: &egui::Ui, text: &dyn egui::TextBuffer, _: f32| {
                        ui.fonts_mut(|f| f.layout_job(code_job(ui, text.as_str(), error_line)))
                    };
                    ui.add(
                        egui::TextEdit::multiline(&mut lab.editor.text)
                            .code_editor()
                            .desired_width(f32::INFINITY)
                            .desired_rows(24)
                            .layouter(&mut layouter),
                    )
                    .on_hover_text("The preset JSON (DESIGN.md limits: 256 KiB, 512 joints)");
                });
            });
        if let Some(problem) = &lab.editor.problem {
            let at = problem
                .line
                .map(|line| format!(" (line {line})"))
                .unwrap_or_default();
            ui.colored_label(PROBLEM, format!("Invalid preset{at}: {}", problem.message));
        } else if let Some(note) = &lab.editor.applied_note {
            ui.horizontal(|ui| {
                ui.colored_label(APPLIED, note);
                if lab.editor.before_apply.is_some()
                    && ui
                        .button("Undo")
                        .on_hover_text("Run the preset as it was before this Apply again")
                        .clicked()
                {
                    undo = true;
                }
            });
        }
    });
    if apply {
        // The message is kept in the editor; the creature stays on a bad edit.
        let _ = lab.editor_apply();
    }
    if revert {
        lab.editor_revert();
    }
    if undo && let Err(error) = lab.editor_undo_apply() {
        lab.report_error(error);
    }
    if !open {
        lab.set_editor_open(false);
    }
}

/// The colour of a good Apply's note.
const APPLIED: egui::Color32 = egui::Color32::from_rgb(60, 160, 90);

/// The editor's line numbers, one per line of `text`, the problem's line in
/// the problem colour.
fn line_numbers(ui: &mut egui::Ui, text: &str, error_line: Option<usize>) {
    let lines = text.split('\n').count().max(1);
    let width = lines.to_string().len();
    let mut job = egui::text::LayoutJob::default();
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    for line in 1..=lines {
        let colour = if Some(line) == error_line {
            PROBLEM
        } else {
            ui.visuals().weak_text_color()
        };
        let end = if line < lines { "\n" } else { "" };
        job.append(
            &format!("{line:>width$}{end}"),
            0.0,
            egui::TextFormat::simple(font.clone(), colour),
        );
    }
    ui.label(job);
}

/// The editor's text laid out without soft wraps (lines keep the numbers
/// beside them), the problem's line on a tinted background.
fn code_job(ui: &egui::Ui, text: &str, error_line: Option<usize>) -> egui::text::LayoutJob {
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    let colour = ui.visuals().text_color();
    let mut job = egui::text::LayoutJob::default();
    job.wrap.max_width = f32::INFINITY;
    for (k, line) in text.split_inclusive('\n').enumerate() {
        let mut format = egui::TextFormat::simple(font.clone(), colour);
        if Some(k + 1) == error_line {
            format.background = PROBLEM.gamma_multiply(0.3);
        }
        job.append(line, 0.0, format);
    }
    job
}
