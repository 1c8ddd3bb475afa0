//! The solver configurations a comparison view can run (She 2006 §4.4's
//! transpose, pinv, DLS and SDLS; PODA eq. 6's null-space centering; CCD as a
//! non-Jacobian contrast) and the per-view parameters each one takes.

use gaitlab_core::ik::IkOptions;
use gaitlab_core::ik::{Method, TransposeAlpha};

/// A solver configuration a view can run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareMethod {
    /// Jacobian transpose (§4.4.1).
    Transpose,
    /// Pseudoinverse (§4.4.2).
    Pinv,
    /// Damped least squares (§4.4.3).
    Dls,
    /// Selectively damped least squares (§4.4.5).
    Sdls,
    /// Pseudoinverse with PODA's null-space centering (eq. 6).
    PinvCentering,
    /// DLS with PODA's null-space centering.
    DlsCentering,
    /// Cyclic coordinate descent.
    Ccd,
}

/// Which slider a method's card shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parameter {
    /// DLS damping λ, metres.
    Lambda,
    /// SDLS γmax, radians.
    GammaMax,
    /// Step clamp α, radians per iteration.
    MaxStep,
    /// Rank tolerance (relative to σmax).
    RankTolerance,
    /// Null-space gain k.
    NullSpaceGain,
}

impl CompareMethod {
    /// Every configuration.
    pub const ALL: [CompareMethod; 7] = [
        CompareMethod::Transpose,
        CompareMethod::Pinv,
        CompareMethod::Dls,
        CompareMethod::Sdls,
        CompareMethod::PinvCentering,
        CompareMethod::DlsCentering,
        CompareMethod::Ccd,
    ];

