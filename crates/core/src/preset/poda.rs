//! `scenario.poda`: the parameters of Girard & Maciejewski 1985's kinematic
//! locomotion model (PODA) as they appear in a preset — which effectors are
//! legs, the gait (period P, duty factor, relative phases Rᵢ; eq. 7–9), body
//! speed, step height, the key leg positions of the transfer trajectory
//! (the foot's place, and optionally centre angles and gains for the leg's
//! joints), the body path, and the simple dynamics' body mass and leg forces
//! (eq. 12–15).
//!
//! Only values that need no gait model are checked here (ranges, names,
//! finiteness); the gait engine in `gaitlab-motion` checks the relations
//! between them (eq. 7–8) and the gait name when it is built.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::PresetError;
use super::poda_params::PODA_PARAMS;
use crate::params::row;

/// Most key leg positions in a transfer trajectory.
pub const MAX_TRANSFER_KEYS: usize = 16;
/// Most control points of a body path.
pub const MAX_PATH_POINTS: usize = 64;
/// Most joints one key leg position gives a centre angle and gain.
pub const MAX_KEY_CENTER_JOINTS: usize = 64;
/// Largest magnitude of a key position's centre angle, radians (metres for a
/// prismatic joint); the driver also keeps it within the joint's limits.
pub const MAX_KEY_CENTER: f64 = 100.0;

/// The centre angles and gains (eq. 6's `θcᵢ`, `αᵢ`) one key leg position
/// gives joints of the legs (Girard & Maciejewski 1985, "Leg Support and
/// Transfer Trajectories": "a key position records the position of the foot
/// … and the center angles and gains that are associated with that
/// position"), each `[center, gain]`: the centre in radians (metres for a
/// prismatic joint), within the joint's limits, the gain in [0, 1].
///
/// A key is either
/// - a joint's place in its leg, counted from the leg's first joint (the
///   hip) `"0"`: that joint of **every** leg (`"3"` is the fourth joint of
///   each leg; every leg must have a joint there, and the value must lie
///   within the limits of each joint it applies to); or
/// - a joint's name: that joint alone, over its place's entry (a leg whose
///   joint is named takes the name's value, and the place's value need not
///   fit that joint).
///
/// A key of digits only is read as a place. Joints a key position does not
/// name keep their own (skeleton) centre and gain at that key; an empty
/// object is a key position that gives none.
///
/// ```json
/// {"3": [-1.2, 1.0], "left_hind_knee_x": [1.2, 1.0], "right_hind_knee_x": [1.2, 1.0]}
/// ```
pub type KeyCenters = BTreeMap<String, [f64; 2]>;

/// One leg: the effector that is its foot and the first joint that belongs
/// to the leg (the hip). The leg's joints are the foot's chain from the hip
/// down; joints above the hip (a spine) belong to the body.
///
/// ```json
/// {"name": "left_front", "effector": "left_front_foot", "hip": "left_front_shoulder_x"}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PodaLegSpec {
    /// Leg name for metrics and the UI; default: the effector's name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The foot effector.
    pub effector: String,
    /// The leg's first joint.
    pub hip: String,
}

/// Spline family of a body path (PODA "Horizontal Control": "a cubic spline
/// (Catmull-Rom or B-spline)").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PathKindSpec {
    /// Interpolating: the path passes through every control point.
    #[default]
    CatmullRom,
    /// Approximating uniform cubic B-spline.
    BSpline,
}

