//! `scenario.physics`: a Raibert & Hodgins 1991 creature as it appears in a
//! preset — the mass, mass centre and inertia of every body (Table 3), which
//! joints form each leg (hip, leg spring, knee, foot), the tail and neck,
//! the gait, desired speed and hop height, the dynamic scale factor L
//! (Table 1), the integration step, the control rate, the ground's springs,
//! the gait controller's parameters and any obstacles.
//!
//! The skeleton gives the bodies' geometry: each joint moves one body, the
//! root is the trunk (a free-floating base) or, for a planar model, fixed in
//! the world with the base's slides and pitch as the first joints. Only values
//! are checked here (ranges, names); `gaitlab-physics` checks the structure
//! its controllers need (leg counts, gait names) when it builds the creature.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::PresetError;
use super::limits::MAX_LIMBS;

/// Smallest and largest dynamic scale factor L.
pub const SCALE_RANGE: (f64, f64) = (0.05, 20.0);
/// Smallest and largest integration step, seconds.
pub const DT_RANGE_S: (f64, f64) = (1e-5, 2e-3);
/// Largest desired speed magnitude, m/s (at scale 1).
pub const MAX_PHYSICS_SPEED_MPS: f64 = 15.0;
/// Lowest and highest desired hop height, metres (at scale 1). One range for
/// presets, the page's slider and command, and the driver's setter: it
/// guards validity (a finite, non-negative height the legs could reach), not
/// stability — a high hop may still fall, and the blow-up guard says so.
pub const HOP_HEIGHT_RANGE_M: (f64, f64) = (0.0, 2.0);
/// Most integration steps between two runs of the controller.
pub const MAX_CONTROL_EVERY: u32 = 100;
/// Largest ground spring stiffness (N/m) or damping (N·s/m) at scale 1.
pub const MAX_GROUND_COEFFICIENT: f64 = 1e8;
/// Largest magnitude of a gait controller parameter.
pub const MAX_CONTROLLER_VALUE: f64 = 1e7;
/// Most gait controller parameters one preset may set (in `controller`, and
/// for each gait in `controller_by_gait`).
pub const MAX_CONTROLLER_VALUES: usize = 64;
/// Most gaits `controller_by_gait` may name.
pub const MAX_GAITS: usize = 8;

/// Checks a desired speed (m/s at scale 1) against [`MAX_PHYSICS_SPEED_MPS`].
///
/// # Errors
/// `path: must be a speed within ±15 m/s`.
pub fn check_speed_mps(path: &str, speed_mps: f64) -> Result<(), PresetError> {
    if speed_mps.is_finite() && speed_mps.abs() <= MAX_PHYSICS_SPEED_MPS {
        Ok(())
    } else {
        Err(PresetError::new(
            path,
            format!("must be a speed within ±{MAX_PHYSICS_SPEED_MPS} m/s"),
        ))
    }
}

/// Checks a path of waypoints `[x, z]` (m at scale 1): at most
/// [`MAX_WAYPOINTS`], each within ±10 000 m.
///
/// # Errors
/// `path: at most 64 waypoints` or `path[i]: must be [x, z] within ±10000 m`.
pub fn check_waypoints(path: &str, waypoints: &[[f64; 2]]) -> Result<(), PresetError> {
    if waypoints.len() > MAX_WAYPOINTS {
        return Err(PresetError::new(
            path,
            format!("at most {MAX_WAYPOINTS} waypoints"),
        ));
    }
    for (i, w) in waypoints.iter().enumerate() {
        if !w.iter().all(|x| x.is_finite() && x.abs() <= 1e4) {
            return Err(PresetError::new(
                format!("{path}[{i}]"),
                "must be [x, z] within ±10000 m",
            ));
        }
    }
    Ok(())
}

/// Checks a desired hop height (m at scale 1) against [`HOP_HEIGHT_RANGE_M`].
///
/// # Errors
/// `path: must be a height in [0, 2] m`.
pub fn check_hop_height_m(path: &str, height_m: f64) -> Result<(), PresetError> {
    let (lo, hi) = HOP_HEIGHT_RANGE_M;
    if height_m.is_finite() && (lo..=hi).contains(&height_m) {
        Ok(())
    } else {
        Err(PresetError::new(
            path,
            format!("must be a height in [{lo}, {hi}] m"),
        ))
    }
}

