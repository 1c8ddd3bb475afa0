//! PODA's changing state (Girard & Maciejewski 1985): what the stages
//! write frame by frame — the time and the gait with the legs' clock (eq. 9
//! or their own cycles), the body's planned track (eq. 14–15 and yaw) and
//! pose, each leg's run (support, planted foot, footholds of eq. 11, foot
//! target and, where the leg holds it, the foot's orientation target of
//! eq. 2), the IK's pose and workspace (eq. 5–6), the metrics, and the
//! live edits queued since the last frame ([`super::edits`]).

use gaitlab_core::driver::IkFrameReport;
use gaitlab_core::ik::Targets;
use gaitlab_core::preset::Creature;
use gaitlab_core::preset::poda::MAX_TRANSFER_KEYS;
use gaitlab_core::{Kinematics, Pose};
use glam::{DQuat, DVec2, DVec3};

use super::body_track::{BodyDynamics, BodyTrack};
use super::edits::Edits;
use super::gait::{GaitParams, LegPhase};
use super::gait_metrics::GaitMetrics;
use super::leg_clock::LegClock;
use super::leg_ik::LegIk;
use super::model::{GRAVITY_MPS2, PodaModel};
use super::stability::StabilityMeter;
use super::transition::TransitionBounds;
use super::vertical_centre::VerticalCentre;

/// A leg's running state.
#[derive(Clone, Copy, Debug, Default)]
pub struct LegRun {
    /// Whether the foot supports.
    pub support: bool,
    /// Where the foot stands while supporting, world metres.
    pub planted: DVec3,
    /// Lift-off point in the body frame at lift-off.
    pub liftoff_body: DVec3,
    /// Planned foothold in the body frame at touchdown (eq. 11, f₂).
    pub foothold_body: DVec3,
    /// Planned foothold in the world (eq. 11, f₁, on the ground: where an
    /// uneven spot moved it, [`crate::poda::terrain_feet`]).
    pub foothold_world: DVec3,
    /// Eq. 11's own spot on the ground, before an uneven one moved.
    pub foothold_nominal: DVec3,
    /// Whether eq. 11's spot was unacceptable and the foothold moved.
    pub foothold_moved: bool,
    /// The highest ground between the lift-off point and the foothold,
    /// metres (the transfer's apex clears it by the step height).
    pub highest_m: f64,
    /// The foot's target this frame, world metres.
    pub target: DVec3,
    /// The transfer's progress this frame, the foot spline's parameter in
    /// [0, 1] (meaningless while supporting).
    pub progress: f64,
    /// The leg's state this frame (eq. 9 or its cycle); `None` leaves the
    /// leg as it was.
    pub phase: Option<LegPhase>,
    /// This frame's lift-off time, when the foot lifted since the last frame.
    pub liftoff_s: Option<f64>,
    /// This frame's touchdown time, when the foot landed since the last frame.
    pub touchdown_s: Option<f64>,
    /// The orientation the foot touched down with (eq. 2; from the foot's
    /// frame to the world), held through the support and turned from in
    /// the transfer after it. Kept only for a leg that holds its foot's
    /// orientation (identity for the others).
    pub planted_rotation: DQuat,
    /// The foot's orientation target this frame (eq. 2; from the foot's
    /// frame to the world): the planted orientation in support, on its way
    /// to the touchdown orientation in transfer. Kept only for a leg that
    /// holds its foot's orientation (identity for the others).
    pub rotation_target: DQuat,
    /// Whether the leg holds its foot's orientation now, in this support and
    /// the transfer after it (decided at each touchdown; only for a leg of
    /// six joints or more with `foot_orientation` on).
    pub holding: bool,
    /// Supports in a row in which the leg's joints refused its planted
    /// foot's orientation (the foot ended a frame more than a degree from
    /// it); 0 after a support held to its lift-off.
    pub orientation_refusals: u32,
    /// Supports the leg still holds its foot's position alone after its
    /// last refusal (one after the first refusal in a row, doubling with
    /// each further one, at most eight).
    pub supports_alone: u32,
}

