//! The body stage (Girard & Maciejewski 1985, "Horizontal Control",
//! "Vertical Control", "Rotational Control"): the ground-plane pose planned
//! ahead by [`BodyTrack`](crate::poda::body_track::BodyTrack) — path
//! following with the legs' horizontal force limits (eq. 14–15) and yaw from
//! the legs' push / restore toward the direction of travel — raised by the
//! superposition of each leg's vertical push / fall / restore (eq. 12–13),
//! pitched by the legs' vertical motion front against rear (Figure 2) and
//! surged fore and aft. While legs take a gait change on, the height and
//! pitch stay within [`crate::poda::transition`]'s bounds. On ground that is
//! not flat the ground under the legs is added to the height and pitch
//! ([`crate::poda::terrain_feet`], the lab's).
//!
//! Reads the gait, the path, the legs' clock; writes the track, the legs'
//! cycles (brought to this frame: each leg's vertical contribution), the
//! root, the pitch and the surge.

use gaitlab_core::RootTransform;
use gaitlab_core::portable::Portable;
use glam::{DMat3, DVec3};

use crate::poda::model::{GRAVITY_MPS2, PodaModel};
use crate::poda::spline::eval_open;
use crate::poda::state::PodaState;
use crate::poda::surge::{surge_coefficient, surge_superposition_m};
use crate::poda::terrain_feet;

/// The body from `t_prev` to `t`: the track planned anew beyond the
/// footholds already planned when `replan` (a speed, period or duty-factor
/// edit, [`crate::poda::edits`]), brought to `t` with the legs' cycles, and
/// the root placed ([`place`]).
pub fn advance(model: &PodaModel, state: &mut PodaState, t_prev: f64, t: f64, replan: bool) {
    if replan {
        let keep = state
            .clock
            .planned_ahead_s(t_prev, &state.gait, model.legs.len());
        state.track.replan(t_prev, keep, &model.path, &state.gait);
    }
    state.track.advance_to(t, &model.path, &state.gait);
    state.clock.advance_to(t, &state.gait);
    place(model, state, t);
}

/// The root's height and the body's pitch slope (dy/dz, body frame) at
/// `t_s`: eq. 12–13's superposition, centred, and the least-squares line
/// of the model's pitch weights through the legs' sections, taken at the root.
fn height_and_slope(model: &PodaModel, state: &mut PodaState, t_s: f64) -> (f64, f64) {
    let centre = state
        .centre
        .value_m(&state.clock, &state.gait, t_s, GRAVITY_MPS2);
    let gain = model.params.vertical_gain;
    let gait = &state.gait;
    let weights = &model.pitch_weights;
    let by_cycles = state.clock.by_cycles();
    let (sum, weighted) = if by_cycles {
        let g_n = gait.gravity_share_mps2(GRAVITY_MPS2);
        state
            .clock
            .cycles()
            .vertical_sums_m(t_s, gait, g_n, weights)
    } else {
        (
            gait.vertical_superposition_m(t_s, GRAVITY_MPS2),
            gait.vertical_weighted_m(t_s, GRAVITY_MPS2, weights),
        )
    };
    // The weights are 0 without `body_pitch`. While legs take a change
    // on, the pitch stays within the two steady gaits' (as the height
    // stays above their lowest point, `transition_low_m`).
    let slope = if by_cycles {
        state.bounds.refresh(gait, t_s, GRAVITY_MPS2, weights);
        gain * state.bounds.pitch_slope(weighted)
    } else {
        gain * weighted
    };
    let height = model.stand_height_m + gain * (sum - centre) - slope * model.legs_mean_z_m;
    (height, slope)
}

/// The ground under the legs at `t` on ground that is not flat (`None` on
/// the floor): each leg's ground point — its planted foot in support,
/// blended in the world from its lift-off point to its foothold along the
/// transfer — in
/// the body's ground frame, as the height at the root and the slope of the
/// line through them ([`terrain_feet::ground_under`]). It moves only as the
/// legs do, so the body rises a step as its feet climb it.
fn ground_under_legs(model: &PodaModel, state: &PodaState, t: f64) -> Option<(f64, f64)> {
    if model.terrain.is_flat() {
        return None;
    }
    let ground = state.track.ground_pose(t);
    let points = state.runs.iter().map(move |run| {
        if run.support {
            (ground.to_body(run.planted).z, run.planted.y)
        } else {
            // Between its lift-off point and its foothold in the world, so
            // on a plane the point stays on it.
            let along = eval_open(&model.keys, run.progress).x;
            let point = run.planted.lerp(run.foothold_world, along);
            (ground.to_body(point).z, point.y)
        }
    });
    Some(terrain_feet::ground_under(points))
}

/// Places the root at `t`: the planned ground pose, raised, pitched and
/// surged; while legs take a change on, within the transition's height
/// bounds (the planted feet's reach is the IK stage's).
pub fn place(model: &PodaModel, state: &mut PodaState, t: f64) {
    let ground = state.track.ground_pose(t);
    let (height, slope) = height_and_slope(model, state, t);
    let under = ground_under_legs(model, state, t);
    let slope = under.map_or(slope, |(_, ground_slope)| slope + ground_slope);
    // Nose up (the front higher, slope > 0) turns +z toward +y: about −x.
    state.pitch_rad = slope.patan2(1.0);
    state.ground_pitch_rad = under.map_or(0.0, |(_, ground_slope)| ground_slope.patan2(1.0));
    state.ground_root_m = model.stand_height_m + under.map_or(0.0, |(ground_m, _)| ground_m);
    let gait = &state.gait;
    let by_cycles = state.clock.by_cycles();
    state.surge_m = if !model.params.fore_aft_surge {
        0.0
    } else if by_cycles {
        let g_n = gait.gravity_share_mps2(GRAVITY_MPS2);
        let c = surge_coefficient(gait, g_n, model.stand_height_m);
        state.clock.cycles().surge_m(t, gait, c)
    } else {
        surge_superposition_m(gait, t, GRAVITY_MPS2, model.stand_height_m)
    };
    let surge = ground.to_world(DVec3::new(0.0, 0.0, state.surge_m));
    let rotation = ground.rotation() * DMat3::from_rotation_x(-state.pitch_rad);
    let height = if by_cycles {
        height
            .max(model.stand_height_m + state.bounds.low_m())
            .min(model.stand_height_m + state.bounds.high_m())
    } else {
        height
    };
    // The ground under the legs, at the root.
    let height = under.map_or(height, |(ground_m, _)| height + ground_m);
    state.pose.root = RootTransform {
        position: DVec3::new(surge.x, height, surge.z),
        rotation,
    };
}
