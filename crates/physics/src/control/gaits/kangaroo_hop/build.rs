//! The kangaroo hop's controller built from a preset's physics section (its
//! row of the gait table): the preset's first obstacle (the jump), its
//! controller parameters by name and the lab's additions it runs with.

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::builder::{Misfit, with_parameters};
use crate::control::gaits::gait::Gait;
use crate::control::gaits::kangaroo_hop::KangarooHop;
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
    let d = KangarooHopParams::default();
    let obstacle = params.obstacles.first();
    let p = KangarooHopParams {
        jump_at_m: obstacle.map(|o| o.at_m),
        obstacle_height_m: obstacle.map_or(d.obstacle_height_m, |o| o.height_m),
        obstacle_depth_m: obstacle.map_or(d.obstacle_depth_m, |o| o.depth_m),
        ..d
    };
    let mut p = with_parameters(p, params, "hop")?;
    p.speed_trim = additions.speed_trim;
    p.speed_ramp = additions.speed_ramp;
    p.tail_feedback = additions.tail_feedback;
    p.hop_integrator = additions.hop_integrator;
    Ok(Box::new(KangarooHop::new(p)))
}
