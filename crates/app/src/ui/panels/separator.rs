//! A separating line between groups of panels.

use super::panel::Panel;
use crate::app::App;

/// A horizontal line.
pub struct Separator;

impl Panel for Separator {
    fn title(&self) -> &'static str {
        "—"
    }

    fn ui(&self, _lab: &mut App, ui: &mut egui::Ui) {
        ui.separator();
    }
}