/// Checks a map of controller parameters at `path`: at most
/// [`MAX_CONTROLLER_VALUES`], each finite within ±[`MAX_CONTROLLER_VALUE`].
/// (Whether the gait's controller has each name is the physics crate's to
/// say when it builds the controller.)
///
/// # Errors
/// `path` for too many values, `path.NAME` for a value out of range.
pub fn check_controller(path: &str, values: &BTreeMap<String, f64>) -> Result<(), PresetError> {
    if values.len() > MAX_CONTROLLER_VALUES {
        return Err(PresetError::new(
            path,
            format!("at most {MAX_CONTROLLER_VALUES} parameters"),
        ));
    }
    for (name, value) in values {
        if !(value.is_finite() && value.abs() <= MAX_CONTROLLER_VALUE) {
            return Err(PresetError::new(
                format!("{path}.{name}"),
                format!("must be a finite number within ±{MAX_CONTROLLER_VALUE}"),
            ));
        }
    }
    Ok(())
}
/// Most obstacles on the ground.
pub const MAX_OBSTACLES: usize = 32;
/// Most waypoints of a path.
pub const MAX_WAYPOINTS: usize = 64;

/// Which of the paper's controller families drives the creature.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PhysicsModel {
    /// Two telescoping legs on ball hips: run, both gallops.
    #[default]
    Biped,
    /// Four telescoping legs on gimbal hips: trot, bound, gallop.
    Quadruped,
    /// The planar kangaroo: hop (and jump).
    Kangaroo,
}

impl PhysicsModel {
    /// The name used in presets and the CLI.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            PhysicsModel::Biped => "biped",
            PhysicsModel::Quadruped => "quadruped",
            PhysicsModel::Kangaroo => "kangaroo",
        }
    }
}

/// How the trunk moves in the world.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PhysicsBase {
    /// Six degrees of freedom: the skeleton's root is the trunk.
    #[default]
    Free,
    /// Planar: the root is fixed in the world; the skeleton's first joints
    /// slide and pitch the trunk in the sagittal plane.
    Planar,
}

/// The state a run starts from (`scenario.physics.start`). The paper leaves
/// it to the animator: "the animator must also initialize the state of the
/// model" (Figure 2's text).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PhysicsStart {
    /// The gait's own start: the kangaroo just before a landing, the
    /// quadruped in level flight, the biped in the preset's pose.
    #[default]
    Gait,
    /// On the gait's cycle at the desired speed (the kangaroo; other
    /// creatures take their gait's start): before t = 0, out of sight, the
    /// lab runs the gait from its own start, ramping the commanded speed up
    /// to the desired one, and the run begins at a flight apex once it has
    /// hopped there a while (docs/physics.md, "The start on the cycle").
    OnCycle,
}

/// A rigid body's mass properties (Table 3's columns).
///
/// ```json
/// {"mass_kg": 1.4, "com_m": [0, -0.095, 0], "inertia_kgm2": [0.017, 0.0014, 0.018]}
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct MassSpec {
    /// Mass (kg), ≥ 0.
    pub mass_kg: f64,
    /// Centre of mass in the body's frame (m).
    #[serde(default)]
    pub com_m: [f64; 3],
    /// Principal moments of inertia about the centre of mass along the
    /// body's axes (kg·m²), each ≥ 0.
    #[serde(default)]
    pub inertia_kgm2: [f64; 3],
}

/// The body a joint moves, with its mass properties.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PhysicsBodySpec {
    /// The skeleton joint that moves this body.
    pub joint: String,
    /// Its mass properties.
    #[serde(flatten)]
    pub mass: MassSpec,
}

