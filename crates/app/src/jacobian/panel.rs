//! The Jacobian panel's figures (issue 44 item 2): per view, the singular
//! values and the condition number in words; one log–log plot of each
//! method's gain against σ — its formula as a line (1/σ, σ/(σ² + λ²), α·σ),
//! and at each of this iteration's σᵢ a dot at the gain the method actually
//! gave that direction, clamps included, so a dot below its line is a clamp
//! at work; the smallest σ and the condition number over the last seconds;
//! and each iteration's ‖Δθ‖ and the error before and after it.

use egui::Color32;
use egui_plot::{
    GridMark, HoverPosition, Legend, Line, MarkerShape, PlotPoints, Points, uniform_grid_spacer,
};
use gaitlab_core::ik::GainLaw;

use super::probe::{JacobianProbe, TRACE_S};

/// Height of each plot, points.
const PLOT_HEIGHT_PT: f32 = 120.0;

/// Measured gains below this show as a cross on the floor: the direction
/// got no step (a joint at its limit, or the error had no part there), rad/m.
const GAIN_FLOOR: f64 = 1e-3;

/// Samples along each gain line.
const CURVE_SAMPLES: usize = 64;

/// The traces' colours (Okabe & Ito: blue, vermilion).
const FIRST: Color32 = Color32::from_rgb(0x00, 0x72, 0xB2);
const SECOND: Color32 = Color32::from_rgb(0xD5, 0x5E, 0x00);

/// A σ list in words: the largest, the smallest and how many.
fn sigma_words(sigma: &[f64], zero: usize) -> String {
    match (sigma.first(), sigma.last()) {
        (Some(max), Some(min)) => {
            let zero = if zero > 0 {
                format!(", and {zero} at 0")
            } else {
                String::new()
            };
            format!("{} σ from {max:.3} to {min:.3} m/rad{zero}", sigma.len())
        }
        _ => "no singular values (J is zero)".to_owned(),
    }
}

/// The law's formula in words.
fn law_words(law: GainLaw) -> String {
    match law {
        GainLaw::Transpose { alpha } => format!("Gain α·σ, α = {alpha:.3}."),
        GainLaw::Pinv { cutoff } => format!("Gain 1/σ (0 below σ = {cutoff:.1e})."),
        GainLaw::Dls { lambda } => format!(
            "Gain σ/(σ² + λ²), λ = {lambda:.3} m: at most {:.2}.",
            0.5 / lambda
        ),
        GainLaw::Sdls { gamma_max } => {
            format!("Gain 1/σ, clamped per direction (γmax = {gamma_max:.3} rad).")
        }
        GainLaw::None => "No Jacobian.".to_owned(),
    }
}

/// Draws the panel's figures for `views` (each view's label and colour, in
/// the probe's order).
pub fn figures(ui: &mut egui::Ui, probe: &JacobianProbe, views: &[(String, Color32)]) {
    let mut low = f64::INFINITY;
    let mut high = f64::NEG_INFINITY;
    for (i, (label, colour)) in views.iter().enumerate() {
        let Some(spectrum) = probe.spectrum(i) else {
            ui.colored_label(
                *colour,
                format!("{label}: no Jacobian (CCD turns one joint at a time)"),
            );
            continue;
        };
        let sigma: Vec<f64> = spectrum.directions().iter().map(|d| d.sigma).collect();
        let condition = spectrum.condition().map_or("—".to_owned(), |c| {
            if c.is_finite() {
                format!("{c:.1}")
            } else {
                "∞".to_owned()
            }
        });
        let law = spectrum.law().map_or(String::new(), law_words);
        ui.colored_label(
            *colour,
            format!(
                "{label}: {}; condition {condition}. {law}",
                sigma_words(&sigma, spectrum.zero_count())
            ),
        );
        for s in sigma {
            low = low.min(s);
            high = high.max(s);
        }
    }
    if low.is_finite() && high.is_finite() {
        ui.label(
            "Gain per singular direction (rad/m) — line: the method's formula; dots: at this \
             iteration's σᵢ, the gain the direction actually got, (vᵢ·Δθ)/(uᵢ·e). A dot under \
             its line is a clamp at work; a cross on the floor, a direction that got no step \
             (a joint at its limit).",
        );
        gain_plot(ui, probe, views, low, high);
    }
    let frames: Vec<_> = probe.frames().copied().collect();
    if !frames.is_empty() {
        ui.label(format!(
            "Smallest σ and condition number, last {TRACE_S:.0} s (log):"
        ));
        let sigma_min: Vec<[f64; 2]> = frames
            .iter()
            .filter(|p| p.sigma_min > 0.0)
            .map(|p| [p.time_s, p.sigma_min.log10()])
            .collect();
        let condition: Vec<[f64; 2]> = frames
            .iter()
            .filter(|p| p.condition.is_finite())
            .map(|p| [p.time_s, p.condition.log10()])
            .collect();
        trace_plot(
            ui,
            "jacobian_conditioning",
            "time (s)",
            true,
            &[
                ("σmin (m/rad)", FIRST, sigma_min),
                ("condition", SECOND, condition),
            ],
        );
    }
    let iterations: Vec<_> = probe.iterations().copied().collect();
    if !iterations.is_empty() {
        ui.label("Each iteration: ‖Δθ‖ (rad), and the largest error before and after it (mm):");
        let steps: Vec<[f64; 2]> = iterations
            .iter()
            .enumerate()
            .map(|(k, p)| [k as f64, p.step_norm])
            .collect();
        trace_plot(
            ui,
            "jacobian_steps",
            "iteration",
            false,
            &[("‖Δθ‖", FIRST, steps)],
        );
        let before: Vec<[f64; 2]> = iterations
            .iter()
            .enumerate()
            .filter(|(_, p)| p.error_before_m.is_finite())
            .map(|(k, p)| [k as f64, p.error_before_m * 1e3])
            .collect();
        let after: Vec<[f64; 2]> = iterations
            .iter()
            .enumerate()
            .filter(|(_, p)| p.error_after_m.is_finite())
            .map(|(k, p)| [k as f64, p.error_after_m * 1e3])
            .collect();
        trace_plot(
            ui,
            "jacobian_errors",
            "iteration",
            false,
            &[
                ("before (mm)", SECOND, before),
                ("after (mm)", FIRST, after),
            ],
        );
    }
}

