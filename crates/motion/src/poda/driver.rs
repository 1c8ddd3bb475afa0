//! The PODA driver (Girard & Maciejewski 1985, "Modeling the Kinematics of
//! Legged Locomotion"). Each frame runs the stages
//! `body → leg_states → footholds → foot_targets → key_centers → ik`:
//! - **body**: the ground-plane pose planned ahead by [`BodyTrack`] — path
//!   following with the legs' horizontal force limits (eq. 14–15) and yaw
//!   from the legs' push / restore toward the direction of travel — raised by
//!   the superposition of each leg's vertical push / fall / restore (eq. 12–13).
//!   On a path with speeds (`scenario.poda.path.speeds_mps`) the gait takes
//!   on the desired speed where the desired point is whenever a leg reaches
//!   mid-stance, as a speed edit does (stroke kept, period derived; with gait
//!   by speed the gait and stride follow), and the legs take it on one by one;
//! - **leg_states**: eq. 9 for every leg until the gait changes; from then
//!   each leg's own cycles ([`LegCycles`]), which take a change on at each
//!   leg's mid-stance, with the body kept within [`super::transition`]'s
//!   bounds while they do;
//! - **footholds**: at lift-off (time t), eq. 11 — the body's predicted pose at
//!   f₁ = t + transfer + support/2 carries the leg's reference position into
//!   the world, and the body's pose at f₂ = t + transfer expresses that
//!   foothold in the body frame;
//! - **foot_targets**: a supporting foot stays where it landed (eq. 10); a
//!   transferring foot follows the Catmull-Rom spline through the key leg
//!   positions — the spline's "along" fraction moves it from its lift-off
//!   point to its foothold in the body frame, its "height" sets the world
//!   height;
//! - **key_centers**: while a leg transfers, the centre angles and gains its
//!   key leg positions carry (`scenario.poda.transfer_key_centers`) follow the
//!   foot's spline parameter ([`super::key_centers`]); in support the joints'
//!   own;
//! - **ik**: every leg by pseudoinverse with null-space centering (eq. 5–6).

use std::sync::Arc;

use gaitlab_core::driver::{Driver, IkFrameReport};
use gaitlab_core::ik::Targets;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::poda::{KeyCenters, MAX_TRANSFER_KEYS, check_transfer_key_centers};
use gaitlab_core::preset::{Creature, PathSpec, PodaParams, check_transfer_keys};
use gaitlab_core::{Kinematics, Pose, RootTransform, Skeleton};
use glam::{DMat3, DVec2, DVec3};

use super::body_track::{BodyDynamics, BodyTrack};
use super::gait::{Derived, GaitError, GaitParams, LegPhase};
use super::gait_by_speed::{froude, gait_index, speed_gaits};
use super::gait_metrics::GaitMetrics;
use super::gaits::{gait_names, named_gait};
use super::ground_pose::GroundPose;
use super::key_centers::{self, LegKeyCenters};
use super::leg_cycles::LegCycles;
use super::leg_ik::{LegIk, LegIkOptions};
use super::path::BodyPath;
use super::spline::eval_open;
use super::stability::{StabilityMeter, StabilityReport};
use super::surge::{surge_coefficient, surge_superposition_m};
use super::transition::{
    PlantedLeg, REACH, SAMPLES, TransitionBounds, eq9_centre_and_range_m, reach_ceiling_m,
};
use crate::DriverError;

/// Gravity, m/s².
pub const GRAVITY_MPS2: f64 = 9.81;
/// Length of the default straight path, metres (beyond it the path extrapolates).
const DEFAULT_PATH_M: f64 = 1000.0;
/// Fraction of the stroke the legs' reach allows that gait by speed uses
/// (the body bobs, pitches and surges around the stand height).
const STROKE_OF_REACH: f64 = 0.8;
/// A speed edit with gait by speed: the gait and its stride follow.
const EDIT_SPEED_GAIT: Derived = Derived::new(
    "speed_mps",
    &["gait", "period_s", "duty_factor", "stroke_m"],
);
/// A speed edit with gait by speed that keeps the gait: its stride follows.
const EDIT_SPEED_STRIDE: Derived = Derived::new("speed_mps", &["period_s", "stroke_m"]);
/// IK iterations per leg when a reset settles the pose.
const RESET_ITERATIONS: usize = 60;

/// A leg of the creature.
#[derive(Clone, Debug)]
struct Leg {
    name: String,
    ik: LegIk,
    /// Reference (mid-stance) foot position in the body frame, on the ground.
    reference_body: DVec3,
    /// The hip joint's position relative to the root, body frame, metres.
    hip_body: DVec3,
    /// The straight leg's length from the hip joint to the foot, metres.
    length_m: f64,
    /// The leg's joints that key leg positions give centres and gains.
    key_centers: LegKeyCenters,
}

/// A leg's running state.
#[derive(Clone, Copy, Debug, Default)]
struct LegRun {
    support: bool,
    /// Where the foot stands while supporting, world metres.
    planted: DVec3,
    /// Lift-off point in the body frame at lift-off.
    liftoff_body: DVec3,
    /// Planned foothold in the body frame at touchdown (eq. 11, f₂).
    foothold_body: DVec3,
    /// Planned foothold in the world (eq. 11, f₁).
    foothold_world: DVec3,
    /// The foot's target this frame, world metres.
    target: DVec3,
    /// The transfer's progress this frame, the foot spline's parameter in
    /// [0, 1] (meaningless while supporting).
    progress: f64,
}

