//! PODA's fixed model (Girard & Maciejewski 1985): what the driver knows
//! once it is built — the legs (their limbs, the reference foot positions
//! eq. 11 carries into the world, hips and straight lengths), the rest pose
//! and stand height, the transfer spline's key leg positions and the
//! centres they carry ("Leg Support and Transfer Trajectories"), the body
//! path ("Horizontal Control"), the body's pitch weights (Figure 2), the IK
//! options (eq. 5–6) and which legs hold their foot's orientation (eq. 2's
//! last three components, [`super::foot_orientation`]). The stages read it
//! and never write it; only the driver's setters change it, between frames.

use std::sync::Arc;

use gaitlab_core::preset::poda::check_transfer_key_centers;
use gaitlab_core::preset::{Creature, PodaParams};
use gaitlab_core::terrain::Terrain;
use gaitlab_core::{Kinematics, Pose, Skeleton};
use glam::{DQuat, DVec2, DVec3};

use super::foot_orientation::{heading_rad, yaw_rotation};
use super::gait::{GaitError, GaitParams};
use super::gaits::{gait_names, named_gait};
use super::key_centers::{self, LegKeyCenters};
use super::leg_ik::LegIkOptions;
use super::path::BodyPath;
use super::transition::REACH;
use crate::DriverError;

/// Gravity, m/s².
pub const GRAVITY_MPS2: f64 = 9.81;
/// Length of the default straight path, metres (beyond it the path extrapolates).
const DEFAULT_PATH_M: f64 = 1000.0;
/// Fraction of the stroke the legs' reach allows that gait by speed uses
/// (the body bobs, pitches and surges around the stand height).
const STROKE_OF_REACH: f64 = 0.8;

/// A leg of the creature.
#[derive(Clone, Debug)]
pub struct PodaLeg {
    /// The leg's name (its effector's unless the scenario names it).
    pub name: String,
    /// The leg's joints (skeleton indices), hip first.
    pub joints: Vec<usize>,
    /// The foot effector.
    pub effector: usize,
    /// Reference (mid-stance) foot position in the body frame, on the ground.
    pub reference_body: DVec3,
    /// The hip joint's position relative to the root, body frame, metres.
    pub hip_body: DVec3,
    /// The straight leg's length from the hip joint to the foot, metres.
    pub length_m: f64,
    /// The leg's joints that key leg positions give centres and gains.
    pub key_centers: LegKeyCenters,
    /// Whether the leg holds its foot's orientation as well as its position
    /// (eq. 2's six components) where its joints' limits allow (the targets
    /// stage lets a refused foot go): `foot_orientation` is on and the leg
    /// has [`ORIENTATION_JOINTS`] joints or more.
    pub holds_orientation: bool,
    /// The foot's orientation in the rest pose relative to the body's
    /// ground yaw there (from the foot's frame to the body's level frame):
    /// carried by the ground yaw at a touchdown, the orientation the foot
    /// touches down with.
    pub rest_foot_rotation: DQuat,
}

/// The fewest joints a leg needs to hold its foot's orientation as well as
/// its position: one per component of eq. 2's end-effector vector.
pub const ORIENTATION_JOINTS: usize = 6;

