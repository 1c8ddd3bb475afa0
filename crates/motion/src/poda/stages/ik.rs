//! The IK stage (Girard & Maciejewski 1985, "Controlling Redundant Limbs",
//! eq. 5–6): while legs take a gait change on, the root first stands no
//! higher than every planted foot reaches ([`crate::poda::transition`]);
//! then each leg with key centres takes this frame's centre angles and gains
//! ([`crate::poda::key_centers`]: along the transfer the key positions', in
//! support the joints' own); then every leg iterates by pseudoinverse toward
//! its target, one forward-kinematics pass per iteration for the whole body,
//! the first iteration with null-space centering, the later ones exact.
//! While legs take a change on with the body pitched (Figure 2), a frame
//! whose planted foot the legs cannot hold (a joint at its limit) is solved
//! again with less pitch: the largest fraction of it at which every planted
//! foot holds, by bisection. On ground that is not flat (the lab's,
//! [`crate::poda::terrain_feet`] rule 5) the same holds in every frame, for
//! the gait's height and pitch together: a frame in which a planted foot is
//! not held, or a transferring foot ends below the ground, is solved again
//! with the body's height and pitch eased from the planned ones toward the
//! body standing on the ground under its legs (the stand height above the
//! ground line at the root, the ground line's pitch) — the largest fraction
//! of eq. 12–13's and Figure 2's motion at which every foot holds.
//!
//! Reads the root, the pitch, the targets, the legs and their key centres;
//! writes the pose, the pitch, the effectors, the targets of every effector
//! and the IK report.

use gaitlab_core::RootTransform;
use glam::{DMat3, DVec3};

use crate::poda::foot_orientation::orientation_error_rad;
use crate::poda::key_centers;
use crate::poda::model::PodaModel;
use crate::poda::state::PodaState;
use crate::poda::transition::{PlantedLeg, reach_ceiling_m};

/// Bisection steps over the fraction of the pitch kept when the legs
/// cannot hold every planted foot at the planned pitch (the pitch found to
/// 1/64 of the planned one).
const HOLD_STEPS: usize = 6;
/// A planted foot this near its spot after the frame's IK holds, metres
/// (two frames off by as much slip at most half the 1 mm the sweeps allow).
const HOLD_M: f64 = 2.5e-4;

/// The pose that brings every foot to its target, in at most `iterations`.
pub fn solve(model: &PodaModel, state: &mut PodaState, iterations: usize) {
    let planned = (state.pose.root, state.pitch_rad);
    let pitch_rad = planned.1;
    within_reach(model, state, planned, (pitch_rad, planned.0.position.y));
    key_centres(model, state);
    // On ground that is not flat the gait's height and pitch ease (the
    // lab's, `terrain_feet` rule 5) toward the body standing on the ground
    // under the legs: its height and pitch, which the easing keeps.
    let on_terrain = !model.terrain.is_flat();
    if !on_terrain && (!state.clock.by_cycles() || pitch_rad == 0.0) {
        iterate(model, state, iterations);
        return;
    }
    let ground_rad = state.ground_pitch_rad;
    let planned_m = planned.0.position.y;
    let ground_m = state.ground_root_m;
    let eased = |fraction: f64| {
        if on_terrain {
            (
                ground_rad + fraction * (pitch_rad - ground_rad),
                ground_m + fraction * (planned_m - ground_m),
            )
        } else {
            (fraction * pitch_rad, planned_m)
        }
    };
    state.joints_before.copy_from_slice(&state.pose.joints);
    iterate(model, state, iterations);
    if planted_held(model, state) {
        return;
    }
    let (mut held, mut refused) = (0.0, 1.0);
    let mut last_held = false;
    for _ in 0..HOLD_STEPS {
        let mid = 0.5 * (held + refused);
        retry(model, state, planned, eased(mid), iterations);
        last_held = planted_held(model, state);
        if last_held {
            held = mid;
        } else {
            refused = mid;
        }
    }
    if !last_held {
        retry(model, state, planned, eased(held), iterations);
    }
    if on_terrain {
        state.eased = (state.eased.0 + 1, state.eased.1.min(held));
    }
}