    /// Short name used in commands and state.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            CompareMethod::Transpose => "transpose",
            CompareMethod::Pinv => "pinv",
            CompareMethod::Dls => "dls",
            CompareMethod::Sdls => "sdls",
            CompareMethod::PinvCentering => "pinv-ns",
            CompareMethod::DlsCentering => "dls-ns",
            CompareMethod::Ccd => "ccd",
        }
    }

    /// Parses [`CompareMethod::name`].
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// Human label.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            CompareMethod::Transpose => "Jacobian transpose",
            CompareMethod::Pinv => "Pseudoinverse",
            CompareMethod::Dls => "Damped least squares",
            CompareMethod::Sdls => "Selectively damped LS",
            CompareMethod::PinvCentering => "Pseudoinverse + centering",
            CompareMethod::DlsCentering => "DLS + centering",
            CompareMethod::Ccd => "Cyclic coordinate descent",
        }
    }

    /// The method's update rule in Unicode text (`^T` transpose, `_i` subscript).
    #[must_use]
    pub fn formula(self) -> &'static str {
        // Only glyphs egui's bundled monospace font (Hack) has: no ᵀ or ᵢ.
        match self {
            CompareMethod::Transpose => "Δθ = α J^T e,  α = ⟨e, JJ^T e⟩ / (2‖JJ^T e‖²)",
            CompareMethod::Pinv => "Δθ = J⁺e = Σ σ_i⁻¹ v_i u_i^T e",
            CompareMethod::Dls => "Δθ = J^T (JJ^T + λ²I)⁻¹ e",
            CompareMethod::Sdls => "Δθ = ClampMaxAbs(Σ ClampMaxAbs(σ_i⁻¹ α_i v_i, γ_i), γmax)",
            CompareMethod::PinvCentering => "Δθ = J⁺e + (I − J⁺J)(−k∇H),  H = Σ α_j (θ_j − θc_j)²",
            CompareMethod::DlsCentering => "Δθ = Σ σ_i/(σ_i² + λ²) v_i u_i^T e + (I − J⁺J)(−k∇H)",
            CompareMethod::Ccd => "θ_j += atan2(Σ a·(u × v), Σ u·v),  j = leaf … root",
        }
    }

    /// The update rule with `options` as they run: the transpose's α as
    /// She 2006 §4.4.1 prints it or, with `transpose_alpha: buss`, Buss's.
    #[must_use]
    pub fn formula_with(self, options: &IkOptions) -> &'static str {
        match (self, options.transpose_alpha) {
            (CompareMethod::Transpose, TransposeAlpha::Buss) => {
                "Δθ = α J^T e,  α = ⟨e, JJ^T e⟩ / ‖JJ^T e‖²  (Buss)"
            }
            _ => self.formula(),
        }
    }

    /// One sentence on how the method behaves.
    #[must_use]
    pub fn behaviour(self) -> &'static str {
        match self {
            CompareMethod::Transpose => {
                "Cheap: one product with J^T per iteration and no inverse; slow to converge."
            }
            CompareMethod::Pinv => {
                "Exact least-norm steps; near a singular (stretched) pose 1/σ explodes and the limb oscillates."
            }
            CompareMethod::Dls => {
                "Damping λ trades a little accuracy for smooth, bounded steps near singularities."
            }
            CompareMethod::Sdls => {
                "Damps each singular direction by how far it would move the effectors: accurate and smooth."
            }
            CompareMethod::PinvCentering => {
                "Pseudoinverse plus a pull of every joint toward its center angle in the null space."
            }
            CompareMethod::DlsCentering => {
                "Damped least squares plus PODA's null-space pull toward the center angles."
            }
            CompareMethod::Ccd => {
                "No Jacobian: turns one joint at a time toward the targets; robust but stiff-looking."
            }
        }
    }

    /// The sliders this method's card shows.
    #[must_use]
    pub fn parameters(self) -> &'static [Parameter] {
        match self {
            CompareMethod::Transpose | CompareMethod::Ccd => &[Parameter::MaxStep],
            CompareMethod::Pinv => &[Parameter::MaxStep, Parameter::RankTolerance],
            CompareMethod::Dls => &[Parameter::Lambda, Parameter::MaxStep],
            CompareMethod::Sdls => &[Parameter::GammaMax, Parameter::RankTolerance],
            CompareMethod::PinvCentering => &[
                Parameter::MaxStep,
                Parameter::RankTolerance,
                Parameter::NullSpaceGain,
            ],
            CompareMethod::DlsCentering => &[
                Parameter::Lambda,
                Parameter::MaxStep,
                Parameter::NullSpaceGain,
            ],
        }
    }

    /// The core method it runs.
    #[must_use]
    pub fn method(self) -> Method {
        match self {
            CompareMethod::Transpose => Method::Transpose,
            CompareMethod::Pinv | CompareMethod::PinvCentering => Method::Pinv,
            CompareMethod::Dls | CompareMethod::DlsCentering => Method::Dls,
            CompareMethod::Sdls => Method::Sdls,
            CompareMethod::Ccd => Method::Ccd,
        }
    }

    /// Whether PODA's null-space term is on.
    #[must_use]
    pub fn centering(self) -> bool {
        matches!(
            self,
            CompareMethod::PinvCentering | CompareMethod::DlsCentering
        )
    }

    /// Default options for this configuration, from the lab's `base` options.
    #[must_use]
    pub fn options(self, base: &IkOptions) -> IkOptions {
        IkOptions {
            method: self.method(),
            null_space_gain: if self.centering() {
                DEFAULT_NULL_SPACE_GAIN
            } else {
                0.0
            },
            ..base.clone()
        }
    }
}

/// Null-space gain k of the centering configurations unless set.
pub const DEFAULT_NULL_SPACE_GAIN: f64 = 0.2;

impl Parameter {
    /// The key in the `options` objects of the command and state.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Parameter::Lambda => "lambda",
            Parameter::GammaMax => "gamma_max",
            Parameter::MaxStep => "max_step",
            Parameter::RankTolerance => "rank_tolerance",
            Parameter::NullSpaceGain => "null_space_gain",
        }
    }

    /// Accepted range (same units as the option).
    #[must_use]
    pub fn range(self) -> (f64, f64) {
        match self {
            Parameter::Lambda => (1e-4, 2.0),
            Parameter::GammaMax | Parameter::MaxStep => (1e-3, std::f64::consts::PI),
            Parameter::RankTolerance => (1e-12, 0.1),
            Parameter::NullSpaceGain => (0.0, 2.0),
        }
    }

    /// The option's value in `options`, mutably.
    pub fn slot(self, options: &mut IkOptions) -> &mut f64 {
        match self {
            Parameter::Lambda => &mut options.lambda,
            Parameter::GammaMax => &mut options.gamma_max,
            Parameter::MaxStep => &mut options.max_step,
            Parameter::RankTolerance => &mut options.rank_tolerance,
            Parameter::NullSpaceGain => &mut options.null_space_gain,
        }
    }

    /// Every parameter.
    pub const ALL: [Parameter; 5] = [
        Parameter::Lambda,
        Parameter::GammaMax,
        Parameter::MaxStep,
        Parameter::RankTolerance,
        Parameter::NullSpaceGain,
    ];
}