/// Animates a creature with PODA's gait model, footholds and foot splines.
#[derive(Clone, Debug)]
pub struct PodaDriver {
    skeleton: Arc<Skeleton>,
    params: PodaParams,
    gait: GaitParams,
    gait_name: String,
    path: BodyPath,
    legs: Vec<Leg>,
    runs: Vec<LegRun>,
    /// Key leg positions `(along, height fraction, 0)` from lift-off `(0, 0)` to foothold `(1, 0)`.
    keys: Vec<DVec3>,
    /// Control points of one joint's centre and gain along the transfer
    /// (scratch of the key-centres stage).
    center_points: Vec<DVec3>,
    stand_height_m: f64,
    rest: Pose,
    centering: LegIkOptions,
    exact: LegIkOptions,
    pose: Pose,
    kin: Kinematics,
    targets: Targets,
    effectors: Vec<DVec3>,
    time: f64,
    metrics: GaitMetrics,
    /// Static stability of the support feet, measured every frame.
    stability: StabilityMeter,
    /// Gait values `([P, β], phases)` the vertical centre was computed for.
    centre_key: ([f64; 2], Vec<f64>),
    centre_m: f64,
    /// Each foot's distance to its target after the frame's IK (other effectors 0).
    report: IkFrameReport,
    /// The body's planned ground motion (eq. 14–15 and yaw).
    track: BodyTrack,
    /// Speed, period and duty factor the plan was made with.
    track_key: [f64; 3],
    /// Per leg, the weight of its vertical contribution in the body's pitch
    /// slope ([`pitch_weights`]); all 0 when `body_pitch` is off.
    pitch_weights: Vec<f64>,
    /// Mean fore-aft position of the legs' reference feet, body frame, metres.
    legs_mean_z_m: f64,
    /// This frame's body pitch, radians (positive: nose up).
    pitch_rad: f64,
    /// Largest distance of the body from its path since the last reset, metres.
    path_error_max_m: f64,
    /// This frame's fore-aft surge, metres forward (0 when `fore_aft_surge` is off).
    surge_m: f64,
    /// The longest stroke gait by speed gives the legs, metres.
    max_stroke_m: f64,
    /// The legs' own cycles, in use from the first gait change after a
    /// reset (before it, eq. 9 on the gait's values).
    cycles: LegCycles,
    /// Whether the legs run on [`LegCycles`].
    by_cycles: bool,
    /// The gait eq. 9 ran with since the last reset (the cycles start from it).
    steady_gait: GaitParams,
    /// Whether the vertical centre in `centre_m` holds for the cycles' steady gait.
    centre_steady: bool,
    /// The lab's bounds on the body while legs take a change on.
    bounds: TransitionBounds,
    /// The latest mid-stance of any leg at which the gait read the path's
    /// speed, seconds (a path with speeds; [`PodaDriver::follow_path_speed`]).
    path_speed_read_s: f64,
}

/// The body's pitch from its legs' vertical motion (Figure 2; "Rotational
/// Control": the pitch "is due to the separation of the application of
/// vertical acceleration between the front and rear sections of the body").
/// Leg `i`, a one-legged hopper carrying `1/n` of the weight, moves the whole
/// body by `y_i` (eq. 12–13 with `g_n = g/n`); the section of the body above
/// it, carried by that leg alone, would move `n·y_i`. The body is the
/// least-squares line through the points `(z_i, n·y_i)` at the legs'
/// fore-aft positions `z_i`: its height at the legs' mean `z̄` is `Σ y_i`
/// (the superposition) and its slope is `Σ w_i·y_i` with
/// `w_i = n·(z_i − z̄) / Σ_j (z_j − z̄)²`. Legs all at one `z` (a biped) give
/// no pitch: every weight 0.
fn pitch_weights(z_m: &[f64], out: &mut Vec<f64>) -> f64 {
    #[expect(clippy::cast_precision_loss, reason = "leg count ≤ 32")]
    let n = z_m.len() as f64;
    let mean = z_m.iter().sum::<f64>() / n.max(1.0);
    let spread: f64 = z_m.iter().map(|z| (z - mean) * (z - mean)).sum();
    out.clear();
    out.extend(z_m.iter().map(|z| {
        if spread > 1e-12 {
            n * (z - mean) / spread
        } else {
            0.0
        }
    }));
    mean
}

/// The transfer spline's control points: lift-off `(0, 0)`, the key leg
/// positions `(along, height fraction)`, the foothold `(1, 0)`.
fn spline_keys(keys: &[[f64; 2]], out: &mut Vec<DVec3>) {
    out.clear();
    out.push(DVec3::ZERO);
    out.extend(
        keys.iter()
            .map(|&[along, height]| DVec3::new(along, height, 0.0)),
    );
    out.push(DVec3::X);
}

fn gait_error(error: GaitError) -> DriverError {
    DriverError::new(format!("scenario.poda.{}", error.path), error.reason)
}

impl PodaDriver {
    /// A driver for `creature` with its preset's PODA scenario.
    ///
    /// # Errors
    /// A [`DriverError`] naming the scenario value that cannot be used (an
    /// unknown gait for the leg count, gait values out of range, a bad path).
    pub fn new(creature: &Creature) -> Result<Self, DriverError> {
        Self::with_params(creature, creature.scenario.poda_params())
    }