/// What the stages read and never write (module docs).
#[derive(Clone, Debug)]
pub struct PodaModel {
    /// The creature's skeleton (joint centres and gains edited live).
    pub skeleton: Arc<Skeleton>,
    /// The PODA parameters in use (step height, transfer keys, options).
    pub params: PodaParams,
    /// The legs, in the named gaits' leg order.
    pub legs: Vec<PodaLeg>,
    /// Key leg positions `(along, height fraction, 0)` from lift-off `(0, 0)` to foothold `(1, 0)`.
    pub keys: Vec<DVec3>,
    /// The root's height standing, metres.
    pub stand_height_m: f64,
    /// The rest pose a restart starts from.
    pub rest: Pose,
    /// IK options of the first, centering iteration (eq. 6).
    pub centering: LegIkOptions,
    /// IK options of the later, exact iterations.
    pub exact: LegIkOptions,
    /// The body path.
    pub path: BodyPath,
    /// Per leg, the weight of its vertical contribution in the body's pitch
    /// slope ([`pitch_weights`]); all 0 when `body_pitch` is off.
    pub pitch_weights: Vec<f64>,
    /// Mean fore-aft position of the legs' reference feet, body frame, metres.
    pub legs_mean_z_m: f64,
    /// The longest stroke gait by speed gives the legs, metres.
    pub max_stroke_m: f64,
    /// The ground the feet stand on (`scenario.terrain`; the paper's floor
    /// when flat, [`crate::poda::terrain_feet`] otherwise).
    pub terrain: Terrain,
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
pub fn spline_keys(keys: &[[f64; 2]], out: &mut Vec<DVec3>) {
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

/// The legs of `params` on `skeleton`, standing `stand_height_m` high in `rest`.
fn legs(
    skeleton: &Skeleton,
    params: &PodaParams,
    rest: &Pose,
    stand_height_m: f64,
) -> Result<Vec<PodaLeg>, DriverError> {
    let rest_kin = Kinematics::of(skeleton, rest);
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
        let start = chain
            .iter()
            .position(|&j| j == hip)
            .ok_or_else(|| DriverError::new(at("hip"), "not on the chain of the leg's effector"))?;
        let foot = rest_kin.effector_position[effector] - rest.root.position;
        let mut length_m = 0.0;
        let mut last = rest_kin.joint_position[hip];
        for &j in &chain[start + 1..] {
            length_m += (rest_kin.joint_position[j] - last).length();
            last = rest_kin.joint_position[j];
        }
        length_m += (rest_kin.effector_position[effector] - last).length();
        let hip_body =
            rest.root.rotation.transpose() * (rest_kin.joint_position[hip] - rest.root.position);
        let joints = chain[start..].to_vec();
        let rest_yaw = yaw_rotation(heading_rad(rest.root.rotation));
        let rest_foot_rotation = (rest_yaw.conjugate()
            * DQuat::from_mat3(&rest_kin.effector_rotation[effector]))
        .normalize();
        legs.push(PodaLeg {
            hip_body,
            length_m,
            name: spec.name.clone().unwrap_or_else(|| spec.effector.clone()),
            holds_orientation: params.foot_orientation && joints.len() >= ORIENTATION_JOINTS,
            joints,
            effector,
            reference_body: DVec3::new(foot.x, -stand_height_m, foot.z),
            key_centers: LegKeyCenters::new(),
            rest_foot_rotation,
        });
    }
    if legs.is_empty() {
        return Err(DriverError::new("scenario.poda.legs", "no legs"));
    }
    Ok(legs)
}

/// The scenario's gait: its name and values (the leg count's first named
/// gait unless one is named; custom phases and duty factor over the named).
fn scenario_gait(params: &PodaParams, legs: usize) -> Result<(String, GaitParams), DriverError> {
    let gait_name = match &params.gait {
        Some(name) => name.clone(),
        None => gait_names(legs).next().unwrap_or("walk").to_owned(),
    };
    let (mut phases, mut duty) = named_gait(&gait_name, legs).map_err(gait_error)?;
    if let Some(custom) = &params.phases {
        phases.clone_from(custom);
    }
    if let Some(custom) = params.duty_factor {
        duty = custom;
    }
    let gait =
        GaitParams::new(params.period_s, duty, phases, params.speed_mps).map_err(gait_error)?;
    Ok((gait_name, gait))
}

impl PodaModel {
    /// The model of `creature` with `params`, and the scenario's gait (its
    /// name and values) the run starts in.
    ///
    /// # Errors
    /// A [`DriverError`] naming the scenario value that cannot be used (a
    /// leg's effector or hip, an unknown gait for the leg count, gait values
    /// out of range, a bad path, bad key centres).
    pub fn new(
        creature: &Creature,
        params: PodaParams,
    ) -> Result<(Self, String, GaitParams), DriverError> {
        let skeleton = Arc::new(creature.skeleton.clone());
        let rest = creature.rest_pose();
        let stand_height_m = params.stand_height_m.unwrap_or(rest.root.position.y);
        let mut legs = legs(&skeleton, &params, &rest, stand_height_m)?;
        let lowest_hip_m = legs
            .iter()
            .map(|leg| stand_height_m + leg.hip_body.y)
            .fold(f64::INFINITY, f64::min);
        super::terrain_fit::check_fits(&creature.scenario.terrain, &creature.name, lowest_hip_m)?;
        let (gait_name, gait) = scenario_gait(&params, legs.len())?;
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
            legs.iter().map(|l| (l.name.as_str(), l.joints.as_slice())),
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
        let max_stroke_m = legs
            .iter()
            .map(|leg| {
                let reach = REACH * leg.length_m;
                let hip = stand_height_m + leg.hip_body.y;
                2.0 * STROKE_OF_REACH * (reach * reach - hip * hip).max(0.0).sqrt()
            })
            .fold(f64::INFINITY, f64::min);
        let z: Vec<f64> = legs.iter().map(|l| l.reference_body.z).collect();
        let mut weights = Vec::with_capacity(legs.len());
        let legs_mean_z_m = pitch_weights(&z, &mut weights);
        if !params.body_pitch {
            weights.fill(0.0);
        }
        let model = Self {
            skeleton,
            params,
            legs,
            keys,
            stand_height_m,
            rest,
            centering,
            exact,
            path,
            pitch_weights: weights,
            legs_mean_z_m,
            max_stroke_m,
            terrain: creature.scenario.terrain.clone(),
        };
        Ok((model, gait_name, gait))
    }
}
