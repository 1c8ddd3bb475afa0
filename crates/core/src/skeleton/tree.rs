//! The joint tree (She 2006 §3.1, §6.1.1.2): joints in parent-before-child
//! order, named end effectors, and the per-effector ancestor chains that let the
//! Jacobian be filled only where an effector depends on a joint (She 2006 §4.3.1).

use std::fmt;

use super::{Effector, Joint, JointKind, Limb};

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

/// One independent block of the Jacobian: the task rows of a group of
/// effectors and the joints that move them. Rows of different blocks share no
/// nonzero column.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TaskBlock {
    /// Task-row indices, ascending.
    pub rows: Vec<usize>,
    /// Joint (column) indices that move these rows, ascending.
    pub joints: Vec<usize>,
}

impl TaskBlock {
    /// One block holding every row and column of an `rows × cols` Jacobian.
    #[must_use]
    pub fn whole(rows: usize, cols: usize) -> Self {
        Self {
            rows: (0..rows).collect(),
            joints: (0..cols).collect(),
        }
    }
}

/// Which fast path forward kinematics may take for a joint's axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AxisKind {
    /// ±x of the joint frame (the sign, ±1).
    X(f64),
    /// ±y of the joint frame.
    Y(f64),
    /// ±z of the joint frame.
    Z(f64),
    /// Any other direction.
    General,
}

/// Facts about a joint's geometry that forward kinematics uses to skip work.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointShape {
    /// The fixed frame rotation is exactly the identity.
    pub identity_frame: bool,
    /// The axis is a coordinate axis of the joint frame.
    pub axis: AxisKind,
}

impl JointShape {
    fn of(joint: &Joint) -> Self {
        let a = joint.axis;
        let axis = if a.y == 0.0 && a.z == 0.0 && a.x.abs() == 1.0 {
            AxisKind::X(a.x)
        } else if a.x == 0.0 && a.z == 0.0 && a.y.abs() == 1.0 {
            AxisKind::Y(a.y)
        } else if a.x == 0.0 && a.y == 0.0 && a.z.abs() == 1.0 {
            AxisKind::Z(a.z)
        } else {
            AxisKind::General
        };
        Self {
            identity_frame: joint.frame == glam::DMat3::IDENTITY,
            axis,
        }
    }
}

