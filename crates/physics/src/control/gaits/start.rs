//! The state a free-based runner starts a gait from: the trunk level at a
//! chosen height, moving forward at the desired speed, every joint at zero
//! but the leg springs, no foot on the ground. The paper's animator "must
//! also initialize the state of the model" (Figure 2); this is the one place
//! the gaits do it.

use glam::{DQuat, DVec2, DVec3};

use crate::control::gaits::bound::params::{PAIRS, QuadrupedBoundParams, REAR};
use crate::control::gaits::kangaroo_hop::leg::{leg_geometry, leg_ik};
use crate::control::gaits::kangaroo_hop::params::KangarooHopParams;
use crate::control::gaits::trot::params::QuadrupedRunParams;
use crate::dynamics::data::Data;
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
    sim.data.base_velocity.linear = DVec3::new(0.0, 0.0, speed_mps * l.sqrt());
    for c in &mut sim.contacts {
        c.touching = false;
    }
}

/// The creature's first leg's full length (m, scaled); 0 with no legs.
#[must_use]
pub fn first_leg_m(sim: &Sim) -> f64 {
    sim.creature.leg_length_m(0)
}

/// Put the quadruped of `sim` in the initial state for the trot at
/// `speed_mps` (scale-1 speed, scaled by √L): trunk level just above standing
/// height, moving forward along +z, legs hanging, the first pair about to land.
pub fn quadruped_start(sim: &mut Sim, speed_mps: f64) {
    let l = sim.creature.scale;
    let tuning = QuadrupedRunParams::default().trot;
    let height = first_leg_m(sim) + tuning.landing_rest_m * l + 0.03 * l;
    level_flight(sim, speed_mps, height, |_| tuning.idle_rest_m * l);
}

/// Put the quadruped of `sim` at the start of a bound at `speed_mps`
/// (scale-1, scaled by √L): trunk level at landing height, rear legs
/// extended for landing, front legs short, moving forward along +z.
pub fn bound_start(sim: &mut Sim, speed_mps: f64) {
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

/// Put the kangaroo in flight just before landing, moving forward at
/// `speed_mps` (m/s at scale 1; scaled by √L), its leg set for a neutral
/// landing. Expects `sim.creature` to be the kangaroo.
pub fn kangaroo_start(sim: &mut Sim, speed_mps: f64) {
    let creature = &sim.creature;
    let l = creature.scale;
    let p = KangarooHopParams::default();
    let Some(g) = leg_geometry(creature) else {
        return;
    };
    let Some(leg) = creature.legs.first() else {
        return;
    };
    let (Some(&hip), Some(knee)) = (leg.hip.first(), leg.knee) else {
        return;
    };
    let ankle = leg.spring;
    let data: &mut Data = &mut sim.data;
    data.q.fill(0.0);
    data.qd.fill(0.0);
    let r0 = p.landing_leg_m * l;
    let dz = (0.5 * speed_mps * p.stance_guess_s * l).min(0.8 * r0);
    let toe = DVec2::new(dz, -(r0 * r0 - dz * dz).sqrt());
    let (qh, qk) = leg_ik(&g, toe, p.ankle_rest_rad, 0.0);
    data.q[hip] = qh;
    data.q[knee] = qk;
    data.q[ankle] = p.ankle_rest_rad;
    data.q[6] = p.tail_mean_rad;
    // Trunk height: the toe 1 cm (×L) above the ground.
    data.q[1] = -(leg.hip_in_trunk.y + toe.y) + 0.01 * l;
    data.qd[0] = speed_mps * l.sqrt();
    data.qd[1] = -0.5 * l.sqrt();
    crate::dynamics::kinematics::kinematics(&creature.model, data);
}
