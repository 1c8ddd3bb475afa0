//! The state a free-based runner starts a gait from: the trunk level at a
//! chosen height, moving forward at the desired speed, every joint at zero
//! but the leg springs, no foot on the ground. The paper's animator "must
//! also initialize the state of the model" (Figure 2); this is the one place
//! the gaits do it, each gait's own start (its `start.rs`) choosing the
//! height and the springs.

use glam::{DQuat, DVec3};

use crate::control::laws::scale::Scale;
use crate::world::sim::Sim;

/// Put `sim` in level flight: the trunk at `height_m` (m, scaled) moving
/// along +z at `speed_mps` (scale-1 speed, scaled by √L), each leg `i`'s
/// spring at `spring_rest(i)` (m, scaled), every other joint at rest.
pub fn level_flight(
    sim: &mut Sim,
    speed_mps: f64,
    height_m: f64,
    spring_rest: impl Fn(usize) -> f64,
) {
    let l = sim.creature.scale;
    sim.data.q.fill(0.0);
    sim.data.qd.fill(0.0);
    for (i, leg) in sim.creature.legs.iter().enumerate() {
        sim.data.q[leg.spring] = spring_rest(i);
    }
    sim.data.base_orientation = DQuat::IDENTITY;
    sim.data.base_position = DVec3::new(0.0, height_m, 0.0);
    sim.data.base_velocity.angular = DVec3::ZERO;
    sim.data.base_velocity.linear = DVec3::new(0.0, 0.0, speed_mps * Scale::new(l).velocity());
    for c in &mut sim.contacts {
        c.touching = false;
    }
}

/// The creature's first leg's full length (m, scaled); 0 with no legs.
#[must_use]
pub fn first_leg_m(sim: &Sim) -> f64 {
    sim.creature.leg_length_m(0)
}
