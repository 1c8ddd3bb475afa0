//! The lab's layout: controls on the left, live plots at the bottom, the 3-D
//! view in the middle, an error banner on top when something went wrong, and
//! the keyboard shortcuts (space pause, R reset, . single step).

use egui_plot::{Legend, Line, Plot, PlotPoints};

use crate::history::History;
use crate::lab::{Lab, MAX_PLOT_JOINTS};
use crate::render::viewport;
use crate::{panels, panels_compare, panels_editor, panels_gait, panels_path, panels_physics};

impl Lab {
    /// Shows the whole lab in `ui` and advances the animation by the frame's time.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        let dt = ui.input(|i| f64::from(i.stable_dt));
        self.note_frame_time(dt);
        self.keyboard(ui);
        #[cfg(not(target_arch = "wasm32"))]
        self.take_dropped_file(ui);
        self.advance(dt);

        egui::Panel::left("gaitlab-controls")
            .resizable(true)
            .default_size(290.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.heading("gaitlab");
                    panels::engine(ui, self);
                    panels::preset(ui, self);
                    panels_editor::share(ui, self);
                    panels::buttons(ui, self);
                    ui.separator();
                    if self.driver.physics().is_some() {
                        panels_physics::physics(ui, self);
                    } else if self.driver.poda().is_some() {
                        panels_gait::gait(ui, self);
                        panels_path::path(ui, self);
                    } else {
                        panels_compare::controls(ui, self);
                        if self.compare.is_none() {
                            panels::method(ui, self);
                        }
                        panels::motion(ui, self);
                        panels::speed_and_targets(ui, self);
                    }
                    panels::view(ui, self);
                    panels::recording(ui, self);
                    ui.separator();
                    self.readout(ui);
                });
            });
        if self.compare.is_some() {
            egui::Panel::bottom("gaitlab-compare")
                .resizable(true)
                .default_size(330.0)
                .show(ui, |ui| panels_compare::cards(ui, self));
        } else if self.settings.plots {
            egui::Panel::bottom("gaitlab-plots")
                .resizable(true)
                .default_size(170.0)
                .show(ui, |ui| self.plots(ui));
        }
        panels_editor::editor_window(&ui.ctx().clone(), self);
        egui::CentralPanel::default().show(ui, |ui| {
            if let Some(error) = self.last_error.clone() {
                ui.horizontal(|ui| {
                    ui.colored_label(
                        egui::Color32::from_rgb(230, 90, 70),
                        format!("Problem: {error}"),
                    );
                    if ui.small_button("Dismiss").clicked() {
                        self.clear_error();
                    }
                });
            }
            let rect = match &self.compare {
                Some(compare) => {
                    let labels: Vec<String> = compare
                        .views()
                        .iter()
                        .enumerate()
                        .map(|(i, v)| format!("{} · {}", i + 1, v.method.label()))
                        .collect();
                    let panes: Vec<_> = compare
                        .views()
                        .iter()
                        .zip(&labels)
                        .map(|(v, label)| (&v.scene, label.as_str()))
                        .collect();
                    viewport::show_split(ui, &panes, &mut self.camera, &self.settings.view).rect
                }
                None => viewport::show(ui, &self.scene, &mut self.camera, &self.settings.view).rect,
            };
            let ppp = ui.ctx().pixels_per_point();
            self.view_rect_px = [
                rect.min.x * ppp,
                rect.min.y * ppp,
                rect.width() * ppp,
                rect.height() * ppp,
            ];
        });
        if !self.paused {
            ui.ctx().request_repaint();
        }
    }

    fn keyboard(&mut self, ui: &egui::Ui) {
        if ui.ctx().egui_wants_keyboard_input() {
            return;
        }
        let (space, reset, step) = ui.input(|i| {
            (
                i.key_pressed(egui::Key::Space),
                i.key_pressed(egui::Key::R),
                i.key_pressed(egui::Key::Period),
            )
        });
        if space {
            self.set_paused(!self.paused);
        }
        if reset {
            self.reset();
        }
        if step {
            self.set_paused(true);
            self.single_step();
        }
    }

    fn readout(&self, ui: &mut egui::Ui) {
        ui.label(format!(
            "frame {} · t = {:.2} s · {:.0} fps",
            self.frame,
            gaitlab_core::driver::Driver::time(&self.driver),
            self.fps
        ));
        if self.sim_us_per_frame > 0.0 {
            ui.label(format!(
                "simulation + IK: {:.1} µs per frame",
                self.sim_us_per_frame
            ));
        }
        if let Some(report) = gaitlab_core::driver::Driver::ik_report(&self.driver) {
            for (effector, error) in self
                .creature
                .skeleton
                .effectors()
                .iter()
                .zip(&report.effector_error_m)
            {
                ui.label(format!("{}: {:.2} mm", effector.name, error * 1e3));
            }
        }
    }

    fn plots(&mut self, ui: &mut egui::Ui) {
        let physics = self.driver.physics().is_some();
        let half = (ui.available_width() - ui.spacing().item_spacing.x).max(0.0) / 2.0;
        let height = ui.available_height();
        ui.horizontal(|ui| {
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                ui.vertical(|ui| {
                    if physics {
                        ui.label("Body: height, leg length, ground force, state");
                        series_plot(ui, "gaitlab-body-plot", &self.history, 1.0, 1.0);
                    } else {
                        ui.label("Effector error (mm)");
                        series_plot(ui, "gaitlab-error-plot", &self.history, 1e3, 1.0);
                    }
                });
            });
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                ui.vertical(|ui| {
                    if physics {
                        ui.label("Trunk attitude (°)");
                        series_plot(ui, "gaitlab-attitude-plot", &self.joint_history, 1.0, 10.0);
                        return;
                    }
                    ui.horizontal(|ui| {
                        ui.label("Joint angles");
                        self.joint_picker(ui);
                    });
                    series_plot(ui, "gaitlab-joint-plot", &self.joint_history, 1.0, 10.0);
                });
            });
        });
    }

    /// A menu of the creature's joints with a checkbox each (at most
    /// [`MAX_PLOT_JOINTS`] plotted).
    fn joint_picker(&mut self, ui: &mut egui::Ui) {
        let mut chosen: Option<Vec<String>> = None;
        ui.menu_button("Joints…", |ui| {
            egui::ScrollArea::vertical()
                .max_height(300.0)
                .show(ui, |ui| {
                    let joints = self.creature.skeleton.joints();
                    for (j, joint) in joints.iter().enumerate() {
                        let mut on = self.plot_joints.contains(&j);
                        let full = self.plot_joints.len() >= MAX_PLOT_JOINTS;
                        let enabled = on || !full;
                        if ui
                            .add_enabled(enabled, egui::Checkbox::new(&mut on, joint.name.as_str()))
                            .changed()
                        {
                            let mut names: Vec<String> = self
                                .plot_joints
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
