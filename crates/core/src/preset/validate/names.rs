//! Joint and limb names: where each joint name is declared (a listed joint
//! or a limb's row), the units (joints, limbs) the build order sorts, and
//! duplicate joint and limb names refused with the place of the first.

use std::collections::HashMap;
use std::collections::hash_map::Entry;

use crate::preset::{PresetError, SkeletonSpec};

/// A joint or a limb: the units the topological sort orders.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Unit {
    /// `skeleton.joints[i]`.
    Joint(usize),
    /// `skeleton.limbs[l]` (all its rows, in order).
    Limb(usize),
}

/// Where a joint name is declared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum NamePlace {
    Joint(usize),
    LimbRow(usize, usize),
}

impl NamePlace {
    pub(super) fn unit(self) -> Unit {
        match self {
            NamePlace::Joint(i) => Unit::Joint(i),
            NamePlace::LimbRow(l, _) => Unit::Limb(l),
        }
    }

    fn path(self) -> String {
        match self {
            NamePlace::Joint(i) => format!("skeleton.joints[{i}].name"),
            NamePlace::LimbRow(l, r) => format!("skeleton.limbs[{l}].joints[{r}].name"),
        }
    }
}

/// Every joint name (listed and limb rows) with where it is declared; duplicates are errors.
pub(super) fn joint_names(
    skeleton: &SkeletonSpec,
) -> Result<HashMap<&str, NamePlace>, PresetError> {
    let mut names: HashMap<&str, NamePlace> = HashMap::new();
    let listed = skeleton
        .joints
        .iter()
        .enumerate()
        .map(|(i, j)| (j.name.as_str(), NamePlace::Joint(i)));
    let rows = skeleton.limbs.iter().enumerate().flat_map(|(l, limb)| {
        limb.joints
            .iter()
            .enumerate()
            .map(move |(r, row)| (row.name.as_str(), NamePlace::LimbRow(l, r)))
    });
    for (name, place) in listed.chain(rows) {
        match names.entry(name) {
            Entry::Occupied(first) => {
                return Err(PresetError::new(
                    place.path(),
                    format!(
                        "duplicate joint name {name:?} (first at {})",
                        first.get().path()
                    ),
                ));
            }
            Entry::Vacant(slot) => {
                slot.insert(place);
            }
        }
    }
    let mut limb_names: HashMap<&str, usize> = HashMap::new();
    for (l, limb) in skeleton.limbs.iter().enumerate() {
        if let Some(first) = limb_names.insert(limb.name.as_str(), l) {
            return Err(PresetError::new(
                format!("skeleton.limbs[{l}].name"),
                format!(
                    "duplicate limb name {:?} (first at skeleton.limbs[{first}].name)",
                    limb.name
                ),
            ));
        }
    }
    Ok(names)
}
