//! Preset validation before anything is built (DESIGN.md input limits): counts,
//! finite numbers, positive sizes, ordered limits, rest and center values inside
//! their limits, gains in [0, 1], unique names, resolvable parents without
//! cycles, effectors on existing joints, sane thesis parameters (She 2006
//! §5.1.1, §5.2.3) and IK options (She 2006 §4.4). Every error names the JSON path.
//!
//! The result is a [`Plan`]: the joints and limbs in a parent-before-child order
//! that keeps the file's order wherever the parents allow it.
//!
//! # Order of the checks
//! The first failing rule is reported, so the order is part of the format:
//! the preset's name, the counts, the root, each listed joint, each limb, the
//! joint and limb names, the parents (build order), the effectors, then the
//! scenario of the preset's engine.
//!
//! # Files
//! - `values`: names, finite numbers, vectors, gains and limits, the field rules all parts share.
//! - `skeleton`: counts, listed joints and limb rows.
//! - `names`: declared joint names, duplicates, and the units the build order sorts.
//! - `topology`: the build order (parents first), unknown parents and cycles.
//! - `effectors`: effector joints, offsets and unique names.
//! - `scenario`: frame rate and the rules of the scenario's engine.
//! - `thesis`, `roles`, `poda`: each engine's parameter rules.
//! - `purpose`: [`Purpose`], which rules a loaded preset needs.

mod effectors;
mod names;
mod poda;
mod purpose;
mod roles;
mod scenario;
mod skeleton;
mod thesis;
mod topology;
mod values;

pub use crate::ik::check_ik_options;
pub(crate) use names::Unit;
pub use purpose::Purpose;
pub use roles::THESIS_ROLE_COUNT;
pub use thesis::{MAX_FREQUENCY_HZ, MAX_WOUNDED_ADD, MAX_WOUNDED_MULTIPLY, check_thesis_values};
pub(crate) use values::normalized;

use crate::preset::{Preset, PresetError};
use effectors::check_effectors;
use names::joint_names;
use scenario::check_scenario;
use skeleton::{check_counts, check_joints, check_limbs};
use topology::topological_order;
use values::{check_name, check_vector};

/// The outcome of validation: a build order.
#[derive(Clone, Debug)]
pub(crate) struct Plan {
    /// Joints and limbs, every parent before its children.
    pub order: Vec<Unit>,
}

/// Checks every rule that applies to `purpose` and returns the build order.
pub(crate) fn check(preset: &Preset, purpose: Purpose) -> Result<Plan, PresetError> {
    check_name("name", &preset.name)?;
    let skeleton = &preset.skeleton;
    check_counts(skeleton)?;
    check_vector("skeleton.root.position", skeleton.root.position)?;
    check_joints(skeleton)?;
    check_limbs(skeleton)?;
    let names = joint_names(skeleton)?;
    let order = topological_order(skeleton, &names)?;
    check_effectors(skeleton, &names)?;
    check_scenario(preset, &names, purpose)?;
    Ok(Plan { order })
}
