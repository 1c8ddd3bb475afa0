//! The lab's layout: controls on the left, live plots at the bottom, the 3-D
//! view in the middle, an error banner on top when something went wrong, and
//! the keyboard shortcuts (space pause, R reset, . single step). Below
//! [`NARROW_WIDTH_PT`] (a phone, issue 6 "Comfort") the controls become a
//! drawer toggled from a slim top bar and the plots are hidden, so the 3-D
//! view keeps most of the screen.

use egui_plot::{Legend, Line, Plot, PlotPoints};

use crate::history::History;
use crate::lab::{Lab, MAX_PLOT_JOINTS};
use crate::render::viewport;
use panels::ik as basic;
use panels::{
    compare as panels_compare, gait as panels_gait, path as panels_path, physics as panels_physics,
    share as panels_editor,
};

mod panels;

/// Below this width (points, i.e. CSS pixels) the lab takes its phone layout:
/// the 3-D view fills the screen under a slim bar, the controls open as a
/// drawer over the lower part of the screen, and the plots are hidden.
pub const NARROW_WIDTH_PT: f32 = 600.0;

/// Share of the screen height the phone layout's controls drawer takes.
const DRAWER_HEIGHT_FRACTION: f32 = 0.45;

impl Lab {
    /// Shows the whole lab in `ui` and advances the animation by the frame's time.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        self.apply_theme(ui);
        let dt = ui.input(|i| f64::from(i.stable_dt));
        self.note_frame_time(dt);
        self.keyboard(ui);
        #[cfg(not(target_arch = "wasm32"))]
        self.take_dropped_file(ui);
        self.advance(dt);

        self.narrow = self
            .narrow_override
            .unwrap_or(ui.available_width() < NARROW_WIDTH_PT);
        if self.narrow {
            self.phone_layout(ui);
        } else {
            self.controls_button_pt = [0.0; 4];
            egui::Panel::left("gaitlab-controls")
                .resizable(true)
                .default_size(290.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        ui.heading("gaitlab");
                        self.controls(ui);
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
        }
        panels_editor::editor_window(&ui.ctx().clone(), self);
        egui::CentralPanel::default().show(ui, |ui| {
            if let Some(error) = self.last_error.clone() {
                ui.horizontal_wrapped(|ui| {
                    ui.colored_label(
                        egui::Color32::from_rgb(230, 90, 70),
                        format!("Problem: {error}"),
                    );
                    if ui
                        .small_button("Dismiss")
                        .on_hover_text("Hide this message")
                        .clicked()
                    {
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

    /// Every control panel, top to bottom (the wide layout's side panel and
    /// the phone layout's drawer).
    fn controls(&mut self, ui: &mut egui::Ui) {
        basic::engine(ui, self);
        basic::preset(ui, self);
        panels_editor::share(ui, self);
        // The phone layout's bar above the drawer has these already.
        if !self.narrow {
            basic::buttons(ui, self);
        }
        ui.separator();
        if self.driver.physics().is_some() {
            panels_physics::physics(ui, self);
        } else if self.driver.poda().is_some() {
            panels_gait::gait(ui, self);
            panels_path::path(ui, self);
        } else {
            panels_compare::controls(ui, self);
            if self.compare.is_none() {
                basic::method(ui, self);
            }
            basic::motion(ui, self);
            basic::speed_and_targets(ui, self);
        }
        basic::view(ui, self);
        basic::recording(ui, self);
        ui.separator();
        self.readout(ui);
    }

    /// The phone layout: a slim bar (controls drawer toggle, Reset, Play,
    /// Step) over a full-width 3-D view; the drawer, when open, takes the
    /// lower [`DRAWER_HEIGHT_FRACTION`] of the screen with bigger touch targets.
    fn phone_layout(&mut self, ui: &mut egui::Ui) {
        egui::Panel::top("gaitlab-phone-bar").show(ui, |ui| {
            ui.spacing_mut().button_padding = egui::vec2(10.0, 6.0);
            ui.horizontal_wrapped(|ui| {
                let label = if self.controls_open {
                    "Hide controls"
                } else {
                    "Controls"
                };
                let toggle = ui
                    .selectable_label(self.controls_open, label)
                    .on_hover_text(
                        "Open or close the control panels over the lower part of the screen",
                    );
                let r = toggle.rect;
                self.controls_button_pt = [r.min.x, r.min.y, r.width(), r.height()];
                if toggle.clicked() {
                    self.controls_open = !self.controls_open;
                }
                basic::buttons(ui, self);
            });
        });
        if !self.controls_open {
            return;
        }
        let height = (ui.available_height() * DRAWER_HEIGHT_FRACTION).max(160.0);
        egui::Panel::bottom("gaitlab-phone-controls")
            .resizable(false)
            .exact_size(height)
            .show(ui, |ui| {
                let spacing = ui.spacing_mut();
                spacing.button_padding = egui::vec2(10.0, 6.0);
                spacing.interact_size.y = 30.0;
                spacing.item_spacing.y = 8.0;
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.set_width(ui.available_width());
                    self.controls(ui);
                });
            });
    }

    /// Applies the chosen theme to egui (it takes effect from the next frame)
    /// and notes whether this frame is dark.
    fn apply_theme(&mut self, ui: &egui::Ui) {
        let wanted = self.settings.theme.preference();
        if ui.ctx().options(|o| o.theme_preference) != wanted {
            ui.ctx().set_theme(wanted);
            ui.ctx().request_repaint();
        }
        self.dark_mode = ui.visuals().dark_mode;
    }

    /// Whether the last frame used the phone layout.
    #[must_use]
    pub fn narrow(&self) -> bool {
        self.narrow
    }

    /// Whether the phone layout's controls drawer is open.
    #[must_use]
    pub fn controls_open(&self) -> bool {
        self.controls_open
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
        // Side by side, the views' drivers run and the single one waits.
        let time_s = self
            .compare
            .as_ref()
            .and_then(|c| c.views().first())
            .map_or_else(
                || gaitlab_core::driver::Driver::time(&self.driver),
                |view| gaitlab_core::driver::Driver::time(&view.driver),
            );
        ui.label(format!(
            "frame {} · t = {:.2} s · {:.0} fps",
            self.frame, time_s, self.fps
        ));
        if self.compare.is_some() {
            ui.label("Side by side: each view's errors are in its card below.");
            return;
        }
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
        let menu = ui.menu_button("Joints…", |ui| {
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
                            .on_hover_text(format!(
                                "Plot this joint's angle (degrees; prismatic joints in millimetres), at most {MAX_PLOT_JOINTS}"
                            ))
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
