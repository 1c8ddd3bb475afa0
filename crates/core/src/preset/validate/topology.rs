//! The build order: joints and limbs sorted parents first (a topological
//! sort that keeps the file's order wherever the parents allow it), with
//! unknown parents and parent cycles reported at the unit listed first.

use std::collections::HashMap;

use crate::preset::{PresetError, SkeletonSpec};

use super::names::{NamePlace, Unit};

/// Orders joints and limbs parents first. Walks each unit's parent chain up to
/// an already placed unit, so a file already in order keeps its order; a unit met
/// twice on one walk closes a cycle.
pub(super) fn topological_order(
    skeleton: &SkeletonSpec,
    names: &HashMap<&str, NamePlace>,
) -> Result<Vec<Unit>, PresetError> {
    let joint_count = skeleton.joints.len();
    let units: Vec<Unit> = (0..joint_count)
        .map(Unit::Joint)
        .chain((0..skeleton.limbs.len()).map(Unit::Limb))
        .collect();
    let slot = |unit: Unit| match unit {
        Unit::Joint(i) => i,
        Unit::Limb(l) => joint_count + l,
    };
    let describe = |unit: Unit| match unit {
        Unit::Joint(i) => skeleton
            .joints
            .get(i)
            .map_or_else(String::new, |j| format!("{:?}", j.name)),
        Unit::Limb(l) => skeleton
            .limbs
            .get(l)
            .map_or_else(String::new, |limb| format!("limb {:?}", limb.name)),
    };
    let parent_path = |unit: Unit| match unit {
        Unit::Joint(i) => format!("skeleton.joints[{i}].parent"),
        Unit::Limb(l) => format!("skeleton.limbs[{l}].parent"),
    };
    // Resolve every parent name first, so an unknown name is reported before any cycle.
    let mut parents: Vec<Option<Unit>> = Vec::with_capacity(units.len());
    for &unit in &units {
        let parent_name = match unit {
            Unit::Joint(i) => skeleton.joints.get(i).and_then(|j| j.parent.as_deref()),
            Unit::Limb(l) => skeleton
                .limbs
                .get(l)
                .and_then(|limb| limb.parent.as_deref()),
        };
        let parent = match parent_name {
            None => None,
            Some(name) => match names.get(name) {
                Some(place) => Some(place.unit()),
                None => {
                    return Err(PresetError::new(
                        parent_path(unit),
                        format!("no joint named {name:?}"),
                    ));
                }
            },
        };
        parents.push(parent);
    }

    const NEW: u8 = 0;
    const ON_WALK: u8 = 1;
    const PLACED: u8 = 2;
    let mut state = vec![NEW; units.len()];
    let mut order = Vec::with_capacity(units.len());
    let mut walk: Vec<Unit> = Vec::new();
    for &start in &units {
        walk.clear();
        let mut cursor = Some(start);
        while let Some(unit) = cursor {
            let s = slot(unit);
            match state.get(s).copied() {
                Some(NEW) => {
                    if let Some(flag) = state.get_mut(s) {
                        *flag = ON_WALK;
                    }
                    walk.push(unit);
                    cursor = parents.get(s).copied().flatten();
                }
                Some(ON_WALK) => {
                    let from = walk.iter().position(|&u| u == unit).unwrap_or(0);
                    let cycle = walk.get(from..).unwrap_or(&[]);
                    // Report at the cycle member listed first in the file.
                    let first = cycle
                        .iter()
                        .copied()
                        .min_by_key(|&u| slot(u))
                        .unwrap_or(unit);
                    let reason = if cycle.len() == 1 {
                        format!("{} is its own parent", describe(unit))
                    } else {
                        let at = cycle.iter().position(|&u| u == first).unwrap_or(0);
                        let mut chain: Vec<String> = cycle
                            .iter()
                            .cycle()
                            .skip(at)
                            .take(cycle.len())
                            .map(|&u| describe(u))
                            .collect();
                        chain.push(describe(first));
                        format!("parents form a cycle: {}", chain.join(" → "))
                    };
                    return Err(PresetError::new(parent_path(first), reason));
                }
                _ => break,
            }
        }
        for &unit in walk.iter().rev() {
            if let Some(flag) = state.get_mut(slot(unit)) {
                *flag = PLACED;
            }
            order.push(unit);
        }
    }
    Ok(order)
}