/// `scenario.poda.path`: the desired body path on the ground plane, and
/// optionally the desired body speed at each control point ("Horizontal
/// Control": "given the desired body speed along different parts of the
/// curve, PODA may calculate the desired positions and velocities along it
/// using a numerical arclength calculation").
///
/// ```json
/// {"kind": "catmull_rom", "points": [[0, 0], [0, 3], [2, 5]], "closed": false,
///  "speeds_mps": [0.3, 0.6, 0.4]}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PathSpec {
    /// Catmull-Rom (default) or B-spline.
    #[serde(default)]
    pub kind: PathKindSpec,
    /// Control points `[x, z]` on the ground, metres; 2 to 64.
    pub points: Vec<[f64; 2]>,
    /// Whether the path is a loop. Default false.
    #[serde(default)]
    pub closed: bool,
    /// Desired body speed at each control point, m/s, one per point, each in
    /// `scenario.poda.speed_mps`'s range. Between control points the desired
    /// speed is linear in arc length from one point's place on the curve to
    /// the next's (the point itself for Catmull-Rom; for a B-spline the
    /// segment boundary the point weighs most, `(p₋ + 4p + p₊)/6`); on a
    /// loop the last point's speed runs back to the first's. The legs' force
    /// bound (eq. 14) still limits how fast the body takes a change on, and
    /// the gait keeps its stroke with the period derived, as a speed edit
    /// does. Default: absent, every point at `scenario.poda.speed_mps`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speeds_mps: Option<Vec<f64>>,
}

/// A body path's speeds: one per control point (`points` of them), each in
/// `scenario.poda.speed_mps`'s range. `at` is the field's path
/// (`scenario.poda.path.speeds_mps`); errors name it or `{at}[i]`.
///
/// # Errors
/// A [`PresetError`] at `at` when the count differs from `points`
/// (`needs one speed per point (3 points, 2 speeds)`), or at `{at}[i]` for
/// the first speed out of range.
pub fn check_path_speeds(at: &str, points: usize, speeds_mps: &[f64]) -> Result<(), PresetError> {
    if speeds_mps.len() != points {
        return Err(PresetError::new(
            at,
            format!(
                "needs one speed per point ({points} points, {} speeds)",
                speeds_mps.len()
            ),
        ));
    }
    let speed = row(PODA_PARAMS, "scenario.poda.speed_mps");
    for (i, &v) in speeds_mps.iter().enumerate() {
        speed.check_real(&format!("{at}[{i}]"), v)?;
    }
    Ok(())
}

impl PathSpec {
    /// Checks [`PathSpec::speeds_mps`] when present ([`check_path_speeds`]);
    /// `at` is the field's path.
    ///
    /// # Errors
    /// As [`check_path_speeds`].
    pub fn check_speeds(&self, at: &str) -> Result<(), PresetError> {
        match &self.speeds_mps {
            Some(speeds) => check_path_speeds(at, self.points.len(), speeds),
            None => Ok(()),
        }
    }
}

