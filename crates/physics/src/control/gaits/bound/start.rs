//! The bound's and the gallop's own start (Raibert & Hodgins 1991, Figure
//! 2: the animator initializes the state of the model): level flight at
//! landing height, the rear pair set to land first.

use crate::control::additions::Additions;
use crate::control::gaits::bound::params::{PAIRS, QuadrupedBoundParams, REAR};
use crate::control::gaits::start::{first_leg_m, level_flight};
use crate::world::sim::Sim;

/// Put the quadruped of `sim` at the start of a bound at `speed_mps`
/// (scale-1, scaled by √L): trunk level at landing height, rear legs
/// extended for landing, front legs short, moving forward along +z.
pub fn start(sim: &mut Sim, speed_mps: f64, _additions: Additions) {
    let l = sim.creature.scale;
    let p = QuadrupedBoundParams::default();
    let height = first_leg_m(sim) + p.landing_rest_m * l + 0.04 * l;
    level_flight(sim, speed_mps, height, |i| {
        let rest = if PAIRS[REAR].contains(&i) {
            p.landing_rest_m
        } else {
            p.short_rest_m
        };
        rest * l
    });
}
