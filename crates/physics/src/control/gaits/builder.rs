//! What every gait's builder shares (each folder's `build.rs`): the
//! preset's controller parameters set by name, the check that the creature's
//! legs fit the gait, and why a controller cannot be built.

use std::collections::BTreeMap;

use gaitlab_core::preset::{PhysicsParams, PresetError};

use crate::control::gaits::parameters::NamedParameters;
use crate::creatures::PhysicalCreature;

/// `p` with the preset's controller parameters set by name: those of
/// every gait (`scenario.physics.controller`), then this gait's own
/// (`scenario.physics.controller_by_gait.GAIT`).
///
/// # Errors
/// The path of a name the gait's controller lacks.
pub fn with_parameters<P: NamedParameters>(
    mut p: P,
    params: &PhysicsParams,
    gait: &str,
) -> Result<P, PresetError> {
    let mut set = |values: &BTreeMap<String, f64>, at: &dyn Fn() -> String| {
        for (name, &value) in values {
            if !p.set_parameter(name, value) {
                return Err(PresetError::new(
                    format!("scenario.physics.{}.{name}", at()),
                    format!(
                        "the {gait} controller has no such parameter (it has: {})",
                        P::NAMES.join(", ")
                    ),
                ));
            }
        }
        Ok(())
    };
    set(&params.controller, &|| "controller".to_owned())?;
    if let Some(own) = params.controller_by_gait.get(gait) {
        set(own, &|| format!("controller_by_gait.{gait}"))?;
    }
    Ok(p)
}

/// Why a gait's controller cannot be built: legs that do not fit it (what
/// it needs), or a preset field.
pub enum Misfit {
    /// The legs do not fit; what the gait needs.
    Legs(&'static str),
    /// A preset field is wrong.
    Preset(PresetError),
}

impl From<PresetError> for Misfit {
    fn from(e: PresetError) -> Self {
        Misfit::Preset(e)
    }
}

/// Whether `creature` has `count` legs with `hip_joints` hip joints each;
/// else what the gait `needs`.
pub fn legs(
    creature: &PhysicalCreature,
    count: usize,
    hip_joints: usize,
    needs: &'static str,
) -> Result<(), Misfit> {
    let fits =
        creature.legs.len() == count && creature.legs.iter().all(|leg| leg.hip.len() == hip_joints);
    if fits {
        Ok(())
    } else {
        Err(Misfit::Legs(needs))
    }
}

/// The biped's two legs with ball hips.
pub fn biped_legs(creature: &PhysicalCreature) -> Result<(), Misfit> {
    legs(
        creature,
        2,
        3,
        "the biped gaits need two legs with three hip joints each",
    )
}

/// The quadruped's four legs with two hip joints each.
pub fn quadruped_legs(creature: &PhysicalCreature) -> Result<(), Misfit> {
    legs(
        creature,
        4,
        2,
        "the quadruped gaits need four legs with two hip joints each",
    )
}
