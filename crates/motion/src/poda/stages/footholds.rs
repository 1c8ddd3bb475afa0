//! The footholds stage (Girard & Maciejewski 1985, eq. 11): at lift-off
//! (time t) the body's predicted pose at f₁ = t + transfer + support/2 (the
//! next mid-stance) carries the leg's reference position into the world, and
//! the body's pose at f₂ = t + transfer (touchdown) expresses that foothold
//! in the body frame. On the legs' own cycles f₁ and f₂ are those of the
//! cycle the lift-off belongs to, fixed at the mid-stance before it.
//!
//! Reads the legs' lift-offs, the planned track and the legs' clock; writes
//! each lifting leg's lift-off point and foothold.

use crate::poda::model::PodaModel;
use crate::poda::state::PodaState;

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
    let foothold_world = track.ground_pose(f1).to_world(model.legs[i].reference_body);
    let liftoff_body = track.ground_pose(t_lo).to_body(state.runs[i].planted);
    let foothold_body = track.ground_pose(f2).to_body(foothold_world);
    let run = &mut state.runs[i];
    run.liftoff_body = liftoff_body;
    run.foothold_body = foothold_body;
    run.foothold_world = foothold_world;
}
