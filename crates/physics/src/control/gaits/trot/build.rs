//! The trot's controller built from a preset's physics section (its row of
//! the gait table): its controller parameters by name over the trot's own.
//! The trot offers the lab's hop integrator. [`on_pairs`] builds the same
//! state machine on other virtual legs (the pace's).

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::builder::{Misfit, quadruped_legs, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::control::gaits::trot::params::QuadrupedRunParams;
use crate::control::gaits::trot::{QuadrupedRun, TROT_PAIRS};
use crate::creatures::PhysicalCreature;

/// The trot's controller.
///
/// # Errors
/// Legs that are not the quadruped's; a parameter the trot lacks.
pub fn build(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    let own = QuadrupedRunParams::default();
    on_pairs(creature, params, "trot", own, TROT_PAIRS, additions)
}

/// The trot's state machine on the virtual legs `pairs`, for `gait`: its
/// `own` parameters with the preset's by name over them, and the hop
/// integrator if `additions` has it.
///
/// # Errors
/// Legs that are not the quadruped's; a parameter the gait lacks.
pub fn on_pairs(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    gait: &str,
    own: QuadrupedRunParams,
    pairs: [[usize; 2]; 2],
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    quadruped_legs(creature)?;
    let mut p = with_parameters(own, params, gait)?;
    p.hop_integrator = additions.hop_integrator;
    p.ground_ahead = additions.ground_ahead;
    Ok(Box::new(QuadrupedRun::on_pairs(p, creature, pairs)))
}
