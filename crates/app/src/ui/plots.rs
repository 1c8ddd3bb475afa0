//! The live plots under the 3-D view (issue 21 item 2, readable plots): for
//! IK, effector errors (mm) beside the chosen joint angles; for physics, four
//! plots of one unit each — height and leg length (m), vertical ground force
//! (× body weight), the trunk's attitude (°) and Figure 4's state, by name.
//! Every plot labels its axes with their units, keeps its legend above the
//! data, reads out the nearest sample on hover and restarts cleanly when the
//! simulation does ([`History::push`]).

use std::ops::Range;

use egui::Color32;
use egui_plot::{GridMark, HoverPosition, Line, PlotPoints};
use gaitlab_engine::DriverKind;

use crate::plot_scale::{few_round_marks, tick_label};

use crate::app::App;
use crate::history::History;
use crate::lab::MAX_PLOT_JOINTS;

/// The colours of `names`' series: each by its side, as the 3-D view draws
/// it (the figure's left blue, its right orange, the centre line in other
/// hues), the `n`th of a side in its `n`th shade
/// ([`crate::render::scene::series_colour`]).
fn series_colours<'a>(names: impl Iterator<Item = &'a str>) -> impl Iterator<Item = Color32> {
    let mut count = [0_usize; 3];
    names.map(move |name| {
        let side = crate::render::scene::side_of(name) as usize;
        let nth = count[side];
        count[side] += 1;
        let [r, g, b] = crate::render::scene::series_colour(name, nth);
        Color32::from_rgb(r, g, b)
    })
}

/// Figure 4's states in the order of their index, for the state plot's axis.
const STATE_NAMES: [&str; 5] = ["flight", "loading", "compression", "thrust", "unloading"];

/// One live plot: which series of a history it draws, and in what unit.
struct PlotSpec<'a> {
    /// egui id of the plot.
    id: &'a str,
    /// The y axis' label, with its unit.
    y_label: &'a str,
    /// The unit of a hover read-out.
    unit: &'a str,
    /// The history's series this plot draws.
    series: Range<usize>,
    /// Factor from stored values to plotted ones (1e3: m to mm).
    scale: f64,
    /// The y range always includes [0, `min_span`].
    min_span: f64,
    /// Names for the integer y ticks (the states), else numbers.
    y_names: Option<&'static [&'static str]>,
}

impl App {
    /// The plots side by side, filling `ui` (the wide layout's bottom panel).
    pub(crate) fn plots_ui(&mut self, ui: &mut egui::Ui) {
        let count = self.shown_plots().count().max(1);
        let gap = ui.spacing().item_spacing.x;
        let width = ((ui.available_width() - gap * (count - 1) as f32) / count as f32).max(0.0);
        let cell = egui::vec2(width, ui.available_height());
        ui.horizontal(|ui| {
            for k in 0..self.plot_names().len() {
                if self.plot_shown(k) {
                    ui.allocate_ui(cell, |ui| ui.vertical(|ui| self.plot_cell(ui, k)));
                }
            }
        });
    }

