//! What each IK method does with the Jacobian's singular directions — the
//! reading of She 2006 §4.4.1–4.4.5 through the SVD J = Σ σᵢ uᵢ vᵢᵀ (§4.4.4;
//! Buss & Kim 2005): an error e = a·uᵢ along one left singular direction is
//! answered by a joint step Δθ = a·g(σᵢ)·vᵢ along the matching right one, and
//! the methods differ only in their gain g:
//!
//! - transpose (§4.4.1): g = α·σ, with α this error's step length;
//! - pseudoinverse (§4.4.2): g = 1/σ above the rank tolerance, 0 below;
//! - DLS (§4.4.3): g = σ/(σ² + λ²);
//! - SDLS (§4.4.5): g = min(1/σ, γᵢ/(a·max|vᵢ|)), the pseudoinverse clamped
//!   per direction by γᵢ = min(1, Nᵢ/Mᵢ)·γmax, Mᵢ = σᵢ⁻¹ Σⱼ |vⱼᵢ| ρⱼ;
//!
//! and where a method's step is clamped to `max_step` (pinv always, the others
//! with `clamp_every_method`), g ≤ max_step/(a·max|vᵢ|). CCD builds no Jacobian
//! and has no gain. The clamps make g depend on the error's size a, so a
//! spectrum is computed for one size. Buffers are kept between calls.

use nalgebra::DMatrix;

use super::sdls::{block_norm_sum, direction_clamp, fill_rho};
use super::svd::ThinSvd;
use super::transpose::transpose_alpha;
use super::{IkOptions, Method, NoConvergence};
use crate::skeleton::TaskBlock;

/// Singular values below this times σ_max count as zero. The Gram-matrix SVD
/// ([`ThinSvd`]) resolves σ only to about √ε·σ_max ≈ 1.5e-8·σ_max, so a
/// smaller value is noise, not a direction.
pub const ZERO_SIGMA_RELATIVE: f64 = 1e-7;

/// A method's gain law, with this frame's constants. Serialised as
/// `{"law": "dls", "lambda": …}` (the JS API's `state().jacobian`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "law", rename_all = "lowercase")]
pub enum GainLaw {
    /// g = α·σ (She 2006 §4.4.1), α for this frame's error.
    Transpose {
        /// The step length α, 1/m².
        alpha: f64,
    },
    /// g = 1/σ for σ above `cutoff`, else 0 (§4.4.2).
    Pinv {
        /// The rank tolerance times σ_max, m.
        cutoff: f64,
    },
    /// g = σ/(σ² + λ²) (§4.4.3).
    Dls {
        /// The damping λ, m.
        lambda: f64,
    },
    /// g = 1/σ clamped per direction by γᵢ (§4.4.5).
    Sdls {
        /// γmax, radians.
        gamma_max: f64,
    },
    /// CCD: no Jacobian, no gain.
    None,
}

impl GainLaw {
    /// The law's formula alone at `sigma` (no clamp): α·σ, 1/σ, σ/(σ² + λ²),
    /// 1/σ for SDLS before its clamp; `None` for CCD or σ ≤ 0.
    #[must_use]
    pub fn formula(self, sigma: f64) -> Option<f64> {
        if sigma.is_nan() || sigma <= 0.0 {
            return None;
        }
        match self {
            GainLaw::Transpose { alpha } => Some(alpha * sigma),
            GainLaw::Pinv { cutoff } => Some(if sigma > cutoff { 1.0 / sigma } else { 0.0 }),
            GainLaw::Dls { lambda } => Some(sigma / (sigma * sigma + lambda * lambda)),
            GainLaw::Sdls { .. } => Some(1.0 / sigma),
            GainLaw::None => None,
        }
    }
}

/// One singular direction: σᵢ and the shape of vᵢ and uᵢ the clamps read.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Direction {
    /// σᵢ, metres per radian.
    pub sigma: f64,
    /// The triplet's index in the decomposition.
    index: usize,
    /// max |vⱼᵢ|.
    v_max: f64,
    /// Nᵢ = Σℓ ‖uᵢ on effector ℓ‖.
    n_i: f64,
    /// Σⱼ |vⱼᵢ| ρⱼ = Mᵢσᵢ.
    m_sigma: f64,
}

/// The singular values of a Jacobian and each method's gain along them.
#[derive(Clone, Debug, Default)]
pub struct Spectrum {
    svd: ThinSvd,
    rho: Vec<f64>,
    gradient: Vec<f64>,
    scratch: Vec<f64>,
    directions: Vec<Direction>,
    /// min(m, n): how many singular values J has.
    count: usize,
    law: Option<GainLaw>,
    /// `max_step` when the method's step is clamped by it, radians.
    cap: Option<f64>,
    amplitude_m: f64,
}

