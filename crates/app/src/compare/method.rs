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

    /// The configuration running `method` plainly (no centering).
    #[must_use]
    pub fn of(method: Method) -> Self {
        match method {
            Method::Transpose => CompareMethod::Transpose,
            Method::Pinv => CompareMethod::Pinv,
            Method::Dls => CompareMethod::Dls,
            Method::Sdls => CompareMethod::Sdls,
            Method::Ccd => CompareMethod::Ccd,
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

    /// The method's update rule typeset in Unicode (Jᵀ, σᵢ⁻¹; the glyphs
    /// egui's fonts lack come from `ui::fonts`' symbol font).
    #[must_use]
    pub fn formula(self) -> &'static str {
        match self {
            CompareMethod::Transpose => "Δθ = α Jᵀe,  α = ⟨e, JJᵀe⟩ / (2‖JJᵀe‖²)",
            CompareMethod::Pinv => "Δθ = J⁺e = Σ σᵢ⁻¹ vᵢ uᵢᵀ e",
            CompareMethod::Dls => "Δθ = Jᵀ(JJᵀ + λ²I)⁻¹ e",
            CompareMethod::Sdls => "Δθ = ClampMaxAbs(Σ ClampMaxAbs(σᵢ⁻¹ αᵢ vᵢ, γᵢ), γmax)",
            CompareMethod::PinvCentering => "Δθ = J⁺e + (I − J⁺J)(−k∇H),  H = Σ αⱼ (θⱼ − θcⱼ)²",
            CompareMethod::DlsCentering => "Δθ = Σ σᵢ/(σᵢ² + λ²) vᵢ uᵢᵀ e + (I − J⁺J)(−k∇H)",
            CompareMethod::Ccd => "θⱼ += atan2(Σ a·(u × v), Σ u·v),  j = leaf … root",
        }
    }

    /// The update rule with `options` as they run: the transpose's α as
    /// She 2006 §4.4.1 prints it or, with `transpose_alpha: buss`, Buss's.
    #[must_use]
    pub fn formula_with(self, options: &IkOptions) -> &'static str {
        match (self, options.transpose_alpha) {
            (CompareMethod::Transpose, TransposeAlpha::Buss) => {
                "Δθ = α Jᵀe,  α = ⟨e, JJᵀe⟩ / ‖JJᵀe‖²  (Buss)"
            }
            _ => self.formula(),
        }
    }

    /// One sentence on how the method works — its mechanism, never a
    /// comparison with the others (those are the notes' claims, checked
    /// against the run: issue 43 item 1).
    #[must_use]
    pub fn behaviour(self) -> &'static str {
        match self {
            CompareMethod::Transpose => {
                "No inverse: one product with Jᵀ per iteration, a step along the error's gradient scaled by α."
            }
            CompareMethod::Pinv => {
                "The least-norm step that cancels the error; each singular direction is scaled by 1/σ, which grows without bound as a limb straightens (σ → 0)."
            }
            CompareMethod::Dls => {
                "Each singular direction scaled by σ/(σ² + λ²): bounded by 1/(2λ) as σ → 0, at the price of an error that stays where λ is large."
            }
            CompareMethod::Sdls => {
                "Each singular direction's step clamped by how far it would move the effectors (γᵢ), the whole step by γmax."
            }
            CompareMethod::PinvCentering => {
                "Pseudoinverse plus a pull of every joint toward its center angle in the null space."
            }
            CompareMethod::DlsCentering => {
                "Damped least squares plus PODA's null-space pull toward the center angles."
            }
            CompareMethod::Ccd => {
                "No Jacobian: turns one joint at a time, leaf to root, to aim the effectors at their targets."
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
