//! She 2006 §4.4.3's λ trade-off on the page (issue 41 item 3): on request, the
//! running thesis motion is measured with DLS at the docs' 1-2-5 sweep of λ
//! ([`gaitlab_engine::lambda_sweep()`]), and the Method panel draws the error on
//! the targets within reach and the jitter of the limbs out of reach against
//! λ, with the current λ marked. The model, its command key
//! (`measure_lambda_tradeoff`) and its piece of `state().ik` live here; the
//! drawing is [`plot`].

pub mod plot;

use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_engine::lambda_sweep::{SWEEP_LAMBDAS_M, SWEEP_SECONDS};
use gaitlab_engine::{LambdaPoint, lambda_sweep};
use serde::Serialize;

use crate::lab::Lab;

/// One measured sweep and what it was measured on.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct LambdaTradeoff {
    /// The preset it was measured on.
    pub preset: String,
    /// The thesis motion it was measured on.
    pub mode: String,
    /// Seconds each λ ran.
    pub seconds: f64,
    /// One entry per λ, smallest first: `lambda_m`, `reachable_error_m`,
    /// `unreachable_error_m`, `unreachable_oscillation_hz`,
    /// `unreachable_jitter_rad` (null where no effector is of that kind).
    #[cfg_attr(feature = "schema", schemars(with = "Vec<serde_json::Value>"))]
    pub points: Vec<LambdaPoint>,
}

impl LambdaTradeoff {
    /// Whether it was measured on the preset and motion that run now.
    #[must_use]
    pub fn is_for(&self, preset: &str, mode: ThesisMode) -> bool {
        self.preset == preset && self.mode == mode.name()
    }
}

impl Lab {
    /// Measures the λ trade-off of the running thesis motion (the running
    /// preset, motion, parameters and solver options, DLS at each λ of the
    /// sweep for 10 s at the preset's frame rate). The motion on screen is
    /// not touched.
    ///
    /// # Errors
    /// When the running engine is not the thesis' (PODA, physics, a target
    /// recording).
    pub fn measure_lambda_tradeoff(&mut self) -> Result<(), String> {
        let Some(driver) = self.stage.driver.thesis() else {
            return Err(
                "measure_lambda_tradeoff: the λ trade-off is measured on a thesis motion (engine ik)"
                    .to_owned(),
            );
        };
        let fps = 1.0 / self.frame_seconds();
        let points = lambda_sweep(driver, &SWEEP_LAMBDAS_M, SWEEP_SECONDS, fps);
        self.lambda_tradeoff = Some(LambdaTradeoff {
            preset: self.session.creature.name.clone(),
            mode: driver.mode().name().to_owned(),
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