impl Spectrum {
    /// Decomposes `jacobian` (m×n, effector rows in 3-row blocks, `blocks` as
    /// for [`ThinSvd::compute`]) and sets the gain law of `options`' method,
    /// with the transpose α of `error` (length m) and the clamps for an error
    /// of `amplitude_m` metres along a direction. Allocates only when the
    /// matrix grows.
    ///
    /// # Errors
    /// [`NoConvergence`] when `jacobian` holds non-finite values.
    pub fn compute(
        &mut self,
        jacobian: &DMatrix<f64>,
        blocks: &[TaskBlock],
        options: &IkOptions,
        error: &[f64],
        amplitude_m: f64,
    ) -> Result<(), NoConvergence> {
        let (m, n) = jacobian.shape();
        self.count = m.min(n);
        self.directions.clear();
        self.law = None;
        // Every direction above 1e-150: the rank tolerance is the law's, not the view's.
        self.svd.compute(jacobian, blocks, 0.0)?;
        fill_rho(jacobian, &mut self.rho);
        for i in 0..self.svd.rank() {
            let v = self.svd.v(i);
            let (mut v_max, mut m_sigma) = (0.0_f64, 0.0);
            for (x, rho) in v.iter().zip(&self.rho) {
                v_max = v_max.max(x.abs());
                m_sigma += x.abs() * rho;
            }
            self.directions.push(Direction {
                index: i,
                sigma: self.svd.sigma(i),
                v_max,
                n_i: block_norm_sum(self.svd.u(i)),
                m_sigma,
            });
        }
        self.directions
            .sort_unstable_by(|a, b| b.sigma.total_cmp(&a.sigma));
        let sigma_max = self.directions.first().map_or(0.0, |d| d.sigma);
        let floor = ZERO_SIGMA_RELATIVE * sigma_max;
        self.directions.retain(|d| d.sigma > floor);
        self.law = Some(match options.method {
            Method::Transpose => {
                self.gradient.resize(n, 0.0);
                self.scratch.resize(m, 0.0);
                let factor = options.transpose_alpha.factor();
                GainLaw::Transpose {
                    alpha: transpose_alpha(
                        jacobian,
                        &error[..m],
                        factor,
                        &mut self.scratch,
                        &mut self.gradient,
                    ),
                }
            }
            Method::Pinv => GainLaw::Pinv {
                cutoff: options.rank_tolerance * sigma_max,
            },
            Method::Dls => GainLaw::Dls {
                lambda: options.lambda,
            },
            Method::Sdls => GainLaw::Sdls {
                gamma_max: options.gamma_max,
            },
            Method::Ccd => GainLaw::None,
        });
        self.cap = options.clamps_step().then_some(options.max_step);
        self.amplitude_m = amplitude_m;
        Ok(())
    }

    /// The nonzero singular directions, largest σ first.
    #[must_use]
    pub fn directions(&self) -> &[Direction] {
        &self.directions
    }

    /// The left singular vector uᵢ of direction `i` (length m; `None` past
    /// the last direction).
    #[must_use]
    pub fn u(&self, i: usize) -> Option<&[f64]> {
        Some(self.svd.u(self.directions.get(i)?.index))
    }

    /// The right singular vector vᵢ of direction `i` (length n).
    #[must_use]
    pub fn v(&self, i: usize) -> Option<&[f64]> {
        Some(self.svd.v(self.directions.get(i)?.index))
    }

    /// How many of J's min(m, n) singular values are zero (below
    /// [`ZERO_SIGMA_RELATIVE`]·σ_max).
    #[must_use]
    pub fn zero_count(&self) -> usize {
        self.count - self.directions.len()
    }

    /// σ_max / σ_min over all min(m, n) singular values: infinite when one
    /// is zero, `None` for an empty J.
    #[must_use]
    pub fn condition(&self) -> Option<f64> {
        let (first, last) = (self.directions.first()?, self.directions.last()?);
        Some(if self.zero_count() > 0 {
            f64::INFINITY
        } else {
            first.sigma / last.sigma
        })
    }

    /// The method's law with this frame's constants (`None` before a compute).
    #[must_use]
    pub fn law(&self) -> Option<GainLaw> {
        self.law
    }

    /// The error size the clamps are evaluated for, metres.
    #[must_use]
    pub fn amplitude_m(&self) -> f64 {
        self.amplitude_m
    }

    /// The gain the method gives direction `i`'s shape if its singular value
    /// were `sigma`, clamps included (for an error of
    /// [`Spectrum::amplitude_m`]): radians per metre. At `sigma` =
    /// `directions()[i].sigma` this is the solver's actual response
    /// vᵢᵀΔθ / a to e = a·uᵢ. `None` for CCD, a missing direction or σ ≤ 0.
    #[must_use]
    pub fn gain(&self, i: usize, sigma: f64) -> Option<f64> {
        let law = self.law?;
        let direction = self.directions.get(i)?;
        let mut gain = law.formula(sigma)?;
        let size = self.amplitude_m * direction.v_max;
        if let GainLaw::Sdls { gamma_max } = law {
            let gamma = direction_clamp(direction.n_i, direction.m_sigma, sigma, gamma_max);
            if size * gain > gamma && size > 0.0 {
                gain = gamma / size;
            }
        }
        if let Some(cap) = self.cap
            && size * gain > cap
            && size > 0.0
        {
            gain = cap / size;
        }
        Some(gain)
    }
}
