//! The app's side of the λ trade-off ([`crate::lambda_tradeoff`]): measuring
//! it on the running thesis motion (She 2006 §4.4.3; docs/she-2006.md
//! "Choosing λ").

use gaitlab_engine::lambda_sweep::{SWEEP_LAMBDAS_M, SWEEP_SECONDS};
use gaitlab_engine::lambda_sweep_of;

use super::App;
use crate::lambda_tradeoff::LambdaTradeoff;

impl App {
    /// Measures the λ trade-off of the running thesis motion (the running
    /// preset, motion, parameters and solver options, DLS at each λ of the
    /// sweep for 10 s at the preset's frame rate). The motion on screen is
    /// not touched.
    ///
    /// # Errors
    /// When the running engine is not the thesis' (PODA, physics, a target
    /// recording).
    pub fn measure_lambda_tradeoff(&mut self) -> Result<(), String> {
        let fps = 1.0 / self.frame_seconds();
        let points = lambda_sweep_of(&self.stage.driver, &SWEEP_LAMBDAS_M, SWEEP_SECONDS, fps)?;
        self.lambda_tradeoff = Some(LambdaTradeoff {
            preset: self.session.creature.name.clone(),
            mode: self.session.settings.mode.name().to_owned(),
            seconds: SWEEP_SECONDS,
            points,
        });
        Ok(())
    }

    /// The last measured λ trade-off, if any.
    #[must_use]
    pub fn lambda_tradeoff(&self) -> Option<&LambdaTradeoff> {
        self.lambda_tradeoff.as_ref()
    }
}