/// One leg: its hip joints (proximal first), its springy joint, optional knee,
/// and the foot's contact point.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PhysicsLegSpec {
    /// Name for metrics and the UI.
    pub name: String,
    /// Hip joints, proximal first: `[roll, pitch]` gimbal, `[roll, pitch,
    /// yaw]` ball, `[pitch]` planar.
    pub hip: Vec<String>,
    /// The leg's spring: the telescoping joint, or the kangaroo's ankle.
    pub spring: String,
    /// The kangaroo's knee.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub knee: Option<String>,
    /// The joint whose body carries the foot.
    pub foot: String,
    /// The contact point in that body's frame (m).
    pub foot_point_m: [f64; 3],
}

/// A box on the ground ahead of the creature.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ObstacleSpec {
    /// Distance of its near face along the direction of travel (m).
    pub at_m: f64,
    /// Its depth along the direction of travel (m).
    pub depth_m: f64,
    /// Its height (m).
    pub height_m: f64,
}

/// `scenario.physics`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PhysicsParams {
    /// The controller family.
    pub model: PhysicsModel,
    /// Free or planar base. Default free.
    #[serde(default)]
    pub base: PhysicsBase,
    /// The trunk's mass properties (the root body of a free base).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trunk: Option<MassSpec>,
    /// Mass properties of the bodies the joints move; joints not listed move
    /// massless links (the inner axes of a gimbal or ball hip).
    pub bodies: Vec<PhysicsBodySpec>,
    /// The legs.
    pub legs: Vec<PhysicsLegSpec>,
    /// Tail joints, base first.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub tail: Vec<String>,
    /// Neck joint.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub neck: Option<String>,
    /// Gait name, one of the model's in the physics engine's gait table
    /// (the page's gait menu; an unknown name is an error that lists the
    /// model's). Default: the model's first.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gait: Option<String>,
    /// Desired forward speed at scale 1 (m/s). Default 1.5.
    #[serde(default = "default_speed")]
    pub speed_mps: f64,
    /// Desired hop height at scale 1 (m); default: the controller's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hop_height_m: Option<f64>,
    /// Dynamic scale factor L (Table 1). Default 1.
    #[serde(default = "default_scale")]
    pub scale: f64,
    /// Integration step at scale 1 (s). Default 0.0004 (the paper's).
    #[serde(default = "default_dt")]
    pub dt_s: f64,
    /// Run the controller every this many integration steps (1 = every
    /// step; 5 = every 2 ms, the paper's "few ms" of Figure 2, as the
    /// bundled biped and kangaroo do). Default 1: a file without it runs
    /// as it did when control ran every step.
    #[serde(default = "default_control_every", skip_serializing_if = "is_one")]
    pub control_every: u32,
    /// The ground's springs and dampers at scale 1 in place of the model's
    /// ("Modeling": the quadruped's and biped's 50 000 N/m and 500 N·s/m, the
    /// kangaroo's own softer ground). Default: the model's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ground: Option<GroundSpec>,
    /// The gait controller's parameters by name, at scale 1 in the paper's
    /// units, in place of its defaults (`{"thrust_m": 0.05}`); the names are
    /// the controller's (`gaitlab run … --set scenario.physics.controller.x=1`
    /// names them when one is wrong). Default: none changed.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub controller: BTreeMap<String, f64>,
    /// One gait's own controller parameters, by gait name, set after
    /// `controller` when that gait runs (`{"bound": {"pitch_kp": 90}}`;
    /// `--set scenario.physics.controller_by_gait.bound.pitch_kp=90`): a
    /// tuned gait leaves the creature's other gaits as they were. Default:
    /// none.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub controller_by_gait: BTreeMap<String, BTreeMap<String, f64>>,
    /// Boxes on the ground.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub obstacles: Vec<ObstacleSpec>,
    /// Waypoints `[x, z]` on the ground (m at scale 1) the creature steers
    /// through in order, turning its desired heading toward the next one.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub waypoints: Vec<[f64; 2]>,
    /// The lab's additions to the paper's control, each named. `null` or
    /// absent (files made before the additions were optional): every
    /// addition on and the controllers' earlier defaults, so the file runs
    /// as it was made. An object (`{}`): each gait's own defaults, the
    /// paper's laws only where the gait holds its speed with them.
    #[serde(default)]
    pub lab_additions: Option<LabAdditions>,
    /// One gait's own choice of the lab's additions, by gait name, over
    /// `lab_additions` when that gait runs (`{"run": {"hop_integrator":
    /// false}}`): an addition every gait has can be off for one of them.
    /// Default: none.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub lab_additions_by_gait: BTreeMap<String, LabAdditions>,
    /// The state the run starts from. Default `gait` (as every file made
    /// before 2026-12-04 started).
    #[serde(default, skip_serializing_if = "is_gait_start")]
    pub start: PhysicsStart,
    /// Gaits a switch enters at their own start where the creature is —
    /// the state a run of that gait starts from, moved to the trunk's place
    /// and turned to its heading — instead of the paper's take-over at the
    /// next flight. The lab's: Raibert & Hodgins' quadruped changes gait
    /// while running, but this lab's pitching bound and gallop, entered from
    /// a running gait, tumble in most runs (docs/physics.md, "Switching
    /// into the bound"). Default: none (every switch a take-over, as every
    /// file made before 2026-12-04 switched).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub switch_to_start: Vec<String>,
}

