//! The biped gallops' controller built from a preset's physics section
//! (their rows of the gait table): its controller parameters by name and
//! the speed trim if it runs with it.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::biped_gallop::BipedGallop;
use crate::control::gaits::biped_gallop::params::{BipedGallopParams, GallopStyle};
use crate::control::gaits::builder::{Misfit, biped_legs, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::creatures::PhysicalCreature;

/// The gallop whose legs swing in turn (`gallop_alternate`) when
/// `ALTERNATE`, else together (`gallop`).
///
/// # Errors
/// Legs that are not the biped's; a parameter the gallop lacks.
pub fn build<const ALTERNATE: bool>(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    let (style, gait) = if ALTERNATE {
        (GallopStyle::AlternateSwing, "gallop_alternate")
    } else {
        (GallopStyle::TogetherSwing, "gallop")
    };
    biped_legs(creature)?;
    let p = BipedGallopParams {
        style,
        ..BipedGallopParams::default()
    };
    let mut p = with_parameters(p, params, gait)?;
    p.speed_trim = additions.speed_trim;
    p.hop_integrator = additions.hop_integrator;
    Ok(Box::new(BipedGallop::new(p, creature)))
}
