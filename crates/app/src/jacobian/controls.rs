//! The Jacobian panel's step control (issue 44 item 2's "one iteration";
//! item 6: in the feature's folder): the button, and where the open frame's
//! iterations stand. The lab runs the step when asked.

/// The "One iteration" row; `step` is (iterations done, iterations per
/// frame) while a frame is open. Returns whether the button was pressed.
#[must_use]
pub fn iteration_row(ui: &mut egui::Ui, step: Option<(usize, usize)>) -> bool {
    ui.horizontal_wrapped(|ui| {
        let pressed = ui
            .button("One iteration (I)")
            .on_hover_text(
                "Pause and run a single IK iteration; the frame's last iteration closes it",
            )
            .clicked();
        if let Some((done, of)) = step {
            ui.label(format!("iteration {done} of {of} of this frame"));
        }
        pressed
    })
    .inner
}
