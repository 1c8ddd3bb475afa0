//! The 3-D view's orbit camera as JSON, for `state()` and the `camera` command
//! (DESIGN.md "Browser"), so a link can put the camera back exactly.
//!
//! Angles travel twice: in degrees for people (`yaw_deg`, `pitch_deg`) and in
//! radians (`yaw_rad`, `pitch_rad`) holding the camera's `f32` values exactly,
//! which is what a restore reads when present. Distances and the target are
//! world metres (`distance_m`, `target_m` = `[x, y, z]`, y up).

use serde_json::{Value, json};

use crate::render::Camera;
use crate::render::camera::{MAX_DISTANCE, MIN_DISTANCE};
use crate::view::ViewOptions;

/// Farthest a camera target may be from the origin, metres (a sanity bound on link input).
pub const MAX_TARGET_M: f64 = 1.0e5;

/// The camera as a JSON object (`perspective` is the view option the camera follows).
#[must_use]
pub fn camera_json(camera: &Camera, view: &ViewOptions) -> Value {
    json!({
        "yaw_deg": f64::from(camera.yaw.to_degrees()),
        "pitch_deg": f64::from(camera.pitch.to_degrees()),
        "yaw_rad": f64::from(camera.yaw),
        "pitch_rad": f64::from(camera.pitch),
        "distance_m": f64::from(camera.distance),
        "target_m": camera.target.to_array().map(f64::from),
        "follow_offset_m": camera.follow_offset.to_array().map(f64::from),
        "perspective": view.perspective,
    })
}

fn finite(key: &str, value: &Value, lo: f64, hi: f64) -> Result<f32, String> {
    let x = value
        .as_f64()
        .ok_or_else(|| format!("camera.{key}: expected a number"))?;
    if !(x.is_finite() && (lo..=hi).contains(&x)) {
        return Err(format!("camera.{key}: {x} is outside [{lo}, {hi}]"));
    }
    #[expect(
        clippy::cast_possible_truncation,
        reason = "the camera is f32; the range check keeps the value representable"
    )]
    Ok(x as f32)
}

fn point(key: &str, value: &Value) -> Result<glam::Vec3, String> {
    let items = value
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or_else(|| format!("camera.{key}: expected [x, y, z] in metres"))?;
    let mut out = [0.0_f32; 3];
    for (i, item) in items.iter().enumerate() {
        out[i] = finite(&format!("{key}[{i}]"), item, -MAX_TARGET_M, MAX_TARGET_M)?;
    }
    Ok(glam::Vec3::from_array(out))
}

/// Applies a camera object (any subset of the keys [`camera_json`] writes;
/// `yaw_rad` wins over `yaw_deg`, `pitch_rad` over `pitch_deg`). The camera then
/// counts as placed (no automatic framing) and is kept inside its limits.
///
/// # Errors
/// `camera.KEY: reason` for an unknown key, a wrong type or a value out of
/// range; nothing changes then.
pub fn apply_camera(
    camera: &mut Camera,
    view: &mut ViewOptions,
    value: &Value,
) -> Result<(), String> {
    let object = value.as_object().ok_or("camera: expected an object")?;
    let mut next = *camera;
    let mut perspective = view.perspective;
    let angle_deg = 1.0e4;
    for (key, value) in object {
        match key.as_str() {
            "yaw_deg" if !object.contains_key("yaw_rad") => {
                next.yaw = finite(key, value, -angle_deg, angle_deg)?.to_radians();
            }
            "pitch_deg" if !object.contains_key("pitch_rad") => {
                next.pitch = finite(key, value, -90.0, 90.0)?.to_radians();
            }
            "yaw_deg" | "pitch_deg" => {}
            "yaw_rad" => next.yaw = finite(key, value, -angle_deg, angle_deg)?,
            "pitch_rad" => {
                next.pitch = finite(
                    key,
                    value,
                    -std::f64::consts::FRAC_PI_2,
                    std::f64::consts::FRAC_PI_2,
                )?;
            }
            "distance_m" => {
                next.distance =
                    finite(key, value, f64::from(MIN_DISTANCE), f64::from(MAX_DISTANCE))?;
            }
            "target_m" => next.target = point(key, value)?,
            "follow_offset_m" => next.follow_offset = point(key, value)?,
            "perspective" => {
                perspective = value
                    .as_bool()
                    .ok_or("camera.perspective: expected true or false")?;
            }
            _ => return Err(format!("camera.{key}: unknown camera field")),
        }
    }
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
        let text = camera_json(&camera, &view).to_string();
        let mut restored = Camera::default();
        let mut restored_view = ViewOptions::default();
        let value: Value = serde_json::from_str(&text).expect("json");
        apply_camera(&mut restored, &mut restored_view, &value).expect("applies");
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
            let error = apply_camera(&mut camera, &mut view, &input).expect_err("rejected");
            assert!(error.starts_with(expected), "{error}");
        }
        assert_eq!(camera, Camera::default());
    }
}