    /// The running engine's plots by name ([`crate::lesson::PLOT_NAMES`]),
    /// in [`Lab::plot_cell`]'s order: four for physics, two for IK and PODA.
    fn plot_names(&self) -> &'static [&'static str] {
        if self.stage.driver.kind() == DriverKind::Physics {
            &["lengths", "force", "attitude", "state"]
        } else {
            &["errors", "joints"]
        }
    }

    /// Whether plot `k` of [`Lab::plot_names`] shows: every plot when the
    /// lesson pins none of this engine's plots, else only the pinned ones.
    fn plot_shown(&self, k: usize) -> bool {
        let names = self.plot_names();
        match self.lesson() {
            Some(lesson) if names.iter().any(|n| lesson.pins(n)) => lesson.pins(names[k]),
            _ => true,
        }
    }

    /// The names of the plots shown ([`crate::lesson::PLOT_NAMES`]), in order.
    pub fn plots_shown(&self) -> impl Iterator<Item = &'static str> + '_ {
        let names = self.plot_names();
        self.shown_plots().map(move |k| names[k])
    }

    /// The indices of the plots shown (a lesson may pin some).
    fn shown_plots(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.plot_names().len()).filter(move |&k| self.plot_shown(k))
    }

    /// The plots one under another, each `height` points tall, in a
    /// scrolling sheet (the phone layout's plots drawer).
    pub(crate) fn plots_stacked_ui(&mut self, ui: &mut egui::Ui, height: f32) {
        // Scrolled by dragging the sheet: no thin bar to aim at on a phone.
        egui::ScrollArea::vertical()
            .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysHidden)
            .show(ui, |ui| {
                let width = ui.available_width();
                for k in 0..self.plot_names().len() {
                    if self.plot_shown(k) {
                        ui.allocate_ui(egui::vec2(width, height), |ui| {
                            ui.vertical(|ui| self.plot_cell(ui, k))
                        });
                    }
                }
            });
    }

    /// Plot `k` of [`Lab::plot_names`], filling `ui`.
    fn plot_cell(&mut self, ui: &mut egui::Ui, k: usize) {
        if self.stage.driver.kind() == DriverKind::Physics {
            let body = &self.stage.history;
            let attitude = &self.plots.joint_history;
            let (title, history, spec) = match k {
                0 => ("Height and leg length", body, &LENGTHS),
                1 => ("Ground force", body, &FORCE),
                2 => ("Trunk attitude", attitude, &ATTITUDE),
                _ => ("State (Figure 4)", body, &STATE),
            };
            series_plot(ui, title, history, spec);
            return;
        }
        if k == 0 {
            let history = &self.stage.history;
            let spec = PlotSpec {
                series: 0..history.names.len(),
                ..ERRORS
            };
            series_plot(ui, "Effector error (mm)", history, &spec);
            return;
        }
        ui.horizontal(|ui| {
            ui.label("Joint angles");
            self.joint_picker(ui);
        });
        let history = &self.plots.joint_history;
        // One unit per axis unless a prismatic joint is chosen too.
        let mixed = history.names.iter().any(|n| n.ends_with("(mm)"));
        let spec = PlotSpec {
            series: 0..history.names.len(),
            y_label: if mixed { "° or mm" } else { "angle (°)" },
            unit: if mixed { "(° or mm)" } else { "°" },
            ..JOINTS
        };
        series_plot(ui, "", history, &spec);
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
                            .add_enabled(
                                enabled,
                                egui::Checkbox::new(&mut on, crate::words::in_words(&joint.name)),
                            )
                            .on_hover_text(format!(
                                "Plot this joint's angle (degrees; prismatic joints in millimetres), at most {MAX_PLOT_JOINTS} ({})",
                                joint.name
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

const ERRORS: PlotSpec<'static> = PlotSpec {
    id: "gaitlab-error-plot",
    y_label: "error (mm)",
    unit: "mm",
    series: 0..0,
    scale: 1e3,
    min_span: 1.0,
    y_names: None,
};

const JOINTS: PlotSpec<'static> = PlotSpec {
    id: "gaitlab-joint-plot",
    y_label: "angle (°)",
    unit: "°",
    series: 0..0,
    scale: 1.0,
    min_span: 10.0,
    y_names: None,
};

/// The physics body history's series, [`crate::lab::PHYSICS_BODY_SERIES`]:
/// height and leg length, ground force, state.
const LENGTHS: PlotSpec<'static> = PlotSpec {
    id: "gaitlab-body-plot",
    y_label: "length (m)",
    unit: "m",
    series: 0..2,
    scale: 1.0,
    min_span: 0.5,
    y_names: None,
};

const FORCE: PlotSpec<'static> = PlotSpec {
    id: "gaitlab-force-plot",
    y_label: "force (× weight)",
    unit: "× weight",
    series: 2..3,
    scale: 1.0,
    min_span: 2.0,
    y_names: None,
};

const STATE: PlotSpec<'static> = PlotSpec {
    id: "gaitlab-state-plot",
    y_label: "state",
    unit: "",
    series: 3..4,
    scale: 1.0,
    min_span: 4.0,
    y_names: Some(&STATE_NAMES),
};

