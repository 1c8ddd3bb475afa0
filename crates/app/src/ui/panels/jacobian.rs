//! The Jacobian panel (issue 44 item 2) in the lab: this adapter draws the
//! feature's own pieces — [`crate::jacobian::iteration_row`],
//! [`crate::grab::controls`], [`crate::jacobian::figures`] — from the lab's
//! figures and carries out what they ask.

use super::panel::Panel;
use crate::app::App;

/// The Jacobian panel, for the IK engine's thesis script (alone or side by side).
pub struct JacobianPanel;

impl Panel for JacobianPanel {
    fn title(&self) -> &'static str {
        "Jacobian"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().ik_solver().is_some()
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        let open = lab.jacobian.open_request.take();
        egui::CollapsingHeader::new("Jacobian (§4.4, the SVD of J)")
            .open(open)
            .show(ui, |ui| {
                let step = lab
                    .driver()
                    .thesis()
                    .filter(|d| d.frame_open())
                    .map(|d| (d.iteration_log().len(), d.params().iterations_per_frame));
                if crate::jacobian::iteration_row(ui, step)
                    && let Err(error) = lab.step_iteration()
                {
                    lab.report_error(error);
                }
                if crate::grab::controls(ui, &mut lab.grab) {
                    lab.release_all_targets();
                }
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