/// What the stages write (module docs).
#[derive(Clone, Debug)]
pub struct PodaState {
    /// Seconds since the restart.
    pub time: f64,
    /// The gait model (period, duty factor, phases, stroke, speed).
    pub gait: GaitParams,
    /// Name of the named gait in use.
    pub gait_name: String,
    /// Eq. 9 or the legs' own cycles.
    pub clock: LegClock,
    /// The lab's bounds on the body while legs take a change on.
    pub bounds: TransitionBounds,
    /// The constant that centres the vertical superposition.
    pub centre: VerticalCentre,
    /// The body's planned ground motion (eq. 14–15 and yaw).
    pub track: BodyTrack,
    /// Each leg's running state.
    pub runs: Vec<LegRun>,
    /// Each leg's IK, with its workspace and this frame's centre angles.
    pub ik: Vec<LegIk>,
    /// Control points of one joint's centre and gain along the transfer
    /// (scratch of the key-centres step).
    pub center_points: Vec<DVec3>,
    /// The pose this frame.
    pub pose: Pose,
    /// The joints before this frame's IK (scratch of the IK stage, which
    /// solves a frame again at a smaller pitch where a planted foot slips).
    pub joints_before: Vec<f64>,
    /// Forward kinematics of the pose.
    pub kin: Kinematics,
    /// Every effector's target this frame (the feet's, the others where they are).
    pub targets: Targets,
    /// Every effector's position this frame.
    pub effectors: Vec<DVec3>,
    /// Each foot's distance to its target after the frame's IK (other effectors 0).
    pub report: IkFrameReport,
    /// This frame's body pitch, radians (positive: nose up).
    pub pitch_rad: f64,
    /// The pitch of the ground under the legs this frame, radians (0 on
    /// the floor): the part of [`PodaState::pitch_rad`] the ground gives
    /// ([`crate::poda::terrain_feet`]), which the IK stage keeps when it
    /// eases the gait's pitch for a planted foot.
    pub ground_pitch_rad: f64,
    /// The root's height standing on the ground under the legs this frame,
    /// world metres: the stand height above the ground line at the root
    /// (the stand height on the floor), toward which the IK stage eases the
    /// gait's height with its pitch.
    pub ground_root_m: f64,
    /// Footholds moved off an unacceptable spot since the restart
    /// ([`crate::poda::terrain_feet`]).
    pub footholds_moved: u64,
    /// Frames on ground that is not flat in which the body eased its gait's
    /// height and pitch toward the ground's since the restart, and the least
    /// fraction of them it kept (1 when none;
    /// [`crate::poda::terrain_feet`]).
    pub eased: (u64, f64),
    /// This frame's fore-aft surge, metres forward (0 when `fore_aft_surge` is off).
    pub surge_m: f64,
    /// The figures measured since the last restart.
    pub metrics: GaitMetrics,
    /// Static stability of the support feet, measured every frame.
    pub stability: StabilityMeter,
    /// Largest distance of the body from its path since the last restart, metres.
    pub path_error_max_m: f64,
    /// The latest mid-stance of any leg at which the gait read the path's
    /// speed, seconds (a path with speeds).
    pub path_speed_read_s: f64,
    /// The live edits queued since the last frame.
    pub edits: Edits,
    /// Whether some leg had not yet taken the gait on at the last frame
    /// (the targets stage forgets the legs' refused orientations when they
    /// all have).
    pub legs_were_shifting: bool,
}

/// The body's dynamics options of `model` (eq. 14–15 and yaw).
fn body_dynamics(model: &PodaModel) -> BodyDynamics {
    let params = &model.params;
    BodyDynamics {
        mass_kg: params.body_mass_kg,
        max_leg_force_n: params
            .max_leg_force_n
            .unwrap_or(params.body_mass_kg * GRAVITY_MPS2),
        min_turn_radius_m: if params.turn_within_reach {
            model
                .legs
                .iter()
                .map(|l| DVec2::new(l.reference_body.x, l.reference_body.z).length())
                .fold(0.0, f64::max)
        } else {
            0.0
        },
        max_lead_strokes: if params.turn_within_reach { 1.0 } else { 0.0 },
        yaw_toward_actual: params.yaw_toward_actual,
        ..BodyDynamics::default()
    }
}

impl PodaState {
    /// The state of `creature` on `model` before its restart, in the gait
    /// `gait_name` with values `gait`.
    #[must_use]
    pub fn new(
        creature: &Creature,
        model: &PodaModel,
        gait_name: String,
        gait: GaitParams,
    ) -> Self {
        let n = model.legs.len();
        let effectors = model.skeleton.effector_count();
        Self {
            time: 0.0,
            clock: LegClock::new(&gait),
            gait,
            gait_name,
            bounds: TransitionBounds::default(),
            centre: VerticalCentre::default(),
            track: BodyTrack::new(creature.scenario.frame_seconds(), body_dynamics(model)),
            runs: vec![LegRun::default(); n],
            ik: model
                .legs
                .iter()
                .map(|leg| LegIk::new(leg.joints.clone(), leg.effector))
                .collect(),
            center_points: Vec::with_capacity(MAX_TRANSFER_KEYS + 2),
            pose: model.rest.clone(),
            joints_before: model.rest.joints.clone(),
            kin: Kinematics::new(&model.skeleton),
            targets: Targets {
                position: vec![DVec3::ZERO; effectors],
                rotation: Vec::new(),
            },
            effectors: vec![DVec3::ZERO; effectors],
            report: IkFrameReport::new(effectors),
            pitch_rad: 0.0,
            ground_pitch_rad: 0.0,
            ground_root_m: 0.0,
            footholds_moved: 0,
            eased: (0, 1.0),
            surge_m: 0.0,
            metrics: GaitMetrics::new(model.legs.iter().map(|l| l.name.as_str())),
            stability: StabilityMeter::default(),
            path_error_max_m: 0.0,
            path_speed_read_s: f64::NEG_INFINITY,
            edits: Edits::new(n),
            legs_were_shifting: false,
        }
    }

    /// From now on the legs run on their own cycles, starting from eq. 9 on
    /// the gait they ran with (no-op when they already do); `pitch_weights`
    /// are the model's.
    pub fn take_cycles(&mut self, pitch_weights: &[f64]) {
        if self.clock.start_cycles(self.time) {
            self.centre.cycles_started();
            self.bounds
                .start(self.clock.steady(), self.time, GRAVITY_MPS2, pitch_weights);
        }
    }
}
