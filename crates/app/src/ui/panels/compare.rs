//! The side-by-side panels ([`crate::compare`]): the "Side by side" controls
//! (on/off, 2 or 4 views, each view's method, the scenario) and one card per
//! view with the method's formula, its parameters as sliders, a table of its
//! figures (errors, timing, jitter, limit hits, She 2006 §5.3's oscillation and
//! reachability; docs/ik-metrics.md), a per-effector table and a live error plot.

use egui_plot::{Line, PlotPoints};

use crate::plot_scale::{few_round_marks, tick_label};

use super::panel::Panel;
use crate::compare::{
    CompareConfig, CompareMethod, CompareScenario, DEFAULT_VIEWS, Parameter, Verdict,
};
use crate::lab::Lab;
use crate::ui::param_widgets::{self as widgets, Param, key};

/// The "Side by side" controls.
pub struct SideBySidePanel;

impl Panel for SideBySidePanel {
    fn title(&self) -> &'static str {
        "Side by side"
    }

    fn shown_for(&self, lab: &Lab) -> bool {
        lab.driver().is_ik()
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        controls(ui, lab);
    }
}

/// The "Side by side" section of the left panel (IK engine only).
fn controls(ui: &mut egui::Ui, lab: &mut Lab) {
    egui::CollapsingHeader::new("Side by side")
        .default_open(false)
        .show(ui, |ui| {
            if ui
                .button("She 2006 as written: 4 methods")
                .on_hover_text(
                    "Open the she-2006 preset (the thesis' §5.2.2 targets, no posture pull) \
                     and run transpose, pinv, DLS and SDLS side by side on the current motion \
                     (She 2006 §5.3)",
                )
                .clicked()
                && let Err(error) = lab.compare_as_the_thesis()
            {
                lab.report_error(error);
            }
            let mut on = lab.comparison().is_some();
            if ui
                .checkbox(&mut on, "Compare methods")
                .on_hover_text(
                    "Run 2 or 4 IK methods side by side on the same figure and targets, \
                     in lock step, with one shared camera",
                )
                .changed()
            {
                if on {
                    let config =
                        CompareConfig::new(&DEFAULT_VIEWS, CompareScenario::Script, &base(lab));
                    if let Err(error) = lab.start_compare(config) {
                        lab.report_error(error);
                    }
                } else {
                    lab.stop_compare();
                }
            }
            let Some(current) = lab.comparison().map(|c| c.config.clone()) else {
                return;
            };
            let mut config = current.clone();
            ui.horizontal(|ui| {
                for (count, tip) in [
                    (2, "Two views, left and right"),
                    (4, "Four views in a 2 × 2 grid"),
                ] {
                    if ui
                        .radio(config.views.len() == count, format!("{count} views"))
                        .on_hover_text(tip)
                        .clicked()
                    {
                        resize(&mut config, count, &base(lab));
                    }
                }
            });
            for i in 0..config.views.len() {
                let mut method = config.views[i];
                egui::ComboBox::from_label(format!("View {}", i + 1))
                    .selected_text(method.label())
                    .show_ui(ui, |ui| {
                        for m in CompareMethod::ALL {
                            ui.selectable_value(&mut method, m, m.label())
                                .on_hover_text(m.behaviour());
                        }
                    })
                    .response
                    .on_hover_text("The IK method this view runs");
                if method != config.views[i] {
                    config.views[i] = method;
                    config.options[i] = method.options(&base(lab));
                }
            }
            if lab.tracking().is_some() {
                ui.label("Targets: the recording (Recorded targets panel)");
            } else {
                scenario_combo(ui, &mut config);
            }
            ui.horizontal(|ui| {
                for (overlay, label, tip) in [
                    (false, "Side by side", "One 3-D view per method"),
                    (
                        true,
                        "Overlay",
                        "Every method's figure in one 3-D view, each in its card's colour, \
                         chasing the same targets; a bone where methods agree is striped in \
                         their colours, a joint they share is grey",
                    ),
                ] {
                    if ui
                        .radio(config.overlay == overlay, label)
                        .on_hover_text(tip)
                        .clicked()
                    {
                        config.overlay = overlay;
                    }
                }
            });
            if config != current
                && let Err(error) = lab.configure_compare(config)
            {
                lab.report_error(error);
            }
        });
}

