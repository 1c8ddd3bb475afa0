//! The bound's and the gallop's controller built from a preset's physics
//! section (their rows of the gait table): one state machine in two styles,
//! with its controller parameters by name and the speed trim if it runs
//! with it.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::bound::QuadrupedBound;
use crate::control::gaits::bound::params::{BoundStyle, QuadrupedBoundParams};
use crate::control::gaits::builder::{Misfit, quadruped_legs, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::creatures::PhysicalCreature;

/// The gallop when `GALLOP`, else the bound.
///
/// # Errors
/// Legs that are not the quadruped's; a parameter the gait lacks.
pub fn build<const GALLOP: bool>(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    let style = if GALLOP {
        BoundStyle::Gallop
    } else {
        BoundStyle::Bound
    };
    quadruped_legs(creature)?;
    let p = QuadrupedBoundParams {
        style,
        ..QuadrupedBoundParams::default()
    };
    let mut p = with_parameters(p, params, style.name())?;
    p.speed_trim = additions.speed_trim;
    p.hop_integrator = additions.hop_integrator;
    Ok(Box::new(QuadrupedBound::new(p, creature)))
}
