//! The foot-targets stage (Girard & Maciejewski 1985, eq. 10 and "Leg
//! Support and Transfer Trajectories", and eq. 2's foot orientation): a
//! supporting foot stays where it landed (eq. 10); a transferring foot
//! follows the Catmull-Rom spline through the key leg positions — the
//! spline's "along" fraction moves it from its lift-off point to its
//! foothold in the body frame, its "height" sets the world height.
//!
//! A leg that holds its foot's orientation ([`crate::poda::foot_orientation`])
//! keeps the orientation its foot touched down with through the support; in
//! the transfer the foot turns from it (its lift-off orientation) to the one
//! it will touch down with — its rest orientation carried by the body's
//! ground yaw at the touchdown, level and facing the heading — by slerp
//! along the transfer's progress. A leg with key leg positions' centre
//! angles ([`crate::poda::key_centers`]) lets its foot go in the transfer,
//! which the key positions shape, and holds the orientation it lands with.
//!
//! Where the leg's joints refuse a planted foot's orientation (it ends a
//! frame more than [`REFUSED_RAD`] from it: a level foot would need a joint
//! past its limit, as at the bound's crouch), the foot is let go and the
//! leg holds its foot's position alone for one support more, then two,
//! four, at most [`MAX_SUPPORTS_ALONE`] after each refusal in a row, before
//! it holds the orientation again, from the orientation it lands with: a
//! foot held level snaps to the tilt its limits force, and it does so in a
//! few supports only, not in every one. The refusals are forgotten when the
//! legs finish taking a gait change on, and at a restart.
//!
//! Reads each leg's phase, touchdown and footholds, the track, the keys and
//! the feet's orientations after the last frame's IK; writes the planted
//! feet and their orientations, the targets (positions and orientations)
//! and the transfers' progress.

use glam::{DQuat, DVec3};

use crate::poda::foot_orientation::{angle_between_rad, slerp, yaw_rotation};
use crate::poda::model::PodaModel;
use crate::poda::spline::eval_open;
use crate::poda::state::PodaState;
use crate::poda::terrain_feet::{highest_between, transfer_height_m};

/// A held planted foot farther than this from its orientation target after
/// a frame's IK was refused it by its leg's joints, radians (1°).
pub const REFUSED_RAD: f64 = std::f64::consts::PI / 180.0;
/// The most supports a leg holds its foot's position alone after a refusal.
pub const MAX_SUPPORTS_ALONE: u32 = 8;

/// Every leg's target at `t`: a foot that landed this frame is planted at
/// its spline's end, with the orientation it touched down with where the
/// leg holds one.
pub fn place(model: &PodaModel, state: &mut PodaState, t: f64) {
    let shifting = state.clock.is_shifting(t, &state.gait);
    let forget_refusals = state.legs_were_shifting && !shifting;
    state.legs_were_shifting = shifting;
    for i in 0..model.legs.len() {
        let run = state.runs[i];
        let Some(phase) = run.phase else {
            continue;
        };
        if model.legs[i].holds_orientation {
            orient(model, state, i, forget_refusals);
        }
        if let Some(t_td) = run.touchdown_s {
            let landed = transfer_target(model, state, i, t_td, 1.0);
            let ground = model.terrain.height_m(landed.x, landed.z);
            state.runs[i].planted = DVec3::new(landed.x, ground, landed.z);
        }
        let target = if run.support {
            state.runs[i].planted
        } else {
            transfer_target(model, state, i, t, phase.fraction)
        };
        if state.runs[i].holding {
            state.runs[i].rotation_target = if run.support {
                state.runs[i].planted_rotation
            } else {
                transfer_rotation(model, state, i, phase.next_touchdown_s, phase.fraction)
            };
        }
        let run = &mut state.runs[i];
        run.target = target;
        run.progress = phase.fraction;
    }
}

/// Whether leg `i` holds its foot's orientation this frame and, at a
/// touchdown, the orientation it holds: the last frame's IK's verdict on a
/// held planted foot (a refusal lets the foot go, and the leg holds its
/// position alone for one support more, doubling with each refusal in a
/// row, at most [`MAX_SUPPORTS_ALONE`]), the refusals forgotten where
/// `forget_refusals`, and at a touchdown the orientation the foot touched
/// down with — its touchdown orientation after a held transfer, the foot's
/// own after a transfer that held position alone.
fn orient(model: &PodaModel, state: &mut PodaState, i: usize, forget_refusals: bool) {
    let current = DQuat::from_mat3(&state.kin.effector_rotation[model.legs[i].effector]);
    let run = &mut state.runs[i];
    if forget_refusals {
        run.orientation_refusals = 0;
        run.supports_alone = 0;
    }
    let was_planted = (run.support && run.touchdown_s.is_none()) || run.liftoff_s.is_some();
    if run.holding && was_planted {
        if angle_between_rad(run.rotation_target, current) > REFUSED_RAD {
            run.holding = false;
            run.orientation_refusals = run.orientation_refusals.saturating_add(1);
            run.supports_alone =
                (1_u32 << (run.orientation_refusals - 1).min(3)).min(MAX_SUPPORTS_ALONE);
        } else if run.liftoff_s.is_some() {
            // A support held to its lift-off.
            run.orientation_refusals = 0;
        }
    }
    // Key leg positions with centre angles shape the transfer (eq. 6's
    // null space, which a held orientation would take): the foot is let go
    // at lift-off and holds the orientation it lands with.
    if run.liftoff_s.is_some() && !model.legs[i].key_centers.is_empty() {
        run.holding = false;
    }
    let Some(t_td) = run.touchdown_s else {
        return;
    };
    let transfer_held = run.holding;
    if run.supports_alone > 0 {
        run.supports_alone -= 1;
        run.holding = false;
        return;
    }
    run.holding = true;
    state.runs[i].planted_rotation = if transfer_held {
        touchdown_rotation(model, state, i, t_td)
    } else {
        current.normalize()
    };
}

