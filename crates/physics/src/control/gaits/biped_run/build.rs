//! The biped run's controller built from a preset's physics section (its
//! row of the gait table): its controller parameters by name and the lab's
//! additions it runs with.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::biped_run::BipedRun;
use crate::control::gaits::biped_run::params::BipedRunParams;
use crate::control::gaits::builder::{Misfit, biped_legs, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::creatures::PhysicalCreature;

/// The run's controller; a file from before the additions were optional
/// runs with the controller's earlier defaults.
///
/// # Errors
/// Legs that are not the biped's; a parameter the run lacks.
pub fn build(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    biped_legs(creature)?;
    let d = if additions.legacy {
        BipedRunParams::before_lab_additions()
    } else {
        BipedRunParams::default()
    };
    let mut p = with_parameters(d, params, "run")?;
    p.unloading_posture = additions.unloading_posture;
    p.speed_trim = additions.speed_trim;
    p.ground_ahead = additions.ground_ahead;
    let p = p.with_hop_integrator(additions.hop_integrator);
    Ok(Box::new(BipedRun::new(p, creature)))
}