const ATTITUDE: PlotSpec<'static> = PlotSpec {
    id: "gaitlab-attitude-plot",
    y_label: "angle (°)",
    unit: "°",
    series: 0..2,
    scale: 1.0,
    min_span: 10.0,
    y_names: None,
};

/// One live plot of `spec`'s series of `history`, filling the height left,
/// under its title and legend (a row of coloured names above the data, when
/// it draws more than one series): axes labelled with their units, the
/// nearest sample read out on hover.
fn series_plot(ui: &mut egui::Ui, title: &str, history: &History, spec: &PlotSpec<'_>) {
    let series = spec.series.start..spec.series.end.min(history.names.len());
    ui.horizontal_wrapped(|ui| {
        if !title.is_empty() {
            ui.strong(title);
        }
        if series.len() > 1 {
            let names = history.names[series.clone()].iter().map(String::as_str);
            for (s, colour) in series.clone().zip(series_colours(names)) {
                let (swatch, _) =
                    ui.allocate_exact_size(egui::vec2(10.0, 10.0), egui::Sense::hover());
                ui.painter().rect_filled(swatch, 2.0, colour);
                ui.label(
                    egui::RichText::new(crate::words::series_in_words(&history.names[s]))
                        .color(colour),
                )
                .on_hover_text(history.names[s].as_str());
            }
        }
    });
    let y_names = spec.y_names;
    let unit = spec.unit;
    let mut plot = crate::plot_scale::still_plot(spec.id)
        .height(ui.available_height().max(40.0))
        .include_y(0.0)
        .include_y(spec.min_span)
        .x_axis_label("time (s)")
        .y_axis_label(spec.y_label)
        .y_grid_spacer(few_round_marks)
        .y_axis_formatter(|mark, _| tick_label(mark))
        .label_formatter(move |hover| match hover {
            HoverPosition::NearDataPoint {
                plot_name,
                position,
                ..
            } => Some(match y_names {
                Some(names) => format!(
                    "{plot_name}: {} at {:.2} s",
                    state_name(names, position.y),
                    position.x
                ),
                None => format!(
                    "{plot_name}: {:.3} {unit} at {:.2} s",
                    position.y, position.x
                ),
            }),
            HoverPosition::Elsewhere { .. } => None,
        });
    if let Some(names) = y_names {
        plot = plot
            .y_axis_min_width(70.0)
            .y_grid_spacer(|input| {
                (0..STATE_NAMES.len())
                    .map(|k| GridMark {
                        value: k as f64,
                        step_size: 1.0,
                    })
                    .filter(|mark| mark.value >= input.bounds.0 && mark.value <= input.bounds.1)
                    .collect()
            })
            .y_axis_formatter(move |mark, _| {
                if mark.value.fract() == 0.0 {
                    state_name(names, mark.value).to_owned()
                } else {
                    String::new()
                }
            });
    }
    plot.show(ui, |plot| {
        let names = history.names[series.clone()].iter().map(String::as_str);
        for (s, colour) in series.zip(series_colours(names)) {
            let points: Vec<[f64; 2]> = history
                .points(s)
                .map(|[t, v]| [t, v * spec.scale])
                .collect();
            let name = crate::words::series_in_words(&history.names[s]);
            plot.line(Line::new(name, PlotPoints::from(points)).color(colour));
        }
    });
}

/// The name of state index `value` (rounded), or "" outside the list.
fn state_name(names: &'static [&'static str], value: f64) -> &'static str {
    let rounded = value.round();
    if rounded < 0.0 || !rounded.is_finite() {
        return "";
    }
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a non-negative whole number, bounded by the list's length below"
    )]
    let index = rounded as usize;
    names.get(index).copied().unwrap_or("")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_state_axis_names_figure_4s_states() {
        assert_eq!(state_name(&STATE_NAMES, 0.0), "flight");
        assert_eq!(state_name(&STATE_NAMES, 3.2), "thrust");
        assert_eq!(state_name(&STATE_NAMES, 4.0), "unloading");
        assert_eq!(state_name(&STATE_NAMES, 5.0), "");
        assert_eq!(state_name(&STATE_NAMES, -1.0), "");
        assert_eq!(state_name(&STATE_NAMES, f64::NAN), "");
    }
}
