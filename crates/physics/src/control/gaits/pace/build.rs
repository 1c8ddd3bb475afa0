//! The pace's controller built from a preset's physics section (its row of
//! the gait table): the trot's state machine on the lateral pairs, with the
//! pace's own parameters and the preset's by name over them.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::builder::Misfit;
use crate::control::gaits::gait::Gait;
use crate::control::gaits::pace::{PACE_PAIRS, pace_params};
use crate::control::gaits::trot::build::on_pairs;
use crate::creatures::PhysicalCreature;

/// The pace's controller.
///
/// # Errors
/// Legs that are not the quadruped's; a parameter the pace lacks.
pub fn build(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    on_pairs(
        creature,
        params,
        "pace",
        pace_params(),
        PACE_PAIRS,
        additions,
    )
}