    /// A driver for `creature` with `params` instead of the preset's.
    ///
    /// # Errors
    /// As [`PodaDriver::new`].
    pub fn with_params(creature: &Creature, params: PodaParams) -> Result<Self, DriverError> {
        let skeleton = Arc::new(creature.skeleton.clone());
        let rest = creature.rest_pose();
        let stand_height_m = params.stand_height_m.unwrap_or(rest.root.position.y);
        let rest_kin = Kinematics::of(&skeleton, &rest);
        let mut legs = Vec::with_capacity(params.legs.len());
        for (i, spec) in params.legs.iter().enumerate() {
            let at = |field: &str| format!("scenario.poda.legs[{i}].{field}");
            let effector = skeleton
                .effector_index(&spec.effector)
                .ok_or_else(|| DriverError::new(at("effector"), "no such effector"))?;
            let hip = skeleton
                .joint_index(&spec.hip)
                .ok_or_else(|| DriverError::new(at("hip"), "no such joint"))?;
            let chain = skeleton.chain(effector);
            let start = chain.iter().position(|&j| j == hip).ok_or_else(|| {
                DriverError::new(at("hip"), "not on the chain of the leg's effector")
            })?;
            let foot = rest_kin.effector_position[effector] - rest.root.position;
            let mut length_m = 0.0;
            let mut last = rest_kin.joint_position[hip];
            for &j in &chain[start + 1..] {
                length_m += (rest_kin.joint_position[j] - last).length();
                last = rest_kin.joint_position[j];
            }
            length_m += (rest_kin.effector_position[effector] - last).length();
            let hip_body = rest.root.rotation.transpose()
                * (rest_kin.joint_position[hip] - rest.root.position);
            legs.push(Leg {
                hip_body,
                length_m,
                name: spec.name.clone().unwrap_or_else(|| spec.effector.clone()),
                ik: LegIk::new(chain[start..].to_vec(), effector),
                reference_body: DVec3::new(foot.x, -stand_height_m, foot.z),
                key_centers: LegKeyCenters::new(),
            });
        }
        if legs.is_empty() {
            return Err(DriverError::new("scenario.poda.legs", "no legs"));
        }
        let n = legs.len();
        let gait_name = match &params.gait {
            Some(name) => name.clone(),
            None => gait_names(n).next().unwrap_or("walk").to_owned(),
        };
        let (mut phases, mut duty) = named_gait(&gait_name, n).map_err(gait_error)?;
        if let Some(custom) = &params.phases {
            phases.clone_from(custom);
        }
        if let Some(custom) = params.duty_factor {
            duty = custom;
        }
        let gait =
            GaitParams::new(params.period_s, duty, phases, params.speed_mps).map_err(gait_error)?;
        let path = match &params.path {
            Some(spec) => BodyPath::try_from(spec).map_err(|e| {
                DriverError::new(format!("scenario.poda.path.{}", e.path), e.reason)
            })?,
            None => BodyPath::straight(
                DVec2::new(rest.root.position.x, rest.root.position.z),
                0.0,
                DEFAULT_PATH_M,
            )
            .map_err(|e| DriverError::new("scenario.poda.path", e.to_string()))?,
        };
        let mut keys = Vec::with_capacity(params.transfer_keys.len() + 2);
        spline_keys(&params.transfer_keys, &mut keys);
        let field = "scenario.poda.transfer_key_centers";
        check_transfer_key_centers(
            field,
            params.transfer_keys.len(),
            &params.transfer_key_centers,
        )
        .map_err(|e| DriverError::new(e.path, e.reason))?;
        let resolved = key_centers::resolve(
            &skeleton,
            legs.iter().map(|l| (l.name.as_str(), l.ik.joints())),
            &params.transfer_key_centers,
            field,
        )?;
        for (leg, key_centers) in legs.iter_mut().zip(resolved) {
            leg.key_centers = key_centers;
        }
        let centering = LegIkOptions {
            center_gain: params.center_gain,
            ..LegIkOptions::default()
        };
        let exact = LegIkOptions {
            center_gain: 0.0,
            ..LegIkOptions::default()
        };
        let metrics = GaitMetrics::new(legs.iter().map(|l| l.name.as_str()));
        let dynamics = BodyDynamics {
            mass_kg: params.body_mass_kg,
            max_leg_force_n: params
                .max_leg_force_n
                .unwrap_or(params.body_mass_kg * GRAVITY_MPS2),
            min_turn_radius_m: if params.turn_within_reach {
                legs.iter()
                    .map(|l| DVec2::new(l.reference_body.x, l.reference_body.z).length())
                    .fold(0.0, f64::max)
            } else {
                0.0
            },
            max_lead_strokes: if params.turn_within_reach { 1.0 } else { 0.0 },
            yaw_toward_actual: params.yaw_toward_actual,
            ..BodyDynamics::default()
        };
        let steady_gait = gait.clone();
        let mut driver = Self {
            effectors: vec![DVec3::ZERO; skeleton.effector_count()],
            targets: Targets {
                position: vec![DVec3::ZERO; skeleton.effector_count()],
                rotation: Vec::new(),
            },
            kin: Kinematics::new(&skeleton),
            runs: vec![LegRun::default(); n],
            pose: rest.clone(),
            skeleton,
            params,
            gait,
            gait_name,
            path,
            legs,
            keys,
            center_points: Vec::with_capacity(MAX_TRANSFER_KEYS + 2),
            stand_height_m,
            rest,
            centering,
            exact,
            time: 0.0,
            metrics,
            stability: StabilityMeter::default(),
            centre_key: ([f64::NAN; 2], Vec::new()),
            centre_m: 0.0,
            report: IkFrameReport::new(creature.skeleton.effector_count()),
            track: BodyTrack::new(creature.scenario.frame_seconds(), dynamics),
            track_key: [f64::NAN; 3],
            pitch_weights: Vec::with_capacity(n),
            legs_mean_z_m: 0.0,
            pitch_rad: 0.0,
            path_error_max_m: 0.0,
            surge_m: 0.0,
            max_stroke_m: 0.0,
            cycles: LegCycles::default(),
            by_cycles: false,
            steady_gait,
            centre_steady: false,
            bounds: TransitionBounds::new(n),
            path_speed_read_s: f64::NEG_INFINITY,
        };
        driver.max_stroke_m = driver
            .legs
            .iter()
            .map(|leg| {
                let reach = REACH * leg.length_m;
                let hip = stand_height_m + leg.hip_body.y;
                2.0 * STROKE_OF_REACH * (reach * reach - hip * hip).max(0.0).sqrt()
            })
            .fold(f64::INFINITY, f64::min);
        let z: Vec<f64> = driver.legs.iter().map(|l| l.reference_body.z).collect();
        driver.legs_mean_z_m = pitch_weights(&z, &mut driver.pitch_weights);
        if !driver.params.body_pitch {
            driver.pitch_weights.fill(0.0);
        }
        driver.check_path_speeds(&driver.path, "scenario.poda.path.speeds_mps")?;
        driver.reset();
        Ok(driver)
    }

    /// The gait model (period, duty factor, phases, stroke, speed).
    #[must_use]
    pub fn gait(&self) -> &GaitParams {
        &self.gait
    }

    /// Mutable gait model: edits keep eq. 7–8 true and take effect at the next frame.
    pub fn gait_mut(&mut self) -> &mut GaitParams {
        &mut self.gait
    }

    /// The PODA parameters in use (legs, step height, transfer keys, dynamics).
    #[must_use]
    pub fn params(&self) -> &PodaParams {
        &self.params
    }

    /// Each supporting leg's upward force at this gait, newtons: the force
    /// whose average over the cycle carries the body's weight (eq. 12–13 with
    /// the body's mass and [`GRAVITY_MPS2`]).
    #[must_use]
    pub fn leg_force_n(&self) -> f64 {
        self.gait
            .leg_force_for_balance_n(self.params.body_mass_kg, GRAVITY_MPS2)
    }

    /// One leg's share of the body's weight, newtons (`m·g / legs`): a leg
    /// force must exceed it (eq. 12's `a = F/m − g_n` > 0).
    #[must_use]
    pub fn weight_share_n(&self) -> f64 {
        self.gait.gravity_share_mps2(GRAVITY_MPS2) * self.params.body_mass_kg
    }