/// The scenario menu: the thesis script or the singularity stretch.
fn scenario_combo(ui: &mut egui::Ui, config: &mut CompareConfig) {
    egui::ComboBox::from_label("Scenario")
        .selected_text(scenario_label(config.scenario))
        .show_ui(ui, |ui| {
            for s in [CompareScenario::Script, CompareScenario::Singularity] {
                ui.selectable_value(&mut config.scenario, s, scenario_label(s));
            }
        })
        .response
        .on_hover_text(
            "Where the targets go: the thesis script of the chosen motion, or every \
             limb pulled to its full reach and beyond (a singular, stretched pose)",
        );
}

fn scenario_label(scenario: CompareScenario) -> &'static str {
    match scenario {
        CompareScenario::Script => "Thesis script",
        CompareScenario::Singularity => "Singularity (stretched limbs)",
    }
}

/// The lab's IK options, the defaults of a new view.
fn base(lab: &Lab) -> gaitlab_core::ik::IkOptions {
    let mut options = lab.session.settings.ik.clone();
    options.method = lab.session.settings.method;
    options
}

/// Keeps the first `count` views, or adds the default views not yet shown.
fn resize(config: &mut CompareConfig, count: usize, base: &gaitlab_core::ik::IkOptions) {
    config.views.truncate(count);
    config.options.truncate(count);
    for m in DEFAULT_VIEWS.into_iter().chain(CompareMethod::ALL) {
        if config.views.len() >= count {
            break;
        }
        if !config.views.contains(&m) {
            config.views.push(m);
            config.options.push(m.options(base));
        }
    }
}

/// One card per view — in columns, or `stacked` one under another (the
/// phone's drawer) — under the scenario's notes and the views' jitter and
/// oscillation on shared scales.
pub fn cards(ui: &mut egui::Ui, lab: &mut Lab, stacked: bool) {
    let Some(compare) = lab.comparison_mut() else {
        return;
    };
    let count = compare.views().len();
    let y_max_mm = compare.plot_error_max_mm();
    let mut edits = Vec::new();
    // On a phone (stacked) the sheet scrolls by dragging: no thin bar to aim at.
    let bar = if stacked {
        egui::scroll_area::ScrollBarVisibility::AlwaysHidden
    } else {
        egui::scroll_area::ScrollBarVisibility::VisibleWhenNeeded
    };
    egui::ScrollArea::vertical()
        .scroll_bar_visibility(bar)
        .show(ui, |ui| {
            notice_ui(ui, compare);
            super::compare_bars::bars(ui, compare, stacked);
            figures_table(ui, compare, stacked);
            if stacked {
                for i in 0..count {
                    ui.separator();
                    if let Some(options) = card(ui, compare, i, y_max_mm) {
                        edits.push((i, options));
                    }
                }
                return;
            }
            ui.columns(count.max(1), |columns| {
                for (i, column) in columns.iter_mut().enumerate().take(count) {
                    // Left-aligned, not justified: a wrapped formula keeps its
                    // letters together.
                    column.with_layout(egui::Layout::top_down(egui::Align::LEFT), |ui| {
                        if let Some(options) = card(ui, compare, i, y_max_mm) {
                            edits.push((i, options));
                        }
                    });
                }
            });
        });
    for (i, options) in edits {
        compare.set_options(i, options);
    }
}

