//! Thesis parameter ranges (She 2006 §5.1.1, §5.2.3): gait cycles, slowdown,
//! speed, iterations per frame, posture gain, start ramp and wounded weights,
//! and wounded joints that exist and are listed once.

use std::collections::HashMap;

use crate::params::row;
use crate::preset::PresetError;
use crate::preset::listing::{ListingCycle, ListingParams};
use crate::preset::thesis::{CycleShape, ThesisParams};
use crate::preset::thesis_params::THESIS_PARAMS;

use super::names::NamePlace;
use super::values::check_vector;

/// Highest gait-cycle frequency, Hz.
pub const MAX_FREQUENCY_HZ: f64 = 10.0;
/// Largest wounded `multiply` factor.
pub const MAX_WOUNDED_MULTIPLY: f64 = 10.0;
/// Largest magnitude of a wounded `add` term, radians per iteration.
pub const MAX_WOUNDED_ADD: f64 = 0.5;
/// Largest listing coordinate or amplitude, metres.
pub const MAX_LISTING_M: f64 = 10.0;
/// Smallest and largest listing axis period ratio.
pub const LISTING_PERIOD_RATIO: (f64, f64) = (0.1, 10.0);

fn check_cycle(prefix: &str, shape: &CycleShape) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    if !(shape.frequency_hz > 0.0 && shape.frequency_hz <= MAX_FREQUENCY_HZ) {
        return Err(PresetError::new(
            at("frequency_hz"),
            format!("must be in (0, {MAX_FREQUENCY_HZ}] Hz"),
        ));
    }
    for (field, v) in [
        ("front_foot", shape.front_foot),
        ("back_foot", shape.back_foot),
        ("front_hand", shape.front_hand),
        ("back_hand", shape.back_hand),
    ] {
        check_vector(&at(field), v)?;
    }
    if !(shape.root_height_m.is_finite() && shape.root_height_m > 0.0) {
        return Err(PresetError::new(
            at("root_height_m"),
            "must be a positive number of metres",
        ));
    }
    for (field, value) in [
        ("step_height_m", shape.step_height_m),
        ("bounce_m", shape.bounce_m),
    ] {
        if !(value.is_finite() && value >= 0.0) {
            return Err(PresetError::new(
                at(field),
                "must be a finite number of metres ≥ 0",
            ));
        }
    }
    Ok(())
}

fn check_listing_cycle(prefix: &str, cycle: &ListingCycle) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    if !(cycle.frequency_hz > 0.0 && cycle.frequency_hz <= MAX_FREQUENCY_HZ) {
        return Err(PresetError::new(
            at("frequency_hz"),
            format!("must be in (0, {MAX_FREQUENCY_HZ}] Hz"),
        ));
    }
    if !(cycle.root_height_m > 0.0 && cycle.root_height_m <= MAX_LISTING_M) {
        return Err(PresetError::new(
            at("root_height_m"),
            format!("must be in (0, {MAX_LISTING_M}] metres"),
        ));
    }
    for (name, target) in [
        ("left_foot", &cycle.left_foot),
        ("right_foot", &cycle.right_foot),
        ("right_hand", &cycle.right_hand),
        ("left_hand", &cycle.left_hand),
    ] {
        for (field, v) in [("center", target.center), ("amplitude", target.amplitude)] {
            let path = at(&format!("{name}.{field}"));
            check_vector(&path, v)?;
            if v.abs().max_element() > MAX_LISTING_M {
                return Err(PresetError::new(
                    path,
                    format!("each coordinate must be within ±{MAX_LISTING_M} metres"),
                ));
            }
        }
    }
    Ok(())
}

fn check_listing(prefix: &str, listing: &ListingParams) -> Result<(), PresetError> {
    check_listing_cycle(&format!("{prefix}.walk"), &listing.walk)?;
    check_listing_cycle(&format!("{prefix}.run"), &listing.run)?;
    let (lo, hi) = LISTING_PERIOD_RATIO;
    let ratio = listing.axis_period_ratio;
    if !(ratio.is_finite() && ratio.min_element() >= lo && ratio.max_element() <= hi) {
        return Err(PresetError::new(
            format!("{prefix}.axis_period_ratio"),
            format!("each ratio must be between {lo} and {hi}"),
        ));
    }
    Ok(())
}

/// Thesis parameters and wounded joints (engine `ik`); the roles are checked
/// apart, by [`check_thesis_roles`](super::roles::check_thesis_roles), where the script will run.
pub(super) fn check_thesis(
    names: &HashMap<&str, NamePlace>,
    thesis: &ThesisParams,
) -> Result<(), PresetError> {
    check_thesis_values("scenario.thesis", thesis)?;
    let mut wounded_seen: HashMap<&str, usize> = HashMap::new();
    for (i, wounded) in thesis.wounded.iter().enumerate() {
        let at = |field: &str| format!("scenario.thesis.wounded[{i}].{field}");
        if !names.contains_key(wounded.joint.as_str()) {
            return Err(PresetError::new(
                at("joint"),
                format!("no joint named {:?}", wounded.joint),
            ));
        }
        if let Some(first) = wounded_seen.insert(wounded.joint.as_str(), i) {
            return Err(PresetError::new(
                at("joint"),
                format!(
                    "joint {:?} is already listed at scenario.thesis.wounded[{first}]",
                    wounded.joint
                ),
            ));
        }
    }
    Ok(())
}

/// The ranges of every thesis parameter that does not depend on the skeleton
/// (cycle shapes, slowdown, speed, iterations, posture gain, start ramp and the
/// wounded weights), shared by presets and by live edits of a running driver.
/// Paths start with `prefix` (e.g. `scenario.thesis`; empty for none).
///
/// # Errors
/// A [`PresetError`] naming the first value out of range.
pub fn check_thesis_values(prefix: &str, thesis: &ThesisParams) -> Result<(), PresetError> {
    let at = |field: &str| {
        if prefix.is_empty() {
            field.to_owned()
        } else {
            format!("{prefix}.{field}")
        }
    };
    check_cycle(&at("walk"), &thesis.walk)?;
    check_cycle(&at("run"), &thesis.run)?;
    check_listing(&at("listing"), &thesis.listing)?;
    let spec = |field: &str| row(THESIS_PARAMS, &format!("scenario.thesis.{field}"));
    spec("slowdown").check_real(&at("slowdown"), thesis.slowdown)?;
    if let Some(speed) = thesis.speed_mps {
        spec("speed_mps").check_real(&at("speed_mps"), speed)?;
    }
    spec("iterations_per_frame")
        .check_integer(&at("iterations_per_frame"), thesis.iterations_per_frame)?;
    spec("posture_gain").check_real(&at("posture_gain"), thesis.posture_gain)?;
    spec("start_ramp_s").check_real(&at("start_ramp_s"), thesis.start_ramp_s)?;
    for (i, wounded) in thesis.wounded.iter().enumerate() {
        let at = |field: &str| at(&format!("wounded[{i}].{field}"));
        if !(0.0..=MAX_WOUNDED_MULTIPLY).contains(&wounded.multiply) {
            return Err(PresetError::new(
                at("multiply"),
                format!("must be between 0 and {MAX_WOUNDED_MULTIPLY}"),
            ));
        }
        if !(wounded.add.is_finite() && wounded.add.abs() <= MAX_WOUNDED_ADD) {
            return Err(PresetError::new(
                at("add"),
                format!("must be between -{MAX_WOUNDED_ADD} and {MAX_WOUNDED_ADD} radians"),
            ));
        }
    }
    Ok(())
}