/// `scenario.poda`: every field optional.
///
/// ```json
/// {"gait": "trot", "period_s": 0.6, "speed_mps": 1.0, "step_height_m": 0.08,
///  "legs": [{"effector": "left_front_foot", "hip": "left_front_shoulder_x"}]}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct PodaParams {
    /// The legs, in the named-gait leg order. Default: every limb that has an
    /// effector, in limb order (hip = the limb's first joint).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub legs: Vec<PodaLegSpec>,
    /// Named gait (relative phases and duty factor). Default: the first gait
    /// known for the leg count (walk, tripod, wave).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gait: Option<String>,
    /// Gait cycle period P, seconds. Default 1.
    pub period_s: f64,
    /// Duty factor override; default the named gait's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub duty_factor: Option<f64>,
    /// Relative phase override, one per leg in [0, 1); default the named gait's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub phases: Option<Vec<f64>>,
    /// Desired body speed along the path, m/s. Default 0.5.
    pub speed_mps: f64,
    /// Highest point of the transfer trajectory above the ground, metres. Default 0.06.
    pub step_height_m: f64,
    /// Height of the root above the ground when standing, metres. Default: the
    /// root's rest height.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stand_height_m: Option<f64>,
    /// Key leg positions of the transfer trajectory between lift-off and
    /// touchdown, each `[along, height]`: the fraction of the step travelled
    /// (0 lift-off … 1 foothold) and the height as a fraction of
    /// `step_height_m`. Default `[[0.1, 0.7], [0.5, 1.0], [0.9, 0.5]]`.
    pub transfer_keys: Vec<[f64; 2]>,
    /// Centre angles and gains the key leg positions carry (eq. 6; "Leg
    /// Support and Transfer Trajectories"): one [`KeyCenters`] object per
    /// `transfer_keys` entry, in the same order. While a leg transfers, the
    /// centre and gain of each joint some key names follow the keys on a
    /// Catmull-Rom spline with the foot's own parameter — lift-off, each key,
    /// touchdown, evenly spaced in the transfer's time, the ends at the
    /// joint's own (skeleton) centre and gain — so the joint's centre reaches
    /// a key's value just as the foot passes that key's point; the gain is
    /// kept in [0, 1] where the spline overshoots. At lift-off, touchdown and
    /// through the support every joint pulls toward its own centre.
    /// Default empty: every joint keeps its own centre all cycle long, as
    /// before key positions carried centres.
    ///
    /// ```json
    /// "transfer_keys": [[0.1, 0.7], [0.5, 1.0], [0.9, 0.5]],
    /// "transfer_key_centers": [{}, {"2": [0.1, 1.0]}, {}]
    /// ```
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub transfer_key_centers: Vec<KeyCenters>,
    /// The body path; default a straight line ahead from the root.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path: Option<PathSpec>,
    /// Body mass, kg (eq. 12, 14). Default 30.
    pub body_mass_kg: f64,
    /// Largest horizontal force one supporting leg can apply, N (eq. 14).
    /// Default: the body's weight.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_leg_force_n: Option<f64>,
    /// Deprecated: a scale of the vertical leg-force superposition that eq.
    /// 12–13 do not have (0 keeps the body level, 1 is the paper's ballistic
    /// model). Read so that presets made before 2026-12-02 run as they were
    /// made, with a warning ([`crate::preset::Creature::deprecations`]).
    /// Default 1.
    pub vertical_gain: f64,
    /// Pitch the body by the difference of its front and rear legs' vertical
    /// motion (Girard & Maciejewski 1985, Figure 2 and "Rotational Control":
    /// the pitch "is due to the separation of the application of vertical
    /// acceleration between the front and rear sections of the body").
    /// Default on (a `gaitlab-preset/1` file without the key ran level): while
    /// legs take a gait change on, the body pitches less in a frame whose
    /// planted foot the legs could not hold at the full pitch (docs/poda.md,
    /// "Body pitch").
    pub body_pitch: bool,
    /// Hold each foot's orientation, eq. 2's last three components, where
    /// its leg has the joints for it (six or more): a planted foot keeps the
    /// orientation it touched down with, and a foot in transfer turns from
    /// its lift-off orientation to the one it will touch down with (level,
    /// facing the body's heading). Where the joints' limits refuse it (the
    /// quadruped's bound and gallops crouch so low that a level foot would
    /// need a knee past its limit) the position wins: the foot tilts as the
    /// limits force and the leg holds its position alone for a few supports
    /// before trying again (docs/poda.md, "The foot's orientation"). A leg
    /// with fewer joints holds its foot's position alone (`--json`'s
    /// `foot_orientation_legs` says which legs hold it, `foot_turn_max_deg`
    /// how far a planted foot turned). Default on (a `gaitlab-preset/1` file
    /// without the key held positions alone).
    pub foot_orientation: bool,
    /// Follow the body path only as tightly as the legs reach (the lab's
    /// reading of "Horizontal Control": the body's turning and speeding up
    /// "must be coherent with its leg support duration pattern"): the
    /// direction of travel turns on a radius no tighter than the farthest
    /// reference foot's distance from the body's centre (a planted foot then
    /// sweeps sideways no more than half a stroke in half a support), the
    /// body never runs faster than the gait, and the desired point on the
    /// path waits for the body, at most one stroke ahead. The body cuts a
    /// corner the legs cannot take; `path_error_max_m` reports by how much.
    /// Default off, as presets ran before 2026-12-02 (eq. 14–15's force
    /// bound only); the bundled PODA presets turn it on.
    pub turn_within_reach: bool,
    /// Read "Rotational Control"'s `σ_{midStance+P} − σ_{midStance}` with the
    /// body's actual yaw at the leg's mid-stance, so that each leg turns the
    /// body from where it faces to the direction of travel one period later
    /// and a yaw error left over is corrected. Off, each leg adds only the
    /// change of the direction of travel between its mid-stances, and a yaw
    /// error stays (how every preset ran before 2026-12-02); the bundled PODA
    /// presets turn it on.
    pub yaw_toward_actual: bool,
    /// The body's fore-aft surge ("Horizontal Control": "an additional
    /// backward acceleration during the restore duration and forward
    /// acceleration during the push duration"): each supporting leg pushes
    /// along itself, so its eq. 12–13 force has a horizontal part that brakes
    /// before mid-stance and drives after it; the body lags and catches up
    /// around the path's even motion (magnitude derived in docs/poda.md,
    /// "Fore-aft surge"). Off, the body moves evenly along its path, as every
    /// preset ran before 2026-12-02; the bundled PODA presets turn it on.
    pub fore_aft_surge: bool,
    /// Pick the gait and its stride from the body speed whenever the speed
    /// is set (the lab's option after Alexander 1984, PODA's reference 20):
    /// the Froude number `v²/(g·h)`, `h` the standing height, walks below
    /// 0.5, trots to 2.5 and gallops above (wave, ripple and alternating for
    /// six or more legs); the period is Alexander's stride `2.3·Fr^0.3·h`
    /// over the speed, shortened where the stroke would outreach the legs.
    /// Default off.
    pub gait_by_speed: bool,
    /// Largest IK iterations per leg per frame. Default 12.
    pub iterations_per_frame: usize,
    /// Stop iterating a leg once its foot is this close to its target, metres. Default 1e-6.
    pub tolerance_m: f64,
    /// Gain k of the null-space term toward the joints' center angles (eq. 6). Default 0.5.
    pub center_gain: f64,
}

