//! The comparison's jitter and oscillation at a glance (issue 21 item 1):
//! one bar per view in its colour, every view on one labelled scale —
//! She 2006 §5.3's oscillation in Hz, and the joint-velocity jitter on a
//! log scale (the pseudoinverse's can be a thousand times the others').

use egui_plot::{Bar, BarChart, GridMark, uniform_grid_spacer};

use super::comparison::Comparison;

/// Height of one bar chart, points.
const CHART_HEIGHT_PT: f32 = 120.0;

/// Jitter below this shows as this (the log scale's floor), rad per frame².
const JITTER_FLOOR: f64 = 1e-9;

/// The most views a comparison has (one colour each).
const MAX_VIEWS: usize = 4;

/// The views' names and colours, one per bar.
struct Key {
    names: [&'static str; MAX_VIEWS],
    colours: [egui::Color32; MAX_VIEWS],
}

/// The two charts, side by side, or one under the other when `stacked`.
pub(super) fn bars(ui: &mut egui::Ui, compare: &Comparison, stacked: bool) {
    // At most four views: fixed arrays, nothing allocated for them per frame.
    let views = compare.views();
    let n = views.len().min(MAX_VIEWS);
    let mut key = Key {
        names: [""; MAX_VIEWS],
        colours: [egui::Color32::GRAY; MAX_VIEWS],
    };
    let mut jitter = [0.0; MAX_VIEWS];
    let mut oscillation = [0.0; MAX_VIEWS];
    for (i, v) in views.iter().take(n).enumerate() {
        key.names[i] = v.method.name();
        key.colours[i] = compare.colour(i);
        jitter[i] = v.metrics().jitter_rad().max(JITTER_FLOOR).log10();
        oscillation[i] = v.oscillation_hz().unwrap_or(0.0);
    }
    let (jitter, oscillation) = (&jitter[..n], &oscillation[..n]);
    let jitter_chart = |ui: &mut egui::Ui| {
        // Bars rise from a whole power of ten below the smallest.
        let base = jitter.iter().copied().fold(f64::INFINITY, f64::min).floor() - 1.0;
        chart(
            ui,
            "compare-jitter",
            "jitter (rad/frame², log)",
            &key,
            jitter,
            base,
            true,
        )
        .on_hover_text(
            "Joint-velocity jitter over the last 4 s, mean |Δ²θ| per frame², on a log scale: \
             each grid step is ten times the one below",
        );
    };
    let oscillation_chart = |ui: &mut egui::Ui| {
        chart(
            ui,
            "compare-oscillation",
            "oscillation (Hz)",
            &key,
            oscillation,
            0.0,
            false,
        )
        .on_hover_text(
            "She 2006 §5.3's oscillation: sign changes of each limb joint's per-frame Δθ per \
             second, averaged over the effectors since the reset (a smooth swing at f Hz gives 2f)",
        );
    };
    if stacked {
        jitter_chart(ui);
        oscillation_chart(ui);
    } else {
        ui.columns(2, |columns| {
            jitter_chart(&mut columns[0]);
            oscillation_chart(&mut columns[1]);
        });
    }
}

/// A bar chart of `values` (one per view, at x = 1, 2, …) rising from
/// `base`; `log`: the values are base-10 logarithms, the axis reads 1e-n.
fn chart(
    ui: &mut egui::Ui,
    id: &str,
    y_label: &str,
    key: &Key,
    values: &[f64],
    base: f64,
    log: bool,
) -> egui::Response {
    let bars: Vec<Bar> = values
        .iter()
        .enumerate()
        .map(|(i, &v)| {
            let shown = if log {
                format!("{:.2e}", 10f64.powf(v))
            } else {
                format!("{v:.2}")
            };
            Bar::new((i + 1) as f64, v - base)
                .base_offset(base)
                .width(0.6)
                .fill(key.colours[i])
                .name(format!("{} · {}: {shown}", i + 1, key.names[i]))
        })
        .collect();
    let top = values.iter().copied().fold(base, f64::max);
    let labels = &key.names[..values.len()];
    crate::plot_scale::still_plot(id)
        .height(CHART_HEIGHT_PT)
        .include_y(base)
        .include_y(if log { top.ceil() } else { top.max(1.0) * 1.1 })
        .include_x(0.4)
        .include_x(values.len() as f64 + 0.6)
        .y_axis_label(y_label)
        .x_grid_spacer(uniform_grid_spacer(|_| [1.0, 1.0, 1.0]))
        .x_axis_formatter(move |mark: GridMark, _| {
            let k = mark.value.round();
            if (mark.value - k).abs() > 1e-6 || k < 1.0 {
                return String::new();
            }
            labels
                .get(k as usize - 1)
                .map_or_else(String::new, |n| format!("{} · {n}", k as usize))
        })
        .y_grid_spacer(if log {
            uniform_grid_spacer(|_| [1.0, 1.0, 1.0])
        } else {
            Box::new(crate::plot_scale::few_round_marks)
        })
        .y_axis_formatter(move |mark: GridMark, _| {
            if log {
                let k = mark.value.round();
                if (mark.value - k).abs() > 1e-6 {
                    String::new()
                } else {
                    format!("1e{}", k as i32)
                }
            } else {
                crate::plot_scale::tick_label(mark)
            }
        })
        .show(ui, |plot| plot.bar_chart(BarChart::new(y_label, bars)))
        .response
}
