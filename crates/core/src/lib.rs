//! gaitlab-core: the numeric heart of gaitlab.
//!
//! Skeletons of 1-DOF joints (She 2006 §3.1; Denavit–Hartenberg limbs after
//! Girard & Maciejewski 1985, "PODA"), forward kinematics, the geometric
//! Jacobian (She 2006 §4.3.1, PODA eq. 3), the Jacobian IK solvers of She 2006
//! §4.4 with PODA's null-space term (eq. 6), preset parsing and validation,
//! and BVH / CSV writers.
//!
//! # Conventions
//! - SI units: metres, seconds, radians. Degrees appear only in fields named `_deg`.
//! - World frame: y up, x right (the figure's left), z forward.
//! - Rotations are `glam::DMat3` (column vectors, right-handed).
//! - Pure: no I/O, no clocks, no web or GPU crates.

pub mod driver;
pub mod export;
pub mod fk;
pub mod ik;
pub mod jacobian;
pub mod params;
pub mod portable;
pub mod pose;
pub mod preset;
pub mod skeleton;
pub mod terrain;
pub mod trig;

pub use fk::Kinematics;
pub use pose::{Pose, RootTransform};
pub use preset::{Creature, Preset, PresetError, Scenario};
pub use skeleton::{Effector, Joint, JointKind, Skeleton, SkeletonError, TaskBlock};
