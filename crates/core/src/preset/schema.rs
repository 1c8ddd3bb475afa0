//! The preset file format (`gaitlab-preset/2`, reading `/1` too) as serde types: one Rust type per
//! JSON object, every object `deny_unknown_fields`, SI units throughout
//! (metres, radians; degrees only in fields named `_deg`, of which there are none).
//!
//! The skeleton is She 2006 §3.1's tree of 1-DOF joints, written either joint by
//! joint (`skeleton.joints`, any order, parents named) or as PODA
//! Denavit–Hartenberg chains (`skeleton.limbs`). The types only mirror the
//! JSON; [`Preset::validate`](super::Preset::validate) checks values and
//! [`Preset::build`](super::Preset::build) turns them into a [`Skeleton`](crate::Skeleton).
//!
//! Later engines add their own sections next to these (PODA gait tables under
//! `scenario`, physics masses and springs on joints or in a `physics` section);
//! nothing here is a placeholder for them.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::Scenario;
use crate::JointKind;

/// The `format` tag this version of gaitlab writes.
pub const FORMAT: &str = "gaitlab-preset/2";

/// The format tag. Both versions are read; a key a version did not have takes,
/// when it is left out, the behaviour files of that version ran with
/// (`preset/versions.rs`, DESIGN.md "Versions").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub enum Format {
    /// `"gaitlab-preset/1"`: files made before 2026-12-05. Left out, the keys
    /// new in version 2 keep what such files ran with: She 2006's step clamp
    /// on transpose and DLS as well as pinv, and Buss's transpose α.
    #[serde(rename = "gaitlab-preset/1")]
    V1,
    /// `"gaitlab-preset/2"`: a key left out takes the paper's behaviour (She
    /// 2006 §4.4.1's α, §4.4.2's clamp on pinv only).
    #[default]
    #[serde(rename = "gaitlab-preset/2")]
    V2,
}

impl Format {
    /// The tag as written in files.
    #[must_use]
    pub fn tag(self) -> &'static str {
        match self {
            Format::V1 => "gaitlab-preset/1",
            Format::V2 => "gaitlab-preset/2",
        }
    }
}

/// A whole preset file: a creature and its default scenario.
///
/// ```json
/// {"format": "gaitlab-preset/2", "name": "human", "description": "…",
///  "skeleton": {"root": {"position": [0, 0.98, 0]}, "joints": […], "effectors": […]},
///  "scenario": {"engine": "ik", "mode": "walk", "method": "sdls"}}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Preset {
    /// The JSON Schema an editor checks the file against (`"$schema"`, e.g. the
    /// URL or path of `docs/schema/preset.schema.json`); accepted and otherwise
    /// ignored. Kept when the preset is written back. Default none.
    #[serde(rename = "$schema", default, skip_serializing_if = "Option::is_none")]
    pub schema: Option<String>,
    /// `gaitlab-preset/2` (written now) or `gaitlab-preset/1` (read as it ran).
    pub format: Format,
    /// Short name (no whitespace, at most 64 characters), e.g. `human`; used in URLs and the CLI.
    pub name: String,
    /// One or two sentences for people. Default empty.
    #[serde(default)]
    pub description: String,
    /// The creature's joints, limbs and effectors.
    pub skeleton: SkeletonSpec,
    /// What runs on the creature by default.
    pub scenario: Scenario,
}

/// `skeleton`: the root, the joint tree and the effectors.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct SkeletonSpec {
    /// Where the root sits at reset.
    pub root: RootSpec,
    /// Joints in any order; each names its parent. Default none (a skeleton of limbs only).
    #[serde(default)]
    pub joints: Vec<JointSpec>,
    /// Denavit–Hartenberg chains (PODA). Default none.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub limbs: Vec<LimbSpec>,
    /// Named points on joints that IK drives (She 2006 §3.2). Limb effectors come after these.
    #[serde(default)]
    pub effectors: Vec<EffectorSpec>,
}

/// `skeleton.root`: She 2006 §3.1's root node near the hip, which moves the whole skeleton.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct RootSpec {
    /// World position of the root at reset, metres (`[x, y, z]`, y up).
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub position: DVec3,
}

/// What a joint's variable moves, as written in JSON (`"revolute"` or `"prismatic"`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum JointType {
    /// Rotation about the axis; values in radians.
    #[default]
    Revolute,
    /// Translation along the axis; values in metres.
    Prismatic,
}

impl From<JointType> for JointKind {
    fn from(kind: JointType) -> Self {
        match kind {
            JointType::Revolute => JointKind::Revolute,
            JointType::Prismatic => JointKind::Prismatic,
        }
    }
}

