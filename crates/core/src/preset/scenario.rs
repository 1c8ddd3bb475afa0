//! `scenario`: which engine runs on the creature by default and with what
//! settings — for the IK engine She 2006 §5.1.1's control module (mode, method,
//! target-script parameters, wounded weights) and §4.4's solver options.
//!
//! New engines slot in as new [`Engine`] variants, each with its own optional
//! section beside `thesis` (a PODA `gait` table, a `physics` controller), checked
//! by the engine's own validation arm; a section that does not belong to the
//! chosen engine is rejected there.

use crate::terrain::Terrain;
use serde::{Deserialize, Serialize};

use super::physics::PhysicsParams;
use super::poda::PodaParams;
use super::thesis::{ThesisMode, ThesisParams};
use crate::ik::{IkOptions, Method};

/// Default animation rate, frames per second.
pub const DEFAULT_FPS: u32 = 60;

/// Highest accepted animation rate, frames per second.
pub const MAX_FPS: u32 = 1000;

/// The engine a scenario drives (DESIGN.md "engine" column).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum Engine {
    /// She 2006: sinusoidal effector targets tracked by Jacobian IK.
    #[default]
    Ik,
    /// Girard & Maciejewski 1985 (PODA): gait-driven footholds and foot splines.
    Poda,
    /// Raibert & Hodgins 1991: physically simulated running under control.
    Physics,
}

impl Engine {
    /// Every engine.
    pub const ALL: [Engine; 3] = [Engine::Ik, Engine::Poda, Engine::Physics];

    /// The name used in presets, URLs and the CLI.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Engine::Ik => "ik",
            Engine::Poda => "poda",
            Engine::Physics => "physics",
        }
    }

    /// Parses an engine name.
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|e| e.name().eq_ignore_ascii_case(name))
    }
}

/// `scenario`: the default run of a preset.
///
/// ```json
/// {"engine": "ik", "mode": "walk", "method": "sdls", "fps": 60,
///  "ik": {"lambda": 0.05, "limit_passes": 4, "jacobian_at": "effectors"},
///  "thesis": {"iterations_per_frame": 4, "wounded": [{"joint": "left_knee", "multiply": 0.2}]}}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// The engine. Required.
    pub engine: Engine,
    /// Thesis motion (She 2006 §5.2). Default walk.
    #[serde(default = "default_mode")]
    pub mode: ThesisMode,
    /// IK method (She 2006 §4.4). Default SDLS. This is the one place the method is
    /// chosen: `scenario.ik` must not contain `method`.
    #[serde(default = "default_method")]
    pub method: Method,
    /// Solver options; every field optional, defaults from [`IkOptions::default`].
    /// After parsing, `ik.method` equals `method`; use [`Scenario::ik_options`]
    /// after changing `method`.
    #[serde(default, with = "ik_section")]
    #[cfg_attr(feature = "schema", schemars(with = "ik_section::IkSection"))]
    pub ik: IkOptions,
    /// Animation frames per second, 1..=1000. Default 60.
    #[serde(default = "default_fps")]
    pub fps: u32,
    /// Target-script parameters (She 2006 §5.1.1); every field optional.
    #[serde(default)]
    pub thesis: ThesisParams,
    /// PODA gait parameters (engine `poda` only); every field optional.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poda: Option<PodaParams>,
    /// Physical model and controller (engine `physics` only; required there).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub physics: Option<PhysicsParams>,
    /// The ground (issue 45): `{"kind": "flat"}` (the default, every
    /// paper's), `plane`, `stairs`, `height_field` or `rough`. PODA creatures
    /// walk on every kind; the IK and physics engines refuse any but the
    /// floor when the scenario runs.
    #[serde(default, skip_serializing_if = "Terrain::is_flat")]
    pub terrain: Terrain,
}

impl Default for Scenario {
    fn default() -> Self {
        Self {
            engine: Engine::Ik,
            mode: default_mode(),
            method: default_method(),
            ik: IkOptions::default(),
            fps: DEFAULT_FPS,
            thesis: ThesisParams::default(),
            poda: None,
            physics: None,
            terrain: Terrain::Flat,
        }
    }
}

impl Scenario {
    /// The solver options to use: `ik` with its method set to `self.method`.
    #[must_use]
    pub fn ik_options(&self) -> IkOptions {
        IkOptions {
            method: self.method,
            ..self.ik.clone()
        }
    }

    /// The PODA parameters: the preset's `poda` section or the defaults.
    #[must_use]
    pub fn poda_params(&self) -> PodaParams {
        self.poda.clone().unwrap_or_default()
    }

    /// Seconds per animation frame, `1 / fps`.
    #[must_use]
    pub fn frame_seconds(&self) -> f64 {
        1.0 / f64::from(self.fps.max(1))
    }
}

fn default_mode() -> ThesisMode {
    ThesisMode::Walk
}

fn default_method() -> Method {
    Method::Sdls
}

fn default_fps() -> u32 {
    DEFAULT_FPS
}

/// `scenario.ik` as it appears in JSON: [`IkOptions`] without `method`.
mod ik_section {
    use serde::de::Error as _;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    use crate::ik::{IkOptions, JacobianAt, TransposeAlpha};