fn is_gait_start(start: &PhysicsStart) -> bool {
    *start == PhysicsStart::Gait
}

/// The lab's additions to Raibert & Hodgins' control, none of them in the
/// paper (docs/physics.md, "The lab's additions"). A field left out takes
/// the gait's default: off where the gait runs without it, on where it does
/// not yet (a finding, not the paper: docs/physics.md gives the experiment).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct LabAdditions {
    /// Integral speed trim: after every step (or stride) the desired speed
    /// given to eq. 3 is corrected by the last step's speed error, removing
    /// the steady error eq. 3's proportional term leaves.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed_trim: Option<bool>,
    /// Posture torque in Unloading: the biped keeps eq. 4's servo on while
    /// the leg unloads, where Figure 4 zeroes the active hip's torque.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unloading_posture: Option<bool>,
    /// The kangaroo's speed ramp: it starts at no more than 2 m/s and its
    /// commanded speed moves toward the desired one at a set rate.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed_ramp: Option<bool>,
    /// The kangaroo's tail feedback: the tail's rest angle follows the
    /// trunk's pitch error and rate, where the paper only steps it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tail_feedback: Option<bool>,
    /// The hop-height integrator: the thrust (the biped's leg extension, the
    /// kangaroo's apex target, the quadruped's pairs') corrected from each
    /// measured apex or flight, where the paper sets the thrust by eq. 2's
    /// prediction alone.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hop_integrator: Option<bool>,
    /// Ground ahead (issue 45): on ground that is not flat, the controllers
    /// measure eq. 2's hop and eq. 3's touchdown from the local ground plane
    /// under the body (its height and slope, handed to them each control
    /// interval), where the paper's laws take the floor at height 0. No
    /// effect on the floor.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ground_ahead: Option<bool>,
}

impl LabAdditions {
    /// These choices over `base`: each one named here wins, the rest are
    /// `base`'s (a gait's `lab_additions_by_gait` over `lab_additions`).
    #[must_use]
    pub fn over(self, base: Self) -> Self {
        Self {
            speed_trim: self.speed_trim.or(base.speed_trim),
            unloading_posture: self.unloading_posture.or(base.unloading_posture),
            speed_ramp: self.speed_ramp.or(base.speed_ramp),
            tail_feedback: self.tail_feedback.or(base.tail_feedback),
            hop_integrator: self.hop_integrator.or(base.hop_integrator),
            ground_ahead: self.ground_ahead.or(base.ground_ahead),
        }
    }
}

/// The ground's linear springs and dampers (`scenario.physics.ground`), at
/// scale 1; a field left out keeps the model's value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct GroundSpec {
    /// Vertical stiffness (N/m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertical_stiffness: Option<f64>,
    /// Vertical damping (N·s/m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertical_damping: Option<f64>,
    /// Tangential stiffness (N/m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_stiffness: Option<f64>,
    /// Tangential damping (N·s/m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_damping: Option<f64>,
}

