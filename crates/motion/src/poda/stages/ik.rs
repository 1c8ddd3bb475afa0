//! The IK stage (Girard & Maciejewski 1985, "Controlling Redundant Limbs",
//! eq. 5–6): while legs take a gait change on, the root first stands no
//! higher than every planted foot reaches ([`crate::poda::transition`]);
//! then each leg with key centres takes this frame's centre angles and gains
//! ([`crate::poda::key_centers`]: along the transfer the key positions', in
//! support the joints' own); then every leg iterates by pseudoinverse toward
//! its target, one forward-kinematics pass per iteration for the whole body,
//! the first iteration with null-space centering, the later ones exact.
//!
//! Reads the root, the targets, the legs and their key centres; writes the
//! pose, the effectors, the targets of every effector and the IK report.

use crate::poda::key_centers;
use crate::poda::model::PodaModel;
use crate::poda::state::PodaState;
use crate::poda::transition::{PlantedLeg, reach_ceiling_m};

/// The pose that brings every foot to its target, in at most `iterations`.
pub fn solve(model: &PodaModel, state: &mut PodaState, iterations: usize) {
    within_reach(model, state);
    key_centres(model, state);
    iterate(model, state, iterations);
}

/// While legs take a change on, the root no higher than every planted foot
/// reaches at [`crate::poda::transition::REACH`] of its straight leg.
fn within_reach(model: &PodaModel, state: &mut PodaState) {
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
/// whole body), centering first, then exact steps; then the report.
fn iterate(model: &PodaModel, state: &mut PodaState, iterations: usize) {
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
            .map(|(leg, run)| (state.kin.effector_position[leg.effector] - run.target).length())
            .fold(0.0, f64::max);
        if it > 0 && worst < tolerance {
            break;
        }
        let options = if it == 0 {
            &model.centering
        } else {
            &model.exact
        };
        for (ik, run) in state.ik.iter_mut().zip(&state.runs) {
            ik.iterate(
                skeleton,
                &state.kin,
                &mut state.pose.joints,
                run.target,
                options,
            );
        }
    }
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
