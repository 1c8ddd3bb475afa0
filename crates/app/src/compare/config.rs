//! A comparison's configuration — its views, scenario (the thesis script or
//! the singularity stretch) and per-view solver options — read from and
//! written to the `compare` command and `state().compare`.

use gaitlab_core::ik::IkOptions;
use serde_json::{Value, json};

use super::method::CompareMethod;

/// Where the targets come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CompareScenario {
    /// The thesis script of the lab's mode.
    #[default]
    Script,
    /// Every limb target pulled to about its full reach, swinging across it.
    Singularity,
}

impl CompareScenario {
    /// Name used in commands and state.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            CompareScenario::Script => "script",
            CompareScenario::Singularity => "singularity",
        }
    }

    /// Parses [`CompareScenario::name`].
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "script" => Some(CompareScenario::Script),
            "singularity" => Some(CompareScenario::Singularity),
            _ => None,
        }
    }
}

/// What a comparison runs: the views' configurations and options, and the scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct CompareConfig {
    /// One configuration per view (2 or 4).
    pub views: Vec<CompareMethod>,
    /// Options per view (same length as `views`).
    pub options: Vec<IkOptions>,
    /// Target scenario.
    pub scenario: CompareScenario,
    /// Whether the views are drawn as colour-coded figures in one 3-D view
    /// (the overlay) instead of one pane each; changing it keeps the run.
    pub overlay: bool,
}

impl CompareConfig {
    /// `views` with their default options from `base`.
    #[must_use]
    pub fn new(views: &[CompareMethod], scenario: CompareScenario, base: &IkOptions) -> Self {
        Self {
            views: views.to_vec(),
            options: views.iter().map(|m| m.options(base)).collect(),
            scenario,
            overlay: false,
        }
    }

    /// Whether `other` runs the same views on the same targets, so it can
    /// take over this one's run (they may differ in how they are drawn).
    #[must_use]
    pub fn same_run(&self, other: &Self) -> bool {
        self.views == other.views
            && self.options == other.options
            && self.scenario == other.scenario
    }

    /// The configuration as the command's object (without metrics).
    #[must_use]
    pub fn to_json(&self) -> Value {
        json!({
            "views": self.views.iter().map(|m| m.name()).collect::<Vec<_>>(),
            "scenario": self.scenario.name(),
            "overlay": self.overlay,
            "options": self.options.iter().map(|o| json!({
                "lambda": o.lambda,
                "gamma_max": o.gamma_max,
                "max_step": o.max_step,
                "rank_tolerance": o.rank_tolerance,
                "null_space_gain": o.null_space_gain,
            })).collect::<Vec<_>>(),
        })
    }
}

/// The views a comparison starts with when none are named.
pub const DEFAULT_VIEWS: [CompareMethod; 4] = [
    CompareMethod::Transpose,
    CompareMethod::Pinv,
    CompareMethod::Dls,
    CompareMethod::Sdls,
];
