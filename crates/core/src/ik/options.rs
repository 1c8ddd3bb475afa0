//! Options shared by every IK method (She 2006 §4.4; PODA eq. 6), with defaults
//! sized for metre-scale creatures.

use serde::{Deserialize, Serialize};

/// The Jacobian IK methods of She 2006 §4.4.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Jacobian transpose, Δθ = α Jᵀe with §4.4.1's α = Δs·Δt / (2|Δt|²)
    /// (or Buss's, twice that: [`TransposeAlpha`]).
    Transpose,
    /// Moore–Penrose pseudoinverse through a thin SVD with a rank tolerance (§4.4.2, PODA eq. 4–5).
    Pinv,
    /// Damped least squares, Δθ = Jᵀ(JJᵀ + λ²I)⁻¹e (§4.4.3).
    Dls,
    /// Selectively damped least squares (Buss & Kim 2005, §4.4.5).
    Sdls,
    /// Cyclic coordinate descent (Wang & Chen 1991): no Jacobian, one joint at a
    /// time from the effectors back to the root; the non-Jacobian contrast.
    Ccd,
}

impl Method {
    /// Every method: the thesis' four in its order, then CCD.
    pub const ALL: [Method; 5] = [
        Method::Transpose,
        Method::Pinv,
        Method::Dls,
        Method::Sdls,
        Method::Ccd,
    ];

    /// The short name used in presets, URLs and the CLI.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Method::Transpose => "transpose",
            Method::Pinv => "pinv",
            Method::Dls => "dls",
            Method::Sdls => "sdls",
            Method::Ccd => "ccd",
        }
    }

    /// Parses a short name (`transpose`, `pinv`, `dls`, `sdls`, `ccd`; also `pseudoinverse`, `jt`).
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        match name.to_ascii_lowercase().as_str() {
            "transpose" | "jt" | "jacobian-transpose" => Some(Method::Transpose),
            "pinv" | "pseudoinverse" => Some(Method::Pinv),
            "dls" => Some(Method::Dls),
            "sdls" => Some(Method::Sdls),
            "ccd" => Some(Method::Ccd),
            _ => None,
        }
    }
}

/// Where the Jacobian's position columns are taken: She 2006 §3.2's "two ways to
/// control the Jacobian formulation", read as the two Jacobians of Buss's IK code
/// that the thesis started from (§6.1): `Jend`, columns `vⱼ × (sᵢ − pⱼ)` at the
/// end effectors sᵢ, and `Jtarget`, columns `vⱼ × (tᵢ − pⱼ)` at the targets tᵢ.
///
/// In both ways the error stays e = t − s (Buss fills one dS = t − s for both
/// Jacobians) and every method solves J Δθ ≈ e; only the lever arm changes.
/// Prismatic columns (vⱼ) and orientation rows (vⱼ) do not depend on the point,
/// so they are the same in both ways; CCD builds no Jacobian and ignores this.
///
/// Which of §3.2's sentences is which: the effectors way is the usual one
/// ("usually … end effectors are tracking targets' positions"), so it is the
/// second, "move end effectors towards the targets' positions". With the
/// Jacobian at the targets, J Δθ = e asks the limb point now at tᵢ to move by
/// eᵢ; seen from the limb, the (world-fixed) target then moves by −eᵢ = sᵢ − tᵢ,
/// onto the effector — the first way, "move targets towards the end
/// effectors". The thesis gives no formula for either, so this reading rests
/// on the Buss code it names (docs/ik-control-ways.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum JacobianAt {
    /// Columns vⱼ × (sᵢ − pⱼ) at the end effectors (Buss's `Jend`, his default):
    /// end effectors move towards the targets. The default.
    #[default]
    Effectors,
    /// Columns vⱼ × (tᵢ − pⱼ) at the targets (Buss's `Jtarget`): the thesis'
    /// "move targets towards the end effectors".
    Targets,
}

impl JacobianAt {
    /// Both ways, the default first.
    pub const ALL: [JacobianAt; 2] = [JacobianAt::Effectors, JacobianAt::Targets];

    /// The name used in presets, commands, links and the CLI.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            JacobianAt::Effectors => "effectors",
            JacobianAt::Targets => "targets",
        }
    }

    /// Parses `effectors` or `targets` (any case).
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|way| way.name().eq_ignore_ascii_case(name))
    }
}

/// The transpose method's step length α (She 2006 §4.4.1), with Δs = e the
/// effectors' error and Δt = JJᵀe the change Δθ = Jᵀe would make.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum TransposeAlpha {
    /// The thesis' α = Δs·Δt / (2|Δt|²) as printed in §4.4.1: half the α that
    /// brings JΔθ closest to e. The default.
    #[default]
    Thesis,
    /// Buss 2004's α = ⟨e, JJᵀe⟩ / ‖JJᵀe‖², the α that brings JΔθ closest to
    /// e (twice the thesis' value); what gaitlab used before the thesis' α
    /// became the default, and what every `gaitlab-preset/1` file runs.
    Buss,
}

impl TransposeAlpha {
    /// Both, the default first.
    pub const ALL: [TransposeAlpha; 2] = [TransposeAlpha::Thesis, TransposeAlpha::Buss];

    /// The name used in presets, commands and the CLI.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            TransposeAlpha::Thesis => "thesis",
            TransposeAlpha::Buss => "buss",
        }
    }

    /// The factor on Buss's α: ½ for the thesis' formula, 1 for Buss's.
    #[must_use]
    pub fn factor(self) -> f64 {
        match self {
            TransposeAlpha::Thesis => 0.5,
            TransposeAlpha::Buss => 1.0,
        }
    }

    /// Parses `thesis` or `buss` (any case).
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|alpha| alpha.name().eq_ignore_ascii_case(name))
    }
}

