//! The Recording panel (She 2006 §6.2): a motion take saved as BVH or CSV, and
//! a video of the 3-D view at a chosen frame size (in the browser).

use super::panel::Panel;
use crate::app::App;
use crate::settings::VideoSize;

/// The Recording panel.
pub struct RecordingPanel;

impl Panel for RecordingPanel {
    fn title(&self) -> &'static str {
        "Recording"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        recording(ui, lab);
    }
}

/// Recording panel (She 2006 §6.2): a motion take saved as BVH or CSV, and a
/// video of the 3-D view at a chosen frame size (in the browser).
fn recording(ui: &mut egui::Ui, lab: &mut App) {
    ui.collapsing("Recording", |ui| {
        ui.horizontal(|ui| {
            if lab.recording() {
                if ui
                    .button("Stop motion")
                    .on_hover_text("Stop recording; the take stays available to save")
                    .clicked()
                {
                    lab.stop_recording();
                }
            } else if ui
                .button("Record motion")
                .on_hover_text("Record every animation frame: pose, effectors and targets")
                .clicked()
            {
                lab.start_recording();
            }
            if let Some(take) = lab.take() {
                ui.label(format!(
                    "{} frames · {:.1} s",
                    take.frames(),
                    take.seconds()
                ));
            }
        });
        let has_take = lab.take().is_some_and(|t| t.frames() > 0);
        ui.horizontal(|ui| {
            ui.label("Save the last");
            ui.add(
                egui::DragValue::new(&mut lab.session.settings.export_last_s)
                    .range(0.0..=gaitlab_engine::MAX_TAKE_S)
                    .speed(0.1)
                    .max_decimals(2)
                    .suffix(" s"),
            )
            .on_hover_text("Seconds at the end of the take that Save BVH / Save CSV write, in seconds of animation; 0 saves the whole take");
        });
        ui.horizontal(|ui| {
            for (label, format, hint) in [
                (
                    "Save BVH",
                    "bvh",
                    "Motion capture file for Blender, Maya and friends",
                ),
                (
                    "Save CSV",
                    "csv",
                    "Time, root, joint values, effectors and targets",
                ),
            ] {
                if ui
                    .add_enabled(has_take, egui::Button::new(label))
                    .on_hover_text(hint)
                    .clicked()
                    && let Err(error) = lab.save_take_as_set(format)
                {
                    lab.report_error(error);
                }
            }
        });
        ui.separator();
        let mut size = lab.session.settings.video_size;
        egui::ComboBox::from_label("Video frame size")
            .selected_text(size.label())
            .show_ui(ui, |ui| {
                for s in VideoSize::ALL {
                    ui.selectable_value(&mut size, s, s.label())
                        .on_hover_text("Width × height of the recorded video, pixels");
                }
            })
            .response
            .on_hover_text("Frame size of the WebM video, pixels (View size: the 3-D view as shown)");
        lab.session.settings.video_size = size;
        let video_supported = cfg!(target_arch = "wasm32");
        ui.add_enabled_ui(video_supported, |ui| {
            if lab.video_recording() {
                if ui
                    .button("Stop video")
                    .on_hover_text("Stop the video and download it as a WebM file")
                    .clicked()
                {
                    lab.set_video_recording(false);
                }
            } else if ui
                .button("Record video")
                .on_hover_text("Record the 3-D view as a WebM video")
                .clicked()
            {
                lab.set_video_recording(true);
            }
        });
    });
}
