//! The engine selector and the preset picker, at the top of the controls.

use gaitlab_core::preset::bundled_names;

use super::panel::Panel;
use crate::lab::Lab;

/// The engine selector.
pub struct EnginePanel;

impl Panel for EnginePanel {
    fn title(&self) -> &'static str {
        "Engine"
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        engine(ui, lab);
    }
}

/// The preset picker.
pub struct PresetPanel;

impl Panel for PresetPanel {
    fn title(&self) -> &'static str {
        "Preset"
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        preset(ui, lab);
    }
}

/// The engine selector: She 2006's IK tracking or PODA's gait synthesis
/// (switching loads the matching creature).
fn engine(ui: &mut egui::Ui, lab: &mut Lab) {
    use gaitlab_core::preset::Engine;
    let mut engine = lab.engine();
    ui.horizontal(|ui| {
        ui.label("Engine");
        ui.radio_value(&mut engine, Engine::Ik, "IK (She 2006)")
            .on_hover_text("Sinusoidal effector targets tracked by Jacobian IK (She 2006)");
        ui.radio_value(&mut engine, Engine::Poda, "PODA gaits")
            .on_hover_text("Gait synthesis from period, duty factor and phases (Girard & Maciejewski 1985)");
        ui.radio_value(&mut engine, Engine::Physics, "Physics")
            .on_hover_text("Simulated runners under hopping, speed and posture control (Raibert & Hodgins 1991)");
    });
    if engine != lab.engine()
        && let Err(error) = lab.set_engine(engine)
    {
        lab.report_error(error);
    }
}

/// The preset picker.
fn preset(ui: &mut egui::Ui, lab: &mut Lab) {
    let current = lab.creature().name.clone();
    let mut chosen = None;
    egui::ComboBox::from_label("Preset")
        .selected_text(current.as_str())
        .show_ui(ui, |ui| {
            for name in bundled_names() {
                if ui
                    .selectable_label(name == current, name)
                    .on_hover_text("Load this bundled creature with its own scenario")
                    .clicked()
                {
                    chosen = Some(name);
                }
            }
        })
        .response
        .on_hover_text("The creature and its scenario (bundled presets)");
    if let Some(name) = chosen
        && name != current
        && let Err(error) = lab.set_preset(name)
    {
        lab.report_error(error);
    }
}