impl Default for PodaParams {
    fn default() -> Self {
        Self {
            legs: Vec::new(),
            gait: None,
            period_s: 1.0,
            duty_factor: None,
            phases: None,
            speed_mps: 0.5,
            step_height_m: 0.06,
            stand_height_m: None,
            transfer_keys: vec![[0.1, 0.7], [0.5, 1.0], [0.9, 0.5]],
            transfer_key_centers: Vec::new(),
            path: None,
            body_mass_kg: 30.0,
            max_leg_force_n: None,
            vertical_gain: 1.0,
            body_pitch: true,
            foot_orientation: true,
            turn_within_reach: false,
            yaw_toward_actual: false,
            fore_aft_surge: false,
            gait_by_speed: false,
            iterations_per_frame: 12,
            tolerance_m: 1e-6,
            center_gain: 0.5,
        }
    }
}

/// Transfer-trajectory key positions: at most [`MAX_TRANSFER_KEYS`], each
/// `[along, height]` with the step fraction strictly increasing in (0, 1) and
/// the height fraction in [0, 2]. Errors name `path` or `path[i]`.
///
/// # Errors
/// A [`PresetError`] naming the first bad key.
pub fn check_transfer_keys(path: &str, keys: &[[f64; 2]]) -> Result<(), PresetError> {
    if keys.len() > MAX_TRANSFER_KEYS {
        return Err(PresetError::new(
            path,
            format!("at most {MAX_TRANSFER_KEYS} key positions"),
        ));
    }
    let mut previous = 0.0;
    for (i, [along, height]) in keys.iter().copied().enumerate() {
        let key = format!("{path}[{i}]");
        if !(along.is_finite() && along > previous && along < 1.0) {
            return Err(PresetError::new(
                key,
                "the step fraction must increase strictly between 0 and 1",
            ));
        }
        if !(height.is_finite() && (0.0..=2.0).contains(&height)) {
            return Err(PresetError::new(
                key,
                "the height fraction must be between 0 and 2",
            ));
        }
        previous = along;
    }
    Ok(())
}

