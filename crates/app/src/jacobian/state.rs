//! `state().jacobian`: the Jacobian panel's figures for the JS API — each
//! view's singular values, condition number, gain law and gain at each σᵢ,
//! and the last frame's iterations.

use gaitlab_core::ik::{GainLaw, Spectrum};
use serde::Serialize;

use super::probe::JacobianProbe;

/// One view's spectrum.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct SpectrumState {
    /// The nonzero singular values, largest first, m/rad.
    pub sigma: Vec<f64>,
    /// How many more singular values are zero.
    pub zero: usize,
    /// σ_max / σ_min (null when infinite).
    pub condition: Option<f64>,
    /// The running method's law.
    pub law: GainLaw,
    /// The law's formula at each σᵢ (no clamp), rad/m.
    pub formula_gain: Vec<f64>,
    /// The gain the last iteration actually gave each direction,
    /// (vᵢ·Δθ)/(uᵢ·e), clamps and limits included (null where the error had
    /// no part along uᵢ), rad/m.
    pub actual_gain: Vec<Option<f64>>,
    /// This iteration's ‖e‖, m.
    pub error_m: f64,
}

/// One iteration of the last frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct IterationState {
    /// ‖Δθ‖ of its step.
    pub step_norm: f64,
    /// The largest effector error before it, m.
    pub error_before_m: f64,
    /// The largest effector error after it, m.
    pub error_after_m: f64,
}

/// `state().jacobian`.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct JacobianState {
    /// Per view (the single view, or each comparison view), null where the
    /// figure has no Jacobian (CCD, a recording).
    pub views: Vec<Option<SpectrumState>>,
    /// The first view's iterations in the last frame traced.
    pub iterations: Vec<IterationState>,
}

impl SpectrumState {
    /// The figures of `spectrum` and the measured gains `actual` (`None`
    /// without a Jacobian law).
    #[must_use]
    pub fn of(spectrum: &Spectrum, actual: &[Option<f64>]) -> Option<Self> {
        let law = spectrum.law().filter(|l| *l != GainLaw::None)?;
        let directions = spectrum.directions();
        Some(Self {
            sigma: directions.iter().map(|d| d.sigma).collect(),
            zero: spectrum.zero_count(),
            condition: spectrum.condition().filter(|c| c.is_finite()),
            law,
            formula_gain: directions
                .iter()
                .map(|d| law.formula(d.sigma).unwrap_or(0.0))
                .collect(),
            actual_gain: actual.to_vec(),
            error_m: spectrum.amplitude_m(),
        })
    }
}

impl JacobianState {
    /// The probe's figures for `views` views.
    #[must_use]
    pub fn of(probe: &JacobianProbe, views: usize) -> Self {
        let last = probe.iterations().last().map(|p| p.time_s);
        Self {
            views: (0..views)
                .map(|i| {
                    let actual = probe.actual_gains(i).unwrap_or(&[]);
                    probe.spectrum(i).and_then(|s| SpectrumState::of(s, actual))
                })
                .collect(),
            iterations: probe
                .iterations()
                .filter(|p| Some(p.time_s) == last)
                .map(|p| IterationState {
                    step_norm: p.step_norm,
                    error_before_m: p.error_before_m,
                    error_after_m: p.error_after_m,
                })
                .collect(),
        }
    }
}