    /// Sets the support-phase leg force, newtons (see
    /// [`GaitParams::set_leg_force`]); the gait derives period and duty factor.
    ///
    /// # Errors
    /// `force_n` not above [`PodaDriver::weight_share_n`], or a derived value
    /// would leave its range; nothing changes.
    pub fn set_leg_force_n(&mut self, force_n: f64) -> Result<Derived, GaitError> {
        self.gait
            .set_leg_force(force_n, self.params.body_mass_kg, GRAVITY_MPS2)
    }

    /// Sets the body speed, m/s. With `scenario.poda.gait_by_speed` the gait
    /// and its period follow from the Froude number
    /// ([`super::gait_by_speed`]) and the legs take them on one by one;
    /// otherwise as [`GaitParams::set_speed`] (stroke kept, period derived).
    ///
    /// # Errors
    /// The speed, or a value derived from it, out of range; `speed_mps` while
    /// the body path carries its own speeds (`path.speeds_mps`: they set the
    /// speed); nothing changes.
    pub fn set_speed(&mut self, speed_mps: f64) -> Result<Derived, GaitError> {
        if self.path.speeds_mps().is_some() {
            return Err(GaitError::new(
                "speed_mps",
                "the body path sets the speed (path.speeds_mps): edit the path's speeds, \
                 or set a path without them",
            ));
        }
        self.apply_speed(speed_mps)
    }

    /// Sets the body speed as [`PodaDriver::set_speed`] does, whatever the path.
    fn apply_speed(&mut self, speed_mps: f64) -> Result<Derived, GaitError> {
        let (name, next, edit) = self.gait_at_speed(speed_mps)?;
        match name {
            Some(name) => self.adopt(name, next),
            None => self.gait = next,
        }
        Ok(edit)
    }

    /// The gait a speed edit to `speed_mps` leads to, and what it derived:
    /// with gait by speed the named gait the Froude number picks (its name)
    /// and its stride; otherwise this gait with its stroke kept and its
    /// period derived (no name: the gait stays).
    fn gait_at_speed(
        &self,
        speed_mps: f64,
    ) -> Result<(Option<&'static str>, GaitParams, Derived), GaitError> {
        let gaits = speed_gaits(self.legs.len());
        let (Some(gaits), true, true) = (
            gaits,
            self.params.gait_by_speed,
            speed_mps.is_finite() && speed_mps > 0.0,
        ) else {
            let mut next = self.gait.clone();
            let edit = next.set_speed(speed_mps)?;
            return Ok((None, next, edit));
        };
        let fr = froude(speed_mps, self.stand_height_m, GRAVITY_MPS2);
        let name = gaits[gait_index(fr)];
        let (phases, duty) =
            named_gait(name, self.legs.len()).map_err(|e| GaitError::new("speed_mps", e.reason))?;
        let period = super::gait_by_speed::period_s(
            speed_mps,
            self.stand_height_m,
            GRAVITY_MPS2,
            duty,
            self.max_stroke_m,
        );
        let next = GaitParams::new(period, duty, phases, speed_mps)
            .map_err(|e| GaitError::new("speed_mps", format!("{}: {}", e.path, e.reason)))?;
        let edit = if name == self.gait_name {
            EDIT_SPEED_STRIDE
        } else {
            EDIT_SPEED_GAIT
        };
        Ok((Some(name), next, edit))
    }

    /// Every speed of `path` (when it carries speeds) is one the gait can
    /// take on from its present values ([`PodaDriver::set_speed`]'s rule; a
    /// speed between two control points' lies between their periods).
    ///
    /// # Errors
    /// `{field}[i]` for the first speed the gait cannot take, with why.
    fn check_path_speeds(&self, path: &BodyPath, field: &str) -> Result<(), DriverError> {
        for (i, &v) in path.speeds_mps().unwrap_or_default().iter().enumerate() {
            self.gait_at_speed(v).map_err(|e| {
                DriverError::new(
                    format!("{field}[{i}]"),
                    format!("at {v} m/s the gait cannot keep eq. 7–8: {e}"),
                )
            })?;
        }
        Ok(())
    }

    /// On a path with speeds, whenever a leg has reached mid-stance since
    /// the last time, the gait takes on the desired speed where the desired
    /// point is now ([`BodyPath::desired_speed_mps`]), as a speed edit would.
    /// Legs take a change on only at their mid-stances ([`LegCycles`]; the
    /// paper's "at the beginning of its upward pushing phase"), so reading
    /// the speed there, not every frame, changes nothing the legs do and
    /// spares a replan of the body's track every frame. A speed the gait
    /// cannot take leaves it as it is (the path's speeds were checked against
    /// the gait when the path was set).
    fn follow_path_speed(&mut self) {
        if self.path.speeds_mps().is_none() {
            return;
        }
        let latest = (0..self.legs.len())
            .filter_map(|i| self.mid_stance_s(i))
            .fold(f64::NEG_INFINITY, f64::max);
        if latest <= self.path_speed_read_s {
            return;
        }
        self.path_speed_read_s = latest;
        let distance = self.track.interpolate(self.time).desired_m;
        if let Some(v) = self.path.desired_speed_mps(distance)
            && v != self.gait.speed_mps()
        {
            let _ = self.apply_speed(v);
        }
    }

    /// Sets the highest point of the transfer trajectory above the ground.
    ///
    /// # Errors
    /// `step_height_m` unless it is a number of metres in (0, 5].
    pub fn set_step_height(&mut self, step_height_m: f64) -> Result<(), DriverError> {
        gaitlab_core::params::row(
            gaitlab_core::preset::PODA_PARAMS,
            "scenario.poda.step_height_m",
        )
        .check_real("step_height_m", step_height_m)
        .map_err(|e| DriverError::new("step_height_m", e.reason))?;
        self.params.step_height_m = step_height_m;
        Ok(())
    }

