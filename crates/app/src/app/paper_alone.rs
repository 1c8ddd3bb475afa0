//! "Run the paper alone": the running preset again with every lab addition
//! of its engine off (`gaitlab_core::preset::paper_alone`), as a custom
//! preset, with the panel's IK options following the file's.

use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::paper_alone;

use super::App;

impl App {
    /// Runs the preset as its paper alone: every lab addition off, the
    /// file marked `gaitlab-preset/2` (so the keys it leaves out are the
    /// paper's), the method SDLS where it was CCD. The motion starts again.
    ///
    /// # Errors
    /// `paper_alone: reason` when the running preset's text does not parse or
    /// the result does not load; the running creature stays.
    pub fn run_paper_alone(&mut self) -> Result<(), String> {
        let mut preset: serde_json::Value = serde_json::from_str(&self.preset_text())
            .map_err(|e| format!("paper_alone: the running preset is not JSON ({e})"))?;
        paper_alone(&mut preset).map_err(|e| format!("paper_alone: {e}"))?;
        let text =
            serde_json::to_string_pretty(&preset).map_err(|e| format!("paper_alone: {e}"))?;
        self.set_custom_preset(&text)
            .map_err(|e| format!("paper_alone: {e}"))?;
        let method = match self.session.settings.method {
            Method::Ccd => Method::Sdls,
            other => other,
        };
        self.session.settings.method = method;
        self.session.settings.ik = IkOptions {
            method,
            ..self.session.creature.scenario.ik.clone()
        };
        self.apply_ik_options();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::{App, Settings};

    #[test]
    fn every_bundled_preset_runs_the_paper_alone_from_the_page() {
        for name in gaitlab_core::preset::bundled_names() {
            let mut lab = App::new(Settings::default());
            lab.set_preset(name).expect("bundled");
            // Panel choices that are the lab's go too.
            lab.command(r#"{"clamp_every_method": true, "limit_passes": 4}"#)
                .expect("options");
            lab.run_paper_alone().expect("paper alone");
            let left: Vec<_> = lab
                .driver()
                .lab_additions()
                .iter()
                .map(|a| a.name)
                .collect();
            assert!(left.is_empty(), "{name}: {left:?}");
            assert_eq!(
                lab.session.creature.name, name,
                "the creature keeps its name"
            );
            lab.advance(0.5);
        }
    }
}
