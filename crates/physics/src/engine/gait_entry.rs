//! A gait entered at its own start where the creature is: the state a run of
//! that gait starts from (Raibert & Hodgins 1991, Figure 2: the animator
//! "initializes the state of the model"), moved to the trunk's place on the
//! ground and turned to the desired heading. The lab's way into a gait that
//! the paper's take-over at the next flight cannot yet enter from a running
//! one (`scenario.physics.switch_to_start`; docs/physics.md, "Switching into
//! the bound").

use glam::{DQuat, DVec3};

use crate::control::gaits::controller::GaitController;
use crate::dynamics::kinematics::kinematics;
use crate::world::sim::Sim;

/// Put `sim` in `next`'s own start at `speed_mps` (scale 1), with the base
/// over the ground point it is over now and turned to `heading` (rad about
/// +y; 0 = +z). Time, terrain and the clock run on.
pub fn enter_at_start(sim: &mut Sim, next: &GaitController, speed_mps: f64, heading: f64) {
    let here = sim.data.base_position;
    next.start(sim, speed_mps);
    let data = &mut sim.data;
    // The start's base velocity is in the base's own coordinates, so turning
    // the base turns its motion with it.
    data.base_orientation = DQuat::from_rotation_y(heading) * data.base_orientation;
    data.base_position = DVec3::new(here.x, data.base_position.y, here.z);
    kinematics(&sim.creature.model, &mut sim.data);
}
