//! IK option ranges (She 2006 §4.4: damping λ, step limits γmax and
//! max_step, rank tolerance, null-space gain, limit passes), shared by
//! presets and by settings restored from storage.

use std::f64::consts::PI;

use crate::ik::IkOptions;
use crate::preset::PresetError;

/// IK options: λ in (0, 10], γmax and max_step in (0, π], rank tolerance in
/// (0, 1), null-space gain in [0, 10], 1..=16 limit passes. Shared by presets
/// and by settings restored from storage.
///
/// # Errors
/// A [`PresetError`] naming the first value out of range under `prefix`.
pub fn check_ik_options(prefix: &str, ik: &IkOptions) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    if !(ik.lambda > 0.0 && ik.lambda <= 10.0) {
        return Err(PresetError::new(at("lambda"), "must be in (0, 10] metres"));
    }
    if !(ik.gamma_max > 0.0 && ik.gamma_max <= PI) {
        return Err(PresetError::new(
            at("gamma_max"),
            "must be in (0, π] radians",
        ));
    }
    if !(ik.max_step > 0.0 && ik.max_step <= PI) {
        return Err(PresetError::new(at("max_step"), "must be in (0, π]"));
    }
    if !(ik.rank_tolerance > 0.0 && ik.rank_tolerance < 1.0) {
        return Err(PresetError::new(at("rank_tolerance"), "must be in (0, 1)"));
    }
    if !(0.0..=10.0).contains(&ik.null_space_gain) {
        return Err(PresetError::new(
            at("null_space_gain"),
            "must be in [0, 10]",
        ));
    }
    if !(1..=16).contains(&ik.limit_passes) {
        return Err(PresetError::new(
            at("limit_passes"),
            "must be between 1 and 16",
        ));
    }
    Ok(())
}
