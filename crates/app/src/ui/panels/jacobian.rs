//! The Jacobian panel (issue 44 item 2): inside the running method — the
//! figures of [`crate::jacobian::figures`], the one-iteration step, and the
//! grab-and-pull controls (pin on release, let go of every target).

use super::panel::Panel;
use crate::lab::Lab;

/// The Jacobian panel, for the IK engine's thesis script (alone or side by side).
pub struct JacobianPanel;

impl Panel for JacobianPanel {
    fn title(&self) -> &'static str {
        "Jacobian"
    }

    fn shown_for(&self, lab: &Lab) -> bool {
        lab.driver().ik_solver().is_some()
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        let open = lab.layout.jacobian_open.take();
        egui::CollapsingHeader::new("Jacobian (§4.4, the SVD of J)")
            .open(open)
            .show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                if ui
                    .button("One iteration (I)")
                    .on_hover_text(
                        "Pause and run a single IK iteration; the frame's last iteration closes it",
                    )
                    .clicked()
                    && let Err(error) = lab.step_iteration()
                {
                    lab.report_error(error);
                }
                if let Some(step) = lab.driver().thesis().filter(|d| d.frame_open()).map(|d| {
                    (
                        d.iteration_log().len(),
                        d.params().iterations_per_frame,
                    )
                }) {
                    ui.label(format!("iteration {} of {} of this frame", step.0, step.1));
                }
            });
            ui.horizontal_wrapped(|ui| {
                ui.checkbox(&mut lab.grab.pin_on_release, "Pin dragged targets")
                    .on_hover_text(
                        "The lab's addition: a target you drag in the view stays where you leave it",
                    );
                if ui
                    .button("Let go of all")
                    .on_hover_text("Every held or pinned target back to the script")
                    .clicked()
                {
                    lab.release_all_targets();
                }
            });
            ui.label("Drag a target (or a hand or foot) in the view to pull it.");
            let views: Vec<(String, egui::Color32)> = match lab.comparison() {
                Some(compare) => compare
                    .views()
                    .iter()
                    .enumerate()
                    .map(|(i, v)| (v.method.label().to_owned(), compare.colour(i)))
                    .collect(),
                None => vec![(
                    lab.settings().method.name().to_owned(),
                    crate::compare::colour32(crate::compare::method_colour(
                        crate::compare::CompareMethod::of(lab.settings().method),
                    )),
                )],
            };
            crate::jacobian::figures(ui, lab.jacobian(), &views);
        });
    }
}
