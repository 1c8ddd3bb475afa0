//! Thesis roles (`scenario.thesis.roles`): the four effectors the She 2006
//! target script drives as left / right foot and hand, each a distinct
//! existing effector — checked only where the script will run.

use std::collections::HashMap;

use crate::preset::thesis::ThesisParams;
use crate::preset::{PresetError, SkeletonSpec};

use super::skeleton::totals;

/// Effectors a skeleton needs before the four thesis roles are checked.
pub const THESIS_ROLE_COUNT: usize = 4;

/// Roles: the thesis script drives four effectors, so when the skeleton has at
/// least [`THESIS_ROLE_COUNT`] effectors each role must name a distinct existing
/// effector; a skeleton with fewer effectors cannot run the script (it can still
/// track recorded targets) and its roles are not checked. Called for engine `ik`
/// and [`Purpose::Scenario`](super::Purpose::Scenario) only.
pub(super) fn check_thesis_roles(
    skeleton: &SkeletonSpec,
    thesis: &ThesisParams,
) -> Result<(), PresetError> {
    let (_, effector_count) = totals(skeleton);
    if effector_count >= THESIS_ROLE_COUNT {
        let effector_names: Vec<&str> = skeleton
            .effectors
            .iter()
            .map(|e| e.name.as_str())
            .chain(skeleton.limbs.iter().filter_map(|l| l.effector.as_deref()))
            .collect();
        let roles = &thesis.roles;
        let mut used: HashMap<&str, &str> = HashMap::new();
        for (role, name) in [
            ("left_foot", &roles.left_foot),
            ("right_foot", &roles.right_foot),
            ("left_hand", &roles.left_hand),
            ("right_hand", &roles.right_hand),
        ] {
            let path = format!("scenario.thesis.roles.{role}");
            if !effector_names.contains(&name.as_str()) {
                return Err(PresetError::new(
                    path,
                    format!("no effector named {name:?}"),
                ));
            }
            if let Some(other) = used.insert(name.as_str(), role) {
                return Err(PresetError::new(
                    path,
                    format!(
                        "effector {name:?} already plays {other}; each role needs its own effector"
                    ),
                ));
            }
        }
    }
    Ok(())
}
