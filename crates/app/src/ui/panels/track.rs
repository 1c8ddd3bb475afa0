//! The "Recorded targets" panel (issue 21 item 5): the target CSV the figure
//! follows — its file, length and rows, where playback stands in it — and a
//! way back to the creature's own motion.

use super::panel::Panel;
use crate::app::App;
use gaitlab_core::driver::Driver;

/// The "Recorded targets" panel, while a recording is followed.
pub struct TrackPanel;

impl Panel for TrackPanel {
    fn title(&self) -> &'static str {
        "Recorded targets"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.tracking().is_some()
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        let Some(track) = lab.tracking() else {
            return;
        };
        let targets = &track.targets;
        let (start, end) = (targets.start_time(), targets.end_time());
        ui.strong("Recorded targets");
        ui.label(format!(
            "Following {}: {} rows, {} effectors, {:.2} s",
            track.name,
            targets.row_count(),
            targets.effector_count(),
            end - start
        ))
        .on_hover_text(
            "Each effector chases its recorded target (world metres, linear between rows) \
             with the chosen IK method; side by side, every method follows the same recording",
        );
        let t = lab.driver().time();
        if t > end {
            ui.label(format!(
                "Past the end ({end:.2} s): the targets hold their last place; Reset plays it again"
            ));
        } else {
            ui.add(
                egui::ProgressBar::new(((t - start) / (end - start).max(1e-9)) as f32)
                    .text(format!("{t:.2} s of {end:.2} s")),
            );
        }
        if ui
            .button("Stop following")
            .on_hover_text("Back to the creature's own motion")
            .clicked()
            && let Err(error) = lab.stop_tracking()
        {
            lab.report_error(error);
        }
    }
}