/// An immutable articulated figure: joints (parents first) and end effectors.
#[derive(Clone, Debug, PartialEq)]
pub struct Skeleton {
    joints: Vec<Joint>,
    effectors: Vec<Effector>,
    /// For each effector, the joints that move it (its ancestors and its own joint), root first.
    chains: Vec<Vec<usize>>,
    /// For each joint, its children.
    children: Vec<Vec<usize>>,
    /// For each joint, the fast paths forward kinematics may take.
    shapes: Vec<JointShape>,
    /// For each effector, its limb: the part of its chain no other effector shares.
    limbs: Vec<Limb>,
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
            return Err(SkeletonError::new(
                "joints",
                "a skeleton needs at least one joint",
            ));
        }
        if joints.len() > MAX_JOINTS {
            return Err(SkeletonError::new(
                "joints",
                format!(
                    "{} joints is more than the limit of {MAX_JOINTS}",
                    joints.len()
                ),
            ));
        }
        if effectors.len() > MAX_EFFECTORS {
            return Err(SkeletonError::new(
                "effectors",
                format!(
                    "{} effectors is more than the limit of {MAX_EFFECTORS}",
                    effectors.len()
                ),
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
                return Err(SkeletonError::new(
                    format!("effectors[{e}].name"),
                    "must not be empty",
                ));
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
        let chains: Vec<Vec<usize>> = effectors
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
        let shapes = joints.iter().map(JointShape::of).collect();
        let limbs = (0..effectors.len())
            .map(|e| Limb::of(&chains, &joints, &effectors, e))
            .collect();
        Ok(Self {
            joints,
            effectors,
            chains,
            children,
            shapes,
            limbs,
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

    /// Effector `e`'s limb: the joints below its chain's shared root and their
    /// reach (She 2006 §5.3's reachable targets; see [`Limb`]).
    #[must_use]
    pub fn limb(&self, e: usize) -> &Limb {
        &self.limbs[e]
    }

    /// Every effector's limb, in effector order.
    #[must_use]
    pub fn limbs(&self) -> &[Limb] {
        &self.limbs
    }

    /// Fast-path facts about joint `j`'s geometry.
    #[must_use]
    pub fn joint_shape(&self, j: usize) -> JointShape {
        self.shapes[j]
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

    /// Sets joint `j`'s PODA center value θc and gain α (eq. 6: the
    /// null-space term pulls the joint toward θc with weight α). Nothing else
    /// of the skeleton depends on them.
    ///
    /// # Errors
    /// `joints[j]` when there is no such joint; `joints[j].center` when the
    /// center is not finite or lies outside the joint's limits;
    /// `joints[j].gain` unless the gain is in [0, 1]. Nothing changes then.
    pub fn set_center(&mut self, j: usize, center: f64, gain: f64) -> Result<(), SkeletonError> {
        let Some(joint) = self.joints.get_mut(j) else {
            return Err(SkeletonError::new(format!("joints[{j}]"), "no such joint"));
        };
        if !center.is_finite() || joint.clamp(center) != center {
            return Err(SkeletonError::new(
                format!("joints[{j}].center"),
                "must be a finite value within the joint's limits",
            ));
        }
        if !(gain.is_finite() && (0.0..=1.0).contains(&gain)) {
            return Err(SkeletonError::new(
                format!("joints[{j}].gain"),
                "must be between 0 and 1",
            ));
        }
        joint.center = center;
        joint.gain = gain;
        Ok(())
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

    /// The Jacobian's independent blocks: effectors grouped so that no joint
    /// moves effectors of two different groups. J is block diagonal over these
    /// groups (up to row and column permutations), so JJᵀ and its decomposition
    /// split into one small problem per group — e.g. one per leg of a creature
    /// whose legs hang from the root.
    #[must_use]
    pub fn task_blocks(&self) -> Vec<TaskBlock> {
        let k = self.effectors.len();
        // Union-find over effectors; joints link the effectors whose chains contain them.
        let mut parent: Vec<usize> = (0..k).collect();
        fn find(parent: &mut [usize], mut x: usize) -> usize {
            while parent[x] != x {
                parent[x] = parent[parent[x]];
                x = parent[x];
            }
            x
        }
        let mut owner: Vec<Option<usize>> = vec![None; self.joints.len()];
        for (e, chain) in self.chains.iter().enumerate() {
            for &j in chain {
                match owner[j] {
                    Some(other) => {
                        let (a, b) = (find(&mut parent, e), find(&mut parent, other));
                        parent[a] = b;
                    }
                    None => owner[j] = Some(e),
                }
            }
        }
        let mut first_row = Vec::with_capacity(k);
        let mut row = 0;
        for effector in &self.effectors {
            first_row.push(row);
            row += if effector.orientation { 6 } else { 3 };
        }
        let mut groups: Vec<(usize, TaskBlock)> = Vec::new();
        for (e, effector) in self.effectors.iter().enumerate() {
            let root = find(&mut parent, e);
            let rows = first_row[e]..first_row[e] + if effector.orientation { 6 } else { 3 };
            let index = match groups.iter().position(|(r, _)| *r == root) {
                Some(index) => index,
                None => {
                    groups.push((root, TaskBlock::default()));
                    groups.len() - 1
                }
            };
            let block = &mut groups[index].1;
            block.rows.extend(rows);
            block.joints.extend_from_slice(&self.chains[e]);
        }
        groups
            .into_iter()
            .map(|(_, mut block)| {
                block.joints.sort_unstable();
                block.joints.dedup();
                block
            })
            .collect()
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
    for (field, value) in [
        ("rest", joint.rest),
        ("center", joint.center),
        ("gain", joint.gain),
        ("size", joint.size),
    ] {
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
            return Err(SkeletonError::new(
                at("limits"),
                "minimum must not exceed maximum",
            ));
        }
        if joint.kind == JointKind::Revolute && hi - lo > 4.0 * std::f64::consts::PI {
            return Err(SkeletonError::new(
                at("limits"),
                "a revolute range wider than two turns is not a limit",
            ));
        }
        for (field, value) in [("rest", joint.rest), ("center", joint.center)] {
            if value < lo || value > hi {
                return Err(SkeletonError::new(
                    at(field),
                    format!("{value} is outside the limits [{lo}, {hi}]"),
                ));
            }
        }
    }
    Ok(())
}
