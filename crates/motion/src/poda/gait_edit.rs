//! A gait edit's way into the run (Girard & Maciejewski 1985, "Vertical
//! Control": changes are taken on "by adjusting the related dynamic
//! parameters for each leg's contribution independently at the beginning
//! of its upward pushing phase"): a named gait or a speed — the user's, or
//! the body path's own speed read at the legs' mid-stances — changes the
//! gait and queues the edit ([`super::edits`]); at the next frame the legs
//! begin to take it on one by one ([`super::leg_clock`]) and the body stage
//! plans its track anew. Before the first frame the run simply starts in it.

use super::edits::GaitChange;
use super::gait::{Derived, GaitError, GaitParams};
use super::model::PodaModel;
use super::speed_gait::gait_at_speed;
use super::start::restart;
use super::state::PodaState;

/// Switches to the gait `name` with values `next`: before the first frame
/// the run simply starts in it; later the legs take it on one by one.
pub fn adopt(model: &PodaModel, state: &mut PodaState, name: &str, next: GaitParams) {
    name.clone_into(&mut state.gait_name);
    if !state.clock.by_cycles() && state.time == 0.0 {
        state.gait = next;
        restart(model, state);
    } else {
        state.take_cycles(&model.pitch_weights);
        state.edits.gait_edited(&state.gait);
        state.gait = next;
    }
}

/// Sets the body speed: with gait by speed the gait and its stride follow
/// (the legs take them on one by one); otherwise the stroke is kept and the
/// period derived ([`GaitParams::set_speed`]).
///
/// # Errors
/// The speed, or a value derived from it, out of range; nothing changes.
pub fn apply_speed(
    model: &PodaModel,
    state: &mut PodaState,
    speed_mps: f64,
) -> Result<Derived, GaitError> {
    let (name, next, edit) = gait_at_speed(model, state, speed_mps)?;
    match name {
        Some(name) => adopt(model, state, name, next),
        None => {
            state.edits.gait_edited(&state.gait);
            state.gait = next;
        }
    }
    Ok(edit)
}

/// On a path with speeds, whenever a leg has reached mid-stance since the
/// last time (or the path is new), the gait takes on the desired speed
/// where the desired point is now ([`super::path::BodyPath::desired_speed_mps`]),
/// as a speed edit would. Legs take a change on only at their mid-stances
/// ([`super::leg_cycles`]; the paper's "at the beginning of its upward
/// pushing phase"), so reading the speed there, not every frame, changes
/// nothing the legs do and spares a replan of the body's track every
/// frame. A speed the gait cannot take leaves it as it is (the path's
/// speeds were checked against the gait when the path was set).
pub fn follow_path_speed(model: &PodaModel, state: &mut PodaState) {
    if model.path.speeds_mps().is_none() {
        return;
    }
    let latest = (0..model.legs.len())
        .filter_map(|i| state.clock.mid_stance_s(i, state.time, &state.gait))
        .fold(f64::NEG_INFINITY, f64::max);
    let path_new = state.edits.take_path_replaced();
    if !path_new && latest <= state.path_speed_read_s {
        return;
    }
    state.path_speed_read_s = latest;
    let distance = state.track.interpolate(state.time).desired_m;
    if let Some(v) = model.path.desired_speed_mps(distance)
        && v != state.gait.speed_mps()
    {
        let _ = apply_speed(model, state, v);
    }
}

/// Takes on the gait edits queued since the last frame, at `t_prev`: a
/// change of period, duty factor or phases before the first frame restarts
/// the run in it; later the legs begin to take it on one by one and the
/// transition bounds follow the new gait. Returns what the body stage
/// takes on (nothing after a restart).
pub fn take_on(model: &PodaModel, state: &mut PodaState, t_prev: f64) -> GaitChange {
    let change = state.edits.take_gait(&state.gait);
    if !change.rephased {
        return change;
    }
    if !state.clock.by_cycles() && t_prev == 0.0 {
        // An edit before the first frame sets the gait the run starts in.
        restart(model, state);
        return GaitChange::default();
    }
    // An edit that eq. 9 would take on by re-phasing every leg at once:
    // the legs take it on one by one.
    state.take_cycles(&model.pitch_weights);
    state.bounds.gait_changed();
    change
}
