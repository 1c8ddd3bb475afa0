//! The readout under the controls: frame, time, display rate, the lab's
//! additions in force (or that the paper runs alone), the simulation's cost
//! per frame and each effector's current error, and by how much its target is
//! out of reach when it is (She 2006 §5.3).

use gaitlab_core::driver::Driver;

use super::panel::Panel;
use crate::app::App;

/// The readout.
pub struct ReadoutPanel;

impl Panel for ReadoutPanel {
    fn title(&self) -> &'static str {
        "Readout"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        readout(ui, lab);
    }
}

fn readout(ui: &mut egui::Ui, lab: &mut App) {
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
    additions(ui, lab);
    if lab.comparison().is_some() {
        ui.label(if lab.narrow() {
            "Side by side: each view's errors are in its card (Plots)."
        } else {
            "Side by side: each view's errors are in its card below."
        });
        return;
    }
    let sim_us_per_frame = lab.sim_us_per_frame();
    if sim_us_per_frame > 0.0 {
        ui.label(format!(
            "simulation + IK: {sim_us_per_frame:.1} µs per frame"
        ));
    }
    if let Some(report) = lab.driver().ik_report() {
        for (e, (effector, error)) in lab
            .creature()
            .skeleton
            .effectors()
            .iter()
            .zip(&report.effector_error_m)
            .enumerate()
        {
            let beyond = report.out_of_reach_m.get(e).copied().unwrap_or(0.0);
            if beyond > 0.0 {
                ui.label(
                    egui::RichText::new(format!(
                        "{}: {:.2} mm · target out of reach by {:.0} mm",
                        effector.name,
                        error * 1e3,
                        beyond * 1e3
                    ))
                    .color(egui::Color32::from_rgb(0xe0, 0x80, 0x40)),
                )
                .on_hover_text(
                    "The target lies farther from the limb's first joint than the limb is \
                     long: no pose reaches it (She 2006 §5.3's unreachable target)",
                );
            } else {
                ui.label(format!("{}: {:.2} mm", effector.name, error * 1e3));
            }
        }
    }
}

/// The lab's additions in force for what runs, each with its reason on
/// hover, or that the paper runs alone (issue 41: the screen names them).
fn additions(ui: &mut egui::Ui, lab: &mut App) {
    let found = lab.stage.driver.lab_additions();
    if found.is_empty() {
        ui.label("The paper alone: none of the lab's additions in force.")
            .on_hover_text(
                "Every choice that runs is the paper's, or a value the paper leaves open",
            );
        return;
    }
    ui.horizontal_wrapped(|ui| {
        ui.label("Lab's additions in force:")
            .on_hover_text("What gaitlab adds to the paper for this run; hover each for why");
        for addition in found {
            ui.label(egui::RichText::new(addition.name).monospace())
                .on_hover_text(addition.reason);
        }
        let alone = ui
            .button("Run the paper alone")
            .on_hover_text("Start again with every one of these off, as the paper has it");
        if alone.clicked()
            && let Err(error) = lab.run_paper_alone()
        {
            lab.report_error(error);
        }
    });
}
