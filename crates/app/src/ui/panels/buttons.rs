//! The Reset / Pause / Back / Step buttons (keys R, space, comma, period):
//! in the side panel, or in the phone layout's bar above the drawer; the
//! playback rate and the history scrubber ([`crate::app::rewind::REWIND_S`] seconds).

use super::panel::Panel;
use crate::app::App;

/// The buttons in the side panel (the phone layout's bar has them instead).
pub struct ButtonsPanel;

impl Panel for ButtonsPanel {
    fn title(&self) -> &'static str {
        "Reset / Pause / Step"
    }

    fn shown_for(&self, lab: &App) -> bool {
        !lab.narrow()
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        ui.horizontal(|ui| buttons(ui, lab));
    }
}

/// Reset / Pause / Back / Step, with the keyboard shortcuts (R, space,
/// comma, period), added to `ui` as they are: the side panel puts them in a
/// row, the phone bar in its wrapping row (a row of their own would not
/// wrap, and Step went off a narrow screen).
pub fn buttons(ui: &mut egui::Ui, lab: &mut App) {
    if bar_button(ui, "Reset")
        .on_hover_text("Back to time 0 and the rest pose (key R)")
        .clicked()
    {
        lab.reset();
    }
    let label = if lab.paused() { "Play" } else { "Pause" };
    if bar_button(ui, label)
        .on_hover_text("Pause or resume the animation (space bar)")
        .clicked()
    {
        let paused = lab.paused();
        lab.set_paused(!paused);
    }
    if bar_button(ui, "Back")
        .on_hover_text(
            "Pause and go back one animation frame (key ,); the last 10 s are kept, and \
             stepping forward again replays them exactly",
        )
        .clicked()
        && let Err(error) = lab.step_back(1)
    {
        lab.report_error(error);
    }
    if bar_button(ui, "Step")
        .on_hover_text("Pause and advance exactly one animation frame (key .)")
        .clicked()
    {
        lab.set_paused(true);
        lab.single_step();
    }
}

/// A button at least [`crate::ui::TOUCH_TARGET_PT`] wide (short words such
/// as Step stay a full touch target in the phone bar's tighter padding).
fn bar_button(ui: &mut egui::Ui, text: &str) -> egui::Response {
    ui.add(egui::Button::new(text).min_size(egui::vec2(crate::ui::TOUCH_TARGET_PT, 0.0)))
}

/// The playback rate slider, under the buttons (and in the phone drawer).
pub struct RatePanel;

impl Panel for RatePanel {
    fn title(&self) -> &'static str {
        "Playback"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        rate(ui, lab);
        // On a wide screen the scrubber runs along the window's foot.
        if lab.narrow() {
            let width = ui.spacing().slider_width;
            history_scrubber(ui, lab, width);
        }
    }
}

/// Room the scrubber leaves beside its rail for its value and label, points.
const SCRUBBER_LABELS_PT: f32 = 140.0;

/// The history scrubber, its rail `width` points wide (less its value and
/// label): the frame shown among the stored ones, labelled in seconds
/// before the newest; dragging it pauses and goes there.
pub(crate) fn history_scrubber(ui: &mut egui::Ui, lab: &mut App, width: f32) {
    let Some((oldest, newest)) = lab.rewind_range() else {
        return;
    };
    let rail = if width > 2.0 * SCRUBBER_LABELS_PT {
        width - SCRUBBER_LABELS_PT
    } else {
        width
    };
    ui.scope(|ui| {
        ui.spacing_mut().slider_width = rail;
        scrubber(ui, lab, oldest, newest);
    });
}

/// The scrubber's slider between frames `oldest` and `newest`.
fn scrubber(ui: &mut egui::Ui, lab: &mut App, oldest: u64, newest: u64) {
    let dt = lab.frame_seconds();
    let mut frame = lab.frame().clamp(oldest, newest);
    let response = ui
        .add_enabled(
            newest > oldest,
            egui::Slider::new(&mut frame, oldest..=newest)
                .custom_formatter(move |f, _| {
                    let behind_s = (newest as f64 - f) * dt;
                    if behind_s < 0.5 * dt {
                        "now".to_owned()
                    } else {
                        format!("−{behind_s:.2} s")
                    }
                })
                .text("History"),
        )
        .on_hover_text(
            "Drag back through the last 10 s (pauses); Step and Play from there simulate \
             again and replay the same frames exactly",
        );
    if response.changed()
        && let Err(error) = lab.rewind_to(frame)
    {
        lab.report_error(error);
    }
}

/// The playback rate, 0.1× to 2× (the side panel; the same frames, slower or
/// faster, for watching a motion frame by frame).
fn rate(ui: &mut egui::Ui, lab: &mut App) {
    let mut rate = lab.playback.rate();
    let range = crate::lab::PLAYBACK_RATES;
    let response = ui
        .add(
            egui::Slider::new(&mut rate, range)
                .logarithmic(true)
                .custom_formatter(|x, _| format!("{x:.2}×"))
                .text("Playback"),
        )
        .on_hover_text(
            "Simulated time per second of your time: 0.1× to watch a motion slowly, 2× to \
             hurry it; the motion itself is the same",
        );
    lab.layout.widgets_pt.rate_slider = crate::lab::layout::rect_pt(response.rect);
    if response.changed() {
        lab.playback.set_rate(rate);
    }
}
