//! The trot's own start (Raibert & Hodgins 1991, Figure 2: the animator
//! initializes the state of the model): level flight just above standing
//! height, the first pair about to land.

use crate::control::additions::Additions;
use crate::control::gaits::start::{first_leg_m, level_flight};
use crate::control::gaits::trot::params::QuadrupedRunParams;
use crate::world::sim::Sim;

/// Put the quadruped of `sim` in the initial state for the trot at
/// `speed_mps` (scale-1 speed, scaled by √L): trunk level just above standing
/// height, moving forward along +z, legs hanging, the first pair about to land.
pub fn start(sim: &mut Sim, speed_mps: f64, _additions: Additions) {
    let l = sim.creature.scale;
    let tuning = QuadrupedRunParams::default().trot;
    let height = first_leg_m(sim) + tuning.landing_rest_m * l + 0.03 * l;
    level_flight(sim, speed_mps, height, |_| tuning.idle_rest_m * l);
}
