//! Effector rules: each listed effector named, on an existing joint, with a
//! finite offset, and no effector name used twice (listed or a limb's).

use std::collections::HashMap;

use crate::preset::{PresetError, SkeletonSpec};

use super::names::NamePlace;
use super::values::{check_name, check_vector};

/// Listed effectors (`skeleton.effectors`) and limb effectors: names, joints,
/// offsets and uniqueness, in file order.
pub(super) fn check_effectors(
    skeleton: &SkeletonSpec,
    names: &HashMap<&str, NamePlace>,
) -> Result<(), PresetError> {
    let mut seen: HashMap<&str, String> = HashMap::new();
    for (e, effector) in skeleton.effectors.iter().enumerate() {
        let at = |field: &str| format!("skeleton.effectors[{e}].{field}");
        check_name(&at("name"), &effector.name)?;
        if !names.contains_key(effector.joint.as_str()) {
            return Err(PresetError::new(
                at("joint"),
                format!("no joint named {:?}", effector.joint),
            ));
        }
        check_vector(&at("offset"), effector.offset)?;
        if let Some(first) = seen.insert(effector.name.as_str(), at("name")) {
            return Err(PresetError::new(
                at("name"),
                format!(
                    "duplicate effector name {:?} (first at {first})",
                    effector.name
                ),
            ));
        }
    }
    for (l, limb) in skeleton.limbs.iter().enumerate() {
        if let Some(name) = &limb.effector {
            let path = format!("skeleton.limbs[{l}].effector");
            if let Some(first) = seen.insert(name.as_str(), path.clone()) {
                return Err(PresetError::new(
                    path,
                    format!("duplicate effector name {name:?} (first at {first})"),
                ));
            }
        }
    }
    Ok(())
}
