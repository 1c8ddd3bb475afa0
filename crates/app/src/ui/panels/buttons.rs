//! The Reset / Pause / Step buttons (keys R, space, .): in the side panel, or
//! in the phone layout's bar above the drawer; and the playback rate.

use super::panel::Panel;
use crate::lab::Lab;

/// The buttons in the side panel (the phone layout's bar has them instead).
pub struct ButtonsPanel;

impl Panel for ButtonsPanel {
    fn title(&self) -> &'static str {
        "Reset / Pause / Step"
    }

    fn shown_for(&self, lab: &Lab) -> bool {
        !lab.narrow()
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        buttons(ui, lab);
    }
}

/// Reset / Pause / Step, with the keyboard shortcuts (space, R, .).
pub fn buttons(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.horizontal(|ui| {
        if ui
            .button("Reset")
            .on_hover_text("Back to time 0 and the rest pose (key R)")
            .clicked()
        {
            lab.reset();
        }
        let label = if lab.paused() { "Play" } else { "Pause" };
        if ui
            .button(label)
            .on_hover_text("Pause or resume the animation (space bar)")
            .clicked()
        {
            lab.set_paused(!lab.paused());
        }
        if ui
            .button("Step")
            .on_hover_text("Pause and advance exactly one animation frame (key .)")
            .clicked()
        {
            lab.set_paused(true);
            lab.single_step();
        }
    });
}

/// The playback rate slider, under the buttons (and in the phone drawer).
pub struct RatePanel;

impl Panel for RatePanel {
    fn title(&self) -> &'static str {
        "Playback"
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        rate(ui, lab);
    }
}

/// The playback rate, 0.1× to 2× (the side panel; the same frames, slower or
/// faster, for watching a motion frame by frame).
fn rate(ui: &mut egui::Ui, lab: &mut Lab) {
    let mut rate = lab.playback.rate();
    let range = crate::lab::PLAYBACK_RATES;
    if ui
        .add(
            egui::Slider::new(&mut rate, range)
                .logarithmic(true)
                .custom_formatter(|x, _| format!("{x:.2}×"))
                .text("Playback"),
        )
        .on_hover_text(
            "Simulated time per second of your time: 0.1× to watch a motion slowly, 2× to \
             hurry it; the motion itself is the same",
        )
        .changed()
    {
        lab.playback.set_rate(rate);
    }
}
