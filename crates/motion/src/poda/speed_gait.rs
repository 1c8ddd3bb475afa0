//! The gait a speed edit leads to (Girard & Maciejewski 1985, eq. 7–8; with
//! gait by speed, the named gait and stride the Froude number picks,
//! [`super::gait_by_speed`]), and the check that a path's speeds are ones
//! the gait can take on.

use super::gait::{Derived, GaitError, GaitParams};
use super::gait_by_speed::{froude, gait_index, speed_gaits};
use super::gaits::named_gait;
use super::model::{GRAVITY_MPS2, PodaModel};
use super::path::BodyPath;
use super::state::PodaState;
use crate::DriverError;

/// A speed edit with gait by speed: the gait and its stride follow.
const EDIT_SPEED_GAIT: Derived = Derived::new(
    "speed_mps",
    &["gait", "period_s", "duty_factor", "stroke_m"],
);
/// A speed edit with gait by speed that keeps the gait: its stride follows.
const EDIT_SPEED_STRIDE: Derived = Derived::new("speed_mps", &["period_s", "stroke_m"]);

/// The gait a speed edit to `speed_mps` leads to, and what it derived:
/// with gait by speed the named gait the Froude number picks (its name)
/// and its stride; otherwise this gait with its stroke kept and its
/// period derived (no name: the gait stays).
///
/// # Errors
/// The speed, or a value derived from it, out of range.
pub fn gait_at_speed(
    model: &PodaModel,
    state: &PodaState,
    speed_mps: f64,
) -> Result<(Option<&'static str>, GaitParams, Derived), GaitError> {
    let legs = model.legs.len();
    let gaits = speed_gaits(legs);
    let (Some(gaits), true, true) = (
        gaits,
        model.params.gait_by_speed,
        speed_mps.is_finite() && speed_mps > 0.0,
    ) else {
        let mut next = state.gait.clone();
        let edit = next.set_speed(speed_mps)?;
        return Ok((None, next, edit));
    };
    let fr = froude(speed_mps, model.stand_height_m, GRAVITY_MPS2);
    let name = gaits[gait_index(fr)];
    let (phases, duty) =
        named_gait(name, legs).map_err(|e| GaitError::new("speed_mps", e.reason))?;
    let period = super::gait_by_speed::period_s(
        speed_mps,
        model.stand_height_m,
        GRAVITY_MPS2,
        duty,
        model.max_stroke_m,
    );
    let next = GaitParams::new(period, duty, phases, speed_mps)
        .map_err(|e| GaitError::new("speed_mps", format!("{}: {}", e.path, e.reason)))?;
    let edit = if name == state.gait_name {
        EDIT_SPEED_STRIDE
    } else {
        EDIT_SPEED_GAIT
    };
    Ok((Some(name), next, edit))
}

/// Every speed of `path` (when it carries speeds) is one the gait can
/// take on from its present values (a speed edit's rule; a speed between
/// two control points' lies between their periods).
///
/// # Errors
/// `{field}[i]` for the first speed the gait cannot take, with why.
pub fn check_path_speeds(
    model: &PodaModel,
    state: &PodaState,
    path: &BodyPath,
    field: &str,
) -> Result<(), DriverError> {
    for (i, &v) in path.speeds_mps().unwrap_or_default().iter().enumerate() {
        gait_at_speed(model, state, v).map_err(|e| {
            DriverError::new(
                format!("{field}[{i}]"),
                format!("at {v} m/s the gait cannot keep eq. 7–8: {e}"),
            )
        })?;
    }
    Ok(())
}
