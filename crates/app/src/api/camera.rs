//! The 3-D view's orbit camera in the JS API (DESIGN.md "Browser"): the
//! `state().camera` object and the `camera` command that puts it back, so a
//! link can restore the camera exactly.
//!
//! Angles travel twice: in degrees for people (`yaw_deg`, `pitch_deg`) and in
//! radians (`yaw_rad`, `pitch_rad`) holding the camera's `f32` values exactly,
//! which is what a restore reads when present. Distances and the target are
//! world metres (`distance_m`, `target_m` = `[x, y, z]`, y up).

use serde::{Deserialize, Serialize};

use crate::render::Camera;
use crate::render::camera::{MAX_DISTANCE, MIN_DISTANCE};
use crate::view::ViewOptions;

/// Farthest a camera target may be from the origin, metres (a sanity bound on link input).
pub const MAX_TARGET_M: f64 = 1.0e5;

/// `state().camera` (`perspective` is the view option the camera follows).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct CameraState {
    /// Yaw, degrees.
    pub yaw_deg: f64,
    /// Pitch, degrees.
    pub pitch_deg: f64,
    /// Yaw, radians (the camera's `f32` exactly).
    pub yaw_rad: f64,
    /// Pitch, radians (the camera's `f32` exactly).
    pub pitch_rad: f64,
    /// Distance from the target, metres.
    pub distance_m: f64,
    /// What the camera looks at, `[x, y, z]` metres.
    pub target_m: [f64; 3],
    /// The target's offset from the followed figure, metres.
    pub follow_offset_m: [f64; 3],
    /// Perspective (true) or orthographic projection.
    pub perspective: bool,
}

impl CameraState {
    /// The camera's state.
    #[must_use]
    pub fn of(camera: &Camera, view: &ViewOptions) -> Self {
        Self {
            yaw_deg: f64::from(camera.yaw.to_degrees()),
            pitch_deg: f64::from(camera.pitch.to_degrees()),
            yaw_rad: f64::from(camera.yaw),
            pitch_rad: f64::from(camera.pitch),
            distance_m: f64::from(camera.distance),
            target_m: camera.target.to_array().map(f64::from),
            follow_offset_m: camera.follow_offset.to_array().map(f64::from),
            perspective: view.perspective,
        }
    }
}

/// The `camera` command: any subset of [`CameraState`]'s keys; `yaw_rad`
/// wins over `yaw_deg`, `pitch_rad` over `pitch_deg`.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct CameraCommand {
    /// Yaw, degrees, within ±10⁴.
    pub yaw_deg: Option<f64>,
    /// Pitch, degrees, within ±90.
    pub pitch_deg: Option<f64>,
    /// Yaw, radians, within ±10⁴.
    pub yaw_rad: Option<f64>,
    /// Pitch, radians, within ±π/2.
    pub pitch_rad: Option<f64>,
    /// Distance from the target, metres, within the camera's limits.
    pub distance_m: Option<f64>,
    /// What the camera looks at, `[x, y, z]` metres.
    pub target_m: Option<[f64; 3]>,
    /// The target's offset from the followed figure, metres.
    pub follow_offset_m: Option<[f64; 3]>,
    /// Perspective (true) or orthographic projection.
    pub perspective: Option<bool>,
}

impl CameraCommand {
    /// Reads a camera object from JSON.
    ///
    /// # Errors
    /// `camera.KEY: reason` for an unknown key or a wrong type.
    pub fn from_value(value: &serde_json::Value) -> Result<Self, String> {
        if !value.is_object() {
            return Err("camera: expected an object".to_owned());
        }
        super::error::from_value("camera", value.clone())
    }
}

fn finite(key: &str, x: f64, lo: f64, hi: f64) -> Result<f32, String> {
    if !(x.is_finite() && (lo..=hi).contains(&x)) {
        return Err(format!("camera.{key}: {x} is outside [{lo}, {hi}]"));
    }
    #[expect(
        clippy::cast_possible_truncation,
        reason = "the camera is f32; the range check keeps the value representable"
    )]
    Ok(x as f32)
}

fn point(key: &str, value: [f64; 3]) -> Result<glam::Vec3, String> {
    let mut out = [0.0_f32; 3];
    for (i, item) in value.into_iter().enumerate() {
        out[i] = finite(&format!("{key}[{i}]"), item, -MAX_TARGET_M, MAX_TARGET_M)?;
    }
    Ok(glam::Vec3::from_array(out))
}

