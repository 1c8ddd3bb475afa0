//! The PODA gait panel's status lines (issue 21 item 3; issue 43 item 5,
//! a layout that holds still): feet down and the margin of the body's centre
//! over their support polygon (the engine layer's
//! [`gaitlab_engine::readout::StabilityReadout`]), whether the walk leaves
//! it, the values the gait derived and a change being taken on — always the
//! same number of one-line rows, so nothing below them moves when a message
//! comes or goes (the long explanations are their tooltips).

/// Share of a period above which a walk is called statically unstable.
pub const UNSTABLE_WARNING_SHARE: f64 = 0.05;

/// Feet down on average below which a gait cannot stand statically at all
/// (a polygon needs three feet): a trot, a pace, a bound, a run.
const FEET_FOR_A_POLYGON: f64 = 3.0;

/// What the status rows show this frame.
pub(super) struct Status<'a> {
    /// Feet down and the stability margin now.
    pub report: gaitlab_engine::readout::StabilityReadout,
    /// Feet down on average by the gait's design: duty factor × legs.
    pub planned_feet_down: f64,
    /// The values the gait derived (eq. 7–8), if any.
    pub derived: &'a [&'a str],
    /// Whether the legs are taking a gait change on.
    pub shifting: bool,
}

/// The status rows: stability, its warning, the derived values and a gait
/// change — four rows whether or not each has something to say.
pub(super) fn status_lines(ui: &mut egui::Ui, status: &Status<'_>) {
    let report = status.report;
    let weak = Some(ui.visuals().weak_text_color());
    let margin = match report.margin_m {
        Some(m) => format!("stability margin {:+.0} mm", m * 1e3),
        None => "in flight".to_owned(),
    };
    row(
        ui,
        &format!("feet down {} · {margin}", report.feet_down),
        None,
        "Static stability: the distance from the body's centre to the nearest edge of the \
         polygon the feet on the ground span, seen from above (negative: outside it, or fewer \
         than three feet down)",
    );
    if report.unstable_share <= UNSTABLE_WARNING_SHARE {
        row(ui, "", None, "");
    } else if status.planned_feet_down < FEET_FOR_A_POLYGON {
        row(
            ui,
            &format!(
                "statically unstable {:.0} % of the last period, by design",
                report.unstable_share * 100.0
            ),
            None,
            "With fewer than three feet down on average (duty factor × legs), the feet never \
             span a polygon for the body's centre to stand over: a trot, a pace, a bound or a \
             run balances dynamically, as PODA's body dynamics (eq. 12–13) do here",
        );
    } else {
        row(
            ui,
            &format!(
                "Warning: statically unstable {:.0} % of the last period",
                report.unstable_share * 100.0
            ),
            Some(crate::theme::WARNING_COLOR),
            "The body's centre leaves the feet's support polygon. Without dynamic balance a \
             real animal would tip here; raise the duty factor or choose a gait with more feet \
             down.",
        );
    }
    let derived = if status.derived.is_empty() {
        String::new()
    } else {
        format!("derived: {}", status.derived.join(", "))
    };
    row(
        ui,
        &derived,
        weak,
        "Values the gait's equations (eq. 7–8) set from the ones you chose",
    );
    row(
        ui,
        if status.shifting {
            "Legs taking the change on, each at its own mid-stance"
        } else {
            ""
        },
        weak,
        "Girard & Maciejewski: each leg adjusts at the beginning of its push; the diagram \
         shows the gait they are moving to (docs/poda.md, Leg by leg)",
    );
}

/// One row of one line: `text` (cut with … where the panel is narrower),
/// weak unless `colour`; an empty row keeps its height.
fn row(ui: &mut egui::Ui, text: &str, colour: Option<egui::Color32>, hover: &str) {
    let text = if text.is_empty() { " " } else { text };
    let rich = match colour {
        Some(colour) => egui::RichText::new(text).color(colour),
        None => egui::RichText::new(text),
    };
    let response = ui.add(egui::Label::new(rich).truncate());
    if !hover.is_empty() && text != " " {
        response.on_hover_text(hover);
    }
}
