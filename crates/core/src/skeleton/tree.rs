//! The joint tree (She 2006 §3.1, §6.1.1.2): joints in parent-before-child
//! order, named end effectors, and the per-effector ancestor chains that let the
//! Jacobian be filled only where an effector depends on a joint (She 2006 §4.3.1).

use std::fmt;

use super::{Effector, Joint, JointKind};

/// Most joints a skeleton may have (DESIGN.md input limits).
pub const MAX_JOINTS: usize = 512;
/// Most end effectors a skeleton may have (DESIGN.md input limits).
pub const MAX_EFFECTORS: usize = 32;

/// Why a skeleton could not be built. `path` names the offending item
/// (`joints[3].axis`, `effectors[1].joint`) so callers can map it to a JSON path.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SkeletonError {
    /// Where the problem is, relative to the skeleton.
    pub path: String,
    /// What is wrong.
    pub reason: String,
}

impl SkeletonError {
    fn new(path: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            reason: reason.into(),
        }
    }
}

impl fmt::Display for SkeletonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.reason)
    }
}

impl std::error::Error for SkeletonError {}

/// An immutable articulated figure: joints (parents first) and end effectors.
#[derive(Clone, Debug, PartialEq)]
pub struct Skeleton {
    joints: Vec<Joint>,
    effectors: Vec<Effector>,
    /// For each effector, the joints that move it (its ancestors and its own joint), root first.
    chains: Vec<Vec<usize>>,
    /// For each joint, its children.
    children: Vec<Vec<usize>>,
}

impl Skeleton {
    /// Builds a skeleton, checking every joint and effector.
    ///
    /// # Errors
    /// A [`SkeletonError`] naming the first invalid item: too many joints or
    /// effectors, a parent that does not come before its child, duplicate names,
    /// a zero or non-finite axis, a non-finite offset, unordered limits, a rest or
    /// center value outside the limits, a gain outside [0, 1], or an effector on a
    /// missing joint.
    pub fn new(joints: Vec<Joint>, effectors: Vec<Effector>) -> Result<Self, SkeletonError> {
        if joints.is_empty() {
            return Err(SkeletonError::new("joints", "a skeleton needs at least one joint"));
        }
        if joints.len() > MAX_JOINTS {
            return Err(SkeletonError::new(
                "joints",
                format!("{} joints is more than the limit of {MAX_JOINTS}", joints.len()),
            ));
        }
        if effectors.len() > MAX_EFFECTORS {
            return Err(SkeletonError::new(
                "effectors",
                format!("{} effectors is more than the limit of {MAX_EFFECTORS}", effectors.len()),
            ));
        }
        let mut names = std::collections::HashSet::new();
        for (i, joint) in joints.iter().enumerate() {
            check_joint(i, joint)?;
            if !names.insert(joint.name.as_str()) {
                return Err(SkeletonError::new(
                    format!("joints[{i}].name"),
                    format!("duplicate joint name {:?}", joint.name),
                ));
            }
        }
        let mut effector_names = std::collections::HashSet::new();
        for (e, effector) in effectors.iter().enumerate() {
            if effector.joint >= joints.len() {
                return Err(SkeletonError::new(
                    format!("effectors[{e}].joint"),
                    format!("joint index {} does not exist", effector.joint),
                ));
            }
            if !effector.offset.is_finite() {
                return Err(SkeletonError::new(
                    format!("effectors[{e}].offset"),
                    "must be finite",
                ));
            }
            if effector.name.is_empty() {
                return Err(SkeletonError::new(format!("effectors[{e}].name"), "must not be empty"));
            }
            if !effector_names.insert(effector.name.as_str()) {
                return Err(SkeletonError::new(
                    format!("effectors[{e}].name"),
                    format!("duplicate effector name {:?}", effector.name),
                ));
            }
        }
        let mut children = vec![Vec::new(); joints.len()];
        for (i, joint) in joints.iter().enumerate() {
            if let Some(p) = joint.parent {
                children[p].push(i);
            }
        }
        let chains = effectors
            .iter()
            .map(|effector| {
                let mut chain = Vec::new();
                let mut cursor = Some(effector.joint);
                while let Some(j) = cursor {
                    chain.push(j);
                    cursor = joints[j].parent;
                }
                chain.reverse();
                chain
            })
            .collect();
        Ok(Self {
            joints,
            effectors,
            chains,
            children,
        })
    }

