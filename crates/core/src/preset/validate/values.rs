//! Field rules shared by every part of a preset: names (non-empty single
//! tokens), finite numbers and vectors, rotation vectors at most one turn
//! long, gains in [0, 1], ordered limits holding their rest and center values,
//! and the robust unit vector of a joint axis.

use std::f64::consts::TAU;

use glam::DVec3;

use crate::preset::limits::MAX_NAME_CHARS;
use crate::preset::{JointType, PresetError};

/// Names: non-empty, at most [`MAX_NAME_CHARS`] characters, no whitespace or
/// control characters (BVH and the CLI treat names as single tokens).
pub(super) fn check_name(path: &str, name: &str) -> Result<(), PresetError> {
    if name.is_empty() {
        return Err(PresetError::new(path, "must not be empty"));
    }
    if name.chars().count() > MAX_NAME_CHARS {
        return Err(PresetError::new(
            path,
            format!("must be at most {MAX_NAME_CHARS} characters"),
        ));
    }
    if name.chars().any(|c| c.is_whitespace() || c.is_control()) {
        return Err(PresetError::new(
            path,
            format!("{name:?} must not contain spaces or control characters"),
        ));
    }
    Ok(())
}

pub(super) fn check_value(path: &str, value: f64) -> Result<(), PresetError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(PresetError::new(path, "must be a finite number"))
    }
}

pub(super) fn check_vector(path: &str, v: DVec3) -> Result<(), PresetError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(PresetError::new(path, "must be three finite numbers"))
    }
}

/// Rotation vectors (axis × angle) must be finite and at most one turn long:
/// anything longer is almost surely degrees written where radians belong.
pub(super) fn check_rotation_vector(path: &str, v: DVec3) -> Result<(), PresetError> {
    check_vector(path, v)?;
    if v.length() > TAU + 1e-9 {
        return Err(PresetError::new(
            path,
            "a rotation vector longer than 2π (one turn); angles are in radians",
        ));
    }
    Ok(())
}

pub(super) fn check_gain(path: &str, gain: f64) -> Result<(), PresetError> {
    if (0.0..=1.0).contains(&gain) {
        Ok(())
    } else {
        Err(PresetError::new(path, "must be between 0 and 1"))
    }
}

/// Limits finite and ordered, a revolute range at most two turns wide, and the
/// named values (rest, center) inside. `prefix` ends with `.`.
pub(super) fn check_variable_range(
    prefix: &str,
    kind: JointType,
    limits: Option<(f64, f64)>,
    rest: (&str, f64),
    center: (&str, f64),
) -> Result<(), PresetError> {
    let Some((lo, hi)) = limits else {
        return Ok(());
    };
    let path = format!("{prefix}limits");
    if !lo.is_finite() || !hi.is_finite() {
        return Err(PresetError::new(path, "must be two finite numbers"));
    }
    if lo > hi {
        return Err(PresetError::new(
            path,
            format!("minimum {lo} is greater than maximum {hi}"),
        ));
    }
    if kind == JointType::Revolute && hi - lo > 2.0 * TAU {
        return Err(PresetError::new(
            path,
            "a revolute range wider than two turns (4π) is not a limit; angles are in radians",
        ));
    }
    for (field, value) in [rest, center] {
        if value < lo || value > hi {
            return Err(PresetError::new(
                format!("{prefix}{field}"),
                format!("{value} is outside the limits [{lo}, {hi}]"),
            ));
        }
    }
    Ok(())
}

/// The unit vector along `v`, robust to very small and very large components;
/// `None` for a zero or non-finite vector.
pub(crate) fn normalized(v: DVec3) -> Option<DVec3> {
    let scale = v.abs().max_element();
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    (v / scale).try_normalize()
}
