//! The run's start (the driver's reset; Girard & Maciejewski 1985, eq. 9 at
//! time 0): the body at its path's start on its planned track, every leg in
//! eq. 9's state at time 0 — a supporting foot planted where its last
//! mid-stance put it, a transferring one on its way from its lift-off to the
//! foothold eq. 11 planned — and the pose settled by IK.

use glam::DVec3;

use super::measure;
use super::model::PodaModel;
use super::speed_gait::gait_at_speed;
use super::stages::{body, footholds, ik, targets};
use super::state::PodaState;

/// IK iterations per leg when a restart settles the pose.
const RESET_ITERATIONS: usize = 60;

/// Where leg `i` stands when supporting at mid-stance time `t_mid`.
fn reference_world(model: &PodaModel, state: &PodaState, i: usize, t_mid: f64) -> DVec3 {
    state
        .track
        .ground_pose(t_mid)
        .to_world(model.legs[i].reference_body)
}

/// Where a foot stands for eq. 11's spot `p`: on the floor, or on the
/// ground's nearest acceptable spot ([`crate::poda::terrain_feet`]).
fn on_ground(model: &PodaModel, p: DVec3) -> DVec3 {
    super::terrain_feet::foothold(&model.terrain, p.x, p.z).chosen
}

/// Restarts the run at time 0; the queued edits are taken on (the run
/// starts in the gait as it is now).
pub fn restart(model: &PodaModel, state: &mut PodaState) {
    // A path with speeds: the run starts in the gait at its start's speed.
    if let Some(v) = model.path.desired_speed_mps(0.0)
        && v != state.gait.speed_mps()
        && let Ok((name, next, _)) = gait_at_speed(model, state, v)
    {
        if let Some(name) = name {
            name.clone_into(&mut state.gait_name);
        }
        state.gait = next;
    }
    state.edits.clear();
    // The gait reads the path's speed at the first frame.
    state.edits.path_replaced();
    state.time = 0.0;
    state.footholds_moved = 0;
    state.eased = (0, 1.0);
    state.clock.restart(&state.gait);
    state.centre.restart();
    state.pose.clone_from(&model.rest);
    state.track.reset(&model.path, &state.gait);
    let support = state.gait.support_s();
    for i in 0..model.legs.len() {
        let Some(phase) = state.gait.leg_phase(i, 0.0) else {
            continue;
        };
        if phase.support {
            let planted = reference_world(model, state, i, phase.last_touchdown_s + 0.5 * support);
            let run = &mut state.runs[i];
            run.planted = on_ground(model, planted);
            run.support = true;
            run.target = run.planted;
        } else {
            let planted = reference_world(model, state, i, phase.last_liftoff_s - 0.5 * support);
            state.runs[i].planted = on_ground(model, planted);
            footholds::plan_leg(model, state, i, phase.last_liftoff_s);
            state.runs[i].support = false;
            let target = targets::transfer_target(model, state, i, 0.0, phase.fraction);
            let run = &mut state.runs[i];
            run.target = target;
            run.progress = phase.fraction;
        }
    }
    state.path_error_max_m = 0.0;
    body::place(model, state, 0.0);
    targets::place_rotations_at_start(model, state);
    ik::solve(model, state, RESET_ITERATIONS);
    measure::record(model, state, 0.0, 0.0, true);
}