    /// The joints, parents before children.
    #[must_use]
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The end effectors.
    #[must_use]
    pub fn effectors(&self) -> &[Effector] {
        &self.effectors
    }

    /// Number of joints (degrees of freedom), `n`.
    #[must_use]
    pub fn joint_count(&self) -> usize {
        self.joints.len()
    }

    /// Number of end effectors, `k`.
    #[must_use]
    pub fn effector_count(&self) -> usize {
        self.effectors.len()
    }

    /// Joints that move effector `e` (its joint and every ancestor), root first.
    #[must_use]
    pub fn chain(&self, e: usize) -> &[usize] {
        &self.chains[e]
    }

    /// Children of joint `j`.
    #[must_use]
    pub fn children(&self, j: usize) -> &[usize] {
        &self.children[j]
    }

    /// Index of the joint called `name`.
    #[must_use]
    pub fn joint_index(&self, name: &str) -> Option<usize> {
        self.joints.iter().position(|j| j.name == name)
    }

    /// Index of the effector called `name`.
    #[must_use]
    pub fn effector_index(&self, name: &str) -> Option<usize> {
        self.effectors.iter().position(|e| e.name == name)
    }

    /// Rest values of every joint, the configuration a reset returns to.
    #[must_use]
    pub fn rest_values(&self) -> Vec<f64> {
        self.joints.iter().map(|j| j.rest).collect()
    }

    /// Jacobian rows: 3 per effector, plus 3 for each effector with orientation.
    #[must_use]
    pub fn task_rows(&self) -> usize {
        self.effectors
            .iter()
            .map(|e| if e.orientation { 6 } else { 3 })
            .sum()
    }
}

fn check_joint(i: usize, joint: &Joint) -> Result<(), SkeletonError> {
    let at = |field: &str| format!("joints[{i}].{field}");
    if joint.name.is_empty() {
        return Err(SkeletonError::new(at("name"), "must not be empty"));
    }
    if let Some(p) = joint.parent
        && p >= i
    {
        return Err(SkeletonError::new(
            at("parent"),
            format!("parent index {p} must come before joint {i}"),
        ));
    }
    if !joint.axis.is_finite() || joint.axis.length_squared() < 1e-24 {
        return Err(SkeletonError::new(at("axis"), "must be a non-zero vector"));
    }
    if (joint.axis.length() - 1.0).abs() > 1e-9 {
        return Err(SkeletonError::new(at("axis"), "must be a unit vector"));
    }
    if !joint.offset.is_finite() {
        return Err(SkeletonError::new(at("offset"), "must be finite"));
    }
    let frame = joint.frame;
    let orthonormal = (frame.transpose() * frame - glam::DMat3::IDENTITY)
        .to_cols_array()
        .iter()
        .all(|v| v.abs() < 1e-9)
        && (frame.determinant() - 1.0).abs() < 1e-9;
    if !orthonormal {
        return Err(SkeletonError::new(at("frame"), "must be a rotation matrix"));
    }
    for (field, value) in [("rest", joint.rest), ("center", joint.center), ("gain", joint.gain), ("size", joint.size)] {
        if !value.is_finite() {
            return Err(SkeletonError::new(at(field), "must be finite"));
        }
    }
    if !(0.0..=1.0).contains(&joint.gain) {
        return Err(SkeletonError::new(at("gain"), "must be between 0 and 1"));
    }
    if joint.size < 0.0 {
        return Err(SkeletonError::new(at("size"), "must not be negative"));
    }
    if let Some((lo, hi)) = joint.limits {
        if !lo.is_finite() || !hi.is_finite() {
            return Err(SkeletonError::new(at("limits"), "must be finite"));
        }
        if lo > hi {
            return Err(SkeletonError::new(at("limits"), "minimum must not exceed maximum"));
        }
        if joint.kind == JointKind::Revolute && hi - lo > 4.0 * std::f64::consts::PI {
            return Err(SkeletonError::new(at("limits"), "a revolute range wider than two turns is not a limit"));
        }
        for (field, value) in [("rest", joint.rest), ("center", joint.center)] {
            if value < lo || value > hi {
                return Err(SkeletonError::new(at(field), format!("{value} is outside the limits [{lo}, {hi}]")));
            }
        }
    }
    Ok(())
}
