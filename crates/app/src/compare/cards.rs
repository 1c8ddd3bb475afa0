//! The comparison's cards (She 2006 §5.3 side by side; docs/ik-metrics.md):
//! the scenario's "what to notice" lines with this run's verdicts, the
//! jitter and oscillation bars, the one figures table, and one card per
//! view with its method, colour, error plot, formula, parameter sliders and
//! per-effector table. Issue 44 item 6: the comparison's panel code, in its
//! folder, drawn from the [`Comparison`] alone.

use egui_plot::{Line, PlotPoints};

use super::claim::Verdict;
use super::comparison::Comparison;
use super::method::Parameter;
use super::table::{effector_table, figures_table};
use crate::param_widgets::{self as widgets, Param, key};
use crate::plot_scale::{few_round_marks, tick_label};

/// One card per view — in columns, or `stacked` one under another (the
/// phone's drawer) — under the scenario's notes and the views' jitter and
/// oscillation on shared scales.
pub fn cards(ui: &mut egui::Ui, compare: &mut Comparison, stacked: bool) {
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
            super::bars::bars(ui, compare, stacked);
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
    compare: &Comparison,
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

/// The scenario's "what to notice" lines, each with its thesis section; a
/// line that compares methods is followed by this run's verdict, coloured by
/// it (green: holds, amber: level, orange: does not hold, grey: not yet).
fn notice_ui(ui: &mut egui::Ui, compare: &Comparison) {
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
