//! PODA leg rules (Girard & Maciejewski 1985): the parameter ranges, and
//! every leg an existing effector whose chain passes through its hip joint,
//! no effector used by two legs, one phase per leg.

use std::collections::HashMap;

use crate::preset::limits::MAX_JOINTS;
use crate::preset::{PodaParams, PresetError, SkeletonSpec};

use super::names::NamePlace;
use super::values::check_name;

/// PODA parameters: values in range, and every leg an effector on a chain
/// that passes through its hip joint.
pub(super) fn check_poda(
    skeleton: &SkeletonSpec,
    names: &HashMap<&str, NamePlace>,
    poda: &PodaParams,
) -> Result<(), PresetError> {
    poda.check_values("scenario.poda")?;
    let limb_legs = skeleton
        .limbs
        .iter()
        .filter(|l| l.effector.is_some())
        .count();
    if poda.legs.is_empty() && limb_legs == 0 {
        return Err(PresetError::new(
            "scenario.poda.legs",
            "name the legs (effector and hip joint): the skeleton has no limbs with effectors",
        ));
    }
    let parents = joint_parents(skeleton);
    let effector_joint = |name: &str| -> Option<&str> {
        skeleton
            .effectors
            .iter()
            .find(|e| e.name == name)
            .map(|e| e.joint.as_str())
            .or_else(|| {
                skeleton.limbs.iter().find_map(|l| {
                    (l.effector.as_deref() == Some(name))
                        .then(|| l.joints.last().map(|row| row.name.as_str()))
                        .flatten()
                })
            })
    };
    for (i, leg) in poda.legs.iter().enumerate() {
        let at = |field: &str| format!("scenario.poda.legs[{i}].{field}");
        if let Some(name) = &leg.name {
            check_name(&at("name"), name)?;
        }
        let Some(mut joint) = effector_joint(&leg.effector) else {
            return Err(PresetError::new(
                at("effector"),
                format!("no effector called {:?}", leg.effector),
            ));
        };
        if !names.contains_key(leg.hip.as_str()) {
            return Err(PresetError::new(
                at("hip"),
                format!("no joint called {:?}", leg.hip),
            ));
        }
        let mut steps = 0;
        while joint != leg.hip {
            steps += 1;
            match parents.get(joint) {
                Some(Some(parent)) if steps <= MAX_JOINTS => joint = parent,
                _ => {
                    return Err(PresetError::new(
                        at("hip"),
                        format!(
                            "joint {:?} is not on the chain of effector {:?}",
                            leg.hip, leg.effector
                        ),
                    ));
                }
            }
        }
        if let Some(first) = poda.legs[..i]
            .iter()
            .position(|l| l.effector == leg.effector)
        {
            return Err(PresetError::new(
                at("effector"),
                format!("effector {:?} is already leg {first}", leg.effector),
            ));
        }
    }
    if let Some(phases) = &poda.phases {
        let legs = if poda.legs.is_empty() {
            limb_legs
        } else {
            poda.legs.len()
        };
        if phases.len() != legs {
            return Err(PresetError::new(
                "scenario.poda.phases",
                format!("needs one phase per leg ({legs}), got {}", phases.len()),
            ));
        }
    }
    Ok(())
}

/// Parent joint name of every joint name (`None` for joints on the root).
pub(super) fn joint_parents(skeleton: &SkeletonSpec) -> HashMap<&str, Option<&str>> {
    let mut parents = HashMap::new();
    for joint in &skeleton.joints {
        parents.insert(joint.name.as_str(), joint.parent.as_deref());
    }
    for limb in &skeleton.limbs {
        let mut parent = limb.parent.as_deref();
        for row in &limb.joints {
            parents.insert(row.name.as_str(), parent);
            parent = Some(row.name.as_str());
        }
    }
    parents
}
