//! The live plots under the 3-D view: effector errors (or the physics body
//! series) beside the joint angles (or the physics attitude), with a menu to
//! choose the plotted joints.

use egui_plot::{Legend, Line, Plot, PlotPoints};

use crate::history::History;
use crate::lab::{Lab, MAX_PLOT_JOINTS};

impl Lab {
    pub(crate) fn plots_ui(&mut self, ui: &mut egui::Ui) {
        let physics = self.stage.driver.physics().is_some();
        let half = (ui.available_width() - ui.spacing().item_spacing.x).max(0.0) / 2.0;
        let height = ui.available_height();
        ui.horizontal(|ui| {
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                ui.vertical(|ui| {
                    if physics {
                        ui.label("Body: height, leg length, ground force, state");
                        series_plot(ui, "gaitlab-body-plot", &self.stage.history, 1.0, 1.0);
                    } else {
                        ui.label("Effector error (mm)");
                        series_plot(ui, "gaitlab-error-plot", &self.stage.history, 1e3, 1.0);
                    }
                });
            });
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                ui.vertical(|ui| {
                    if physics {
                        ui.label("Trunk attitude (°)");
                        series_plot(
                            ui,
                            "gaitlab-attitude-plot",
                            &self.plots.joint_history,
                            1.0,
                            10.0,
                        );
                        return;
                    }
                    ui.horizontal(|ui| {
                        ui.label("Joint angles");
                        self.joint_picker(ui);
                    });
                    series_plot(
                        ui,
                        "gaitlab-joint-plot",
                        &self.plots.joint_history,
                        1.0,
                        10.0,
                    );
                });
            });
        });
    }

    /// A menu of the creature's joints with a checkbox each (at most
    /// [`MAX_PLOT_JOINTS`] plotted).
    fn joint_picker(&mut self, ui: &mut egui::Ui) {
        let mut chosen: Option<Vec<String>> = None;
        let menu = ui.menu_button("Joints…", |ui| {
            egui::ScrollArea::vertical()
                .max_height(300.0)
                .show(ui, |ui| {
                    let joints = self.session.creature.skeleton.joints();
                    for (j, joint) in joints.iter().enumerate() {
                        let mut on = self.plots.joints.contains(&j);
                        let full = self.plots.joints.len() >= MAX_PLOT_JOINTS;
                        let enabled = on || !full;
                        if ui
                            .add_enabled(enabled, egui::Checkbox::new(&mut on, joint.name.as_str()))
                            .on_hover_text(format!(
                                "Plot this joint's angle (degrees; prismatic joints in millimetres), at most {MAX_PLOT_JOINTS}"
                            ))
                            .changed()
                        {
                            let mut names: Vec<String> = self
                                .plots.joints
                                .iter()
                                .filter(|&&k| k != j)
                                .map(|&k| joints[k].name.clone())
                                .collect();
                            if on {
                                names.push(joint.name.clone());
                            }
                            chosen = Some(names);
                        }
                    }
                });
        });
        menu.response
            .on_hover_text("Choose which joints' angles the plot shows");
        if let Some(names) = chosen
            && let Err(error) = self.set_plot_joints(&names)
        {
            self.report_error(error);
        }
    }
}

/// One live plot of every series in `history`, values scaled by `scale`; the
/// y range always includes [0, `min_span`].
fn series_plot(ui: &mut egui::Ui, id: &str, history: &History, scale: f64, min_span: f64) {
    Plot::new(id)
        .legend(Legend::default())
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .include_y(0.0)
        .include_y(min_span)
        .show(ui, |plot| {
            for (s, name) in history.names.iter().enumerate() {
                let points: Vec<[f64; 2]> =
                    history.points(s).map(|[t, v]| [t, v * scale]).collect();
                plot.line(Line::new(name.as_str(), PlotPoints::from(points)));
            }
        });
}
