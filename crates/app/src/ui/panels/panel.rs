//! A control panel: one type per panel, listed once in the registry
//! ([`super::REGISTRY`]), the way egui_demo_lib registers each demo as a type
//! in one list. Which panels show follows from each panel's own
//! [`Panel::shown_for`], not from a choice over engines in the layout.

use crate::app::App;

/// One panel of the controls (the wide layout's side panel, the phone
/// layout's drawer).
pub trait Panel: Sync {
    /// The panel's name, as its heading or first label says it.
    fn title(&self) -> &'static str;

    /// Whether the panel shows for the lab as it is (its driver, a running
    /// comparison, the layout). All panels show by default.
    fn shown_for(&self, lab: &App) -> bool {
        let _ = lab;
        true
    }

    /// Draws the panel and applies what the person changed.
    fn ui(&self, lab: &mut App, ui: &mut egui::Ui);
}