/// The frame solved again from the previous frame's joints with the body
/// pitched and raised `eased` (pitch, root height) instead of the `planned`
/// root's.
fn retry(
    model: &PodaModel,
    state: &mut PodaState,
    planned: (RootTransform, f64),
    eased: (f64, f64),
    iterations: usize,
) {
    state.pose.joints.copy_from_slice(&state.joints_before);
    within_reach(model, state, planned, eased);
    iterate(model, state, iterations);
}

/// Every planted foot within [`HOLD_M`] of its spot after the IK; on
/// ground that is not flat every transferring foot, too, no more than
/// [`HOLD_M`] below the ground (a leg folded to its limits leaves its foot
/// short of a target near the ground, under it).
fn planted_held(model: &PodaModel, state: &PodaState) -> bool {
    let on_terrain = !model.terrain.is_flat();
    model.legs.iter().zip(&state.runs).all(|(leg, run)| {
        if run.support {
            state.report.effector_error_m[leg.effector] <= HOLD_M
        } else if on_terrain {
            let foot = state.effectors[leg.effector];
            model.terrain.height_m(foot.x, foot.z) - foot.y <= HOLD_M
        } else {
            true
        }
    })
}

/// The `planned` root (with the planned pitch) pitched and raised to `at`
/// (pitch, root height) instead, and while legs take a change on no higher
/// than every planted foot reaches at [`crate::poda::transition::REACH`] of
/// its straight leg.
fn within_reach(
    model: &PodaModel,
    state: &mut PodaState,
    planned: (RootTransform, f64),
    at: (f64, f64),
) {
    let (root, planned_pitch_rad) = planned;
    let (pitch_rad, height_m) = at;
    state.pose.root = root;
    state.pose.root.position.y = height_m;
    state.pitch_rad = pitch_rad;
    if pitch_rad != planned_pitch_rad {
        // Nose up turns +z toward +y, about −x (the body stage's rotation).
        state.pose.root.rotation = root.rotation
            * DMat3::from_rotation_x(planned_pitch_rad)
            * DMat3::from_rotation_x(-pitch_rad);
    }
    if !state.clock.by_cycles() {
        return;
    }
    let planted = model
        .legs
        .iter()
        .zip(&state.runs)
        .filter(|(_, run)| run.support)
        .map(|(leg, run)| PlantedLeg {
            hip_body: leg.hip_body,
            length_m: leg.length_m,
            foot: run.planted,
        });
    let root = &mut state.pose.root;
    root.position.y = root
        .position
        .y
        .min(reach_ceiling_m(root.position, root.rotation, planted));
}

/// Each leg with key centres takes this frame's centre angles and gains
/// ([`key_centers::apply`]); legs without are left as they are (their
/// joints' own).
fn key_centres(model: &PodaModel, state: &mut PodaState) {
    for ((leg, ik), run) in model.legs.iter().zip(&mut state.ik).zip(&state.runs) {
        if leg.key_centers.is_empty() {
            continue;
        }
        key_centers::apply(
            &model.skeleton,
            &leg.key_centers,
            ik,
            (!run.support).then_some(run.progress),
            &mut state.center_points,
        );
    }
}