/// The log–log gain plot over σ ∈ [`low`/10, `high`·3].
fn gain_plot(
    ui: &mut egui::Ui,
    probe: &JacobianProbe,
    views: &[(String, Color32)],
    low: f64,
    high: f64,
) {
    let (x0, x1) = ((low / 10.0).log10(), (high * 3.0).log10());
    crate::plot_scale::still_plot("jacobian_gain")
        .height(PLOT_HEIGHT_PT * 1.5)
        .x_axis_label("σ (m/rad)")
        .y_axis_label("gain (rad/m)")
        .x_grid_spacer(uniform_grid_spacer(|_| [1.0, 1.0, 1.0]))
        .y_grid_spacer(uniform_grid_spacer(|_| [1.0, 1.0, 1.0]))
        .x_axis_formatter(|mark: GridMark, _| crate::plot_scale::power_of_ten_label(mark))
        .y_axis_formatter(|mark: GridMark, _| crate::plot_scale::power_of_ten_label(mark))
        .label_formatter(|hover| match hover {
            HoverPosition::NearDataPoint { position, .. } => Some(format!(
                "σ {:.3e}, gain {:.3e}",
                10f64.powf(position.x),
                10f64.powf(position.y)
            )),
            HoverPosition::Elsewhere { .. } => None,
        })
        .show(ui, |plot| {
            for (i, (label, colour)) in views.iter().enumerate() {
                let Some(spectrum) = probe.spectrum(i) else {
                    continue;
                };
                let Some(law) = spectrum.law() else {
                    continue;
                };
                let line: Vec<[f64; 2]> = (0..CURVE_SAMPLES)
                    .filter_map(|k| {
                        let x = x0 + (x1 - x0) * k as f64 / (CURVE_SAMPLES - 1) as f64;
                        let g = law.formula(10f64.powf(x))?;
                        (g > 0.0).then(|| [x, g.log10()])
                    })
                    .collect();
                plot.line(Line::new(label.clone(), PlotPoints::from(line)).color(*colour));
                let actual = probe.actual_gains(i).unwrap_or(&[]);
                let mut dots = Vec::new();
                let mut stalled = Vec::new();
                for (d, g) in spectrum.directions().iter().zip(actual) {
                    match g {
                        Some(g) if *g >= GAIN_FLOOR => dots.push([d.sigma.log10(), g.log10()]),
                        Some(_) => stalled.push([d.sigma.log10(), GAIN_FLOOR.log10()]),
                        None => {}
                    }
                }
                plot.points(
                    Points::new(format!("{label} σᵢ"), PlotPoints::from(dots))
                        .color(*colour)
                        .radius(3.5),
                );
                plot.points(
                    Points::new(format!("{label}: no step"), PlotPoints::from(stalled))
                        .color(*colour)
                        .shape(MarkerShape::Cross)
                        .radius(4.0),
                );
            }
        });
}

/// A small plot of a few named series against `x_label`; `log_y`: the
/// values are log₁₀ and the axis says powers of ten.
fn trace_plot(
    ui: &mut egui::Ui,
    id: &str,
    x_label: &str,
    log_y: bool,
    series: &[(&str, Color32, Vec<[f64; 2]>)],
) {
    let mut plot = crate::plot_scale::still_plot(id);
    if !log_y {
        plot = plot.include_y(0.0);
    }
    plot.height(PLOT_HEIGHT_PT)
        .legend(Legend::default())
        .x_axis_label(x_label)
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
        .show(ui, |plot| {
            for (name, colour, points) in series {
                plot.line(Line::new(*name, PlotPoints::from(points.clone())).color(*colour));
            }
        });
}
