//! The physics panel (Raibert & Hodgins 1991): the gait, sliders for the
//! desired speed and hop height the controllers regulate (eqs. 2–3), the
//! state machine's state (Figure 4), and the live Table-2 figures beside the
//! paper's animation column.

use gaitlab_core::params::Origin;
use gaitlab_core::preset::physics::MAX_CONTROLLER_VALUE;
use gaitlab_engine::DriverKind;

use super::panel::Panel;
use crate::app::App;
use crate::param_widgets::{self as widgets, Param, key};

/// The physics panel.
pub struct PhysicsPanel;

impl Panel for PhysicsPanel {
    fn title(&self) -> &'static str {
        "Physics"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().kind() == DriverKind::Physics
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        physics(ui, lab);
    }
}

/// The physics panel (shown for physics creatures).
fn physics(ui: &mut egui::Ui, lab: &mut App) {
    let Some(readout) = lab.driver().physics_readout() else {
        return;
    };
    let current = readout.gait;
    let names = readout.gaits;
    let tested = readout.tested_speeds_mps;
    let tested_scale = readout.tested_scales;
    let mut speed = readout.speed_mps;
    let mut hop = readout.hop_height_m.unwrap_or(0.1);
    let summary = readout.figures;
    let phase = readout.phase;
    let time = readout.time_s;
    let resets = readout.resets;
    let gains = readout.gains;
    let additions = readout.lab_additions;
    let on_cycle = readout.started_on_cycle;
    let to_start = readout.switch_to_start.join(", ");
    // The running creature's L; the slider below clamps its own copy to
    // its range, so a scale set from a command or a file is judged as it is.
    let running_scale = readout.scale;
    let mut scale = running_scale;
    let mut new_scale = None;
    let mut place_box = false;
    let mut push = None;
    let push_view = PushView {
        heading_rad: readout.heading_rad,
        steerable: readout.route.steerable,
        last_push: readout.last_push.clone(),
        run_time_s: readout.run_time_s,
    };
    let mut chosen = None;
    let mut edits: Vec<(&str, f64)> = Vec::new();
    let mut gain_edits: Vec<(&'static str, f64)> = Vec::new();
    egui::CollapsingHeader::new("Physics (Raibert & Hodgins)")
        .default_open(true)
        .show(ui, |ui| {
            egui::ComboBox::from_label("Gait")
                .selected_text(current.as_str())
                .show_ui(ui, |ui| {
                    for &name in names {
                        if ui
                            .selectable_label(name == current, name)
                            .on_hover_text("Switch the state machine to this gait")
                            .clicked()
                        {
                            chosen = Some(name);
                        }
                    }
                })
                .response
                .on_hover_text("The gait the controllers' state machine runs");
            let speed_param = Param::new(key::PHYSICS_SPEED).band(speed_band(tested));
            // A wider rail over the gait's own speeds, in steps of 0.05 m/s:
            // a drag moves the speed by what a person can follow; a typed
            // value may leave the rail (the table's range still holds).
            let response = ui
                .scope(|ui| {
                    ui.spacing_mut().slider_width = SPEED_SLIDER_PT;
                    let response = widgets::add(
                        ui,
                        speed_param,
                        egui::Slider::new(&mut speed, speed_param.range())
                            .step_by(SPEED_STEP_MPS)
                            .clamping(egui::SliderClamping::Never)
                            .text(speed_param.text("Desired speed")),
                        "ẋ_d of eq. 3: foot placement about the neutral point regulates it. \
                         The rail spans the gait's tested speeds and 1 m/s either side; type \
                         a value for more",
                    );
                    if let Some(band) = tested {
                        band_under_slider(ui, response.rect, speed_param.range(), band, false);
                    }
                    response
                })
                .inner;
            if response.changed() {
                edits.push((speed_param.command(), speed));
            }
            speed_range_line(ui, speed, tested);
            let hop_param = Param::new(key::HOP_HEIGHT).band(HOP_RANGE_M);
            if widgets::add(
                ui,
                hop_param,
                egui::Slider::new(&mut hop, hop_param.range()).text(hop_param.text("Hop height")),
                "Eq. 2: the thrust in stance is set so each hop reaches this height",
            )
            .changed()
            {
                edits.push((hop_param.command(), hop));
            }
            let scale_param = Param::new(key::SCALE).band(SCALE_RANGE);
            let response = widgets::add(
                ui,
                scale_param,
                egui::Slider::new(&mut scale, scale_param.range())
                    .logarithmic(true)
                    .text(scale_param.text("Scale L")),
                "Table 1's dynamic scaling: lengths ×L, masses ×L³, speeds and times ×√L; \
                 the creature restarts at the new size. The green band: the scales this \
                 gait was tested to hold at (tools/physics_band_sweep.py)",
            );
            if let Some(band) = tested_scale {
                band_under_slider(ui, response.rect, scale_param.range(), band, true);
            }
            if response.drag_stopped() || (response.changed() && !response.dragged()) {
                new_scale = Some(scale);
            }
            if let Some((low, high)) = tested_scale
                && !(low..=high).contains(&running_scale)
            {
                ui.colored_label(
                    crate::theme::WARNING_COLOR,
                    format!("Outside the tested L = {low}–{high}: it may fall"),
                )
                .on_hover_text(
                    "tools/physics_band_sweep.py runs this gait 60 s at L = 0.25, 0.5, 1, 2 and 4 \
                     at the middle of its tested speeds; this scale was not among those that held",
                );
            }
            if current == "hop"
                && ui
                    .button("Place a box 3 m ahead")
                    .on_hover_text(
                        "A 0.25 m × 0.3 m box in the kangaroo's path, for its jump states \
                         (stiffer take-off, tucked leg, damped landing). Measured over 12 \
                         box positions: cleared 11 at 5 m/s, 12 at 3.5 m/s, 5 at 2 m/s \
                         (docs/physics.md)",
                    )
                    .clicked()
            {
                place_box = true;
            }
            push = push_row(ui, &push_view);
            egui::CollapsingHeader::new("Gains").show(ui, |ui| {
                ui.label("Up to 1000× the default: too much and the simulation blows up, and the creature is put back.");
                let rows = widgets::controller_rows(ui, lab.creature(), lab.driver(), gains.iter().map(|g| g.name));
                for gain in &gains {
                    let mut value = gain.value;
                    let hi = if gain.default > 0.0 {
                        (gain.default * 1000.0).min(MAX_CONTROLLER_VALUE)
                    } else {
                        1.0
                    };
                    let row = widgets::controller_row(&rows, gain.name);
                    let lab_row = row.is_some_and(|r| r.origin == Origin::Lab);
                    let text = if gain.unit.is_empty() {
                        gain.label.to_owned()
                    } else {
                        format!("{} ({})", gain.label, gain.unit)
                    };
                    if widgets::marked(ui, lab_row, |ui| {
                        ui.add(
                            egui::Slider::new(&mut value, 0.0..=hi)
                                .logarithmic(true)
                                .text(text),
                        )
                    })
                    .on_hover_ui(|ui| {
                        ui.label(format!(
                            "{}: {} {}, default {}; the preset's key is {}",
                            gain.label, gain.value, gain.unit, gain.default, gain.name
                        ));
                        if let Some(row) = row {
                            widgets::controller_tooltip(ui, row, hi);
                        }
                    })
                    .changed()
                    {
                        gain_edits.push((gain.name, value));
                    }
                }
                if ui
                    .button("Default gains")
                    .on_hover_text("Put every gain back to its default")
                    .clicked()
                {
                    gain_edits.extend(gains.iter().map(|g| (g.name, g.default)));
                }
            });
            ui.label(format!("state: {phase} · t = {time:.2} s · resets: {resets}"));
            let (text, hover) = if additions.is_empty() {
                (
                    "Lab's additions: none".to_owned(),
                    "This gait runs without any of the lab's named additions (docs/physics.md, \"The lab's additions\", lists them and what else differs from the paper)",
                )
            } else {
                (
                    format!(
                        "Lab's additions (not in the paper): {}",
                        additions.join(", ").replace('_', " ")
                    ),
                    "What gaitlab adds to the paper's control for this gait; set them in the preset's scenario.physics.lab_additions (docs/physics.md, \"The lab's additions\")",
                )
            };
            ui.label(text).on_hover_text(hover);
            if on_cycle {
                ui.label("Start: on the gait's cycle (the lab's)").on_hover_text(
                    "The paper leaves the start to the animator. Before t = 0, out of sight, the lab ran this hop up to the desired speed with its ramp and started the run at a flight apex; from t = 0 only the control above acts (scenario.physics.start, docs/physics.md \"The start on the cycle\")",
                );
            }
            if !to_start.is_empty() {
                ui.label(format!("Switch into {to_start}: at the gait's own start (the lab's)"))
                    .on_hover_text(
                        "The paper's creatures change gait while running: the new state machine takes over at the next flight. This file names gaits to enter at their own start instead, where the creature is, turned to its heading (scenario.physics.switch_to_start, the lab's option; the bundled quadruped takes over as the paper does: docs/physics.md \"Switching into the bound\")",
                    );
            }
            measured_line(ui, &summary, time);
            let rows = &readout.table2;
            if rows.is_empty() {
                ui.label("Table 2 has no column for this gait.");
            } else {
                ui.label("Table 2 (after 3 s settling)").on_hover_text(
                    "paper: Table 2's animation column (Raibert & Hodgins 1991); live: this run, \
                     measured from 3 s on; diff: live against paper. Why rows miss, with the \
                     experiments: docs/physics.md, \"Where and why the figures miss\".",
                );
                egui::Grid::new("gaitlab-table2")
                    .striped(true)
                    .show(ui, |ui| {
                        ui.strong("quantity");
                        ui.strong("paper");
                        ui.strong("live");
                        ui.strong("diff");
                        ui.end_row();
                        for c in rows {
                            ui.label(c.quantity);
                            ui.label(format!("{:.3}", c.paper));
                            match c.measured {
                                Some(v) => ui.label(format!("{v:.3}")),
                                None => ui.label("—"),
                            };
                            match (c.input, c.diff_pct) {
                                (true, _) => ui.label("input"),
                                (false, Some(d)) => ui.label(format!("{d:+.0} %")),
                                (false, None) => ui.label(""),
                            };
                            ui.end_row();
                        }
                    });
            }
        });
    if let Some(name) = chosen
        && name != current
        && let Err(error) = lab.set_gait(name)
    {
        lab.report_error(error);
    }
    for (key, value) in edits {
        if let Err(error) = lab.edit_gait(key, value) {
            lab.report_error(error);
        }
    }
    if place_box && let Err(error) = lab.place_obstacle(3.0) {
        lab.report_error(error);
    }
    if let Some(dv) = push
        && let Err(error) = lab.push(dv)
    {
        lab.report_error(error);
    }
    if let Some(l) = new_scale
        && let Err(error) = lab.set_physics_scale(l)
    {
        lab.report_error(error);
    }
    for (name, value) in gain_edits {
        if let Err(error) = lab.set_gain(name, value) {
            lab.report_error(error);
        }
    }
}

/// What the push row reads from the readout.
struct PushView {
    heading_rad: f64,
    steerable: bool,
    last_push: Option<gaitlab_engine::metrics::PushEntry>,
    run_time_s: f64,
}

/// How hard the panel's buttons push, m/s of trunk velocity (issue 42's
/// pushes; `run --push` takes any).
const PUSH_MPS: f64 = 0.3;

/// The push buttons (forward, back and, for a creature that can turn,
/// sideways, relative to its heading) and the last push's verdict; the
/// push asked for, world `[x, z]` m/s.
fn push_row(ui: &mut egui::Ui, view: &PushView) -> Option<[f64; 2]> {
    let (sin, cos) = (view.heading_rad.sin(), view.heading_rad.cos());
    let world = |along: f64, across: f64| {
        [
            PUSH_MPS * (along * sin + across * cos),
            PUSH_MPS * (along * cos - across * sin),
        ]
    };
    let mut asked = None;
    ui.horizontal_wrapped(|ui| {
        ui.label(format!("Push the trunk {PUSH_MPS} m/s:"))
            .on_hover_text(
                "A lab experiment (the paper pushes nothing): the whole creature's velocity \
             changes at once by the push. It recovered if it has not fallen 5 s later and \
             runs within 10 % of the desired speed (docs/physics.md, \"Pushes\"). Or drag \
             the trunk in the view: the push follows the drag, 0.3 m/s per 100 points",
            );
        let mut directions = vec![("forward", 1.0, 0.0), ("back", -1.0, 0.0)];
        if view.steerable {
            directions.push(("sideways", 0.0, 1.0));
        }
        for (name, along, across) in directions {
            if ui
                .button(format!("Push {name}"))
                .on_hover_text(format!(
                    "Push the trunk {PUSH_MPS} m/s {name}, relative to its heading"
                ))
                .clicked()
            {
                asked = Some(world(along, across));
            }
        }
    });
    if let Some(p) = &view.last_push {
        let since = view.run_time_s - p.at_s;
        let verdict = match p.recovered {
            Some(true) => format!(
                "recovered: {:.2} of {:.2} m/s 5 s on",
                p.speed_after_mps.unwrap_or(f64::NAN),
                p.desired_mps
            ),
            Some(false) if p.fell => "fell".to_owned(),
            Some(false) => format!(
                "did not recover its speed: {:.2} of {:.2} m/s 5 s on",
                p.speed_after_mps.unwrap_or(f64::NAN),
                p.desired_mps
            ),
            None => format!(
                "judged in {:.1} s",
                (gaitlab_engine::readout::PUSH_RECOVERY_S - since).max(0.0)
            ),
        };
        ui.label(format!("Last push at t = {:.1} s: {verdict}", p.at_s));
    }
    asked
}

/// Seconds of settling before the run's figures are measured (Table 2's 3 s).
const SETTLE_S: f64 = 3.0;

/// The run's speed and the friction its feet needed, in words, once there
/// is something measured (from [`SETTLE_S`] on; before, it says so rather
/// than show zeros).
fn measured_line(
    ui: &mut egui::Ui,
    summary: &gaitlab_engine::readout::PhysicsFigures,
    time_s: f64,
) {
    if time_s < SETTLE_S {
        ui.weak(format!(
            "Speed and friction are measured from t = {SETTLE_S:.0} s (settling)"
        ));
        return;
    }
    ui.label(format!(
        "speed {:.2} m/s of {:.2} desired",
        summary.speed_mean_mps, summary.speed_desired_mps
    ))
    .on_hover_text("Mean forward speed from 3 s on, of the desired speed");
    ui.label(format!(
        "friction needed {:.2} mid-stance, {:.2} in a stance's first and last 10 ms",
        summary.friction_needed_mid, summary.friction_needed_edges
    ))
    .on_hover_text(format!(
        "The friction coefficient real ground would need so no foot slips: the largest \
         ratio of a stance foot's horizontal to vertical ground force while it carries at \
         least 10 % of the body's weight. The paper: under 1 for the biped, about 0.5 for \
         the quadruped and kangaroo, \"almost 2.0\" for up to 10 ms at touchdown and \
         lift-off; dry rubber on concrete gives about 0.8. Over whole stances this run's \
         largest is {:.2} (docs/physics.md, \"Friction and force, as the paper reads them\").",
        summary.friction_needed_max
    ));
}

/// The desired-speed slider's band, m/s, for a gait with no tested speeds
/// (the table takes ±15 m/s; the slider's tooltip says both).
const SPEED_RANGE_MPS: std::ops::RangeInclusive<f64> = -1.0..=6.0;

/// The desired-speed slider's rail width, points (egui's default is 100).
const SPEED_SLIDER_PT: f32 = 170.0;

/// The desired-speed slider's step, m/s.
const SPEED_STEP_MPS: f64 = 0.05;

/// The speed slider's rail (issue 43 item 3): the gait's tested speeds and
/// 1 m/s either side (not below 0), else [`SPEED_RANGE_MPS`] — so a 45-px
/// drag moves the bound's speed by under 1 m/s, not 3.
fn speed_band(tested: Option<(f64, f64)>) -> std::ops::RangeInclusive<f64> {
    match tested {
        Some((low, high)) => (low - 1.0).max(0.0)..=high + 1.0,
        None => SPEED_RANGE_MPS,
    }
}

/// The hop-height slider's band, m (the table takes 0–2 m; the slider's
/// tooltip says both).
const HOP_RANGE_M: std::ops::RangeInclusive<f64> = 0.02..=0.4;

/// The scale slider's band (logarithmic): the scales the tested bands were
/// swept over (the table takes 0.05–20; the slider's tooltip says both).
const SCALE_RANGE: std::ops::RangeInclusive<f64> = 0.25..=4.0;

/// A green band under a slider's rail (egui's: [`egui::style::Spacing::slider_width`]
/// wide at the left of `slider`, handles inset by the rail height / 2.5)
/// from `band.0` to `band.1` of `range` (`log`: a logarithmic slider): the
/// values known to hold.
fn band_under_slider(
    ui: &egui::Ui,
    slider: egui::Rect,
    range: std::ops::RangeInclusive<f64>,
    band: (f64, f64),
    log: bool,
) {
    let spacing = ui.spacing();
    let inset = spacing.interact_size.y / 2.5;
    let (left, right) = (
        slider.left() + inset,
        slider.left() + spacing.slider_width - inset,
    );
    let (lo, hi) = (*range.start(), *range.end());
    let at = |v: f64| {
        let v = v.clamp(lo, hi);
        if log {
            (v.ln() - lo.ln()) / (hi.ln() - lo.ln())
        } else {
            (v - lo) / (hi - lo)
        }
    };
    let x = |v: f64| left + at(v) as f32 * (right - left);
    let y = slider.bottom() - 1.5;
    ui.painter().line_segment(
        [egui::pos2(x(band.0), y), egui::pos2(x(band.1), y)],
        egui::Stroke::new(3.0, crate::theme::TESTED_COLOR),
    );
}

/// The speeds the gait is tested at, under the speed slider, and a warning
/// outside them.
fn speed_range_line(ui: &mut egui::Ui, speed: f64, tested: Option<(f64, f64)>) {
    let Some((low, high)) = tested else {
        return;
    };
    let hover = "The 60-s sweep of docs/physics.md (\"Gaits: a minute at several speeds\") runs \
                 this gait at these speeds: no fall, and the mean speed within 10 %";
    if (low..=high).contains(&speed) {
        ui.weak(format!("tested {low:.1}–{high:.1} m/s (the green band)"))
            .on_hover_text(hover);
    } else {
        ui.colored_label(
            crate::theme::WARNING_COLOR,
            format!("Outside the tested {low:.1}–{high:.1} m/s: it may fall or miss the speed"),
        )
        .on_hover_text(hover);
    }
}
