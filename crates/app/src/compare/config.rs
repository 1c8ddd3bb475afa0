//! A comparison's configuration — its views, scenario (the thesis script or
//! the singularity stretch) and per-view solver options — read from and
//! written to the `compare` command and `state().compare`.

use gaitlab_core::ik::IkOptions;
use serde_json::{Map, Value, json};

use super::method::{CompareMethod, Parameter};

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
}

impl CompareConfig {
    /// `views` with their default options from `base`.
    #[must_use]
    pub fn new(views: &[CompareMethod], scenario: CompareScenario, base: &IkOptions) -> Self {
        Self {
            views: views.to_vec(),
            options: views.iter().map(|m| m.options(base)).collect(),
            scenario,
        }
    }

    /// Parses the `compare` command's object (see the module docs), taking
    /// defaults from `base` and from `current` where its views match.
    ///
    /// # Errors
    /// `compare.…: reason` naming the bad field.
    pub fn from_json(
        value: &Value,
        base: &IkOptions,
        current: Option<&CompareConfig>,
    ) -> Result<Self, String> {
        let object: &Map<String, Value> = value
            .as_object()
            .ok_or("compare: expected an object or false")?;
        for key in object.keys() {
            if !["views", "scenario", "options", "metrics"].contains(&key.as_str()) {
                return Err(format!(
                    "compare.{key}: unknown key (views, scenario, options)"
                ));
            }
        }
        let views: Vec<CompareMethod> = match object.get("views") {
            Some(views) => {
                let list = views
                    .as_array()
                    .ok_or("compare.views: expected an array of method names")?;
                if list.len() != 2 && list.len() != 4 {
                    return Err(format!(
                        "compare.views: expected 2 or 4 views, got {}",
                        list.len()
                    ));
                }
                list.iter()
                    .enumerate()
                    .map(|(i, name)| {
                        let name = name
                            .as_str()
                            .ok_or_else(|| format!("compare.views[{i}]: expected a string"))?;
                        CompareMethod::parse(name).ok_or_else(|| {
                            format!(
                                "compare.views[{i}]: unknown method {name:?} ({})",
                                CompareMethod::ALL.map(CompareMethod::name).join(", ")
                            )
                        })
                    })
                    .collect::<Result<_, _>>()?
            }
            None => match current {
                Some(current) => current.views.clone(),
                None => DEFAULT_VIEWS.to_vec(),
            },
        };
        let scenario = match object.get("scenario") {
            Some(v) => {
                let name = v.as_str().ok_or("compare.scenario: expected a string")?;
                CompareScenario::parse(name).ok_or_else(|| {
                    format!("compare.scenario: unknown scenario {name:?} (script, singularity)")
                })?
            }
            None => current.map_or(CompareScenario::Script, |c| c.scenario),
        };
        let mut options: Vec<IkOptions> = views
            .iter()
            .enumerate()
            .map(|(i, m)| match current {
                Some(c) if c.views.get(i) == Some(m) => c.options[i].clone(),
                _ => m.options(base),
            })
            .collect();
        if let Some(v) = object.get("options") {
            let list = v
                .as_array()
                .ok_or("compare.options: expected an array of objects")?;
            if list.len() != views.len() {
                return Err(format!(
                    "compare.options: expected {} objects (one per view), got {}",
                    views.len(),
                    list.len()
                ));
            }
            for (i, (item, slot)) in list.iter().zip(options.iter_mut()).enumerate() {
                let item = item
                    .as_object()
                    .ok_or_else(|| format!("compare.options[{i}]: expected an object"))?;
                for (key, value) in item {
                    let parameter = Parameter::ALL
                        .into_iter()
                        .find(|p| p.key() == key)
                        .ok_or_else(|| format!("compare.options[{i}].{key}: unknown option"))?;
                    let x = value
                        .as_f64()
                        .ok_or_else(|| format!("compare.options[{i}].{key}: expected a number"))?;
                    let (lo, hi) = parameter.range();
                    if !(lo..=hi).contains(&x) {
                        return Err(format!(
                            "compare.options[{i}].{key}: {x} is outside [{lo}, {hi}]"
                        ));
                    }
                    *parameter.slot(slot) = x;
                }
            }
        }
        Ok(Self {
            views,
            options,
            scenario,
        })
    }

    /// The configuration as the command's object (without metrics).
    #[must_use]
    pub fn to_json(&self) -> Value {
        json!({
            "views": self.views.iter().map(|m| m.name()).collect::<Vec<_>>(),
            "scenario": self.scenario.name(),
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
