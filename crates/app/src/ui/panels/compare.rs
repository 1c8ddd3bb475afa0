//! The "Side by side" panel and the comparison's cards in the lab
//! ([`crate::compare`] draws both; issue 44 item 6): this adapter hands the
//! comparison's controls the lab's configuration and carries out what they
//! ask, reporting what the lab refuses.

use super::panel::Panel;
use crate::app::App;
use crate::compare::CompareRequest;

/// The "Side by side" controls.
pub struct SideBySidePanel;

impl Panel for SideBySidePanel {
    fn title(&self) -> &'static str {
        "Side by side"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().is_ik()
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        let base = lab.compare_base();
        let request = crate::compare::controls(
            ui,
            lab.comparison().map(|c| &c.config),
            &base,
            lab.tracking().is_some(),
        );
        let outcome = match request {
            None => Ok(()),
            Some(CompareRequest::AsTheThesis) => lab.compare_as_the_thesis(),
            Some(CompareRequest::Start(config)) => lab.start_compare(config),
            Some(CompareRequest::Stop) => {
                lab.stop_compare();
                Ok(())
            }
            Some(CompareRequest::Configure(config)) => lab.configure_compare(config),
        };
        if let Err(error) = outcome {
            lab.report_error(error);
        }
    }
}

/// The comparison's cards, in columns or `stacked` (the phone's drawer).
pub fn cards(ui: &mut egui::Ui, lab: &mut App, stacked: bool) {
    if let Some(compare) = lab.comparison_mut() {
        crate::compare::cards(ui, compare, stacked);
    }
}
