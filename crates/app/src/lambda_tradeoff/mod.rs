//! She 2006 §4.4.3's λ trade-off on the page (issue 41 item 3): on request, the
//! running thesis motion is measured with DLS at the docs' 1-2-5 sweep of λ
//! ([`gaitlab_engine::lambda_sweep()`]), and the Method panel draws the error on
//! the targets within reach and the jitter of the limbs out of reach against
//! λ, with the current λ marked. The model and its piece of `state().ik` live
//! here, the measuring (and the command key `measure_lambda_tradeoff`) in
//! `lab/lambda_tradeoff.rs`, the drawing in [`plot`].

pub mod plot;

use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_engine::LambdaPoint;
use serde::Serialize;

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
