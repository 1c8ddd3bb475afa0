//! The Method panel's λ trade-off section: a Measure button, then two small
//! plots against log₁₀ λ — the error on the targets within reach (mm) and the
//! jitter of the limbs out of reach (mrad/frame², log) — with the current λ
//! as a vertical line and the measured figures on hover.

use egui::Color32;
use egui_plot::{GridMark, HoverPosition, Line, PlotPoints, Points, VLine, uniform_grid_spacer};

use gaitlab_core::preset::thesis::ThesisMode;

use super::LambdaTradeoff;

/// Height of each plot, points.
const PLOT_HEIGHT_PT: f32 = 110.0;

/// The marker colour of the current λ.
const CURRENT: Color32 = Color32::from_rgb(0xD5, 0x5E, 0x00);

/// The series colour (Okabe & Ito's blue).
const SERIES: Color32 = Color32::from_rgb(0x00, 0x72, 0xB2);

/// Jitter below this shows as this (the log scale's floor), rad per frame².
const JITTER_FLOOR: f64 = 1e-6;

/// What runs now, as the section compares a measurement with it.
#[derive(Clone, Copy, Debug)]
pub struct Running<'a> {
    /// The thesis motion.
    pub mode: ThesisMode,
    /// The preset's name.
    pub preset: &'a str,
    /// The current DLS damping λ, metres.
    pub lambda_m: f64,
}

/// The section, for the running thesis motion: its button and, once
/// measured (`sweep`), the plots and whether they belong to what runs now.
/// Returns whether Measure was pressed (the caller runs the sweep).
pub fn section(ui: &mut egui::Ui, running: &Running, sweep: Option<&LambdaTradeoff>) -> bool {
    let mut measure = false;
    ui.collapsing("λ trade-off (§4.4.3)", |ui| {
        ui.label(
            "DLS's λ trades tracking for calm: measure this motion at λ = 0.01 … 1 m \
             (10 s each) and see the error within reach and the jitter out of reach.",
        );
        measure = ui
            .button("Measure")
            .on_hover_text("Runs the motion with DLS at seven values of λ, off screen")
            .clicked();
        if let Some(sweep) = sweep {
            if !sweep.is_for(running.preset, running.mode) {
                ui.label(format!(
                    "Measured on {} ({}); measure again for what runs now.",
                    sweep.preset, sweep.mode
                ));
            }
            plots(ui, sweep, running.lambda_m);
        }
    });
    measure
}

fn plots(ui: &mut egui::Ui, sweep: &LambdaTradeoff, current_lambda_m: f64) {
    let series = |f: &dyn Fn(&gaitlab_engine::LambdaPoint) -> Option<f64>| -> Vec<[f64; 2]> {
        sweep
            .points
            .iter()
            .filter_map(|p| f(p).map(|v| [p.lambda_m.log10(), v]))
            .collect()
    };
    let error_mm = series(&|p| p.reachable_error_m.map(|e| e * 1e3));
    let jitter = series(&|p| {
        p.unreachable_jitter_rad
            .map(|j| (j * 1e3).max(JITTER_FLOOR * 1e3).log10())
    });
    let marker = current_lambda_m.log10();
    ui.label(
        egui::RichText::new(format!(
            "Current λ = {current_lambda_m:.3} m (the orange line)"
        ))
        .color(CURRENT),
    );
    if error_mm.is_empty() {
        ui.label("No target was within reach in this motion.");
    } else {
        ui.label("Error on the targets within reach:");
        small_plot(ui, "lambda_error", "mm", &error_mm, marker, false);
    }
    if !jitter.is_empty() {
        ui.label("Jitter of the limbs out of reach, mean |Δ²θ| (log):");
        small_plot(ui, "lambda_jitter", "mrad/frame²", &jitter, marker, true);
    }
}

fn small_plot(
    ui: &mut egui::Ui,
    id: &str,
    y_label: &str,
    points: &[[f64; 2]],
    current_log_lambda: f64,
    log_y: bool,
) {
    crate::plot_scale::still_plot(id)
        .height(PLOT_HEIGHT_PT)
        .include_y(0.0)
        .x_axis_label("λ (m)")
        .y_axis_label(y_label)
        .x_grid_spacer(uniform_grid_spacer(|_| [1.0, 1.0, 1.0]))
        .x_axis_formatter(|mark: GridMark, _| crate::plot_scale::power_of_ten_label(mark))
        .y_grid_spacer(if log_y {
            uniform_grid_spacer(|_| [1.0, 1.0, 1.0])
        } else {
            Box::new(crate::plot_scale::few_round_marks)
        })
        .y_axis_formatter(move |mark: GridMark, _| {
            if log_y {
                crate::plot_scale::power_of_ten_label(mark)
            } else {
                crate::plot_scale::tick_label(mark)
            }
        })
        .label_formatter(move |hover| match hover {
            HoverPosition::NearDataPoint { position, .. } => {
                let y = if log_y {
                    10f64.powf(position.y)
                } else {
                    position.y
                };
                Some(format!("λ {:.3} m: {y:.3}", 10f64.powf(position.x)))
            }
            HoverPosition::Elsewhere { .. } => None,
        })
        .show(ui, |plot| {
            plot.line(Line::new(y_label, PlotPoints::from(points.to_vec())).color(SERIES));
            plot.points(
                Points::new(y_label, PlotPoints::from(points.to_vec()))
                    .color(SERIES)
                    .radius(3.0),
            );
            plot.vline(VLine::new("current λ", current_log_lambda).color(CURRENT));
        });
}
