//! Building a gait's controller from a preset's physics section (Raibert &
//! Hodgins 1991, "Gaits": which state machine drives each gait of each
//! model): the preset's speed, hop height and obstacles, its controller
//! parameters by name, and the lab's additions resolved against what each
//! controller offers.

use gaitlab_core::preset::{PhysicsParams, PresetError};

use crate::control::additions::Additions;
use crate::control::gaits::builder::Misfit;
use crate::control::gaits::controller::GaitController;
use crate::control::gaits::table::{gait_names, row};
use crate::creatures::PhysicalCreature;

/// Whether every gait `controller_by_gait`, `lab_additions_by_gait` and
/// `switch_to_start` name is one of the model's.
///
/// # Errors
/// `scenario.physics.controller_by_gait.NAME`,
/// `scenario.physics.lab_additions_by_gait.NAME` or
/// `scenario.physics.switch_to_start[I]` for a gait the model lacks.
fn known_gaits(creature: &PhysicalCreature, params: &PhysicsParams) -> Result<(), PresetError> {
    let names = gait_names(creature.species);
    let unknown = |g: &String| !names.contains(&g.as_str());
    let by_gait = params
        .controller_by_gait
        .keys()
        .find(|g| unknown(g))
        .map(|g| format!("scenario.physics.controller_by_gait.{g}"))
        .or_else(|| {
            (params.lab_additions_by_gait.keys())
                .find(|g| unknown(g))
                .map(|g| format!("scenario.physics.lab_additions_by_gait.{g}"))
        });
    let to_start = || {
        params
            .switch_to_start
            .iter()
            .position(unknown)
            .map(|i| format!("scenario.physics.switch_to_start[{i}]"))
    };
    match by_gait.or_else(to_start) {
        Some(path) => Err(PresetError::new(
            path,
            format!("this model has no such gait (it has: {})", names.join(", ")),
        )),
        None => Ok(()),
    }
}

/// The controller of `gait` for `creature`, with `params`' speed, hop height,
/// obstacles, controller parameters and the lab's additions (which win over
/// a controller parameter they zero).
///
/// # Errors
/// `scenario.physics.gait` for a gait the model lacks; `scenario.physics.legs`
/// when the legs do not fit the gait's controller; `scenario.physics.controller.NAME`
/// for a parameter it does not have.
pub fn make_controller(
    creature: &PhysicalCreature,
    gait: &str,
    params: &PhysicsParams,
) -> Result<GaitController, PresetError> {
    known_gaits(creature, params)?;
    let Some(row) = row(creature.species, gait) else {
        let names = gait_names(creature.species);
        return Err(PresetError::new(
            "scenario.physics.gait",
            format!(
                "unknown gait \"{gait}\" (this model has: {})",
                names.join(", ")
            ),
        ));
    };
    let spec = match params.lab_additions_by_gait.get(gait) {
        Some(own) => Some(own.over(params.lab_additions.unwrap_or_default())),
        None => params.lab_additions,
    };
    let additions = Additions::resolve(spec.as_ref(), row.offers);
    let inner = (row.build)(creature, params, additions).map_err(|e| match e {
        Misfit::Legs(needs) => PresetError::new("scenario.physics.legs", needs),
        Misfit::Preset(e) => e,
    })?;
    Ok(GaitController::new(row, additions, inner))
}