/// Iterates every leg toward its target (one FK per iteration for the
/// whole body), centering first, then exact steps; then the report. A leg
/// that holds its foot's orientation iterates toward its orientation target
/// too (eq. 2's six rows), and iterates until its
/// foot is within the tolerance in position and in turn (the turn that
/// moves a point one straight leg away by the tolerance), its turn left
/// out where its joints refused it; a planted foot of such a leg still off
/// its spot after the iterations is solved again ([`reseed_stuck_feet`]).
fn iterate(model: &PodaModel, state: &mut PodaState, iterations: usize) {
    /// A leg that holds its foot's orientation iterates until its foot is
    /// within this share of the tolerance: its steps' turn leaves a
    /// second-order residual in the foot's position, and a planted foot's
    /// slip is the difference of two frames' residuals.
    const POSITION_SHARE_OF_TOLERANCE: f64 = 0.5;
    let tolerance = model.params.tolerance_m;
    let skeleton = &model.skeleton;
    let mut used = 0;
    for it in 0..iterations {
        used = it + 1;
        state
            .kin
            .update(skeleton, &state.pose.root, &state.pose.joints);
        let worst = model
            .legs
            .iter()
            .zip(&state.runs)
            .zip(&state.ik)
            .map(|((leg, run), ik)| {
                let miss_m = foot_miss_m(state, leg.effector, run.target);
                if leg.holds_orientation && run.holding && !ik.turn_refused() {
                    let turn_rad = orientation_error_rad(
                        run.rotation_target,
                        state.kin.effector_rotation[leg.effector],
                    )
                    .length();
                    (miss_m / POSITION_SHARE_OF_TOLERANCE).max(turn_rad * leg.length_m)
                } else {
                    miss_m
                }
            })
            .fold(0.0, f64::max);
        if it > 0 && worst < tolerance {
            break;
        }
        for ((ik, run), leg) in state.ik.iter_mut().zip(&state.runs).zip(&model.legs) {
            if it == 0 {
                ik.clear_turn_refused();
            }
            let options = if it == 0 {
                &model.centering
            } else {
                &model.exact
            };
            ik.iterate_pose(
                skeleton,
                &state.kin,
                &mut state.pose.joints,
                run.target,
                (leg.holds_orientation && run.holding).then_some(run.rotation_target),
                options,
            );
        }
    }
    reseed_stuck_feet(model, state);
    state
        .kin
        .update(skeleton, &state.pose.root, &state.pose.joints);
    state
        .effectors
        .copy_from_slice(&state.kin.effector_position);
    state.targets.position.copy_from_slice(&state.effectors);
    state.report.effector_error_m.fill(0.0);
    for (leg, run) in model.legs.iter().zip(&state.runs) {
        let e = leg.effector;
        state.targets.position[e] = run.target;
        state.report.effector_error_m[e] = (state.effectors[e] - run.target).length();
    }
    state.report.iterations = used;
    state.report.max_error_m = state
        .report
        .effector_error_m
        .iter()
        .copied()
        .fold(0.0, f64::max);
}

/// How far the effector `effector` is from `target` in the last forward
/// kinematics, metres.
fn foot_miss_m(state: &PodaState, effector: usize, target: DVec3) -> f64 {
    (state.kin.effector_position[effector] - target).length()
}

/// A planted foot of a leg that holds its foot's orientation still off its
/// spot after the frame's iterations (a foot held level until a knee or an
/// elbow reached its limit: the position rows over the joints left are
/// near a singularity there and the solve creeps, or the joints left push
/// against limits of their own): the leg's joints are put back at their
/// rest angles and the leg solved again for its position alone, as a
/// restart settles it. Its foot then stands tilted as the limits force it;
/// the targets stage sees the refused orientation at the next frame and
/// lets it go ([`crate::poda::stages::targets::place`]).
fn reseed_stuck_feet(model: &PodaModel, state: &mut PodaState) {
    /// Iterations of the legs solved again (a restart's).
    const RESEED_ITERATIONS: usize = 60;
    let tolerance = model.params.tolerance_m;
    // Ten times the tolerance: a foot the iterations left this far is stuck.
    let stuck_m = 10.0 * tolerance;
    let skeleton = &model.skeleton;
    // One bit per leg (the legs solved again); legs past 64 are never.
    let mut reseeded: u64 = 0;
    for (i, (leg, run)) in model.legs.iter().zip(&state.runs).enumerate().take(64) {
        if leg.holds_orientation
            && run.support
            && foot_miss_m(state, leg.effector, run.target) > stuck_m
        {
            for &j in &leg.joints {
                state.pose.joints[j] = model.rest.joints[j];
            }
            reseeded |= 1 << i;
        }
    }
    if reseeded == 0 {
        return;
    }
    let is_reseeded = |i: usize| i < 64 && reseeded & (1 << i) != 0;
    for it in 0..RESEED_ITERATIONS {
        state
            .kin
            .update(skeleton, &state.pose.root, &state.pose.joints);
        let worst = model
            .legs
            .iter()
            .zip(&state.runs)
            .enumerate()
            .filter(|(i, _)| is_reseeded(*i))
            .map(|(_, (leg, run))| foot_miss_m(state, leg.effector, run.target))
            .fold(0.0, f64::max);
        if it > 0 && worst < tolerance {
            break;
        }
        let options = if it == 0 {
            &model.centering
        } else {
            &model.exact
        };
        for (i, (ik, run)) in state.ik.iter_mut().zip(&state.runs).enumerate() {
            if is_reseeded(i) {
                ik.iterate(
                    skeleton,
                    &state.kin,
                    &mut state.pose.joints,
                    run.target,
                    options,
                );
            }
        }
    }
}
