//! The biped gallops' controller built from a preset's physics section
//! (their rows of the gait table): the preset's speed and hop height, its
//! controller parameters by name and the speed trim if it runs with it.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::biped_gallop::BipedGallop;
use crate::control::gaits::biped_gallop::params::{BipedGallopParams, GallopStyle};
use crate::control::gaits::builder::{Misfit, biped_legs, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::creatures::PhysicalCreature;

/// The gallop whose legs swing together (`gallop`).
///
/// # Errors
/// Legs that are not the biped's; a parameter the gallop lacks.
pub fn together_swing(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    build(creature, params, additions, GallopStyle::TogetherSwing)
}

/// The gallop whose legs swing in turn (`gallop_alternate`).
///
/// # Errors
/// Legs that are not the biped's; a parameter the gallop lacks.
pub fn alternate_swing(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    build(creature, params, additions, GallopStyle::AlternateSwing)
}

fn build(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
    style: GallopStyle,
) -> Result<Box<dyn Gait>, Misfit> {
    biped_legs(creature)?;
    let d = BipedGallopParams::default();
    let p = BipedGallopParams { style, ..d };
    let gait = match style {
        GallopStyle::TogetherSwing => "gallop",
        GallopStyle::AlternateSwing => "gallop_alternate",
    };
    let mut p = with_parameters(p, params, gait)?;
    p.speed_trim = additions.speed_trim;
    Ok(Box::new(BipedGallop::new(p, creature)))
}