/// The transfer target of leg `i` at time `t` with transfer progress `u`.
#[must_use]
pub fn transfer_target(model: &PodaModel, state: &PodaState, i: usize, t: f64, u: f64) -> DVec3 {
    let run = &state.runs[i];
    let key = eval_open(&model.keys, u);
    let body = run.liftoff_body.lerp(run.foothold_body, key.x);
    let mut world = state.track.ground_pose(t).to_world(body);
    if model.terrain.is_flat() {
        world.y = key.y * model.params.step_height_m;
    } else {
        // The lab's, on ground that is not flat (`terrain_feet`): from the
        // lift-off's height to the foothold's, the apex clearing the ground
        // between them by the step height, and never below the ground
        // still ahead of the foot (so it rises before a riser, not through it).
        let height = transfer_height_m(
            key.x,
            key.y,
            model.params.step_height_m,
            run.planted.y,
            run.foothold_world.y,
            run.highest_m,
        );
        let here = DVec3::new(world.x, model.terrain.height_m(world.x, world.z), world.z);
        world.y = height.max(highest_between(&model.terrain, here, run.foothold_world));
    }
    world
}

/// The orientation the foot of leg `i` touches down with at `t_td`: its
/// rest orientation carried by the body's ground yaw at `t_td` (level,
/// facing the heading); on ground that is not flat, turned onto the
/// ground's normal at its foothold.
#[must_use]
pub fn touchdown_rotation(model: &PodaModel, state: &PodaState, i: usize, t_td: f64) -> DQuat {
    let level =
        yaw_rotation(state.track.ground_pose(t_td).yaw_rad) * model.legs[i].rest_foot_rotation;
    if model.terrain.is_flat() {
        return level.normalize();
    }
    // On ground that is not flat the sole lies on the ground at the
    // foothold: level turned onto its normal (the lab's, `terrain_feet`).
    let at = state.runs[i].foothold_world;
    let onto = DQuat::from_rotation_arc(DVec3::Y, model.terrain.normal(at.x, at.z));
    (onto * level).normalize()
}

/// The orientation target of leg `i`'s transferring foot at transfer
/// progress `u`, touching down at `t_td`: from its lift-off orientation
/// (the one it was planted with) to its touchdown orientation, by slerp.
#[must_use]
pub fn transfer_rotation(
    model: &PodaModel,
    state: &PodaState,
    i: usize,
    t_td: f64,
    u: f64,
) -> DQuat {
    let landing = touchdown_rotation(model, state, i, t_td);
    slerp(state.runs[i].planted_rotation, landing, u)
}

/// The orientation targets at a restart (eq. 9 at time 0, as the restart
/// plants the feet): every leg that holds its foot's orientation holds it
/// (but in a transfer that key positions shape), its refusals forgotten; a
/// supporting foot holds the orientation of its last touchdown, a
/// transferring one is on its way from the orientation of the touchdown
/// before its lift-off to that of its next touchdown. The restart
/// (`crate::poda::start`) calls it after placing the feet's positions.
pub fn place_rotations_at_start(model: &PodaModel, state: &mut PodaState) {
    state.legs_were_shifting = false;
    let support_s = state.gait.support_s();
    for i in 0..model.legs.len() {
        if !model.legs[i].holds_orientation {
            continue;
        }
        let run = &mut state.runs[i];
        run.orientation_refusals = 0;
        run.supports_alone = 0;
        run.holding = true;
        let Some(phase) = state.gait.leg_phase(i, 0.0) else {
            continue;
        };
        if phase.support {
            let planted = touchdown_rotation(model, state, i, phase.last_touchdown_s);
            let run = &mut state.runs[i];
            run.planted_rotation = planted;
            run.rotation_target = planted;
        } else {
            state.runs[i].planted_rotation =
                touchdown_rotation(model, state, i, phase.last_liftoff_s - support_s);
            state.runs[i].rotation_target =
                transfer_rotation(model, state, i, phase.next_touchdown_s, phase.fraction);
            // Key positions shape the transfer (as after a lift-off, `orient`).
            state.runs[i].holding = model.legs[i].key_centers.is_empty();
        }
    }
}
