//! Scenario rules per engine: the frame rate and IK options every engine
//! uses, then the parameters of the scenario's engine only — `ik` (She 2006
//! thesis script, roles where it runs), `poda` (Girard & Maciejewski 1985
//! legs) or `physics` (Raibert & Hodgins 1991 model) — with a block for
//! another engine refused.

use std::collections::HashMap;

use crate::preset::{Engine, MAX_FPS, Preset, PresetError};

use super::names::NamePlace;
use super::poda::check_poda;
use super::purpose::Purpose;
use super::roles::check_thesis_roles;
use super::thesis::check_thesis;
use crate::ik::check_ik_options;

/// `scenario`: every rule for its engine that applies to `purpose`.
pub(super) fn check_scenario(
    preset: &Preset,
    names: &HashMap<&str, NamePlace>,
    purpose: Purpose,
) -> Result<(), PresetError> {
    let scenario = &preset.scenario;
    if !(1..=MAX_FPS).contains(&scenario.fps) {
        return Err(PresetError::new(
            "scenario.fps",
            format!("must be between 1 and {MAX_FPS}"),
        ));
    }
    check_ik_options("scenario.ik", &scenario.ik)?;
    scenario
        .terrain
        .check()
        .map_err(|e| PresetError::new(e.path("scenario.terrain"), e.reason))?;
    if scenario.physics.is_some() && scenario.engine != Engine::Physics {
        return Err(PresetError::new(
            "scenario.physics",
            format!(
                "belongs to engine \"physics\"; this scenario's engine is \"{}\"",
                scenario.engine.name()
            ),
        ));
    }
    match scenario.engine {
        Engine::Ik => {
            if scenario.poda.is_some() {
                return Err(PresetError::new(
                    "scenario.poda",
                    "belongs to engine \"poda\"; this scenario's engine is \"ik\"",
                ));
            }
            check_thesis(names, &scenario.thesis)?;
            // The thesis script, the one reader of the roles, runs only for this
            // engine and only when the scenario itself is run.
            if purpose == Purpose::Scenario {
                check_thesis_roles(&preset.skeleton, &scenario.thesis)?;
            }
            Ok(())
        }
        Engine::Poda => check_poda(&preset.skeleton, names, &scenario.poda_params()),
        Engine::Physics => {
            let Some(physics) = &scenario.physics else {
                return Err(PresetError::new(
                    "scenario.physics",
                    "engine \"physics\" needs the creature's physical model",
                ));
            };
            let known = |n: &str| matches!(names.get(n), Some(NamePlace::Joint(_)));
            physics.check("scenario.physics", &known)
        }
    }
}