    /// Replaces the key leg positions of the transfer trajectory, each
    /// `[along, height]` (step fraction strictly increasing in (0, 1), height
    /// fraction of the step height in [0, 2]). Feet in transfer follow the new
    /// spline from their current progress. Centre angles the key positions
    /// carry ([`PodaDriver::set_transfer_key_centers`]) stay with them, key by
    /// key.
    ///
    /// # Errors
    /// `transfer_keys[i]` naming the first bad key; `transfer_keys` for a new
    /// count of keys while the keys carry centre angles (set
    /// `transfer_key_centers` to none first); nothing changes.
    pub fn set_transfer_keys(&mut self, keys: &[[f64; 2]]) -> Result<(), DriverError> {
        check_transfer_keys("transfer_keys", keys)
            .map_err(|e| DriverError::new(e.path, e.reason))?;
        let carried = self.params.transfer_key_centers.len();
        if carried > 0 && keys.len() != carried {
            return Err(DriverError::new(
                "transfer_keys",
                format!(
                    "the {carried} key positions carry centre angles (transfer_key_centers): \
                     give {carried} keys, or set transfer_key_centers to none first"
                ),
            ));
        }
        spline_keys(keys, &mut self.keys);
        self.params.transfer_keys = keys.to_vec();
        Ok(())
    }

    /// Replaces the centre angles and gains the key leg positions carry: one
    /// [`KeyCenters`] object per transfer key, or none (every joint its own
    /// centre all cycle). Legs in transfer follow them from the next frame.
    ///
    /// # Errors
    /// `transfer_key_centers` for a count that is not the keys';
    /// `transfer_key_centers[i].{key}` for an unknown joint or place, a gain
    /// outside [0, 1] or a centre outside the joint's limits; nothing changes.
    pub fn set_transfer_key_centers(&mut self, centers: &[KeyCenters]) -> Result<(), DriverError> {
        let field = "transfer_key_centers";
        check_transfer_key_centers(field, self.params.transfer_keys.len(), centers)
            .map_err(|e| DriverError::new(e.path, e.reason))?;
        let resolved = key_centers::resolve(
            &self.skeleton,
            self.legs.iter().map(|l| (l.name.as_str(), l.ik.joints())),
            centers,
            field,
        )?;
        for (leg, key_centers) in self.legs.iter_mut().zip(resolved) {
            leg.key_centers = key_centers;
            leg.ik.clear_center_overrides();
        }
        self.params.transfer_key_centers = centers.to_vec();
        Ok(())
    }

    /// The centre angle and gain eq. 6 pulls leg `leg`'s `place`-th joint
    /// (the hip 0) toward this frame: a key position's while the leg
    /// transfers ([`super::key_centers`]), the joint's own otherwise.
    #[must_use]
    pub fn leg_center(&self, leg: usize, place: usize) -> Option<[f64; 2]> {
        self.legs.get(leg)?.ik.center_of(&self.skeleton, place)
    }

    /// Sets a leg joint's center angle and gain (eq. 6), by joint name.
    ///
    /// # Errors
    /// `center.joint` for an unknown joint or one that belongs to no leg;
    /// `center.center` / `center.gain` for values out of range.
    pub fn set_center(&mut self, joint: &str, center: f64, gain: f64) -> Result<(), DriverError> {
        let Some(j) = self.skeleton.joint_index(joint) else {
            return Err(DriverError::new(
                "center.joint",
                format!("no joint called {joint:?}"),
            ));
        };
        if !self.legs.iter().any(|leg| leg.ik.joints().contains(&j)) {
            return Err(DriverError::new(
                "center.joint",
                format!("{joint:?} belongs to no leg"),
            ));
        }
        Arc::make_mut(&mut self.skeleton)
            .set_center(j, center, gain)
            .map_err(|e| {
                let field = if e.path.ends_with("gain") {
                    "gain"
                } else {
                    "center"
                };
                DriverError::new(format!("center.{field}"), e.reason)
            })
    }

    /// Each leg's name and joints (skeleton indices, hip first).
    pub fn leg_joints(&self) -> impl Iterator<Item = (&str, &[usize])> {
        self.legs.iter().map(|l| (l.name.as_str(), l.ik.joints()))
    }

    /// Replaces the body path; the body joins it at the point closest to
    /// where it is and plans ahead along it (footholds already planned stay).
    /// With `speeds_mps` the body takes on the path's speed from there
    /// (eq. 14's ramp) and the gait at the next frame, then at the legs'
    /// mid-stances; without, the body keeps the speed it has.
    ///
    /// # Errors
    /// `path.…` naming the bad control point, speed or rule (a speed the gait
    /// cannot take on: `path.speeds_mps[i]`); nothing changes.
    pub fn set_path(&mut self, spec: &PathSpec) -> Result<(), DriverError> {
        let path = BodyPath::try_from(spec)
            .map_err(|e| DriverError::new(format!("path.{}", e.path), e.reason))?;
        self.check_path_speeds(&path, "path.speeds_mps")?;
        let here = self.track.interpolate(self.time).position;
        let distance = path.closest_distance(here);
        self.path = path;
        self.params.path = Some(spec.clone());
        self.path_speed_read_s = f64::NEG_INFINITY;
        self.track
            .follow_new_path(self.time, distance, &self.path, &self.gait);
        Ok(())
    }

    /// Name of the named gait in use.
    #[must_use]
    pub fn gait_name(&self) -> &str {
        &self.gait_name
    }

    /// Switches to the named gait; each leg takes it on at its next
    /// mid-stance ([`LegCycles`]), `P` and speed stay. Before the first
    /// frame the run simply starts in it.
    ///
    /// # Errors
    /// `gait` when the name is unknown for this leg count, or its stroke at
    /// this period and speed is out of range; nothing changes.
    pub fn set_gait(&mut self, name: &str) -> Result<(), DriverError> {
        let (phases, duty) =
            named_gait(name, self.legs.len()).map_err(|e| DriverError::new("gait", e.reason))?;
        let mut next = self.gait.clone();
        next.set_shape(&phases, duty)
            .map_err(|e| DriverError::new("gait", e.to_string()))?;
        self.adopt(name, next);
        Ok(())
    }

    /// Switches to the gait `name` with values `next`: before the first
    /// frame the run simply starts in it; later the legs take it on one by
    /// one ([`LegCycles`]).
    fn adopt(&mut self, name: &str, next: GaitParams) {
        name.clone_into(&mut self.gait_name);
        if !self.by_cycles && self.time == 0.0 {
            self.gait = next;
            self.reset();
        } else {
            self.take_cycles();
            self.gait = next;
        }
    }

    /// From now on the legs run on their own cycles, starting from eq. 9 on
    /// the gait they ran with (no-op when they already do).
    fn take_cycles(&mut self) {
        if !self.by_cycles {
            self.cycles.start(&self.steady_gait, self.time);
            self.by_cycles = true;
            self.centre_steady = false;
            self.bounds.start(
                &self.steady_gait,
                self.time,
                GRAVITY_MPS2,
                &self.pitch_weights,
            );
        }
    }