/// View `i`'s card: its method and colour, the error plot on the shared
/// scale `y_max_mm`, formula, behaviour, parameter sliders (the edited
/// options when one moved) and per-effector table; the figures are in the
/// one table above the cards ([`figures_table`]).
fn card(
    ui: &mut egui::Ui,
    compare: &crate::compare::Comparison,
    i: usize,
    y_max_mm: f64,
) -> Option<gaitlab_core::ik::IkOptions> {
    let (view, options) = (&compare.views()[i], &compare.config.options[i]);
    let method = view.method;
    let colour = compare.colour(i);
    ui.horizontal(|ui| {
        let (swatch, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
        ui.painter().rect_filled(swatch, 3.0, colour);
        ui.strong(format!("{} · {}", i + 1, method.label()))
            .on_hover_text(method.behaviour());
    });
    let points: Vec<[f64; 2]> = view
        .stage
        .history
        .points(0)
        .map(|[t, v]| [t, v * 1e3])
        .collect();
    // Every card on one y range, so the cards compare by eye: 0 to the
    // shared top, which no view's error exceeds.
    crate::plot_scale::still_plot(("compare-plot", i))
        .height(110.0)
        .include_y(0.0)
        .include_y(y_max_mm)
        .x_axis_label("time (s)")
        .y_axis_label("max error (mm)")
        .y_grid_spacer(few_round_marks)
        .y_axis_formatter(|mark, _| tick_label(mark))
        .show(ui, |plot| {
            plot.line(Line::new("max error (mm)", PlotPoints::from(points)).color(colour));
        })
        .response
        .on_hover_text(
            "Largest effector error per frame, mm; every card's plot has the same \
             scale",
        );
    ui.monospace(method.formula_with(options))
        .on_hover_text("The update rule of one IK iteration");
    ui.label(method.behaviour());
    let mut edited = options.clone();
    let mut changed = false;
    // The step clamp only where it acts: pinv and CCD, and transpose and
    // DLS with the lab's clamp on every method (She 2006 §4.4.2).
    let shown = method
        .parameters()
        .iter()
        .filter(|p| **p != Parameter::MaxStep || options.uses_max_step());
    for &parameter in shown {
        changed |= slider(ui, parameter, &mut edited);
    }
    effector_table(ui, i, view);
    changed.then_some(edited)
}

/// Every view's figures in one table (issue 43 item 5: each card had its own,
/// at its own height): a row per figure, a column per view under its
/// method's name in its colour, so a row reads across the methods.
fn figures_table(ui: &mut egui::Ui, compare: &crate::compare::Comparison, stacked: bool) {
    type Cell = fn(&crate::compare::CompareView, &gaitlab_core::ik::IkOptions) -> String;
    let rows: [(&str, &str, Cell); 11] = [
        (
            "mean error",
            "Mean effector-to-target distance since the reset, averaged over the effectors",
            |v, _| format!("{:.2} mm", v.mean_error_m() * 1e3),
        ),
        (
            "max error",
            "Largest effector-to-target distance since the reset",
            |v, _| format!("{:.2} mm", v.max_error_m() * 1e3),
        ),
        (
            "µs / iteration",
            "Wall time per IK iteration (forward kinematics, Jacobian, solve)",
            |v, _| format!("{:.1}", v.metrics().us_per_iteration()),
        ),
        (
            "jitter",
            "Joint-velocity jitter: mean |Δ²θ| over the joints and the last 4 s, radians per frame²",
            |v, _| format!("{:.2e} rad/frame²", v.metrics().jitter_rad()),
        ),
        (
            "limit hits",
            "Times a joint ran into one of its limits since the reset",
            |v, _| v.metrics().limit_hits.to_string(),
        ),
        (
            "oscillation",
            "Sign changes of each limb joint's per-frame Δθ (|Δθ| ≥ 1e-6 rad) per second, averaged over the limb's joints and the effectors since the reset (She 2006 §5.3's oscillation; a smooth swing at the gait's f Hz gives 2f)",
            |v, _| optional(v.oscillation_hz(), 1.0, "Hz", 2),
        ),
        (
            "reachable",
            "Share of frames whose target lay within the limb's length of its first joint, averaged over the effectors (She 2006 §5.3's reachable targets)",
            |v, _| optional(v.reachable(), 100.0, "%", 0),
        ),
        (
            "error, reachable",
            "Mean effector error over the frames its target was within reach, averaged over the effectors",
            |v, _| optional(v.mean_error_reachable_m(), 1e3, "mm", 2),
        ),
        (
            "error, unreachable",
            "Mean effector error over the frames its target was out of reach, averaged over the effectors",
            |v, _| optional(v.mean_error_unreachable_m(), 1e3, "mm", 2),
        ),
        (
            "posture pull",
            "The lab's addition, not in She 2006: before each frame's IK every joint moves this fraction of its joint gain toward its centre angle (Motion panel; the she-2006 preset has it off)",
            |v, _| posture_pull(v),
        ),
        (
            "joint limits",
            "How a joint past its limit is handled: clamped to the limit (She 2006 §6.1.1.1), or clamped and the IK solved again without it (the lab's addition; Method panel, Limit passes)",
            |_, o| limit_rule(o),
        ),
    ];
    // On a phone the table scrolls by dragging: no thin bar to aim at.
    let bar = if stacked {
        egui::scroll_area::ScrollBarVisibility::AlwaysHidden
    } else {
        egui::scroll_area::ScrollBarVisibility::VisibleWhenNeeded
    };
    egui::ScrollArea::horizontal()
        .id_salt("compare-figures")
        .scroll_bar_visibility(bar)
        .show(ui, |ui| {
            egui::Grid::new("compare-figures-table")
                .num_columns(1 + compare.views().len())
                .striped(true)
                .show(ui, |ui| {
                    ui.label("");
                    for (i, view) in compare.views().iter().enumerate() {
                        ui.label(
                            egui::RichText::new(format!("{} · {}", i + 1, view.method.name()))
                                .strong()
                                .color(compare.colour(i)),
                        )
                        .on_hover_text(view.method.label());
                    }
                    ui.end_row();
                    for (name, tip, cell) in rows {
                        ui.label(name).on_hover_text(tip);
                        for (view, options) in compare.views().iter().zip(&compare.config.options) {
                            ui.label(cell(view, options)).on_hover_text(tip);
                        }
                        ui.end_row();
                    }
                });
        });
}

/// The scenario's "what to notice" lines, each with its thesis section; a
/// line that compares methods is followed by this run's verdict, coloured by
/// it (green: holds, amber: level, orange: does not hold, grey: not yet).
fn notice_ui(ui: &mut egui::Ui, compare: &crate::compare::Comparison) {
    egui::CollapsingHeader::new("What to notice")
        .id_salt("compare-notice")
        .default_open(true)
        .show(ui, |ui| {
            let font = egui::TextStyle::Body.resolve(ui.style());
            let (text, weak) = (ui.visuals().text_color(), ui.visuals().weak_text_color());
            for (line, checked) in compare.notes() {
                // One wrapped paragraph: the line, its source in grey, then
                // the run's verdict in the verdict's colour.
                let mut job = egui::text::LayoutJob::default();
                let plain = |color| egui::TextFormat::simple(font.clone(), color);
                job.append(&format!("• {}  ", line.text), 0.0, plain(text));
                job.append(line.source, 0.0, plain(weak));
                if let (Some(claim), Some(checked)) = (line.claim, checked) {
                    let colour = verdict_colour(checked.verdict, ui.visuals().dark_mode, weak);
                    job.append(
                        &format!("  {}", checked.sentence(&claim)),
                        0.0,
                        plain(colour),
                    );
                }
                ui.add(egui::Label::new(job).wrap());
            }
        });
}

/// A verdict's colour: green holds, amber level, orange does not hold, the
/// weak text colour where nothing was compared (darker shades on the light
/// theme, so the text stays readable).
fn verdict_colour(verdict: Verdict, dark: bool, weak: egui::Color32) -> egui::Color32 {
    let [r, g, b] = match (verdict, dark) {
        (Verdict::Holds, true) => [0x4C, 0xC2, 0x7A],
        (Verdict::Holds, false) => [0x1A, 0x80, 0x45],
        (Verdict::Level, true) => [0xE0, 0xC0, 0x40],
        (Verdict::Level, false) => [0x8A, 0x6A, 0x00],
        (Verdict::Fails, true) => [0xF0, 0x80, 0x30],
        (Verdict::Fails, false) => [0xB8, 0x48, 0x10],
        (Verdict::NotInRun | Verdict::NotMeasured, _) => return weak,
    };
    egui::Color32::from_rgb(r, g, b)
}

/// The view's posture pull (the lab's addition): its gain, or "off (thesis)".
fn posture_pull(view: &crate::compare::CompareView) -> String {
    let gain = view
        .driver()
        .thesis_readout()
        .map_or(0.0, |t| t.params.posture_gain);
    if gain > 0.0 {
        format!("{gain:.2} (lab)")
    } else {
        "off (thesis)".to_owned()
    }
}

/// The view's joint-limit handling: "clamp (thesis)", "clamp + re-solve ×N
/// (lab)" or "off".
fn limit_rule(options: &gaitlab_core::ik::IkOptions) -> String {
    match (options.enforce_limits, options.limit_passes) {
        (false, _) => "off".to_owned(),
        (true, 0 | 1) => "clamp (thesis)".to_owned(),
        (true, passes) => format!("clamp + {} re-solves (lab)", passes - 1),
    }
}

/// `value · scale` with `decimals` decimals and `unit`, or "–" when there is none.
fn optional(value: Option<f64>, scale: f64, unit: &str, decimals: usize) -> String {
    value.map_or_else(
        || "–".to_owned(),
        |v| format!("{:.decimals$} {unit}", v * scale),
    )
}

/// Per effector: how far its target is out of reach now, the share of frames
/// it was reachable and its limb's oscillation.
fn effector_table(ui: &mut egui::Ui, index: usize, view: &crate::compare::CompareView) {
    egui::CollapsingHeader::new("per effector")
        .id_salt(("compare-effectors", index))
        .default_open(false)
        .show(ui, |ui| {
            egui::Grid::new(("compare-effector-table", index))
                .num_columns(4)
                .striped(true)
                .show(ui, |ui| {
                    for (header, tip) in [
                        ("effector", "The end effector"),
                        ("beyond reach", "How far the target lies beyond the limb's reach this frame, mm (negative: inside)"),
                        ("reachable", "Share of frames with the target within reach since the reset"),
                        ("oscillation", "Oscillation of the limb's joints since the reset, Hz"),
                    ] {
                        ui.small(header).on_hover_text(tip);
                    }
                    ui.end_row();
                    for effector in view.effectors() {
                        ui.small(effector.metrics.name);
                        ui.small(optional(effector.out_of_reach_m, 1e3, "mm", 0));
                        ui.small(optional(effector.metrics.reachable, 100.0, "%", 0));
                        ui.small(optional(effector.metrics.oscillation_hz, 1.0, "Hz", 2));
                        ui.end_row();
                    }
                });
        });
}

/// A slider for `parameter` of `options`; whether it changed.
fn slider(
    ui: &mut egui::Ui,
    parameter: Parameter,
    options: &mut gaitlab_core::ik::IkOptions,
) -> bool {
    let (lo, hi) = parameter.range();
    let slot = parameter.slot(options);
    let (text, tip, degrees, logarithmic) = match parameter {
        Parameter::Lambda => (
            "λ",
            "DLS damping λ: larger is smoother but less accurate",
            false,
            true,
        ),
        Parameter::GammaMax => (
            "γmax",
            "SDLS: largest change of any joint per iteration",
            true,
            false,
        ),
        Parameter::MaxStep => (
            "step clamp",
            "Largest joint change per iteration: pinv's (She 2006 §4.4.2), CCD's per joint turn, and transpose's and DLS's with the lab's clamp on every method (Method panel)",
            true,
            false,
        ),
        Parameter::RankTolerance => (
            "rank tol.",
            "Singular values below this fraction of σmax count as zero",
            false,
            true,
        ),
        Parameter::NullSpaceGain => (
            "null-space k",
            "Gain of the pull toward the center angles (PODA eq. 6)",
            false,
            false,
        ),
    };
    let row = Param::new(match parameter {
        Parameter::Lambda => key::LAMBDA,
        Parameter::GammaMax => key::GAMMA_MAX,
        Parameter::MaxStep => key::MAX_STEP,
        Parameter::RankTolerance => key::RANK_TOLERANCE,
        Parameter::NullSpaceGain => key::NULL_SPACE_GAIN,
    });
    let row = if degrees {
        row.in_degrees().band(lo.to_degrees()..=hi.to_degrees())
    } else {
        row.band(lo..=hi)
    };
    let mut value = if degrees { slot.to_degrees() } else { *slot };
    let changed = widgets::add(
        ui,
        row,
        egui::Slider::new(&mut value, row.range())
            .logarithmic(logarithmic)
            .text(row.text(text)),
        tip,
    )
    .changed();
    if changed {
        *slot = if degrees { value.to_radians() } else { value }.clamp(lo, hi);
    }
    changed
}