/// Applies a camera command. The camera then counts as placed (no automatic
/// framing) and is kept inside its limits.
///
/// # Errors
/// `camera.KEY: reason` for a value out of range; nothing changes then.
pub fn apply_camera(
    camera: &mut Camera,
    view: &mut ViewOptions,
    command: &CameraCommand,
) -> Result<(), String> {
    let mut next = *camera;
    let angle_deg = 1.0e4;
    match (command.yaw_rad, command.yaw_deg) {
        (Some(rad), _) => next.yaw = finite("yaw_rad", rad, -angle_deg, angle_deg)?,
        (None, Some(deg)) => {
            next.yaw = finite("yaw_deg", deg, -angle_deg, angle_deg)?.to_radians();
        }
        (None, None) => {}
    }
    match (command.pitch_rad, command.pitch_deg) {
        (Some(rad), _) => {
            let half = std::f64::consts::FRAC_PI_2;
            next.pitch = finite("pitch_rad", rad, -half, half)?;
        }
        (None, Some(deg)) => next.pitch = finite("pitch_deg", deg, -90.0, 90.0)?.to_radians(),
        (None, None) => {}
    }
    if let Some(distance) = command.distance_m {
        next.distance = finite(
            "distance_m",
            distance,
            f64::from(MIN_DISTANCE),
            f64::from(MAX_DISTANCE),
        )?;
        // A distance asked for (a link's camera) stays: follow mode does not widen it.
        next.zoomed = true;
    }
    if let Some(target) = command.target_m {
        next.target = point("target_m", target)?;
    }
    if let Some(offset) = command.follow_offset_m {
        next.follow_offset = point("follow_offset_m", offset)?;
    }
    let perspective = command.perspective.unwrap_or(view.perspective);
    next.framed = true;
    next.perspective = perspective;
    next.constrain();
    *camera = next;
    view.perspective = perspective;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::{Value, json};

    fn apply(camera: &mut Camera, view: &mut ViewOptions, value: &Value) -> Result<(), String> {
        apply_camera(camera, view, &CameraCommand::from_value(value)?)
    }

    #[test]
    fn a_camera_round_trips_exactly_through_json() {
        let mut camera = Camera {
            yaw: 1.234_567,
            pitch: 0.321,
            distance: 4.56,
            target: glam::Vec3::new(0.1, 0.7, -2.3),
            follow_offset: glam::Vec3::new(0.2, 0.0, 0.05),
            ..Camera::default()
        };
        camera.constrain();
        let view = ViewOptions {
            perspective: false,
            ..ViewOptions::default()
        };
        let camera_json = |c: &Camera, v: &ViewOptions| {
            serde_json::to_value(CameraState::of(c, v)).expect("camera state")
        };
        let text = camera_json(&camera, &view).to_string();
        let mut restored = Camera::default();
        let mut restored_view = ViewOptions::default();
        let value: Value = serde_json::from_str(&text).expect("json");
        apply(&mut restored, &mut restored_view, &value).expect("applies");
        assert_eq!(restored.yaw.to_bits(), camera.yaw.to_bits());
        assert_eq!(restored.pitch.to_bits(), camera.pitch.to_bits());
        assert_eq!(restored.distance.to_bits(), camera.distance.to_bits());
        assert_eq!(restored.target, camera.target);
        assert_eq!(restored.follow_offset, camera.follow_offset);
        assert!(restored.framed && !restored.perspective && !restored_view.perspective);
        assert_eq!(camera_json(&restored, &restored_view).to_string(), text);
    }

    #[test]
    fn bad_camera_fields_are_named_and_change_nothing() {
        let mut camera = Camera::default();
        let mut view = ViewOptions::default();
        for (input, expected) in [
            (json!({"distance_m": 1e9}), "camera.distance_m"),
            (json!({"target_m": [0, 1]}), "camera.target_m"),
            (json!({"target_m": [0, "x", 1]}), "camera.target_m[1]"),
            (json!({"yaw_rad": "a"}), "camera.yaw_rad"),
            (json!({"zoom": 2}), "camera.zoom"),
            (json!([1, 2]), "camera"),
        ] {
            let error = apply(&mut camera, &mut view, &input).expect_err("rejected");
            assert!(error.starts_with(expected), "{error}");
        }
        assert_eq!(camera, Camera::default());
    }
}