/// Where the digits-only key `key` of a [`KeyCenters`] object is a joint's
/// place in its leg, that place (`"3"` → 3); `None` for a joint's name.
#[must_use]
pub fn key_center_place(key: &str) -> Option<usize> {
    if key.is_empty() || !key.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    // Digits beyond `usize` name no joint of any leg.
    Some(key.parse().unwrap_or(usize::MAX))
}

/// The centre angles and gains of the key leg positions, as far as they can
/// be checked without the skeleton: none, or one object per key position
/// (`keys` of them); in each at most [`MAX_KEY_CENTER_JOINTS`] entries, keys
/// a joint's place or a name (not empty, no spaces), each `[center, gain]`
/// with a finite centre of at most [`MAX_KEY_CENTER`] and a gain in [0, 1].
/// `at` is the field's path (`scenario.poda.transfer_key_centers`); errors
/// name it, `{at}[i]` or `{at}[i].{key}`. The driver checks the names and
/// places against the legs and the centres against the joints' limits.
///
/// # Errors
/// A [`PresetError`] naming the first bad entry.
pub fn check_transfer_key_centers(
    at: &str,
    keys: usize,
    centers: &[KeyCenters],
) -> Result<(), PresetError> {
    if centers.is_empty() {
        return Ok(());
    }
    if centers.len() != keys {
        return Err(PresetError::new(
            at,
            format!(
                "needs one object per key position ({keys} transfer_keys, {} objects)",
                centers.len()
            ),
        ));
    }
    for (i, key_centers) in centers.iter().enumerate() {
        if key_centers.len() > MAX_KEY_CENTER_JOINTS {
            return Err(PresetError::new(
                format!("{at}[{i}]"),
                format!("at most {MAX_KEY_CENTER_JOINTS} joints"),
            ));
        }
        for (key, &[center, gain]) in key_centers {
            let path = format!("{at}[{i}].{key}");
            if key.is_empty() || key.chars().any(|c| c.is_whitespace() || c.is_control()) {
                return Err(PresetError::new(
                    path,
                    "must be a joint's place in its leg (\"0\" the hip) or a joint's name",
                ));
            }
            if !(center.is_finite() && center.abs() <= MAX_KEY_CENTER) {
                return Err(PresetError::new(
                    path,
                    format!(
                        "the centre {center} must be a finite angle (radians) within the joint's limits"
                    ),
                ));
            }
            if !(gain.is_finite() && (0.0..=1.0).contains(&gain)) {
                return Err(PresetError::new(
                    path,
                    format!("the gain {gain} must be between 0 and 1"),
                ));
            }
        }
    }
    Ok(())
}