    /// Leg `i`'s latest mid-stance at or before now, seconds.
    #[must_use]
    pub fn mid_stance_s(&self, i: usize) -> Option<f64> {
        if self.by_cycles {
            return self.cycles.mid_stance_s(i, self.time, &self.gait);
        }
        let half = 0.5 * self.gait.support_s();
        let phase = self.gait.leg_phase(i, self.time)?;
        Some(self.time - (phase.state_s - half).rem_euclid(self.gait.period_s()))
    }

    /// Whether some leg has not yet taken on the gait's present values.
    #[must_use]
    pub fn is_shifting(&self) -> bool {
        self.by_cycles && !self.cycles.is_steady(self.time, &self.gait)
    }

    /// How far past `t_s` footholds are already planned, seconds: to the
    /// legs' next mid-stances (eq. 11's f₁).
    fn planned_ahead_s(&self, t_s: f64) -> f64 {
        let steady = self.gait.transfer_s() + 0.5 * self.gait.support_s();
        if !self.by_cycles {
            return steady;
        }
        (0..self.legs.len())
            .filter_map(|i| self.cycles.cycle_at(i, t_s, &self.gait))
            .map(|c| c.end_s() - t_s)
            .fold(steady, f64::max)
    }

    /// Leg `i`'s state at `t_s`: its own cycles after a change, eq. 9 before.
    fn leg_phase(&self, i: usize, t_s: f64) -> Option<LegPhase> {
        if self.by_cycles {
            self.cycles.leg_phase(i, t_s, &self.gait)
        } else {
            self.gait.leg_phase(i, t_s)
        }
    }

    /// The figures measured since the last reset.
    #[must_use]
    pub fn metrics(&self) -> &GaitMetrics {
        &self.metrics
    }

    /// Leg names, in leg order.
    pub fn leg_names(&self) -> impl Iterator<Item = &str> {
        self.legs.iter().map(|l| l.name.as_str())
    }

    /// The body path.
    #[must_use]
    pub fn path(&self) -> &BodyPath {
        &self.path
    }

