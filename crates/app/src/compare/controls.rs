//! The "Side by side" controls (issue 44 item 6: the comparison's own panel
//! code, in its folder): on or off, 2 or 4 views, each view's method, the
//! scenario and the layout. They read the running configuration and return
//! what the person asked ([`CompareRequest`]); the lab carries it out.

use gaitlab_core::ik::IkOptions;

use super::config::{CompareConfig, CompareScenario, DEFAULT_VIEWS};
use super::method::CompareMethod;

/// What a person asked of the comparison in its controls; the lab carries
/// it out (and says why where it cannot).
#[derive(Clone, Debug, PartialEq)]
pub enum CompareRequest {
    /// Open the she-2006 preset and its four methods side by side.
    AsTheThesis,
    /// Start a comparison.
    Start(CompareConfig),
    /// Leave it.
    Stop,
    /// Change the running one.
    Configure(CompareConfig),
}

/// The "Side by side" section of the left panel (IK engine only): on/off,
/// 2 or 4 views, each view's method, the scenario (`tracking`: the targets
/// are a recording, which then replaces the scenario menu) and the layout.
/// `current` is the running comparison's configuration, `base` the lab's IK
/// options (a new view's defaults).
#[must_use]
pub fn controls(
    ui: &mut egui::Ui,
    current: Option<&CompareConfig>,
    base: &IkOptions,
    tracking: bool,
) -> Option<CompareRequest> {
    let mut request = None;
    egui::CollapsingHeader::new("Side by side")
        .default_open(false)
        .show(ui, |ui| {
            if ui
                .button("She 2006 as written: 4 methods")
                .on_hover_text(
                    "Open the she-2006 preset (the thesis' §5.2.2 targets, no posture pull) \
                     and run transpose, pinv, DLS and SDLS side by side on the current motion \
                     (She 2006 §5.3)",
                )
                .clicked()
            {
                request = Some(CompareRequest::AsTheThesis);
            }
            let mut on = current.is_some();
            if ui
                .checkbox(&mut on, "Compare methods")
                .on_hover_text(
                    "Run 2 or 4 IK methods side by side on the same figure and targets, \
                     in lock step, with one shared camera",
                )
                .changed()
            {
                request = Some(if on {
                    CompareRequest::Start(CompareConfig::new(
                        &DEFAULT_VIEWS,
                        CompareScenario::Script,
                        base,
                    ))
                } else {
                    CompareRequest::Stop
                });
            }
            let Some(current) = current else {
                return;
            };
            let mut config = current.clone();
            ui.horizontal(|ui| {
                for (count, tip) in [
                    (2, "Two views, left and right"),
                    (4, "Four views in a 2 × 2 grid"),
                ] {
                    if ui
                        .radio(config.views.len() == count, format!("{count} views"))
                        .on_hover_text(tip)
                        .clicked()
                    {
                        resize(&mut config, count, base);
                    }
                }
            });
            for i in 0..config.views.len() {
                let mut method = config.views[i];
                egui::ComboBox::from_label(format!("View {}", i + 1))
                    .selected_text(method.label())
                    .show_ui(ui, |ui| {
                        for m in CompareMethod::ALL {
                            ui.selectable_value(&mut method, m, m.label())
                                .on_hover_text(m.behaviour());
                        }
                    })
                    .response
                    .on_hover_text("The IK method this view runs");
                if method != config.views[i] {
                    config.views[i] = method;
                    config.options[i] = method.options(base);
                }
            }
            if tracking {
                ui.label("Targets: the recording (Recorded targets panel)");
            } else {
                scenario_combo(ui, &mut config);
            }
            ui.horizontal(|ui| {
                for (overlay, label, tip) in [
                    (false, "Side by side", "One 3-D view per method"),
                    (
                        true,
                        "Overlay",
                        "Every method's figure in one 3-D view, each in its card's colour, \
                         chasing the same targets; a bone where methods agree is striped in \
                         their colours, a joint they share is grey",
                    ),
                ] {
                    if ui
                        .radio(config.overlay == overlay, label)
                        .on_hover_text(tip)
                        .clicked()
                    {
                        config.overlay = overlay;
                    }
                }
            });
            if request.is_none() && config != *current {
                request = Some(CompareRequest::Configure(config));
            }
        });
    request
}

/// The scenario menu: the thesis script or the singularity stretch.
fn scenario_combo(ui: &mut egui::Ui, config: &mut CompareConfig) {
    egui::ComboBox::from_label("Scenario")
        .selected_text(scenario_label(config.scenario))
        .show_ui(ui, |ui| {
            for s in [CompareScenario::Script, CompareScenario::Singularity] {
                ui.selectable_value(&mut config.scenario, s, scenario_label(s));
            }
        })
        .response
        .on_hover_text(
            "Where the targets go: the thesis script of the chosen motion, or every \
             limb pulled to its full reach and beyond (a singular, stretched pose)",
        );
}

fn scenario_label(scenario: CompareScenario) -> &'static str {
    match scenario {
        CompareScenario::Script => "Thesis script",
        CompareScenario::Singularity => "Singularity (stretched limbs)",
    }
}

/// Keeps the first `count` views, or adds the default views not yet shown.
fn resize(config: &mut CompareConfig, count: usize, base: &IkOptions) {
    config.views.truncate(count);
    config.options.truncate(count);
    for m in DEFAULT_VIEWS.into_iter().chain(CompareMethod::ALL) {
        if config.views.len() >= count {
            break;
        }
        if !config.views.contains(&m) {
            config.views.push(m);
            config.options.push(m.options(base));
        }
    }
}
