//! The foot-targets stage (Girard & Maciejewski 1985, eq. 10 and "Leg
//! Support and Transfer Trajectories"): a supporting foot stays where it
//! landed (eq. 10); a transferring foot follows the Catmull-Rom spline
//! through the key leg positions — the spline's "along" fraction moves it
//! from its lift-off point to its foothold in the body frame, its "height"
//! sets the world height.
//!
//! Reads each leg's phase, touchdown and footholds, the track and the keys;
//! writes the planted feet, the targets and the transfers' progress.

use glam::DVec3;

use crate::poda::model::PodaModel;
use crate::poda::spline::eval_open;
use crate::poda::state::PodaState;

/// Every leg's target at `t`: a foot that landed this frame is planted at
/// its spline's end.
pub fn place(model: &PodaModel, state: &mut PodaState, t: f64) {
    for i in 0..model.legs.len() {
        let run = state.runs[i];
        let Some(phase) = run.phase else {
            continue;
        };
        if let Some(t_td) = run.touchdown_s {
            let landed = transfer_target(model, state, i, t_td, 1.0);
            state.runs[i].planted = DVec3::new(landed.x, 0.0, landed.z);
        }
        let target = if run.support {
            state.runs[i].planted
        } else {
            transfer_target(model, state, i, t, phase.fraction)
        };
        let run = &mut state.runs[i];
        run.target = target;
        run.progress = phase.fraction;
    }
}

/// The transfer target of leg `i` at time `t` with transfer progress `u`.
#[must_use]
pub fn transfer_target(model: &PodaModel, state: &PodaState, i: usize, t: f64, u: f64) -> DVec3 {
    let run = &state.runs[i];
    let key = eval_open(&model.keys, u);
    let body = run.liftoff_body.lerp(run.foothold_body, key.x);
    let mut world = state.track.ground_pose(t).to_world(body);
    world.y = key.y * model.params.step_height_m;
    world
}