/// How a joint's participation is weighted: She 2006 §5.1.1's "wounded" parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointWeight {
    /// Multiply form: the joint's step is scaled by this factor in every method
    /// (0 freezes the joint, below 1 stiffens it, above 1 loosens it). Default 1.
    pub multiply: f64,
    /// Add form: radians (or metres) added to the joint's step on every iteration,
    /// a steady push the other joints must work against. Default 0.
    pub add: f64,
}

impl Default for JointWeight {
    fn default() -> Self {
        Self {
            multiply: 1.0,
            add: 0.0,
        }
    }
}

/// Options for [`IkSolver`](super::IkSolver). Every field has a default suited to
/// metre-scale figures.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct IkOptions {
    /// The method. Default SDLS (the thesis' best performer).
    pub method: Method,
    /// DLS damping λ, metres. Default 0.2: the thesis names none (§4.4.3: it
    /// "must be chosen very carefully"); 0.2 is the smallest λ of a 1-2-5
    /// sweep at which the 20-joint human's unreachable hands are as calm as
    /// any λ makes them, walking and running (docs/she-2006.md "Choosing λ").
    /// `gaitlab-preset/1` files without it run with 0.05, as they were made.
    pub lambda: f64,
    /// SDLS γmax, the largest change of any joint per iteration, radians. Default π/4
    /// (the thesis misprints 4/π).
    pub gamma_max: f64,
    /// Largest joint change per iteration for pinv (She 2006 §4.4.2's "maximum
    /// rotation angle changed value", whose value the thesis does not give), for
    /// transpose and DLS too when `clamp_every_method` is on, and per joint turn
    /// for CCD; radians (metres for prismatic joints). Default 0.2.
    pub max_step: f64,
    /// The lab's addition: `max_step` clamps transpose and DLS as well as pinv
    /// (§4.4.2 clamps pinv only; Buss's code clamps every method). Default off;
    /// on in every `gaitlab-preset/1` file, which ran with it. Serialized
    /// options without the key (settings stored before it existed) read it
    /// as on, as they ran.
    #[serde(default = "before_2026_12_05_clamp")]
    pub clamp_every_method: bool,
    /// The lab's addition from Buss's IK code: each effector's position error
    /// is clamped to this length, metres, before every method's solve (his
    /// `CalcdTClampedFromdS` with its fixed base, `BaseMaxTargetDist`; his
    /// SDLS always clamps, his other methods never), so a far target pulls
    /// no harder than one this far away. The reported errors stay the
    /// unclamped distances. 0 turns it off (default: the thesis clamps no
    /// target).
    pub target_clamp_m: f64,
    /// The transpose method's α: §4.4.1's as printed (default) or Buss's.
    /// Serialized options without the key read Buss's, as they ran.
    #[serde(default = "before_2026_12_05_alpha")]
    pub transpose_alpha: TransposeAlpha,
    /// Singular values below `rank_tolerance · σ_max` count as zero. Default 1e-6.
    pub rank_tolerance: f64,
    /// Gain k of PODA's null-space term Δθ += (I − J⁺J)(−k∇H), H = Σ αᵢ(θᵢ − θcᵢ)²,
    /// applied with pinv and DLS. 0 turns it off. Default 0.
    pub null_space_gain: f64,
    /// Keep joints inside their limits by clamping and re-solving without the clamped
    /// joints. Default true.
    pub enforce_limits: bool,
    /// Solves per iteration while joints hit their limits: 1 clamps each
    /// joint to its limits, the thesis' way (§6.1.1.1; default); more re-solve
    /// without the clamped joints, the lab's addition (4 in a
    /// `gaitlab-preset/1` file without the key).
    pub limit_passes: usize,
    /// She 2006 §3.2's control way: the Jacobian at the end effectors (default;
    /// effectors move towards the targets) or at the targets (Buss's `Jtarget`;
    /// targets move towards the effectors). See [`JacobianAt`].
    pub jacobian_at: JacobianAt,
}

/// What serialized [`IkOptions`] written before `clamp_every_method` existed
/// ran with: the clamp on every method.
fn before_2026_12_05_clamp() -> bool {
    true
}

/// What serialized [`IkOptions`] written before `transpose_alpha` existed ran
/// with: Buss's α.
fn before_2026_12_05_alpha() -> TransposeAlpha {
    TransposeAlpha::Buss
}

impl IkOptions {
    /// Whether `max_step` clamps this method's step: pinv always (§4.4.2),
    /// transpose and DLS with `clamp_every_method`; SDLS has its own γmax and
    /// CCD clamps each joint turn itself.
    #[must_use]
    pub fn clamps_step(&self) -> bool {
        match self.method {
            Method::Pinv => true,
            Method::Transpose | Method::Dls => self.clamp_every_method,
            Method::Sdls | Method::Ccd => false,
        }
    }

    /// Whether `max_step` changes anything for this method: the clamped ones
    /// ([`IkOptions::clamps_step`]) and CCD, which bounds each joint turn by it.
    #[must_use]
    pub fn uses_max_step(&self) -> bool {
        self.clamps_step() || self.method == Method::Ccd
    }
}

impl Default for IkOptions {
    fn default() -> Self {
        Self {
            method: Method::Sdls,
            lambda: 0.2,
            gamma_max: std::f64::consts::FRAC_PI_4,
            max_step: 0.2,
            clamp_every_method: false,
            target_clamp_m: 0.0,
            transpose_alpha: TransposeAlpha::Thesis,
            rank_tolerance: 1e-6,
            null_space_gain: 0.0,
            enforce_limits: true,
            limit_passes: 1,
            jacobian_at: JacobianAt::Effectors,
        }
    }
}
