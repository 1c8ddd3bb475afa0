//! Pinned targets as `state().pinned_targets`, the `pinned_targets` command
//! and links carry them (issue 44 items 1 and 5): effector name → where, in
//! the root's frame, metres — read from a figure's held targets, and
//! checked before the lab pins them.

use std::collections::BTreeMap;

use gaitlab_core::Skeleton;
use gaitlab_engine::HeldTargets;
use glam::DVec3;

use super::command::MAX_DRAG_M;

/// The pinned targets of `held` (the figure of `skeleton`), by effector
/// name, each where it is held in the root's frame.
#[must_use]
pub fn pinned(skeleton: &Skeleton, held: &HeldTargets) -> BTreeMap<String, [f64; 3]> {
    skeleton
        .effectors()
        .iter()
        .enumerate()
        .filter(|(e, _)| held.is_pinned(*e))
        .filter_map(|(e, effector)| Some((effector.name.clone(), held.held_at(e)?.to_array())))
        .collect()
}

/// `pins` resolved on `skeleton`: each effector's index and its point in
/// the root's frame.
///
/// # Errors
/// `pinned_targets.NAME: …` for an effector the figure lacks or a
/// coordinate beyond ±[`MAX_DRAG_M`] (or NaN).
pub fn resolve(
    skeleton: &Skeleton,
    pins: &BTreeMap<String, [f64; 3]>,
) -> Result<Vec<(usize, DVec3)>, String> {
    pins.iter()
        .map(|(name, at)| {
            let e = skeleton
                .effector_index(name)
                .ok_or_else(|| format!("pinned_targets.{name}: no effector named {name:?}"))?;
            if let Some(x) = at.iter().find(|x| x.is_nan() || x.abs() > MAX_DRAG_M) {
                return Err(format!(
                    "pinned_targets.{name}: {x} is outside ±{MAX_DRAG_M} m"
                ));
            }
            Ok((e, DVec3::from_array(*at)))
        })
        .collect()
}