/// One 1-DOF joint (She 2006 §3.1 node).
///
/// ```json
/// {"name": "left_knee", "parent": "left_hip_abduct", "type": "revolute",
///  "axis": [1, 0, 0], "offset": [0, -0.44, 0], "limits": [0, 2.4],
///  "rest": 0.2, "center": 0.2, "gain": 0.1, "size": 0.06}
/// ```
///
/// The joint's placement is `Trans(offset) · Rot(frame_rotation) · Motion(axis, value)`
/// relative to its parent's moving frame (or the root frame).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct JointSpec {
    /// Unique name (no whitespace, at most 64 characters).
    pub name: String,
    /// Name of the parent joint (a joint or a limb joint); `null` or absent hangs the joint on the root.
    #[serde(default)]
    pub parent: Option<String>,
    /// Revolute (default) or prismatic.
    #[serde(default, rename = "type")]
    pub kind: JointType,
    /// Joint axis in the joint frame; any non-zero length (normalised when built).
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub axis: DVec3,
    /// Joint origin in the parent's moving frame, metres.
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub offset: DVec3,
    /// Fixed rotation of the joint frame as a rotation vector (axis × angle), radians. Default zero.
    #[serde(default, skip_serializing_if = "is_zero")]
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub frame_rotation: DVec3,
    /// `[min, max]` of the joint value (radians or metres). Default unlimited.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<(f64, f64)>,
    /// Value at reset (radians or metres). Default 0.
    #[serde(default)]
    pub rest: f64,
    /// PODA center value θc for the null-space term. Default: `rest`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub center: Option<f64>,
    /// PODA center gain α in [0, 1]. Default 0.
    #[serde(default)]
    pub gain: f64,
    /// Drawing radius of the bone that ends at this joint, metres (She 2006 §3.1 "Size"). Default 0.03.
    #[serde(default = "default_size")]
    pub size: f64,
}

/// A Denavit–Hartenberg chain (PODA "Modeling Articulated Figures"), link transform
/// `RotZ(θ)·TransZ(d)·TransX(a)·RotX(α)`; built with [`DhLimb::append_to`](crate::skeleton::DhLimb::append_to).
///
/// ```json
/// {"name": "front_left", "parent": null, "base_offset": [0.2, 0, 0.3],
///  "base_rotation": [1.5707963267948966, 0, 0],
///  "joints": [{"name": "fl_hip", "a": 0.3, "theta": 0.1, "limits": [-1, 1]},
///             {"name": "fl_knee", "a": 0.3, "gain": 0.2}],
///  "effector": "front_left_foot"}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct LimbSpec {
    /// Unique limb name.
    pub name: String,
    /// Joint the limb hangs from; `null` or absent for the root.
    #[serde(default)]
    pub parent: Option<String>,
    /// Origin of DH frame 0 in the parent's moving frame, metres. Default zero.
    #[serde(default)]
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub base_offset: DVec3,
    /// Orientation of DH frame 0 (its z axis is the first joint axis) as a rotation vector, radians.
    /// Default zero.
    #[serde(default)]
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub base_rotation: DVec3,
    /// DH rows, proximal first; at least one.
    pub joints: Vec<DhJointSpec>,
    /// Name of an effector placed at the origin of the last DH frame; `null` for none.
    #[serde(default)]
    pub effector: Option<String>,
}

/// One row of a DH table. The variable is `theta` (revolute) or `d` (prismatic);
/// its value here is the rest value.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct DhJointSpec {
    /// Unique joint name (shares the namespace of `skeleton.joints`).
    pub name: String,
    /// Revolute (default) or prismatic.
    #[serde(default, rename = "type")]
    pub kind: JointType,
    /// Link length a, metres. Default 0.
    #[serde(default)]
    pub a: f64,
    /// Link twist α, radians. Default 0.
    #[serde(default)]
    pub alpha: f64,
    /// Link offset d, metres. Default 0.
    #[serde(default)]
    pub d: f64,
    /// Joint angle θ, radians. Default 0.
    #[serde(default)]
    pub theta: f64,
    /// `[min, max]` of the joint variable. Default unlimited.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<(f64, f64)>,
    /// PODA center value. Default: the rest value (`theta` or `d`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub center: Option<f64>,
    /// PODA center gain in [0, 1]. Default 0.
    #[serde(default)]
    pub gain: f64,
}

impl DhJointSpec {
    /// The rest value of the joint variable: `theta` for revolute rows, `d` for prismatic ones.
    #[must_use]
    pub fn rest(&self) -> f64 {
        match self.kind {
            JointType::Revolute => self.theta,
            JointType::Prismatic => self.d,
        }
    }

    /// The JSON field that holds the rest value (`theta` or `d`).
    #[must_use]
    pub fn rest_field(&self) -> &'static str {
        match self.kind {
            JointType::Revolute => "theta",
            JointType::Prismatic => "d",
        }
    }
}

/// An end effector (She 2006 §3.2).
///
/// ```json
/// {"name": "left_foot", "joint": "left_ankle", "offset": [0, -0.06, 0.1], "orientation": false}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct EffectorSpec {
    /// Unique effector name.
    pub name: String,
    /// Name of the joint that carries it.
    pub joint: String,
    /// Position in that joint's moving frame, metres. Default zero.
    #[serde(default)]
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub offset: DVec3,
    /// Whether IK also tracks its orientation (3 more Jacobian rows). Default false.
    #[serde(default)]
    pub orientation: bool,
}

fn default_size() -> f64 {
    0.03
}

fn is_zero(v: &DVec3) -> bool {
    *v == DVec3::ZERO
}
