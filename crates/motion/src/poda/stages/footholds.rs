//! The footholds stage (Girard & Maciejewski 1985, eq. 11): at lift-off
//! (time t) the body's predicted pose at f₁ = t + transfer + support/2 (the
//! next mid-stance) carries the leg's reference position into the world, and
//! the body's pose at f₂ = t + transfer (touchdown) expresses that foothold
//! in the body frame. On the legs' own cycles f₁ and f₂ are those of the
//! cycle the lift-off belongs to, fixed at the mid-stance before it.
//!
//! On ground that is not flat the foothold lies on the surface, moved to
//! the nearest acceptable spot where eq. 11's is not
//! ([`crate::poda::terrain_feet`]).
//!
//! Reads the legs' lift-offs, the planned track and the legs' clock; writes
//! each lifting leg's lift-off point and foothold.

use crate::poda::model::PodaModel;
use crate::poda::state::PodaState;
use crate::poda::terrain_feet::{self, Foothold};

/// Eq. 11 for every leg that lifted off this frame.
pub fn plan(model: &PodaModel, state: &mut PodaState) {
    for i in 0..model.legs.len() {
        if let Some(t_lo) = state.runs[i].liftoff_s {
            plan_leg(model, state, i, t_lo);
        }
    }
}

/// Eq. 11: the foothold of leg `i` for a lift-off at `t_lo`.
pub fn plan_leg(model: &PodaModel, state: &mut PodaState, i: usize, t_lo: f64) {
    let gait = &state.gait;
    // The touchdown (f₂) and the next mid-stance (f₁) of the cycle the
    // lift-off belongs to: fixed at the mid-stance before it.
    let (f1, f2) = match state.clock.cycle_at(i, t_lo, gait) {
        Some(cycle) => (cycle.end_s(), cycle.touchdown_s()),
        None => {
            let transfer = gait.transfer_s();
            (t_lo + transfer + 0.5 * gait.support_s(), t_lo + transfer)
        }
    };
    let track = &state.track;
    let spot = track.ground_pose(f1).to_world(model.legs[i].reference_body);
    // On the ground, or the nearest acceptable spot (the lab's, for ground
    // that is not flat: `terrain_feet`; the floor keeps eq. 11's spot).
    let foothold = if model.terrain.is_flat() {
        Foothold {
            nominal: spot,
            chosen: spot,
            moved: false,
        }
    } else {
        terrain_feet::foothold(&model.terrain, spot.x, spot.z)
    };
    let planted = state.runs[i].planted;
    let liftoff_body = track.ground_pose(t_lo).to_body(planted);
    let foothold_body = track.ground_pose(f2).to_body(foothold.chosen);
    let highest_m = terrain_feet::highest_between(&model.terrain, planted, foothold.chosen);
    let run = &mut state.runs[i];
    run.liftoff_body = liftoff_body;
    run.foothold_body = foothold_body;
    run.foothold_world = foothold.chosen;
    run.foothold_nominal = foothold.nominal;
    run.foothold_moved = foothold.moved;
    run.highest_m = highest_m;
    state.footholds_moved += u64::from(foothold.moved);
}
