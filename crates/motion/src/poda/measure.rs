//! What the driver measures after each frame (the lab's, not the paper's):
//! the gait metrics of the feet and body ([`super::gait_metrics`]: their
//! slip and, against eq. 2's orientation, their turn in support), the
//! static stability of the support feet under the body's centre, where
//! PODA's body dynamics put the mass ([`super::stability`]), and the body's
//! distance from its path.

use glam::DVec2;

use super::gait_metrics::GaitMetrics;
use super::model::PodaModel;
use super::state::PodaState;

/// Records the frame from `t_prev` to `t`; `first` starts the figures anew
/// (a restart).
pub fn record(model: &PodaModel, state: &mut PodaState, t_prev: f64, t: f64, first: bool) {
    let legs = &model.legs;
    let runs = &state.runs;
    let effectors = &state.effectors;
    // Heights above the ground under each foot (on the floor, the foot's own).
    let terrain = &model.terrain;
    let above_ground =
        |p: glam::DVec3| glam::DVec3::new(p.x, p.y - terrain.height_m(p.x, p.z), p.z);
    let feet = legs
        .iter()
        .zip(runs)
        .map(|(leg, run)| (above_ground(effectors[leg.effector]), run.support));
    if first {
        state.metrics = GaitMetrics::new(legs.iter().map(|l| l.name.as_str()))
            .holding_orientation(legs.iter().map(|l| l.holds_orientation));
        state.stability.clear();
    }
    state
        .metrics
        .record(t_prev, t, feet, state.pose.root.position, state.pitch_rad);
    let rotations = &state.kin.effector_rotation;
    state.metrics.record_turns(
        legs.iter()
            .zip(runs)
            .map(|(leg, run)| (rotations[leg.effector], run.support)),
    );
    state.metrics.record_surge(state.surge_m);
    // The support feet's polygon against the body's centre, where PODA's
    // body dynamics put the mass.
    let down = legs
        .iter()
        .zip(runs)
        .filter(|(_, run)| run.support)
        .map(|(leg, _)| effectors[leg.effector])
        .map(|p| DVec2::new(p.x, p.z));
    let root = state.pose.root.position;
    state.stability.record(
        t_prev,
        t,
        down,
        DVec2::new(root.x, root.z),
        state.gait.period_s(),
    );
}

/// This frame's distance of the body's ground position (the root, with
/// its surge) from its path, metres.
#[must_use]
pub fn path_error_m(model: &PodaModel, state: &PodaState) -> f64 {
    let root = state.pose.root.position;
    let position = DVec2::new(root.x, root.z);
    let closest = model.path.sample(model.path.closest_distance(position));
    (closest.position - position).length()
}