    /// Each leg's foot target this frame and whether it is supporting.
    pub fn foot_targets(&self) -> impl Iterator<Item = (DVec3, bool)> + '_ {
        self.runs.iter().map(|r| (r.target, r.support))
    }

    /// The footholds planned for the feet now in transfer (eq. 11), world metres.
    pub fn footholds(&self) -> impl Iterator<Item = DVec3> + '_ {
        self.runs
            .iter()
            .filter(|r| !r.support)
            .map(|r| r.foothold_world)
    }

    /// Largest distance of the body's ground position from its path since
    /// the last reset, metres: how far it cut corners its legs could not
    /// take (`turn_within_reach`) or lagged behind the path.
    #[must_use]
    pub fn path_error_max_m(&self) -> f64 {
        self.path_error_max_m
    }

    /// This frame's fore-aft surge, metres ahead of the body's even motion
    /// along its path (0 when `scenario.poda.fore_aft_surge` is off).
    #[must_use]
    pub fn surge_m(&self) -> f64 {
        self.surge_m
    }

    /// This frame's distance of the body's ground position (the root, with
    /// its surge) from its path, metres.
    #[must_use]
    pub fn path_error_m(&self) -> f64 {
        let root = self.pose.root.position;
        let position = DVec2::new(root.x, root.z);
        let closest = self.path.sample(self.path.closest_distance(position));
        (closest.position - position).length()
    }

    /// Arc length of the desired point on the body path now, metres.
    #[must_use]
    pub fn path_distance_m(&self) -> f64 {
        self.track.interpolate(self.time).desired_m
    }

    /// The body's planned ground pose at time `t_s` (known about one gait
    /// period ahead of the current time).
    #[must_use]
    pub fn ground_pose(&self, t_s: f64) -> GroundPose {
        self.track.ground_pose(t_s)
    }

    /// The planned body motion.
    #[must_use]
    pub fn body_track(&self) -> &BodyTrack {
        &self.track
    }

    /// The constant that centres [`GaitParams::vertical_superposition_m`] so that, averaged over
    /// every leg's support phase, the body stands at its standing height (the
    /// legs then reach the ground however high the flights are). Recomputed
    /// only when the gait changes.
    fn vertical_centre_m(&mut self, t_s: f64) -> f64 {
        if self.by_cycles {
            // While a change is taken on, over the legs' own coming supports;
            // once they are steady, once.
            let steady = self.cycles.is_steady(t_s, &self.gait);
            if !(steady && self.centre_steady) {
                let g_n = self.gait.gravity_share_mps2(GRAVITY_MPS2);
                self.centre_m = self.cycles.vertical_centre_m(t_s, &self.gait, g_n, SAMPLES);
                self.centre_steady = steady;
            }
            return self.centre_m;
        }
        let key = [self.gait.period_s(), self.gait.duty_factor()];
        let unchanged = self.centre_key.0 == key && self.centre_key.1 == self.gait.phases();
        if !unchanged {
            self.centre_key.0 = key;
            self.centre_key.1.clear();
            self.centre_key.1.extend_from_slice(self.gait.phases());
            self.centre_m = eq9_centre_and_range_m(&self.gait, t_s, GRAVITY_MPS2).0;
        }
        self.centre_m
    }

    /// The root's height and the body's pitch slope (dy/dz, body frame) at
    /// `t_s`: eq. 12–13's superposition, centred, and the least-squares line
    /// of [`pitch_weights`] through the legs' sections, taken at the root.
    fn body_height_and_slope(&mut self, t_s: f64) -> (f64, f64) {
        let centre = self.vertical_centre_m(t_s);
        let gain = self.params.vertical_gain;
        let (sum, weighted) = if self.by_cycles {
            let g_n = self.gait.gravity_share_mps2(GRAVITY_MPS2);
            self.cycles
                .vertical_sums_m(t_s, &self.gait, g_n, &self.pitch_weights)
        } else {
            (
                self.gait.vertical_superposition_m(t_s, GRAVITY_MPS2),
                self.gait
                    .vertical_weighted_m(t_s, GRAVITY_MPS2, &self.pitch_weights),
            )
        };
        // The weights are 0 without `body_pitch`. While legs take a change
        // on, the pitch stays within the two steady gaits' (as the height
        // stays above their lowest point, `transition_low_m`).
        let slope = if self.by_cycles {
            self.bounds
                .refresh(&self.gait, t_s, GRAVITY_MPS2, &self.pitch_weights);
            gain * self.bounds.pitch_slope(weighted)
        } else {
            gain * weighted
        };
        let height = self.stand_height_m + gain * (sum - centre) - slope * self.legs_mean_z_m;
        (height, slope)
    }

    /// Eq. 11: the foothold of leg `i` for a lift-off at `t_lo`.
    fn plan_foothold(&mut self, i: usize, t_lo: f64) {
        // The touchdown (f₂) and the next mid-stance (f₁) of the cycle the
        // lift-off belongs to: fixed at the mid-stance before it.
        let (f1, f2) = match self.cycles.cycle_at(i, t_lo, &self.gait) {
            Some(cycle) if self.by_cycles => (cycle.end_s(), cycle.touchdown_s()),
            _ => {
                let transfer = self.gait.transfer_s();
                (
                    t_lo + transfer + 0.5 * self.gait.support_s(),
                    t_lo + transfer,
                )
            }
        };
        let foothold_world = self.ground_pose(f1).to_world(self.legs[i].reference_body);
        let liftoff_body = self.ground_pose(t_lo).to_body(self.runs[i].planted);
        let foothold_body = self.ground_pose(f2).to_body(foothold_world);
        let run = &mut self.runs[i];
        run.liftoff_body = liftoff_body;
        run.foothold_body = foothold_body;
        run.foothold_world = foothold_world;
    }

    /// The transfer target of leg `i` at time `t` with transfer progress `u`.
    fn transfer_target(&self, i: usize, t: f64, u: f64) -> DVec3 {
        let run = &self.runs[i];
        let key = eval_open(&self.keys, u);
        let body = run.liftoff_body.lerp(run.foothold_body, key.x);
        let mut world = self.ground_pose(t).to_world(body);
        world.y = key.y * self.params.step_height_m;
        world
    }

    /// Where leg `i` stands when supporting at mid-stance time `t_mid`.
    fn reference_world(&self, i: usize, t_mid: f64) -> DVec3 {
        self.ground_pose(t_mid)
            .to_world(self.legs[i].reference_body)
    }

    /// The leg-state stage for leg `i` between `t_prev` and `t`: lift-offs plan
    /// footholds, touchdowns plant the foot.
    fn advance_leg(&mut self, i: usize, t_prev: f64, phase: &LegPhase) {
        // Lift-off: the leg state passed the support duration since the last
        // frame. While a gait blend shifts the phases, `last_liftoff_s` (under
        // the current phases) may lie before the previous frame: the crossing
        // still happened in this frame, so the state decides, not the time.
        if self.runs[i].support && (!phase.support || phase.last_liftoff_s > t_prev) {
            let t_lo = phase.last_liftoff_s.clamp(t_prev, self.time);
            self.plan_foothold(i, t_lo);
            self.runs[i].support = false;
        }
        if !self.runs[i].support && phase.support {
            let t_td = phase.last_touchdown_s.clamp(t_prev, self.time);
            let landed = self.transfer_target(i, t_td, 1.0);
            self.runs[i].planted = DVec3::new(landed.x, 0.0, landed.z);
            self.runs[i].support = true;
        }
        self.runs[i].target = if self.runs[i].support {
            self.runs[i].planted
        } else {
            self.transfer_target(i, self.time, phase.fraction)
        };
        self.runs[i].progress = phase.fraction;
    }

    /// The key-centres stage: each leg with key centres takes this frame's
    /// centre angles and gains ([`super::key_centers::apply`]); legs without
    /// are left as they are (their joints' own).
    fn key_centers(&mut self) {
        for (leg, run) in self.legs.iter_mut().zip(&self.runs) {
            if leg.key_centers.is_empty() {
                continue;
            }
            key_centers::apply(
                &self.skeleton,
                &leg.key_centers,
                &mut leg.ik,
                (!run.support).then_some(run.progress),
                &mut self.center_points,
            );
        }
    }

    /// The IK stage: iterate every leg toward its target (one FK per iteration
    /// for the whole body), centering first, then exact steps.
    fn solve(&mut self, iterations: usize) {
        let tolerance = self.params.tolerance_m;
        let mut used = 0;
        for it in 0..iterations {
            used = it + 1;
            self.kin
                .update(&self.skeleton, &self.pose.root, &self.pose.joints);
            let worst = self
                .legs
                .iter()
                .zip(&self.runs)
                .map(|(leg, run)| {
                    (self.kin.effector_position[leg.ik.effector()] - run.target).length()
                })
                .fold(0.0, f64::max);
            if it > 0 && worst < tolerance {
                break;
            }
            let options = if it == 0 {
                &self.centering
            } else {
                &self.exact
            };
            for (leg, run) in self.legs.iter_mut().zip(&self.runs) {
                leg.ik.iterate(
                    &self.skeleton,
                    &self.kin,
                    &mut self.pose.joints,
                    run.target,
                    options,
                );
            }
        }
        self.kin
            .update(&self.skeleton, &self.pose.root, &self.pose.joints);
        self.effectors.copy_from_slice(&self.kin.effector_position);
        self.targets.position.copy_from_slice(&self.effectors);
        self.report.effector_error_m.fill(0.0);
        for (leg, run) in self.legs.iter().zip(&self.runs) {
            let e = leg.ik.effector();
            self.targets.position[e] = run.target;
            self.report.effector_error_m[e] = (self.effectors[e] - run.target).length();
        }
        self.report.iterations = used;
        self.report.max_error_m = self
            .report
            .effector_error_m
            .iter()
            .copied()
            .fold(0.0, f64::max);
    }

    fn place_body(&mut self, t: f64) {
        let ground = self.ground_pose(t);
        let (height, slope) = self.body_height_and_slope(t);
        // Nose up (the front higher, slope > 0) turns +z toward +y: about −x.
        self.pitch_rad = slope.patan2(1.0);
        self.surge_m = if !self.params.fore_aft_surge {
            0.0
        } else if self.by_cycles {
            let g_n = self.gait.gravity_share_mps2(GRAVITY_MPS2);
            let c = surge_coefficient(&self.gait, g_n, self.stand_height_m);
            self.cycles.surge_m(t, &self.gait, c)
        } else {
            surge_superposition_m(&self.gait, t, GRAVITY_MPS2, self.stand_height_m)
        };
        let surge = ground.to_world(DVec3::new(0.0, 0.0, self.surge_m));
        let rotation = ground.rotation() * DMat3::from_rotation_x(-self.pitch_rad);
        let height = if self.by_cycles {
            let planted = self
                .legs
                .iter()
                .zip(&self.runs)
                .filter(|(_, run)| run.support)
                .map(|(leg, run)| PlantedLeg {
                    hip_body: leg.hip_body,
                    length_m: leg.length_m,
                    foot: run.planted,
                });
            height
                .max(self.stand_height_m + self.bounds.low_m())
                .min(self.stand_height_m + self.bounds.high_m())
                .min(reach_ceiling_m(surge, rotation, planted))
        } else {
            height
        };
        self.pose.root = RootTransform {
            position: DVec3::new(surge.x, height, surge.z),
            rotation,
        };
    }

    fn record_metrics(&mut self, t_prev: f64, t: f64, first: bool) {
        let legs = &self.legs;
        let runs = &self.runs;
        let effectors = &self.effectors;
        let feet = legs
            .iter()
            .zip(runs)
            .map(|(leg, run)| (effectors[leg.ik.effector()], run.support));
        if first {
            self.metrics = GaitMetrics::new(legs.iter().map(|l| l.name.as_str()));
            self.stability.clear();
        }
        self.metrics
            .record(t_prev, t, feet, self.pose.root.position, self.pitch_rad);
        self.metrics.record_surge(self.surge_m);
        // The support feet's polygon against the body's centre, where PODA's
        // body dynamics put the mass.
        let down = legs
            .iter()
            .zip(runs)
            .filter(|(_, run)| run.support)
            .map(|(leg, _)| effectors[leg.ik.effector()])
            .map(|p| DVec2::new(p.x, p.z));
        let root = self.pose.root.position;
        self.stability.record(
            t_prev,
            t,
            down,
            DVec2::new(root.x, root.z),
            self.gait.period_s(),
        );
    }

    /// Static stability now: feet down, the margin of the body's centre over
    /// their support polygon, and the share of the last gait period it stood
    /// statically unstable ([`super::stability`]).
    #[must_use]
    pub fn stability(&self) -> StabilityReport {
        self.stability.report()
    }

    /// The support polygon of the feet down now (ground x, z), counter-clockwise.
    #[must_use]
    pub fn support_polygon(&self) -> &[DVec2] {
        self.stability.polygon()
    }
}