    /// A `method` key inside `scenario.ik`: always rejected, so that the method
    /// has one source (`scenario.method`).
    #[derive(Clone, Copy, Debug, Default)]
    pub(super) struct NoMethod;

    impl<'de> Deserialize<'de> for NoMethod {
        fn deserialize<D: Deserializer<'de>>(_: D) -> Result<Self, D::Error> {
            Err(D::Error::custom(
                "set the method with scenario.method, not scenario.ik.method",
            ))
        }
    }

    /// Mirror of [`IkOptions`] minus `method`. A unit test checks that every
    /// `IkOptions` field is here. Its JSON Schema (feature `schema`) lists no
    /// `method`, so a schema-aware editor flags one, as the parser does.
    #[derive(Serialize, Deserialize)]
    #[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
    #[serde(default, deny_unknown_fields)]
    pub(super) struct IkSection {
        #[serde(skip_serializing)]
        #[cfg_attr(feature = "schema", schemars(skip))]
        method: NoMethod,
        lambda: f64,
        gamma_max: f64,
        max_step: f64,
        /// The lab's addition: `max_step` clamps transpose and DLS too (She
        /// 2006 §4.4.2 clamps pinv only). Default false; a
        /// `gaitlab-preset/1` file without it runs with true, as it was made.
        clamp_every_method: bool,
        /// The lab's addition from Buss's code: each effector's error is
        /// clamped to this length, metres, before the solve. Default 0, off.
        target_clamp_m: f64,
        /// The transpose method's α: `thesis` (§4.4.1 as printed, default) or
        /// `buss` (Buss 2004's, twice the thesis'; what a `gaitlab-preset/1`
        /// file without this key runs).
        transpose_alpha: TransposeAlpha,
        rank_tolerance: f64,
        null_space_gain: f64,
        enforce_limits: bool,
        limit_passes: usize,
        /// She 2006 §3.2's control way: `effectors` (default; the Jacobian at
        /// the end effectors, which move towards the targets) or `targets`
        /// (the Jacobian at the targets, Buss's `Jtarget`: targets move
        /// towards the end effectors). The error is target − effector in both.
        jacobian_at: JacobianAt,
    }

    impl Default for IkSection {
        fn default() -> Self {
            Self::from(&IkOptions::default())
        }
    }

    impl From<&IkOptions> for IkSection {
        fn from(ik: &IkOptions) -> Self {
            Self {
                method: NoMethod,
                lambda: ik.lambda,
                gamma_max: ik.gamma_max,
                max_step: ik.max_step,
                clamp_every_method: ik.clamp_every_method,
                target_clamp_m: ik.target_clamp_m,
                transpose_alpha: ik.transpose_alpha,
                rank_tolerance: ik.rank_tolerance,
                null_space_gain: ik.null_space_gain,
                enforce_limits: ik.enforce_limits,
                limit_passes: ik.limit_passes,
                jacobian_at: ik.jacobian_at,
            }
        }
    }

    impl From<IkSection> for IkOptions {
        fn from(section: IkSection) -> Self {
            Self {
                lambda: section.lambda,
                gamma_max: section.gamma_max,
                max_step: section.max_step,
                clamp_every_method: section.clamp_every_method,
                target_clamp_m: section.target_clamp_m,
                transpose_alpha: section.transpose_alpha,
                rank_tolerance: section.rank_tolerance,
                null_space_gain: section.null_space_gain,
                enforce_limits: section.enforce_limits,
                limit_passes: section.limit_passes,
                jacobian_at: section.jacobian_at,
                ..IkOptions::default()
            }
        }
    }

    pub(super) fn serialize<S: Serializer>(
        ik: &IkOptions,
        serializer: S,
    ) -> Result<S::Ok, S::Error> {
        IkSection::from(ik).serialize(serializer)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<IkOptions, D::Error> {
        IkSection::deserialize(deserializer).map(IkOptions::from)
    }

    #[cfg(test)]
    mod tests {
        use super::*;

        /// Every `IkOptions` field except `method` round-trips through the mirror,
        /// so a field added to `IkOptions` fails here until it is added to `IkSection`.
        #[test]
        fn section_mirrors_every_ik_option() {
            let options = IkOptions {
                lambda: 0.3,
                gamma_max: 0.4,
                max_step: 0.5,
                clamp_every_method: true,
                target_clamp_m: 0.25,
                transpose_alpha: TransposeAlpha::Buss,
                rank_tolerance: 1e-3,
                null_space_gain: 2.0,
                enforce_limits: false,
                limit_passes: 7,
                jacobian_at: JacobianAt::Targets,
                ..IkOptions::default()
            };
            let mut full = serde_json::to_value(&options).expect("IkOptions serialises");
            let section =
                serde_json::to_value(IkSection::from(&options)).expect("IkSection serialises");
            if let Some(map) = full.as_object_mut() {
                map.remove("method");
            }
            assert_eq!(full, section);
            let back: IkSection = serde_json::from_value(section).expect("IkSection parses");
            assert_eq!(IkOptions::from(back), options);
        }
    }
}
