//! Skeleton rules (DESIGN.md input limits): joint, limb and effector counts
//! within the limits, and every listed joint and every limb's
//! Denavit–Hartenberg row well formed — axis, offsets, frame rotations, rest
//! and center inside the limits, gain and size.

use std::f64::consts::TAU;

use crate::preset::limits::{MAX_EFFECTORS, MAX_JOINTS, MAX_LIMBS};
use crate::preset::{DhJointSpec, PresetError, SkeletonSpec};

use super::values::{
    check_gain, check_name, check_rotation_vector, check_value, check_variable_range, check_vector,
    normalized,
};

/// Total joints (listed plus limb rows) and effectors (listed plus limb effectors).
pub(super) fn totals(skeleton: &SkeletonSpec) -> (usize, usize) {
    let limb_joints: usize = skeleton
        .limbs
        .iter()
        .fold(0, |sum, limb| sum.saturating_add(limb.joints.len()));
    let limb_effectors = skeleton
        .limbs
        .iter()
        .filter(|l| l.effector.is_some())
        .count();
    (
        skeleton.joints.len().saturating_add(limb_joints),
        skeleton.effectors.len().saturating_add(limb_effectors),
    )
}

pub(super) fn check_counts(skeleton: &SkeletonSpec) -> Result<(), PresetError> {
    let (joints, effectors) = totals(skeleton);
    let joints_path = if skeleton.joints.len() > MAX_JOINTS || skeleton.limbs.is_empty() {
        "skeleton.joints"
    } else {
        "skeleton.limbs"
    };
    if joints == 0 {
        return Err(PresetError::new(
            "skeleton.joints",
            "a skeleton needs at least one joint",
        ));
    }
    if joints > MAX_JOINTS {
        return Err(PresetError::new(
            joints_path,
            format!("{joints} joints is more than the limit of {MAX_JOINTS}"),
        ));
    }
    if skeleton.limbs.len() > MAX_LIMBS {
        return Err(PresetError::new(
            "skeleton.limbs",
            format!(
                "{} limbs is more than the limit of {MAX_LIMBS}",
                skeleton.limbs.len()
            ),
        ));
    }
    if effectors > MAX_EFFECTORS {
        let path = if skeleton.effectors.len() > MAX_EFFECTORS || skeleton.limbs.is_empty() {
            "skeleton.effectors"
        } else {
            "skeleton.limbs"
        };
        return Err(PresetError::new(
            path,
            format!("{effectors} effectors is more than the limit of {MAX_EFFECTORS}"),
        ));
    }
    Ok(())
}

/// Every listed joint (`skeleton.joints`), in file order.
pub(super) fn check_joints(skeleton: &SkeletonSpec) -> Result<(), PresetError> {
    for (i, joint) in skeleton.joints.iter().enumerate() {
        let at = |field: &str| format!("skeleton.joints[{i}].{field}");
        check_name(&at("name"), &joint.name)?;
        let axis = joint.axis;
        if !axis.is_finite() || normalized(axis).is_none() {
            return Err(PresetError::new(at("axis"), "must be a non-zero vector"));
        }
        check_vector(&at("offset"), joint.offset)?;
        check_rotation_vector(&at("frame_rotation"), joint.frame_rotation)?;
        check_value(&at("rest"), joint.rest)?;
        let center = joint.center.unwrap_or(joint.rest);
        check_value(&at("center"), center)?;
        check_variable_range(
            &at(""),
            joint.kind,
            joint.limits,
            ("rest", joint.rest),
            ("center", center),
        )?;
        check_gain(&at("gain"), joint.gain)?;
        if !(joint.size.is_finite() && joint.size > 0.0) {
            return Err(PresetError::new(
                at("size"),
                "must be a positive number of metres",
            ));
        }
    }
    Ok(())
}

/// Every limb (`skeleton.limbs`) and its Denavit–Hartenberg rows, in file order.
pub(super) fn check_limbs(skeleton: &SkeletonSpec) -> Result<(), PresetError> {
    for (l, limb) in skeleton.limbs.iter().enumerate() {
        let at = |field: &str| format!("skeleton.limbs[{l}].{field}");
        check_name(&at("name"), &limb.name)?;
        check_vector(&at("base_offset"), limb.base_offset)?;
        check_rotation_vector(&at("base_rotation"), limb.base_rotation)?;
        if limb.joints.is_empty() {
            return Err(PresetError::new(
                at("joints"),
                "a limb needs at least one joint",
            ));
        }
        for (r, row) in limb.joints.iter().enumerate() {
            check_dh_row(&format!("skeleton.limbs[{l}].joints[{r}]"), row)?;
        }
        if let Some(effector) = &limb.effector {
            check_name(&at("effector"), effector)?;
        }
    }
    Ok(())
}

fn check_dh_row(prefix: &str, row: &DhJointSpec) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    check_name(&at("name"), &row.name)?;
    for (field, value) in [
        ("a", row.a),
        ("alpha", row.alpha),
        ("d", row.d),
        ("theta", row.theta),
    ] {
        check_value(&at(field), value)?;
    }
    if row.alpha.abs() > TAU {
        return Err(PresetError::new(
            at("alpha"),
            "a twist beyond ±2π; angles are in radians",
        ));
    }
    let rest = row.rest();
    let center = row.center.unwrap_or(rest);
    check_value(&at("center"), center)?;
    check_variable_range(
        &at(""),
        row.kind,
        row.limits,
        (row.rest_field(), rest),
        ("center", center),
    )?;
    check_gain(&at("gain"), row.gain)
}