impl PodaParams {
    /// Checks every value that needs no skeleton or gait model. Paths start with `prefix`.
    ///
    /// # Errors
    /// A [`PresetError`] naming the first bad value.
    pub fn check_values(&self, prefix: &str) -> Result<(), PresetError> {
        let at = |field: &str| format!("{prefix}.{field}");
        let spec = |field: &str| row(PODA_PARAMS, &format!("scenario.poda.{field}"));
        let real = |field: &str, value: f64| spec(field).check_real(&at(field), value);
        real("period_s", self.period_s)?;
        if let Some(duty) = self.duty_factor {
            real("duty_factor", duty)?;
        }
        if let Some(phases) = &self.phases {
            for (i, phase) in phases.iter().enumerate() {
                if !phase.is_finite() {
                    return Err(PresetError::new(
                        format!("{prefix}.phases[{i}]"),
                        "must be a finite fraction of the period",
                    ));
                }
            }
        }
        real("speed_mps", self.speed_mps)?;
        real("step_height_m", self.step_height_m)?;
        if let Some(height) = self.stand_height_m {
            real("stand_height_m", height)?;
        }
        check_transfer_keys(&at("transfer_keys"), &self.transfer_keys)?;
        check_transfer_key_centers(
            &at("transfer_key_centers"),
            self.transfer_keys.len(),
            &self.transfer_key_centers,
        )?;
        if let Some(path) = &self.path {
            let n = path.points.len();
            if !(2..=MAX_PATH_POINTS).contains(&n) {
                return Err(PresetError::new(
                    at("path.points"),
                    format!("needs 2 to {MAX_PATH_POINTS} points"),
                ));
            }
            for (i, point) in path.points.iter().enumerate() {
                if !point.iter().all(|v| v.is_finite() && v.abs() <= 1e6) {
                    return Err(PresetError::new(
                        format!("{prefix}.path.points[{i}]"),
                        "must be two finite coordinates in metres",
                    ));
                }
            }
            path.check_speeds(&at("path.speeds_mps"))?;
        }
        real("body_mass_kg", self.body_mass_kg)?;
        if let Some(force) = self.max_leg_force_n {
            real("max_leg_force_n", force)?;
        }
        real("vertical_gain", self.vertical_gain)?;
        spec("iterations_per_frame")
            .check_integer(&at("iterations_per_frame"), self.iterations_per_frame)?;
        real("tolerance_m", self.tolerance_m)?;
        real("center_gain", self.center_gain)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn object(entries: &[(&str, [f64; 2])]) -> KeyCenters {
        entries.iter().map(|(k, v)| ((*k).to_owned(), *v)).collect()
    }

    #[test]
    fn a_key_of_digits_is_a_place_and_anything_else_a_name() {
        assert_eq!(key_center_place("3"), Some(3));
        assert_eq!(key_center_place("012"), Some(12));
        assert_eq!(
            key_center_place("99999999999999999999999"),
            Some(usize::MAX)
        );
        assert_eq!(key_center_place("left_knee"), None);
        assert_eq!(key_center_place("-1"), None);
        assert_eq!(key_center_place(""), None);
    }

    #[test]
    fn key_centres_need_one_object_per_key_and_gains_in_range() {
        let at = "scenario.poda.transfer_key_centers";
        assert!(check_transfer_key_centers(at, 3, &[]).is_ok());
        let good = [object(&[]), object(&[("3", [-1.2, 1.0])]), object(&[])];
        assert!(check_transfer_key_centers(at, 3, &good).is_ok());
        for (keys, centers, path, words) in [
            (
                2,
                good.to_vec(),
                at.to_owned(),
                "(2 transfer_keys, 3 objects)",
            ),
            (
                1,
                vec![object(&[("knee", [0.0, 1.01])])],
                format!("{at}[0].knee"),
                "gain 1.01 must be between 0 and 1",
            ),
            (
                1,
                vec![object(&[("knee", [f64::INFINITY, 0.5])])],
                format!("{at}[0].knee"),
                "finite",
            ),
            (
                1,
                vec![object(&[("left knee", [0.0, 0.5])])],
                format!("{at}[0].left knee"),
                "a joint's place in its leg",
            ),
        ] {
            let error = check_transfer_key_centers(at, keys, &centers).expect_err("refused");
            assert_eq!(error.path, path);
            assert!(error.reason.contains(words), "{error}");
        }
    }

    #[test]
    fn the_field_is_left_out_when_empty_and_read_back_when_given() {
        let text = serde_json::to_string(&PodaParams::default()).expect("json");
        assert!(!text.contains("transfer_key_centers"));
        let params: PodaParams =
            serde_json::from_str(r#"{"transfer_key_centers": [{}, {"2": [0.1, 1]}, {}]}"#)
                .expect("parses");
        assert_eq!(params.transfer_key_centers[1]["2"], [0.1, 1.0]);
        assert!(params.check_values("scenario.poda").is_ok());
    }
}
