//! The readout under the controls: frame, time, display rate, the simulation's
//! cost per frame and each effector's current error.

use gaitlab_core::driver::Driver;

use super::panel::Panel;
use crate::lab::Lab;

/// The readout.
pub struct ReadoutPanel;

impl Panel for ReadoutPanel {
    fn title(&self) -> &'static str {
        "Readout"
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        readout(ui, lab);
    }
}

fn readout(ui: &mut egui::Ui, lab: &Lab) {
    // Side by side, the views' drivers run and the single one waits.
    let time_s = lab
        .comparison()
        .and_then(|c| c.views().first())
        .map_or_else(|| lab.driver().time(), |view| view.driver().time());
    ui.label(format!(
        "frame {} · t = {:.2} s · {:.0} fps",
        lab.frame(),
        time_s,
        lab.playback.fps
    ));
    if lab.comparison().is_some() {
        ui.label("Side by side: each view's errors are in its card below.");
        return;
    }
    let sim_us_per_frame = lab.sim_us_per_frame();
    if sim_us_per_frame > 0.0 {
        ui.label(format!(
            "simulation + IK: {sim_us_per_frame:.1} µs per frame"
        ));
    }
    if let Some(report) = lab.driver().ik_report() {
        for (effector, error) in lab
            .creature()
            .skeleton
            .effectors()
            .iter()
            .zip(&report.effector_error_m)
        {
            ui.label(format!("{}: {:.2} mm", effector.name, error * 1e3));
        }
    }
}
