//! The PODA gait panel (Girard & Maciejewski 1985, "Gait Design in PODA"):
//! the named gait, sliders for period, duty factor, body speed and stroke
//! (each edit keeps eq. 7–8 true and the panel says what was derived), the
//! support and transfer durations, and a footfall diagram — each leg's
//! support bar over one cycle (eq. 9) with a live cursor.

use gaitlab_engine::DriverKind;
use gaitlab_engine::readout::{Footfall, JointCenterReadout};

use super::panel::Panel;
use crate::app::App;
use crate::lab::GaitShapeEdit;
use crate::param_widgets::{self as widgets, Param, key};

/// The PODA gait panel.
pub struct GaitPanel;

impl Panel for GaitPanel {
    fn title(&self) -> &'static str {
        "Gait"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().kind() == DriverKind::Poda
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        gait(ui, lab);
    }
}

/// Height of one leg's row in the footfall diagram, points.
const ROW_HEIGHT: f32 = 18.0;

/// Size of the footfall diagram's leg names, points.
const LABEL_FONT_PT: f32 = 13.0;

/// The gait panel (shown for PODA creatures).
fn gait(ui: &mut egui::Ui, lab: &mut App) {
    let Some(gait) = lab.driver().poda_readout() else {
        return;
    };
    let current = gait.gait.clone();
    let force_n = gait.leg_force_n;
    let weight_share = gait.weight_share_n;
    let shifting = gait.shifting;
    let stability = gait.stability;
    let leg_names: Vec<String> = gait
        .legs
        .iter()
        .map(|leg| crate::words::in_words(&leg.name))
        .collect();
    let mut chosen = None;
    let mut edits: Vec<(&str, f64)> = Vec::new();
    egui::CollapsingHeader::new("Gait (PODA)")
        .default_open(true)
        .show(ui, |ui| {
            egui::ComboBox::from_label("Gait")
                .selected_text(current.as_str())
                .show_ui(ui, |ui| {
                    for &name in &gait.gaits {
                        if ui
                            .selectable_label(name == current, name)
                            .on_hover_text("Switch to this gait: each leg takes it on at its own mid-stance, over a few strides")
                            .clicked()
                        {
                            chosen = Some(name);
                        }
                    }
                })
                .response
                .on_hover_text("A named gait: its duty factor and relative phases");
            for (param, mut value, name, hint) in [
                (
                    Param::new(key::PERIOD).band(0.2..=3.0),
                    gait.period_s,
                    "Period P",
                    "Time of one gait cycle, seconds (eq. 7–8 derive the rest)",
                ),
                (
                    Param::new(key::DUTY_FACTOR),
                    gait.duty_factor,
                    "Duty factor",
                    "Fraction of the period each leg supports (unitless, 0–1)",
                ),
                (
                    Param::new(key::PODA_SPEED).band(0.02..=4.0),
                    gait.speed_mps,
                    "Body speed",
                    "Forward body speed along the path, metres per second",
                ),
                (
                    Param::new(key::STROKE).band(0.01..=1.5),
                    gait.stroke_m,
                    "Stroke",
                    "Distance a supporting foot travels relative to the body, metres",
                ),
            ] {
                if widgets::add(
                    ui,
                    param,
                    egui::Slider::new(&mut value, param.range()).text(param.text(name)),
                    hint,
                )
                .changed()
                {
                    edits.push((param.command(), value));
                }
            }
            let mut force = force_n;
            let param =
                Param::new(key::LEG_FORCE).band(weight_share * 1.05..=weight_share * 12.0);
            if widgets::add(
                ui,
                param,
                egui::Slider::new(&mut force, param.range()).text(param.text("Leg force")),
                "Upward force of a supporting leg (eq. 12–13): more force, longer flights",
            )
            .changed()
            {
                edits.push((param.command(), force));
            }
            ui.label(format!(
                "support {:.3} s · transfer {:.3} s (eq. 7: support = stroke / speed)",
                gait.support_s, gait.transfer_s
            ));
            super::stability::status_lines(
                ui,
                &super::stability::Status {
                    report: stability,
                    planned_feet_down: gait.duty_factor * leg_names.len() as f64,
                    derived: lab.gait_derived(),
                    shifting,
                },
            );
            footfall_diagram(ui, &leg_names, &gait.footfall);
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
    shape(ui, lab);
    centers(ui, lab);
}

/// Center angle and gain of every leg joint (PODA eq. 6: the null-space term
/// pulls each joint toward its center with its gain, without moving the foot).
fn centers(ui: &mut egui::Ui, lab: &mut App) {
    let Some(readout) = lab.driver().poda_readout() else {
        return;
    };
    let mut edit: Option<(String, f64, f64)> = None;
    let center_param = Param::new(key::CENTER);
    let gain_param = center_param.band(0.0..=1.0);
    ui.collapsing("Center angles and gains", |ui| {
        for leg in readout.legs {
            ui.collapsing(leg.name, |ui| {
                for JointCenterReadout {
                    joint,
                    center,
                    gain,
                    revolute,
                } in leg.joints
                {
                    ui.horizontal(|ui| {
                        ui.label(joint.as_str());
                        let mut shown = if revolute {
                            center.to_degrees()
                        } else {
                            center
                        };
                        let mut new_gain = gain;
                        let unit = if revolute { "°" } else { " m" };
                        let moved = widgets::add(
                            ui,
                            center_param,
                            egui::DragValue::new(&mut shown).speed(0.5).suffix(unit),
                            if revolute {
                                "Center angle the null-space term pulls this joint to, degrees (eq. 6)"
                            } else {
                                "Center length the null-space term pulls this joint to, metres (eq. 6)"
                            },
                        )
                        .changed();
                        let weighted = widgets::add(
                            ui,
                            gain_param,
                            egui::Slider::new(&mut new_gain, gain_param.range()).text("gain"),
                            "How strongly this joint is pulled to its center (eq. 6, unitless 0–1)",
                        )
                        .changed();
                        if moved || weighted {
                            let value = if revolute { shown.to_radians() } else { shown };
                            edit = Some((joint.clone(), value, new_gain));
                        }
                    });
                }
            });
        }
    });
    if let Some((joint, center, gain)) = edit
        && let Err(error) = lab.set_center(&joint, center, gain)
    {
        lab.report_error(error);
    }
}

/// The gait's shape: each leg's relative phase (eq. 9), the step height and
/// the key leg positions of the transfer trajectory (PODA "Leg Support and
/// Transfer Trajectories").
fn shape(ui: &mut egui::Ui, lab: &mut App) {
    let Some(readout) = lab.driver().poda_readout() else {
        return;
    };
    let names: Vec<String> = readout.legs.into_iter().map(|leg| leg.name).collect();
    let mut phases = readout.phases;
    let mut step_height = readout.step_height_m;
    let mut keys = readout.transfer_keys;
    let mut edits: Vec<GaitShapeEdit<'_>> = Vec::new();
    let mut keys_changed = false;
    ui.collapsing("Phases and steps", |ui| {
        let phase_param = Param::new(key::PHASES).band(0.0..=0.999);
        for (leg, (name, phase)) in names.iter().zip(phases.iter_mut()).enumerate() {
            if widgets::add(
                ui,
                phase_param,
                egui::Slider::new(phase, phase_param.range()).text(name.as_str()),
                "Relative phase of this leg: when it lifts, as a fraction of the period (eq. 9)",
            )
            .changed()
            {
                edits.push(GaitShapeEdit::Phase { leg, phase: *phase });
            }
        }
        let height_param = Param::new(key::STEP_HEIGHT).band(0.005..=0.3);
        if widgets::add(
            ui,
            height_param,
            egui::Slider::new(&mut step_height, height_param.range())
                .text(height_param.text("Step height")),
            "Highest point of a transferring foot above its support line, metres",
        )
        .changed()
        {
            edits.push(GaitShapeEdit::StepHeight(step_height));
        }
        let transfer = Param::new(key::TRANSFER_KEYS);
        transfer.hover(
            ui.label("Transfer key positions (step fraction, height fraction):"),
            "Key leg positions of a transferring foot, on a Catmull-Rom spline",
        );
        let (along_param, height_param) = (transfer.band(0.01..=0.99), transfer.band(0.0..=2.0));
        for [along, height] in &mut keys {
            ui.horizontal(|ui| {
                keys_changed |= along_param
                    .hover(
                        ui.add(
                            egui::DragValue::new(along)
                                .speed(0.005)
                                .range(along_param.range()),
                        ),
                        "Key position along the step, fraction of the step length (0–1)",
                    )
                    .changed();
                keys_changed |= height_param
                    .hover(
                        ui.add(
                            egui::DragValue::new(height)
                                .speed(0.01)
                                .range(height_param.range()),
                        ),
                        "Key height, fraction of the step height",
                    )
                    .changed();
            });
        }
    });
    for edit in edits {
        if let Err(error) = lab.edit_gait_shape(edit) {
            lab.report_error(error);
        }
    }
    if keys_changed && let Err(error) = lab.edit_gait_shape(GaitShapeEdit::TransferKeys(&keys)) {
        lab.report_error(error);
    }
}

/// Each leg's support bar over one cycle (filled while the foot is planted),
/// and a cursor at the current time within the cycle.
fn footfall_diagram(ui: &mut egui::Ui, names: &[String], footfall: &Footfall) {
    let font = egui::FontId::proportional(LABEL_FONT_PT);
    // As wide as the longest name, so none is clipped.
    let label_width = names
        .iter()
        .map(|name| {
            ui.painter()
                .layout_no_wrap(name.clone(), font.clone(), egui::Color32::WHITE)
                .size()
                .x
        })
        .fold(40.0_f32, f32::max)
        + 8.0;
    let width = ui.available_width().max(label_width + 40.0);
    let rows = ROW_HEIGHT * names.len() as f32;
    let height = rows + 2.0 * ROW_HEIGHT;
    let (rect, response) = ui.allocate_exact_size(egui::vec2(width, height), egui::Sense::hover());
    response.on_hover_text(
        "One row per leg, one gait cycle across (0 to 1 of the period): a filled bar while \
         the foot is down (stance, supporting), the empty track while it swings through the \
         air (transfer); the vertical line is now",
    );
    let painter = ui.painter_at(rect);
    let visuals = ui.visuals();
    let bar = visuals.selection.bg_fill;
    let track = visuals.extreme_bg_color;
    let text = visuals.text_color();
    let x0 = rect.left() + label_width;
    let span = rect.right() - x0;
    let x = |fraction: f64| x0 + span * fraction as f32;
    for (i, (name, support)) in names.iter().zip(&footfall.support).enumerate() {
        let top = rect.top() + ROW_HEIGHT * i as f32;
        painter.text(
            egui::pos2(rect.left(), top + ROW_HEIGHT * 0.5),
            egui::Align2::LEFT_CENTER,
            name,
            font.clone(),
            text,
        );
        let row = egui::Rect::from_min_max(
            egui::pos2(x0, top + 2.0),
            egui::pos2(rect.right(), top + ROW_HEIGHT - 2.0),
        );
        painter.rect_filled(row, 0.0, track);
        // One bar per support phase.
        for &[from, to] in support {
            painter.rect_filled(
                egui::Rect::from_min_max(
                    egui::pos2(x(from), row.top()),
                    egui::pos2(x(to), row.bottom()),
                ),
                1.0,
                bar,
            );
        }
    }
    let now = x(footfall.now.clamp(0.0, 1.0));
    painter.line_segment(
        [
            egui::pos2(now, rect.top()),
            egui::pos2(now, rect.top() + rows),
        ],
        egui::Stroke::new(1.5, visuals.warn_fg_color),
    );
    // The time axis: fractions of the cycle, ticks at quarters.
    let weak = visuals.weak_text_color();
    let axis = rect.top() + rows + 1.0;
    painter.line_segment(
        [egui::pos2(x0, axis), egui::pos2(rect.right(), axis)],
        egui::Stroke::new(1.0, weak),
    );
    for (k, label) in ["0", "¼", "½", "¾", "1"].iter().enumerate() {
        let at = x(k as f64 / 4.0);
        painter.line_segment(
            [egui::pos2(at, axis), egui::pos2(at, axis + 3.0)],
            egui::Stroke::new(1.0, weak),
        );
        let align = match k {
            0 => egui::Align2::LEFT_TOP,
            4 => egui::Align2::RIGHT_TOP,
            _ => egui::Align2::CENTER_TOP,
        };
        painter.text(
            egui::pos2(at, axis + 3.0),
            align,
            *label,
            font.clone(),
            weak,
        );
    }
    painter.text(
        egui::pos2(rect.left(), axis + 3.0),
        egui::Align2::LEFT_TOP,
        "cycle",
        font.clone(),
        weak,
    );
    // The key: stance, swing, now.
    let key_y = rect.top() + rows + ROW_HEIGHT + 2.0;
    let mut at = rect.left();
    for (fill, line, label) in [
        (Some(bar), None, "stance (foot down)"),
        (Some(track), None, "swing"),
        (None, Some(visuals.warn_fg_color), "now"),
    ] {
        let swatch = egui::Rect::from_min_size(
            egui::pos2(at, key_y + 2.0),
            egui::vec2(12.0, ROW_HEIGHT - 6.0),
        );
        if let Some(fill) = fill {
            painter.rect_filled(swatch, 1.0, fill);
        }
        if let Some(line) = line {
            painter.line_segment(
                [swatch.center_top(), swatch.center_bottom()],
                egui::Stroke::new(1.5, line),
            );
        }
        let label = painter.text(
            egui::pos2(swatch.right() + 4.0, swatch.center().y),
            egui::Align2::LEFT_CENTER,
            label,
            font.clone(),
            text,
        );
        at = label.right() + 12.0;
    }
}
