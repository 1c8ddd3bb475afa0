//! The trot's controller built from a preset's physics section (its row of
//! the gait table): the preset's speed and hop height and its controller
//! parameters by name. The trot offers none of the lab's additions.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::builder::{Misfit, quadruped_legs, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::control::gaits::trot::QuadrupedRun;
use crate::control::gaits::trot::params::QuadrupedRunParams;
use crate::creatures::PhysicalCreature;

/// The trot's controller.
///
/// # Errors
/// Legs that are not the quadruped's; a parameter the trot lacks.
pub fn build(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    _additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    quadruped_legs(creature)?;
    let p = with_parameters(QuadrupedRunParams::default(), params, "trot")?;
    Ok(Box::new(QuadrupedRun::new(p, creature)))
}
