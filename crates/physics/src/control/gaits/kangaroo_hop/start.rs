//! The kangaroo hop's own start (Raibert & Hodgins 1991, Figure 2: the
//! animator initializes the state of the model): in flight just before a
//! landing, the leg set for a neutral landing.

use glam::DVec2;

use crate::control::additions::Additions;
use crate::control::gaits::kangaroo_hop::leg::{leg_geometry, leg_ik};
use crate::control::gaits::kangaroo_hop::params::KangarooHopParams;
use crate::control::laws::scale::Scale;
use crate::dynamics::data::Data;
use crate::world::sim::Sim;

/// With the lab's speed ramp, the kangaroo starts no faster than this (m/s
/// at scale 1) and its controller ramps to the desired speed: started at
/// 5 m/s it tumbles.
pub const KANGAROO_START_MPS: f64 = 2.0;

/// Put the kangaroo in flight just before landing, moving forward at
/// `speed_mps` (m/s at scale 1; scaled by √L) — with the lab's speed ramp,
/// at no more than [`KANGAROO_START_MPS`], the controller ramping to the
/// rest — its leg set for a neutral landing. Expects `sim.creature` to be
/// the kangaroo.
pub fn start(sim: &mut Sim, speed_mps: f64, additions: Additions) {
    let speed_mps = if additions.speed_ramp {
        speed_mps.clamp(0.0, KANGAROO_START_MPS)
    } else {
        speed_mps
    };
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
    data.qd[0] = speed_mps * Scale::new(l).velocity();
    data.qd[1] = -0.5 * Scale::new(l).velocity();
    crate::dynamics::kinematics::kinematics(&creature.model, data);
}
