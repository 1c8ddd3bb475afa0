//! The `compare` command's value: `false` (or `null`) leaves the side-by-side
//! IK comparison, an object `{views, scenario, overlay, options}` starts or
//! reconfigures it (see [`crate::compare`]). `metrics`, as `state().compare`
//! writes it, is accepted and ignored, so a state's object can be sent back.

use serde::Deserialize;

use gaitlab_core::ik::IkOptions;

use super::config::{CompareConfig, CompareScenario, DEFAULT_VIEWS};
use super::method::{CompareMethod, Parameter};
use crate::named::named;
use crate::off_or::OffOr;

named!(
    /// `compare.views[i]`: one comparison view's configuration.
    CompareMethodName(CompareMethod), "method", CompareMethod::parse,
    ["transpose", "pinv", "dls", "sdls", "pinv-ns", "dls-ns", "ccd"]
);
named!(
    /// `compare.scenario`: where the comparison's targets come from.
    ScenarioName(CompareScenario), "scenario", CompareScenario::parse,
    ["script", "singularity"]
);

/// One view's solver options (any subset; ranges as the panel's sliders).
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct CompareOptions {
    /// DLS damping λ, metres.
    pub lambda: Option<f64>,
    /// SDLS γmax, radians.
    pub gamma_max: Option<f64>,
    /// Step clamp α, radians per iteration.
    pub max_step: Option<f64>,
    /// Rank tolerance (relative to σmax).
    pub rank_tolerance: Option<f64>,
    /// Null-space gain k.
    pub null_space_gain: Option<f64>,
}

impl CompareOptions {
    /// The value set for the option named `key` ([`crate::compare::Parameter::key`]).
    #[must_use]
    pub fn get(&self, key: &str) -> Option<f64> {
        match key {
            "lambda" => self.lambda,
            "gamma_max" => self.gamma_max,
            "max_step" => self.max_step,
            "rank_tolerance" => self.rank_tolerance,
            "null_space_gain" => self.null_space_gain,
            _ => None,
        }
    }
}

/// The `compare` object: what to change; what is left out stays (or takes
/// its default when no comparison runs).
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct CompareCommand {
    /// The views' configurations, 2 or 4.
    pub views: Option<Vec<CompareMethodName>>,
    /// Where the targets come from.
    pub scenario: Option<ScenarioName>,
    /// Options per view, one object per view.
    pub options: Option<Vec<CompareOptions>>,
    /// Draw the views as colour-coded figures in one 3-D view (`true`) or
    /// one pane each (`false`); left out, it stays as it is.
    pub overlay: Option<bool>,
    /// `state().compare.metrics`, ignored.
    #[cfg_attr(feature = "schema", schemars(with = "Option<serde_json::Value>"))]
    pub metrics: Option<serde::de::IgnoredAny>,
    /// `state().compare.plot_error_max_mm`, ignored.
    #[cfg_attr(feature = "schema", schemars(with = "Option<f64>"))]
    pub plot_error_max_mm: Option<serde::de::IgnoredAny>,
    /// `state().compare.notice`, ignored.
    #[cfg_attr(feature = "schema", schemars(with = "Option<Vec<String>>"))]
    pub notice: Option<serde::de::IgnoredAny>,
    /// `state().compare.claims`, ignored.
    #[cfg_attr(feature = "schema", schemars(with = "Option<Vec<serde_json::Value>>"))]
    pub claims: Option<serde::de::IgnoredAny>,
}

/// The `compare` key's value: `false` (or `null`) leaves the comparison, an
/// object starts or reconfigures it.
pub type CompareValue = OffOr<CompareCommand>;

/// The comparison a `compare` object asks for (see the module docs),
/// taking defaults from `base` and from `current` where its views match.
///
/// # Errors
/// `compare.…: reason` naming the bad field (a count or a range).
pub fn config_from_command(
    command: &CompareCommand,
    base: &IkOptions,
    current: Option<&CompareConfig>,
) -> Result<CompareConfig, String> {
    let views: Vec<CompareMethod> = match &command.views {
        Some(list) => {
            if list.len() != 2 && list.len() != 4 {
                return Err(format!(
                    "compare.views: expected 2 or 4 views, got {}",
                    list.len()
                ));
            }
            list.iter().map(|m| m.0).collect()
        }
        None => match current {
            Some(current) => current.views.clone(),
            None => DEFAULT_VIEWS.to_vec(),
        },
    };
    let scenario = match command.scenario {
        Some(scenario) => scenario.0,
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
    if let Some(list) = &command.options {
        if list.len() != views.len() {
            return Err(format!(
                "compare.options: expected {} objects (one per view), got {}",
                views.len(),
                list.len()
            ));
        }
        for (i, (item, slot)) in list.iter().zip(options.iter_mut()).enumerate() {
            for parameter in Parameter::ALL {
                let Some(x) = item.get(parameter.key()) else {
                    continue;
                };
                let (lo, hi) = parameter.range();
                if !(lo..=hi).contains(&x) {
                    return Err(format!(
                        "compare.options[{i}].{}: {x} is outside [{lo}, {hi}]",
                        parameter.key()
                    ));
                }
                *parameter.slot(slot) = x;
            }
        }
    }
    Ok(CompareConfig {
        views,
        options,
        scenario,
        overlay: command
            .overlay
            .unwrap_or_else(|| current.is_some_and(|c| c.overlay)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_method_names_are_the_enums_names() {
        for m in CompareMethod::ALL {
            assert!(serde_json::from_value::<CompareMethodName>(m.name().into()).is_ok());
        }
        for s in ["script", "singularity"] {
            assert!(serde_json::from_value::<ScenarioName>(s.into()).is_ok());
        }
    }
}