impl GroundSpec {
    /// Checks every value given: finite, ≥ 0 and at most
    /// [`MAX_GROUND_COEFFICIENT`] (stiffness must be > 0).
    ///
    /// # Errors
    /// The first offending value, with its JSON path under `prefix`.
    pub fn check(&self, prefix: &str) -> Result<(), PresetError> {
        for (name, value, positive) in [
            ("vertical_stiffness", self.vertical_stiffness, true),
            ("vertical_damping", self.vertical_damping, false),
            ("tangential_stiffness", self.tangential_stiffness, true),
            ("tangential_damping", self.tangential_damping, false),
        ] {
            let Some(v) = value else { continue };
            let ok = v.is_finite()
                && v <= MAX_GROUND_COEFFICIENT
                && (v > 0.0 || (!positive && v == 0.0));
            if !ok {
                let least = if positive {
                    "more than 0"
                } else {
                    "at least 0"
                };
                return Err(PresetError::new(
                    format!("{prefix}.{name}"),
                    format!("must be {least} and at most {MAX_GROUND_COEFFICIENT}"),
                ));
            }
        }
        Ok(())
    }
}

fn default_control_every() -> u32 {
    1
}

fn is_one(n: &u32) -> bool {
    *n == 1
}

fn default_speed() -> f64 {
    1.5
}

fn default_scale() -> f64 {
    1.0
}

fn default_dt() -> f64 {
    0.0004
}

fn finite3(path: String, v: [f64; 3], max: f64) -> Result<(), PresetError> {
    if v.iter().all(|x| x.is_finite() && x.abs() <= max) {
        Ok(())
    } else {
        Err(PresetError::new(
            path,
            format!("must be three finite numbers within ±{max}"),
        ))
    }
}

impl MassSpec {
    /// Check the values: mass and moments finite and ≥ 0, centre finite.
    ///
    /// # Errors
    /// The offending field under `prefix`.
    pub fn check(&self, prefix: &str) -> Result<(), PresetError> {
        if !(self.mass_kg.is_finite() && (0.0..=1e6).contains(&self.mass_kg)) {
            return Err(PresetError::new(
                format!("{prefix}.mass_kg"),
                "must be a mass in [0, 1e6] kg",
            ));
        }
        finite3(format!("{prefix}.com_m"), self.com_m, 1e3)?;
        if !self
            .inertia_kgm2
            .iter()
            .all(|x| x.is_finite() && (0.0..=1e6).contains(x))
        {
            return Err(PresetError::new(
                format!("{prefix}.inertia_kgm2"),
                "must be three moments of inertia in [0, 1e6] kg·m²",
            ));
        }
        Ok(())
    }
}

