//! The engine selector and the preset picker, at the top of the controls.

use gaitlab_core::preset::{Engine, bundled_catalog};

use super::panel::Panel;
use crate::app::App;

/// The engine selector.
pub struct EnginePanel;

impl Panel for EnginePanel {
    fn title(&self) -> &'static str {
        "Engine"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        engine(ui, lab);
    }
}

/// The preset picker.
pub struct PresetPanel;

impl Panel for PresetPanel {
    fn title(&self) -> &'static str {
        "Preset"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        preset(ui, lab);
    }
}

/// The engine selector: She 2006's IK tracking or PODA's gait synthesis
/// (switching loads the matching creature).
fn engine(ui: &mut egui::Ui, lab: &mut App) {
    let mut engine = lab.engine();
    ui.horizontal(|ui| {
        ui.label("Engine");
        for e in Engine::ALL {
            ui.radio_value(&mut engine, e, engine_label(e))
                .on_hover_text(engine_hover(e));
        }
    });
    if engine != lab.engine()
        && let Err(error) = lab.set_engine(engine)
    {
        lab.report_error(error);
    }
}

/// An engine's name in the selector and the preset menu's groups.
fn engine_label(engine: Engine) -> &'static str {
    match engine {
        Engine::Ik => "IK (She 2006)",
        Engine::Poda => "PODA gaits",
        Engine::Physics => "Physics",
    }
}

fn engine_hover(engine: Engine) -> &'static str {
    match engine {
        Engine::Ik => "Sinusoidal effector targets tracked by Jacobian IK (She 2006)",
        Engine::Poda => {
            "Gait synthesis from period, duty factor and phases (Girard & Maciejewski 1985)"
        }
        Engine::Physics => {
            "Simulated runners under hopping, speed and posture control (Raibert & Hodgins 1991)"
        }
    }
}

/// The preset picker: the bundled presets grouped by engine, each with its
/// description as its tooltip; an edited or loaded preset is marked so.
fn preset(ui: &mut egui::Ui, lab: &mut App) {
    let current = lab.creature().name.clone();
    let edited = lab.session.custom_preset.is_some();
    let title = crate::words::preset_title(&current);
    let shown = if edited {
        format!("{title} (edited)")
    } else {
        title.to_owned()
    };
    let mut chosen = None;
    let mut entries = crate::lab::layout::MenuRects::new();
    let combo = egui::ComboBox::from_label("Preset")
        .selected_text(shown)
        .height(480.0)
        .show_ui(ui, |ui| {
            for engine in Engine::ALL {
                ui.label(egui::RichText::new(engine_label(engine)).strong());
                for info in bundled_catalog().iter().filter(|i| i.engine == engine) {
                    let title = crate::words::preset_title(info.name);
                    let entry = ui
                        .selectable_label(!edited && info.name == current, title)
                        .on_hover_text(format!("{} ({})", info.description, info.name));
                    entries.insert(info.name, crate::lab::layout::rect_pt(entry.rect));
                    if entry.clicked() {
                        chosen = Some(info.name);
                    }
                }
            }
        })
        .response
        .on_hover_text("The creature and its scenario: the bundled presets, by engine");
    lab.layout.widgets_pt.preset_combo = crate::lab::layout::rect_pt(combo.rect);
    if combo.clicked() {
        lab.layout.preset_combo_clicks += 1;
    }
    lab.layout.preset_menu_pt = entries;
    if let Some(name) = chosen
        && (name != current || edited)
        && let Err(error) = lab.set_preset(name)
    {
        lab.report_error(error);
    }
}
