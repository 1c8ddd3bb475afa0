//! The PODA gait panel's static-stability lines (issue 21 item 3): feet
//! down, the margin of the body's centre over their support polygon
//! (the engine layer's [`gaitlab_engine::readout::StabilityReadout`]), and a
//! warning when a walk leaves it.

/// Share of a period above which a walk is called statically unstable.
pub const UNSTABLE_WARNING_SHARE: f64 = 0.05;

/// Feet down and the static stability margin now, and a warning when the
/// body's centre left the support polygon for part of the last period.
pub(super) fn stability_lines(
    ui: &mut egui::Ui,
    report: gaitlab_engine::readout::StabilityReadout,
) {
    let margin = match report.margin_m {
        Some(m) => format!("stability margin {:+.0} mm", m * 1e3),
        None => "in flight".to_owned(),
    };
    ui.label(format!("feet down {} · {margin}", report.feet_down))
        .on_hover_text(
            "Static stability: the distance from the body's centre to the nearest edge of the \
         polygon the feet on the ground span, seen from above (negative: outside it, or fewer \
         than three feet down)",
        );
    if report.unstable_share > UNSTABLE_WARNING_SHARE {
        ui.colored_label(
            crate::theme::WARNING_COLOR,
            format!(
                "Warning: statically unstable {:.0} % of the last period: the body's centre \
                 leaves the feet's support polygon. Without dynamic balance a real animal would \
                 tip here; raise the duty factor or choose a gait with more feet down.",
                report.unstable_share * 100.0
            ),
        );
    }
}
