//! The comparison's figures as tables: every view's figures in one table, a
//! column per view (errors, timing, jitter, limit hits, She 2006 §5.3's
//! oscillation and reachability; docs/ik-metrics.md), and a view's
//! per-effector table.

use super::comparison::Comparison;
use super::view::CompareView;

/// Every view's figures in one table (issue 43 item 5: each card had its own,
/// at its own height): a row per figure, a column per view under its
/// method's name in its colour, so a row reads across the methods.
pub(super) fn figures_table(ui: &mut egui::Ui, compare: &Comparison, stacked: bool) {
    type Cell = fn(&CompareView, &gaitlab_core::ik::IkOptions) -> String;
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

/// The view's posture pull (the lab's addition): its gain, or "off (thesis)".
fn posture_pull(view: &CompareView) -> String {
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
pub(super) fn effector_table(ui: &mut egui::Ui, index: usize, view: &CompareView) {
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
