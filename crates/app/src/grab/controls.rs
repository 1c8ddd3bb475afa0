//! The hand's controls in the Jacobian panel (issue 44 item 1; item 6: in
//! the drag's folder): *Pin dragged targets* and *Let go of all*.

use super::hand::Grab;

/// The row: the pin toggle, set on `grab`, and *Let go of all*, whose press
/// is returned (the lab lets go of every figure's targets).
#[must_use]
pub fn controls(ui: &mut egui::Ui, grab: &mut Grab) -> bool {
    let let_go = ui
        .horizontal_wrapped(|ui| {
            ui.checkbox(&mut grab.pin_on_release, "Pin dragged targets")
                .on_hover_text(
                    "The lab's addition: a target you drag in the view stays where you leave it",
                );
            ui.button("Let go of all")
                .on_hover_text("Every held or pinned target back to the script")
                .clicked()
        })
        .inner;
    ui.label("Drag a target (or a hand or foot) in the view to pull it.");
    let_go
}