impl Driver for PodaDriver {
    fn step(&mut self, dt: f64) {
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        self.follow_path_speed();
        let t_prev = self.time;
        let t = t_prev + dt;
        let steady = &self.steady_gait;
        let rephased = self.gait.period_s() != steady.period_s()
            || self.gait.duty_factor() != steady.duty_factor()
            || self.gait.phases() != steady.phases();
        if rephased && !self.by_cycles && t_prev == 0.0 {
            // An edit before the first frame sets the gait the run starts in.
            self.reset();
        } else if rephased {
            // An edit since the last frame that eq. 9 would take on by
            // re-phasing every leg at once: the legs take it on one by one.
            self.take_cycles();
        }
        self.time = t;
        let key = [
            self.gait.speed_mps(),
            self.gait.period_s(),
            self.gait.duty_factor(),
        ];
        if key != self.track_key {
            // A gait edit: plan anew beyond the footholds already planned.
            self.track_key = key;
            let keep = self.planned_ahead_s(t_prev);
            self.track.replan(t_prev, keep, &self.path, &self.gait);
        }
        self.track.advance_to(t, &self.path, &self.gait);
        self.cycles.advance_to(t, &self.gait);
        for i in 0..self.legs.len() {
            if let Some(phase) = self.leg_phase(i, t) {
                self.advance_leg(i, t_prev, &phase);
            }
        }
        self.place_body(t);
        self.key_centers();
        self.solve(self.params.iterations_per_frame);
        self.record_metrics(t_prev, t, false);
        self.path_error_max_m = self.path_error_max_m.max(self.path_error_m());
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn reset(&mut self) {
        // A path with speeds: the run starts in the gait at its start's speed.
        if let Some(v) = self.path.desired_speed_mps(0.0)
            && v != self.gait.speed_mps()
            && let Ok((name, next, _)) = self.gait_at_speed(v)
        {
            if let Some(name) = name {
                name.clone_into(&mut self.gait_name);
            }
            self.gait = next;
        }
        self.path_speed_read_s = f64::NEG_INFINITY;
        self.time = 0.0;
        self.by_cycles = false;
        self.centre_steady = false;
        self.steady_gait.clone_from(&self.gait);
        self.pose.clone_from(&self.rest);
        self.track.reset(&self.path, &self.gait);
        self.track_key = [
            self.gait.speed_mps(),
            self.gait.period_s(),
            self.gait.duty_factor(),
        ];
        let support = self.gait.support_s();
        for i in 0..self.legs.len() {
            let Some(phase) = self.gait.leg_phase(i, 0.0) else {
                continue;
            };
            if phase.support {
                let planted = self.reference_world(i, phase.last_touchdown_s + 0.5 * support);
                self.runs[i].planted = DVec3::new(planted.x, 0.0, planted.z);
                self.runs[i].support = true;
                self.runs[i].target = self.runs[i].planted;
            } else {
                let planted = self.reference_world(i, phase.last_liftoff_s - 0.5 * support);
                self.runs[i].planted = DVec3::new(planted.x, 0.0, planted.z);
                self.plan_foothold(i, phase.last_liftoff_s);
                self.runs[i].support = false;
                self.runs[i].target = self.transfer_target(i, 0.0, phase.fraction);
                self.runs[i].progress = phase.fraction;
            }
        }
        self.path_error_max_m = 0.0;
        self.place_body(0.0);
        self.key_centers();
        self.solve(RESET_ITERATIONS);
        self.record_metrics(0.0, 0.0, true);
    }

    fn skeleton(&self) -> &Skeleton {
        &self.skeleton
    }

    fn pose(&self) -> &Pose {
        &self.pose
    }

    fn effector_positions(&self) -> &[DVec3] {
        &self.effectors
    }

    fn targets(&self) -> Option<&Targets> {
        Some(&self.targets)
    }

    fn ik_report(&self) -> Option<&IkFrameReport> {
        Some(&self.report)
    }
}
