//! The lab's plots: the effector-error (or physics body) series beside the
//! joint-angle (or physics attitude) series, which joints are plotted (resolved
//! from the settings' names) and their legend labels with units.

use gaitlab_core::preset::Creature;
use gaitlab_core::{JointKind, Skeleton};

use crate::history::History;

/// The physics engine's body plot: trunk height (m), first leg's length (m),
/// vertical ground force (body weights) and the state machine's state (0 flight … 4 unloading;
/// the plot names them).
pub const PHYSICS_BODY_SERIES: [&str; 4] = ["height", "leg length", "ground force", "state"];

/// The physics engine's attitude plot, degrees (the plot's axis names the unit).
pub const PHYSICS_ATTITUDE_SERIES: [&str; 2] = ["pitch", "roll"];

/// Most joints plotted at once.
pub const MAX_PLOT_JOINTS: usize = 8;

/// Joints plotted when the settings name none the creature has.
const DEFAULT_PLOT_JOINTS: [&str; 4] =
    ["left_hip_flex", "left_knee", "right_hip_flex", "right_knee"];

/// A joint value as plotted: degrees for revolute joints, millimetres for prismatic ones.
fn display_value(skeleton: &Skeleton, joint: usize, value: f64) -> f64 {
    match skeleton.joints()[joint].kind {
        JointKind::Revolute => value.to_degrees(),
        JointKind::Prismatic => value * 1e3,
    }
}

/// A plotted joint's legend label with its unit.
fn plot_label(skeleton: &Skeleton, joint: usize) -> String {
    let j = &skeleton.joints()[joint];
    match j.kind {
        JointKind::Revolute => format!("{} (°)", j.name),
        JointKind::Prismatic => format!("{} (mm)", j.name),
    }
}

/// The joint plot: its history and the skeleton indices it plots.
#[derive(Default)]
pub struct Plots {
    /// Joint-angle history (the joints in `joints`), or the physics attitude.
    pub(crate) joint_history: History,
    /// Skeleton indices of the plotted joints.
    pub(crate) joints: Vec<usize>,
}

/// Checks plotted-joint names against `creature`.
///
/// # Errors
/// A name the creature lacks, or more than [`MAX_PLOT_JOINTS`].
pub fn check_plot_joints(creature: &Creature, names: &[String]) -> Result<(), String> {
    if names.len() > MAX_PLOT_JOINTS {
        return Err(format!(
            "plot_joints: at most {MAX_PLOT_JOINTS} joints, got {}",
            names.len()
        ));
    }
    for (i, name) in names.iter().enumerate() {
        if creature.skeleton.joint_index(name).is_none() {
            return Err(format!(
                "plot_joints[{i}]: {} has no joint named {name:?}",
                creature.name
            ));
        }
    }
    Ok(())
}

impl Plots {
    /// The plotted joints' indices from `names`; falls back to the hips and
    /// knees, or each PODA leg's hip, or the first joints, when none of the
    /// names exist. Starts an empty joint history.
    pub fn resolve(&mut self, creature: &Creature, names: &[String]) {
        let skeleton = &creature.skeleton;
        let find = |names: Vec<&str>| -> Vec<usize> {
            let mut found: Vec<usize> = names
                .into_iter()
                .filter_map(|n| skeleton.joint_index(n))
                .collect();
            found.dedup();
            found.truncate(MAX_PLOT_JOINTS);
            found
        };
        let mut joints = find(names.iter().map(String::as_str).collect());
        if joints.is_empty() {
            joints = find(DEFAULT_PLOT_JOINTS.to_vec());
        }
        if joints.is_empty()
            && let Some(poda) = &creature.scenario.poda
        {
            // Each leg's hip, up to four legs.
            joints = find(poda.legs.iter().take(4).map(|l| l.hip.as_str()).collect());
        }
        if joints.is_empty() {
            joints = (0..skeleton.joint_count().min(4)).collect();
        }
        let names = joints.iter().map(|&j| plot_label(skeleton, j)).collect();
        self.joints = joints;
        self.joint_history = History::new(names);
    }

    /// Plots the physics attitude instead of joints.
    pub fn show_physics_attitude(&mut self) {
        self.joint_history = History::new(PHYSICS_ATTITUDE_SERIES.map(str::to_owned).to_vec());
    }

    /// Appends the plotted joints' values at time `t` (allocates nothing).
    pub fn record_joints(&mut self, t: f64, skeleton: &Skeleton, joints: &[f64]) {
        self.joint_history.push(
            t,
            self.joints
                .iter()
                .map(|&j| display_value(skeleton, j, joints[j])),
        );
    }

    /// The plotted joints' skeleton indices.
    #[must_use]
    pub fn joints(&self) -> &[usize] {
        &self.joints
    }
}
