//! The kangaroo hop's controller built from a preset's physics section (its
//! row of the gait table): the preset's obstacles (each one jumped), its
//! controller parameters by name and the lab's additions it runs with.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::builder::{Misfit, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::control::gaits::kangaroo_hop::KangarooHop;
use crate::control::gaits::kangaroo_hop::jumps::QueuedJump;
use crate::control::gaits::kangaroo_hop::params::KangarooHopParams;
use crate::creatures::PhysicalCreature;

/// The hop's controller.
///
/// # Errors
/// A body that is not the kangaroo's; a parameter the hop lacks.
pub fn build(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    additions: Additions,
) -> Result<Box<dyn Gait>, Misfit> {
    let fits = creature.legs.len() == 1
        && creature.legs[0].knee.is_some()
        && creature.legs[0].hip.len() == 1
        && creature.tail.len() == 3
        && creature.neck.is_some()
        && creature.model.joint_count() >= 10;
    if !fits {
        return Err(Misfit::Legs(
            "the kangaroo hop needs a planar base, one leg with hip, knee and ankle, a three-joint tail and a neck",
        ));
    }
    let mut p = with_parameters(KangarooHopParams::default(), params, "hop")?;
    p.speed_trim = additions.speed_trim;
    p.speed_ramp = additions.speed_ramp;
    p.tail_feedback = additions.tail_feedback;
    p.hop_integrator = additions.hop_integrator;
    p.ground_ahead = additions.ground_ahead;
    let mut hop = KangarooHop::new(p);
    // Every box of the file is jumped, nearest first.
    for o in &params.obstacles {
        hop.jump_over(QueuedJump {
            at_m: o.at_m,
            depth_m: o.depth_m,
            height_m: o.height_m,
        });
    }
    Ok(Box::new(hop))
}
