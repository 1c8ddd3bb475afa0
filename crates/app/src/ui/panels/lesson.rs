//! The lesson's note window and the "Lesson" panel ([`crate::lesson`]): for
//! a student, the running lesson's note again and a way out; for a teacher,
//! a note, panels to hide and plots to pin, set here and handed out with
//! "Copy link".

use super::panel::Panel;
use crate::app::App;
use crate::lesson::{LESSON_PANEL, Lesson, OPENABLE_PANELS, PLOT_NAMES};

/// The "Lesson" panel.
pub struct LessonPanel;

impl Panel for LessonPanel {
    fn title(&self) -> &'static str {
        LESSON_PANEL
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        if lab.lesson().is_some() {
            running(ui, lab);
        }
        maker(ui, lab);
    }
}

/// The running lesson: show its note again, or leave it.
fn running(ui: &mut egui::Ui, lab: &mut App) {
    ui.horizontal_wrapped(|ui| {
        ui.strong("Lesson");
        if ui
            .button("Show the note")
            .on_hover_text("The teacher's note this link opened with")
            .clicked()
        {
            lab.layout.lesson_note_open = true;
        }
        if ui
            .button("Leave the lesson")
            .on_hover_text("Show every panel and plot again")
            .clicked()
        {
            // Leaving checks nothing and cannot fail.
            let _ = lab.set_lesson(None, &[]);
        }
    });
}

/// The teacher's side: a draft kept in egui's memory until applied.
fn maker(ui: &mut egui::Ui, lab: &mut App) {
    egui::CollapsingHeader::new("Make a lesson")
        .id_salt("lesson-maker")
        .default_open(false)
        .show(ui, |ui| {
            let id = ui.make_persistent_id("lesson-draft");
            let mut draft: Lesson = ui
                .data_mut(|d| d.get_temp::<Lesson>(id))
                .or_else(|| lab.lesson().cloned())
                .unwrap_or_default();
            ui.label("A note the class reads first:");
            ui.add(
                egui::TextEdit::multiline(&mut draft.note)
                    .desired_rows(3)
                    .desired_width(f32::INFINITY)
                    .hint_text("What to watch for, what to try…"),
            );
            ui.label("Hide these panels:");
            ui.horizontal_wrapped(|ui| {
                for title in super::hideable_titles() {
                    toggle(ui, &mut draft.hide_panels, title);
                }
            });
            ui.label("Open these panels:");
            ui.horizontal_wrapped(|ui| {
                for title in OPENABLE_PANELS {
                    toggle(ui, &mut draft.open_panels, title);
                }
            });
            ui.label("Pin these plots (the others hide):");
            ui.horizontal_wrapped(|ui| {
                for name in PLOT_NAMES {
                    toggle(ui, &mut draft.pin_plots, name);
                }
            });
            ui.horizontal_wrapped(|ui| {
                if ui
                    .button("Start the lesson")
                    .on_hover_text(
                        "Apply the note, hidden and opened panels and pinned plots here; Copy \
                         link then hands the lesson out, with the pinned targets and view \
                         options as they are",
                    )
                    .clicked()
                    && let Err(error) =
                        lab.set_lesson(Some(draft.clone()), &super::hideable_titles())
                {
                    lab.report_error(error);
                }
            });
            ui.data_mut(|d| d.insert_temp(id, draft));
        });
}

/// A checkbox adding `name` to or removing it from `list`.
fn toggle(ui: &mut egui::Ui, list: &mut Vec<String>, name: &str) {
    let mut on = list.iter().any(|n| n == name);
    if ui.checkbox(&mut on, name).changed() {
        list.retain(|n| n != name);
        if on {
            list.push(name.to_owned());
        }
    }
}

/// The lesson's note, over the lab, when open (first thing a lesson link shows).
pub fn lesson_window(ctx: &egui::Context, lab: &mut App) {
    if !lab.layout.lesson_note_open {
        return;
    }
    if lab.lesson().is_none() {
        lab.layout.lesson_note_open = false;
        return;
    }
    let mut open = true;
    let mut start = false;
    let placement = crate::ui::window::Placement {
        width_pt: 420.0,
        height_pt: None,
        height_share: 0.8,
        centred: true,
        scrolls: true,
    };
    let narrow = lab.narrow();
    crate::ui::window::show(ctx, "Lesson", narrow, &mut open, placement, |ui| {
        let note = lab.lesson().map_or("", |l| l.note.as_str());
        ui.add(egui::Label::new(note).wrap());
        ui.add_space(8.0);
        start = ui
            .button("Start")
            .on_hover_text("Close the note (Lesson panel: Show the note)")
            .clicked();
    });
    if !open || start {
        lab.layout.lesson_note_open = false;
    }
}