impl PhysicsParams {
    /// Check every value and that every joint name is one of `joint_names`.
    ///
    /// # Errors
    /// The first offending value, with its JSON path under `prefix`.
    pub fn check(
        &self,
        prefix: &str,
        joint_names: &dyn Fn(&str) -> bool,
    ) -> Result<(), PresetError> {
        let at = |field: &str| format!("{prefix}.{field}");
        let name = |path: String, n: &str| {
            if joint_names(n) {
                Ok(())
            } else {
                Err(PresetError::new(path, format!("no joint named \"{n}\"")))
            }
        };
        match (&self.trunk, self.base) {
            (Some(t), _) => t.check(&at("trunk"))?,
            (None, PhysicsBase::Free) => {
                return Err(PresetError::new(
                    at("trunk"),
                    "a free base needs the trunk's mass properties",
                ));
            }
            (None, PhysicsBase::Planar) => {}
        }
        for (i, body) in self.bodies.iter().enumerate() {
            let p = format!("{prefix}.bodies[{i}]");
            name(format!("{p}.joint"), &body.joint)?;
            if self.bodies[..i].iter().any(|b| b.joint == body.joint) {
                return Err(PresetError::new(format!("{p}.joint"), "listed twice"));
            }
            body.mass.check(&p)?;
        }
        if self.legs.is_empty() || self.legs.len() > MAX_LIMBS {
            return Err(PresetError::new(
                at("legs"),
                format!("must list 1 to {} legs", MAX_LIMBS),
            ));
        }
        for (i, leg) in self.legs.iter().enumerate() {
            let p = format!("{prefix}.legs[{i}]");
            if leg.hip.is_empty() || leg.hip.len() > 3 {
                return Err(PresetError::new(
                    format!("{p}.hip"),
                    "must list 1 to 3 hip joints",
                ));
            }
            for (k, h) in leg.hip.iter().enumerate() {
                name(format!("{p}.hip[{k}]"), h)?;
            }
            name(format!("{p}.spring"), &leg.spring)?;
            if let Some(knee) = &leg.knee {
                name(format!("{p}.knee"), knee)?;
            }
            name(format!("{p}.foot"), &leg.foot)?;
            finite3(format!("{p}.foot_point_m"), leg.foot_point_m, 1e3)?;
        }
        for (i, t) in self.tail.iter().enumerate() {
            name(format!("{prefix}.tail[{i}]"), t)?;
        }
        if let Some(neck) = &self.neck {
            name(at("neck"), neck)?;
        }
        check_speed_mps(&at("speed_mps"), self.speed_mps)?;
        if let Some(h) = self.hop_height_m {
            check_hop_height_m(&at("hop_height_m"), h)?;
        }
        let (lo, hi) = SCALE_RANGE;
        if !(self.scale.is_finite() && (lo..=hi).contains(&self.scale)) {
            return Err(PresetError::new(
                at("scale"),
                format!("must be a scale factor in [{lo}, {hi}]"),
            ));
        }
        let (lo, hi) = DT_RANGE_S;
        if !(self.dt_s.is_finite() && (lo..=hi).contains(&self.dt_s)) {
            return Err(PresetError::new(
                at("dt_s"),
                format!("must be a time step in [{lo}, {hi}] s"),
            ));
        }
        if self.control_every == 0 || self.control_every > MAX_CONTROL_EVERY {
            return Err(PresetError::new(
                at("control_every"),
                format!("must be a whole number of steps from 1 to {MAX_CONTROL_EVERY}"),
            ));
        }
        if let Some(ground) = &self.ground {
            ground.check(&at("ground"))?;
        }
        check_controller(&at("controller"), &self.controller)?;
        if self.controller_by_gait.len() > MAX_GAITS {
            return Err(PresetError::new(
                at("controller_by_gait"),
                format!("at most {MAX_GAITS} gaits"),
            ));
        }
        for (gait, values) in &self.controller_by_gait {
            let p = format!("{prefix}.controller_by_gait.{gait}");
            if !is_gait_word(gait) {
                return Err(PresetError::new(
                    p,
                    "must be a gait's name (lower-case letters and _)",
                ));
            }
            check_controller(&p, values)?;
        }
        if self.lab_additions_by_gait.len() > MAX_GAITS {
            return Err(PresetError::new(
                at("lab_additions_by_gait"),
                format!("at most {MAX_GAITS} gaits"),
            ));
        }
        if let Some(gait) = self.lab_additions_by_gait.keys().find(|g| !is_gait_word(g)) {
            return Err(PresetError::new(
                format!("{prefix}.lab_additions_by_gait.{gait}"),
                "must be a gait's name (lower-case letters and _)",
            ));
        }
        if self.obstacles.len() > MAX_OBSTACLES {
            return Err(PresetError::new(
                at("obstacles"),
                format!("at most {MAX_OBSTACLES} obstacles"),
            ));
        }
        check_waypoints(&at("waypoints"), &self.waypoints)?;
        for (i, o) in self.obstacles.iter().enumerate() {
            let p = format!("{prefix}.obstacles[{i}]");
            let ok = |v: f64, lo: f64| v.is_finite() && v >= lo && v <= 1e3;
            if !ok(o.at_m, -1e3) || !ok(o.depth_m, 0.01) || !ok(o.height_m, 0.001) {
                return Err(PresetError::new(
                    p,
                    "needs at_m, depth_m ≥ 0.01 and height_m ≥ 0.001, all within 1000 m",
                ));
            }
        }
        Ok(())
    }
}

/// A gait's name as a preset may key it: 1–32 lower-case letters and `_`.
fn is_gait_word(gait: &str) -> bool {
    !gait.is_empty() && gait.len() <= 32 && gait.chars().all(|c| c.is_ascii_lowercase() || c == '_')
}
