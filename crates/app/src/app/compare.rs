//! The app's side of the IK comparison ([`crate::compare`]): starting and
//! leaving it, the `compare` command and the `compare` state object
//! (DESIGN.md "Browser"). Comparison runs on the IK engine only.

use serde_json::Value;

use super::App;
use crate::compare::{CompareConfig, CompareScenario, Comparison, DEFAULT_VIEWS};
use crate::compare::{CompareValue, config_from_command};
use crate::lab::Effect;

/// The bundled preset that runs She 2006 as written.
pub const THESIS_PRESET: &str = "she-2006";

impl App {
    /// The lab's IK options with its method: a new comparison view's
    /// defaults.
    #[must_use]
    pub fn compare_base(&self) -> gaitlab_core::ik::IkOptions {
        let mut base = self.session.settings.ik.clone();
        base.method = self.session.settings.method;
        base
    }

    /// The running comparison, if any.
    #[must_use]
    pub fn comparison(&self) -> Option<&Comparison> {
        self.compare.as_ref()
    }

    /// The running comparison, mutably.
    pub fn comparison_mut(&mut self) -> Option<&mut Comparison> {
        self.compare.as_mut()
    }

    /// Starts (or restarts) a comparison with `config`, from time 0.
    ///
    /// # Errors
    /// `compare: …` when the engine is not `ik`; nothing changes then.
    pub fn start_compare(&mut self, config: CompareConfig) -> Result<(), String> {
        if !self.stage.driver.is_ik() {
            return Err(format!(
                "compare: engine {} has no IK methods to compare (use the ik engine: human, she-2006 or ik-quadruped)",
                self.session.engine_name()
            ));
        }
        let mut template = self.stage.driver.clone();
        gaitlab_core::driver::Driver::reset(&mut template);
        self.compare = Some(Comparison::new(
            config,
            &template,
            &self.session.settings.view,
        ));
        self.stage.frame = 0;
        self.rewind_restart();
        self.outbox.push(Effect::LinkChanged);
        Ok(())
    }

    /// Changes the running comparison to `config`: in place when only how it
    /// is drawn changes (the overlay), else by [`App::start_compare`] (a
    /// restart from time 0, also when nothing changes).
    ///
    /// # Errors
    /// As [`App::start_compare`].
    pub fn configure_compare(&mut self, config: CompareConfig) -> Result<(), String> {
        if let Some(compare) = self.compare.as_mut()
            && compare.config.same_run(&config)
            && compare.config.overlay != config.overlay
        {
            compare.set_overlay(config.overlay);
            self.outbox.push(Effect::LinkChanged);
            return Ok(());
        }
        self.start_compare(config)
    }

    /// She 2006 §5.3's comparison as the thesis runs it: opens the bundled
    /// `she-2006` preset (the §5.2.2 listing, no posture pull) and starts the
    /// four thesis methods side by side on the current motion.
    ///
    /// # Errors
    /// As [`App::set_preset`] and [`App::start_compare`]; the lab keeps its
    /// state where the preset cannot load.
    pub fn compare_as_the_thesis(&mut self) -> Result<(), String> {
        let mode = self.session.settings.mode;
        self.set_preset(THESIS_PRESET)?;
        self.set_mode(mode);
        // As written: the preset's own IK options (clamp-only joint limits),
        // whatever the panel held.
        self.session.settings.ik = self.session.creature.scenario.ik.clone();
        self.apply_ik_options();
        self.start_compare(CompareConfig::new(
            &DEFAULT_VIEWS,
            CompareScenario::Script,
            &self.compare_base(),
        ))
    }

    /// Leaves the comparison (the single view carries on).
    pub fn stop_compare(&mut self) {
        if self.compare.take().is_some() {
            self.rewind_restart();
            self.outbox.push(Effect::LinkChanged);
        }
    }

    /// Applies the `compare` command's value: `false` leaves, an object starts
    /// or reconfigures (see [`crate::compare`] for the shape).
    ///
    /// # Errors
    /// `compare…: reason`; nothing changes then.
    pub fn apply_compare_command(&mut self, value: &CompareValue) -> Result<(), String> {
        let CompareValue::On(command) = value else {
            self.stop_compare();
            return Ok(());
        };
        let base = self.compare_base();
        let config = config_from_command(command, &base, self.compare.as_ref().map(|c| &c.config))?;
        self.configure_compare(config)
    }

    /// The state's `compare` value: `null`, or the configuration plus metrics.
    #[must_use]
    pub fn compare_state(&self) -> Value {
        self.compare.as_ref().map_or(Value::Null, Comparison::state)
    }

    /// After the creature changed: rebuild the comparison on it. Picking a
    /// PODA or physics creature ends the comparison quietly: the person chose
    /// another engine, which is not a mistake.
    pub(crate) fn rebuild_compare(&mut self) {
        let Some(config) = self.compare.take().map(|c| c.config) else {
            return;
        };
        if !self.stage.driver.is_ik() {
            self.outbox.push(Effect::LinkChanged);
            return;
        }
        if let Err(error) = self.start_compare(config) {
            self.report_error(error);
        }
    }
}
