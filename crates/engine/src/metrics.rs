//! The figures a run reports — DESIGN.md's metric keys, one serializable type
//! for every front end: `gaitlab run --json` and `gaitlab track --json` print
//! it, the page's `state()` carries it as `views[0].metrics`. IK tracking (She 2006
//! §5.3's effector distance `d`), PODA gaits as measured from the motion
//! (Girard & Maciejewski 1985: duty factor, relative phase, stride, slip), and
//! Raibert & Hodgins 1991's Table-2 quantities.
//!
//! The engine layer reads no clocks: wall-time figures come in a [`Timing`]
//! measured by the caller around [`gaitlab_core::driver::Driver::step`].

use gaitlab_core::driver::{Driver, IkMetrics};
use gaitlab_core::{Pose, Skeleton};
use gaitlab_motion::PodaDriver;
use gaitlab_physics::PhysicsDriver;
use serde::Serialize;

use crate::AnyDriver;

/// What the caller measured while driving.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Timing {
    /// Frames stepped.
    pub frames: usize,
    /// Wall time spent inside `Driver::step`, milliseconds.
    pub step_ms: f64,
    /// The whole loop including output, milliseconds.
    pub wall_ms: f64,
    /// Whether every joint value stayed finite and within its limits.
    pub within_limits: bool,
}

impl Timing {
    /// Microseconds per stepped frame (0 before any frame).
    #[must_use]
    pub fn us_per_frame(&self) -> f64 {
        if self.frames > 0 {
            self.step_ms * 1e3 / self.frames as f64
        } else {
            0.0
        }
    }
}

/// Whether every joint value of `pose` is finite and within its limits
/// (1e-9 slack): [`Timing::within_limits`] holds this for every frame.
#[must_use]
pub fn pose_within_limits(skeleton: &Skeleton, pose: &Pose) -> bool {
    pose.joints
        .iter()
        .zip(skeleton.joints())
        .all(|(value, joint)| {
            value.is_finite()
                && joint
                    .limits
                    .is_none_or(|(lo, hi)| *value >= lo - 1e-9 && *value <= hi + 1e-9)
        })
}

/// A run's figures, by engine (serialized without a tag: the `engine` key says which).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum RunMetrics {
    /// Thesis motions and recorded-target tracking.
    Ik(IkRunMetrics),
    /// PODA gaits.
    Gait(GaitRunMetrics),
    /// Physical simulation.
    Physics(PhysicsRunMetrics),
}

impl RunMetrics {
    /// The figures of `driver` after a run of preset `preset` that `timing` measured.
    #[must_use]
    pub fn of(preset: &str, driver: &AnyDriver, timing: &Timing) -> Self {
        let additions: Vec<&'static str> = driver.lab_additions().iter().map(|a| a.name).collect();
        match driver {
            AnyDriver::Poda(poda) => {
                Self::Gait(GaitRunMetrics::of(preset, poda, timing, additions))
            }
            AnyDriver::Physics(physics) => {
                Self::Physics(PhysicsRunMetrics::of(preset, physics, timing, additions))
            }
            AnyDriver::Thesis(thesis) => {
                let mut metrics = IkRunMetrics::of(preset, "ik", driver, timing, additions);
                metrics.mode = Some(thesis.mode().name());
                metrics.speed_mps = Some(thesis.script().speed_mps());
                metrics.distance_m = Some(thesis.distance_m());
                Self::Ik(metrics)
            }
            AnyDriver::Track(_) => {
                Self::Ik(IkRunMetrics::of(preset, "track", driver, timing, additions))
            }
        }
    }

    /// The same figures with the run's frame rate (`fps`) added; the physics
    /// figures have none (the simulation steps at its own `dt`).
    #[must_use]
    pub fn with_fps(mut self, fps: f64) -> Self {
        match &mut self {
            Self::Ik(ik) => ik.fps = Some(fps),
            Self::Gait(gait) => gait.fps = Some(fps),
            Self::Physics(_) => {}
        }
        self
    }
}

/// One effector's tracking over a run (She 2006 §5.3's `d`, split into
/// reachable and unreachable targets, and the oscillation §5.3 describes);
/// docs/ik-metrics.md defines each figure.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EffectorMetrics {
    /// Effector name.
    pub name: String,
    /// Mean distance to its target over the finite frames, metres.
    pub mean_error_m: Option<f64>,
    /// Largest distance to its target, metres (infinite if a frame went non-finite).
    pub max_error_m: Option<f64>,
    /// Length of the effector's limb (the joints below its chain's shared
    /// root), metres: the reach its targets are measured against.
    pub limb_length_m: f64,
    /// Fraction of the frames whose target lay within the limb's length of the
    /// limb's first joint (null before any frame).
    pub reachable: Option<f64>,
    /// Mean distance to its target over the frames it was reachable, metres
    /// (null without such frames).
    pub mean_error_reachable_m: Option<f64>,
    /// Mean distance to its target over the frames it was out of reach, metres
    /// (null without such frames).
    pub mean_error_unreachable_m: Option<f64>,
    /// Oscillation of the limb's joints, Hz: reversals of each joint's per-frame
    /// Δθ (|Δθ| ≥ 1e-6 rad) per second, averaged over the joints (a smooth
    /// swing at f Hz gives 2f; null for a limb without joints).
    pub oscillation_hz: Option<f64>,
    /// Jitter of the limb's joints: mean |Δ²θ|, radians per frame² (null for a
    /// limb without joints).
    pub jitter_rad: Option<f64>,
}

impl EffectorMetrics {
    /// Effector `e`'s figures since the reset (the one place they are
    /// gathered: `--json`, `state()` and the side-by-side cards).
    #[must_use]
    pub fn of(skeleton: &Skeleton, metrics: &IkMetrics, e: usize) -> Self {
        Self {
            name: skeleton
                .effectors()
                .get(e)
                .map_or_else(String::new, |effector| effector.name.clone()),
            mean_error_m: metrics.mean_error_m(e),
            max_error_m: metrics.max_error_m(e),
            limb_length_m: skeleton.limbs().get(e).map_or(0.0, |limb| limb.length_m),
            reachable: metrics.reachable(e),
            mean_error_reachable_m: metrics.mean_error_reachable_m(e),
            mean_error_unreachable_m: metrics.mean_error_unreachable_m(e),
            oscillation_hz: metrics.oscillation_hz(e),
            jitter_rad: metrics.jitter_rad(e),
        }
    }
}

/// DESIGN.md's `always` and `IK` keys.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct IkRunMetrics {
    /// Preset name.
    pub preset: String,
    /// `ik`, or `track` for recorded targets.
    pub engine: &'static str,
    /// IK method.
    pub method: &'static str,
    /// Frames stepped.
    pub frames: usize,
    /// Simulated seconds.
    pub sim_seconds: f64,
    /// Wall time of the run, milliseconds.
    pub wall_ms: f64,
    /// IK iterations run.
    pub iterations: u64,
    /// Wall time per IK iteration, µs.
    pub us_per_iteration: f64,
    /// Wall time per frame, µs.
    pub us_per_frame: f64,
    /// Each effector's tracking error.
    pub effectors: Vec<EffectorMetrics>,
    /// Whether every joint value stayed finite and within its limits.
    pub within_limits: bool,
    /// Frames whose solve went non-finite and was undone.
    pub restored_frames: u64,
    /// The lab's additions to She 2006 in force (empty: the thesis alone;
    /// [`AnyDriver::lab_additions`] gives each one's reason).
    pub lab_additions: Vec<&'static str>,
    /// Thesis motion (engine `ik`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mode: Option<&'static str>,
    /// The motion's speed, m/s (engine `ik`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_mps: Option<f64>,
    /// Distance walked, metres (engine `ik`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub distance_m: Option<f64>,
    /// Frames per second of the run (set by the front end).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fps: Option<f64>,
    /// The recorded targets' file (`gaitlab track`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub targets_file: Option<String>,
}

impl IkRunMetrics {
    fn of(
        preset: &str,
        engine: &'static str,
        driver: &AnyDriver,
        timing: &Timing,
        lab_additions: Vec<&'static str>,
    ) -> Self {
        let skeleton = driver.skeleton();
        let (iterations, effectors, sim_seconds, restored_frames) = match driver.ik_metrics() {
            Some(metrics) => (
                metrics.iterations,
                (0..skeleton.effector_count())
                    .map(|e| EffectorMetrics::of(skeleton, metrics, e))
                    .collect(),
                metrics.sim_seconds,
                metrics.restored_frames,
            ),
            None => (0, Vec::new(), driver.time(), 0),
        };
        let us_per_iteration = if iterations > 0 {
            timing.step_ms * 1e3 / iterations as f64
        } else {
            0.0
        };
        let method = driver
            .ik_options()
            .map_or("", |options| options.method.name());
        Self {
            preset: preset.to_owned(),
            engine,
            method,
            frames: timing.frames,
            sim_seconds,
            wall_ms: timing.wall_ms,
            iterations,
            us_per_iteration,
            us_per_frame: timing.us_per_frame(),
            effectors,
            within_limits: timing.within_limits,
            restored_frames,
            lab_additions,
            mode: None,
            speed_mps: None,
            distance_m: None,
            fps: None,
            targets_file: None,
        }
    }
}

/// One PODA leg's measured duty factor and relative phase beside the gait's.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GaitLegMetrics {
    /// Leg name.
    pub name: String,
    /// Measured duty factor (eq. 7).
    pub duty_factor: Option<f64>,
    /// Measured relative phase (eq. 9), a fraction of the period.
    pub relative_phase: Option<f64>,
    /// The gait's duty factor.
    pub duty_factor_set: f64,
    /// The gait's relative phase.
    pub relative_phase_set: f64,
    /// Largest horizontal drift of this planted foot, metres.
    pub slip_max_m: f64,
}

/// DESIGN.md's `always` and `gait` keys, plus the gait's parameters beside
/// what was measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GaitRunMetrics {
    /// Preset name.
    pub preset: String,
    /// `poda`.
    pub engine: &'static str,
    /// Frames recorded.
    pub frames: u64,
    /// Simulated seconds.
    pub sim_seconds: f64,
    /// Wall time of the run, milliseconds.
    pub wall_ms: f64,
    /// Wall time per frame, µs.
    pub us_per_frame: f64,
    /// Gait name.
    pub gait: String,
    /// The gaits this creature's leg count has.
    pub gaits_available: Vec<&'static str>,
    /// Largest horizontal drift of any planted foot during support, metres.
    pub foot_slip_max_m: f64,
    /// The legs that hold their foot's orientation as well as its position
    /// where their joints' limits allow (Girard & Maciejewski 1985 eq. 2's
    /// six components: legs of six joints or more, with
    /// `scenario.poda.foot_orientation` on); empty when none.
    pub foot_orientation_legs: Vec<String>,
    /// Largest turn of any planted foot during its support, degrees: the
    /// angle of its orientation from the one it had at the support's start.
    pub foot_turn_max_deg: f64,
    /// Largest distance of the body from its path, metres (corners it cut).
    pub path_error_max_m: f64,
    /// Each leg's figures.
    pub legs: Vec<GaitLegMetrics>,
    /// Measured period, seconds.
    pub period_s: Option<f64>,
    /// The gait's period, seconds.
    pub period_s_set: f64,
    /// Measured stride, metres.
    pub stride_length_m: Option<f64>,
    /// Measured body speed, m/s.
    pub body_speed_mps: f64,
    /// The gait's speed, m/s.
    pub speed_mps_set: f64,
    /// The gait's stroke, metres.
    pub stroke_m: f64,
    /// The gait's duty factor β.
    pub duty_factor_set: f64,
    /// Each leg's upward force during support, newtons (eq. 12–13).
    pub leg_force_n_set: f64,
    /// Lowest and highest body height, metres.
    pub body_height_range_m: [f64; 2],
    /// Lowest and highest body pitch, degrees (positive: nose up; Figure 2).
    pub body_pitch_range_deg: [f64; 2],
    /// Most the body fell behind and ran ahead of its even motion along the
    /// path, metres (the fore-aft surge, `scenario.poda.fore_aft_surge`).
    pub body_surge_range_m: [f64; 2],
    /// Longest time with no foot planted, seconds.
    pub flight_duration_max_s: f64,
    /// Whether every joint value stayed finite and within its limits.
    pub within_limits: bool,
    /// The lab's additions to Girard & Maciejewski in force, and Figure 2's
    /// body pitch where it is left out (`without_body_pitch`); empty: the
    /// paper alone ([`AnyDriver::lab_additions`] gives reasons).
    pub lab_additions: Vec<&'static str>,
    /// Frames per second of the run (set by the front end).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fps: Option<f64>,
    /// On ground that is not flat (`scenario.terrain`), what the walk over
    /// it measured; absent on the floor.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub terrain: Option<TerrainRunMetrics>,
}

/// A walk or run over ground that is not flat (issue 45 items 2 and 3).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TerrainRunMetrics {
    /// The terrain's kind (`plane`, `stairs`, `height_field`, `rough`).
    pub kind: &'static str,
    /// Horizontal distance from the root's start to its end, metres.
    pub made_good_m: f64,
    /// The root's height at the end above its start, metres.
    pub climbed_m: f64,
    /// Deepest any foot went below the ground under it at a frame, metres
    /// (0 or less: never below).
    pub foot_below_ground_max_m: f64,
    /// Footholds moved off a spot too steep or too near an edge.
    pub footholds_moved: u64,
    /// PODA: frames in which the body eased its gait's height and pitch
    /// toward the ground's so that its legs hold their feet (`terrain_feet`
    /// rule 5; 0 for physics).
    pub body_eased_frames: u64,
    /// PODA: the least fraction of the gait's height and pitch the body kept
    /// in those frames (1 when none, and for physics).
    pub body_eased_least_kept: f64,
    /// Physics: the lowest and highest trunk height above the ground under
    /// it after settling, metres (absent for PODA).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trunk_height_range_m: Option<[f64; 2]>,
}

impl GaitRunMetrics {
    fn of(
        preset: &str,
        driver: &PodaDriver,
        timing: &Timing,
        lab_additions: Vec<&'static str>,
    ) -> Self {
        let metrics = driver.metrics();
        let gait = driver.gait();
        let period = metrics.period_s();
        let legs = metrics
            .legs
            .iter()
            .zip(gait.phases())
            .map(|(leg, &phase)| GaitLegMetrics {
                name: leg.name.clone(),
                duty_factor: leg.duty_factor(),
                relative_phase: period.and_then(|p| leg.relative_phase(p)),
                duty_factor_set: gait.duty_factor(),
                relative_phase_set: phase,
                slip_max_m: leg.slip_max_m,
            })
            .collect();
        let speed = metrics.body_speed_mps();
        let (low, high) = metrics.body_height_range_m;
        Self {
            preset: preset.to_owned(),
            engine: "poda",
            frames: metrics.frames,
            sim_seconds: metrics.sim_seconds,
            wall_ms: timing.wall_ms,
            us_per_frame: timing.us_per_frame(),
            gait: driver.gait_name().to_owned(),
            gaits_available: gaitlab_motion::poda::gait_names(gait.leg_count()).collect(),
            foot_slip_max_m: metrics.foot_slip_max_m(),
            foot_orientation_legs: metrics.orientation_legs().map(str::to_owned).collect(),
            foot_turn_max_deg: metrics.foot_turn_max_rad().to_degrees(),
            path_error_max_m: driver.path_error_max_m(),
            legs,
            period_s: period,
            period_s_set: gait.period_s(),
            stride_length_m: period.map(|p| p * speed),
            body_speed_mps: speed,
            speed_mps_set: gait.speed_mps(),
            stroke_m: gait.stroke_m(),
            duty_factor_set: gait.duty_factor(),
            leg_force_n_set: driver.leg_force_n(),
            body_height_range_m: [low, high],
            body_pitch_range_deg: [
                metrics.body_pitch_range_rad.0.to_degrees(),
                metrics.body_pitch_range_rad.1.to_degrees(),
            ],
            body_surge_range_m: [metrics.body_surge_range_m.0, metrics.body_surge_range_m.1],
            flight_duration_max_s: metrics.flight_max_s,
            within_limits: timing.within_limits,
            lab_additions,
            fps: None,
            terrain: terrain_metrics(driver),
        }
    }
}

/// The terrain figures of a PODA walk, `None` on the floor.
fn terrain_metrics(driver: &PodaDriver) -> Option<TerrainRunMetrics> {
    let terrain = driver.terrain();
    if terrain.is_flat() {
        return None;
    }
    let metrics = driver.metrics();
    let (first, last) = metrics.root_first_last.unwrap_or_default();
    Some(TerrainRunMetrics {
        kind: terrain.kind_name(),
        made_good_m: glam::DVec2::new(last.x - first.x, last.z - first.z).length(),
        climbed_m: last.y - first.y,
        foot_below_ground_max_m: metrics.below_ground_max_m,
        footholds_moved: driver.footholds_moved(),
        body_eased_frames: driver.body_eased().0,
        body_eased_least_kept: driver.body_eased().1,
        trunk_height_range_m: None,
    })
}

/// The terrain figures of a physics run, `None` on the floor: made good
/// and climbed by the centre of mass from the end of settling to the end.
fn physics_terrain_metrics(driver: &PhysicsDriver) -> Option<TerrainRunMetrics> {
    let surface = &driver.sim().terrain.surface;
    if surface.is_flat() {
        return None;
    }
    let s = driver.summary();
    let (first, last) = s.com_first_last.unwrap_or_default();
    let (low, high) = s.trunk_height_range_m;
    Some(TerrainRunMetrics {
        kind: surface.kind_name(),
        made_good_m: glam::DVec2::new(last.x - first.x, last.z - first.z).length(),
        climbed_m: last.y - first.y,
        foot_below_ground_max_m: s.foot_below_ground_max_m,
        footholds_moved: 0,
        body_eased_frames: 0,
        body_eased_least_kept: 1.0,
        trunk_height_range_m: low.is_finite().then_some([low, high]),
    })
}

/// One physics leg's mean stance time.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PhysicsLegMetrics {
    /// Leg name.
    pub name: String,
    /// Mean stance duration, seconds.
    pub stance_duration_s: f64,
}

/// One row of Raibert & Hodgins 1991's Table 2 (animation column) beside
/// the run's figure: DESIGN.md's `table2` entries.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Table2Entry {
    /// The quantity as the paper words it.
    pub quantity: &'static str,
    /// The paper's animation figure.
    pub paper: f64,
    /// The run's figure (`null` when the run has none, e.g. no flight yet).
    pub measured: Option<f64>,
    /// `(measured / paper − 1) · 100`, percent.
    pub diff_pct: Option<f64>,
    /// `true` for a desired speed: an input of the run, not a result.
    pub input: bool,
}

/// How nearly one virtual leg's legs act in unison, in `run --json`
/// (`gaitlab_physics::engine::pair_timing`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PairTimingEntry {
    /// The pair's legs, the one meant to land first first.
    pub legs: [String; 2],
    /// Mean gap between the two touchdowns of a shared stance (s).
    pub touchdown_gap_s: f64,
    /// Mean gap between the two lift-offs (s).
    pub liftoff_gap_s: f64,
    /// Stances of the first leg the second shared.
    pub shared: usize,
    /// Stances of the first leg the second did not touch down in.
    pub alone: usize,
}

/// One time the creature was put back at the start, in `run --json`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PutBackEntry {
    /// Seconds into the whole run (the attempt clocks added up).
    pub run_time_s: f64,
    /// The guard's message.
    pub why: String,
}

/// One push of the run and what followed (`run --push`, `run --json`'s
/// `pushes`, `state().physics.pushes`; `gaitlab_physics::engine::push`).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct PushEntry {
    /// Seconds into the whole run.
    pub at_s: f64,
    /// The change of the trunk's velocity, world [x (sideways), z
    /// (forward at heading 0)], m/s.
    pub dv_mps: [f64; 2],
    /// The desired speed then, m/s.
    pub desired_mps: f64,
    /// Forward speed over the last second of the five after the push, m/s
    /// (none when the run ended sooner or the creature fell).
    pub speed_after_mps: Option<f64>,
    /// Whether it fell or was put back within those five seconds.
    pub fell: bool,
    /// No fall, and that speed within 10 % of the desired one; none when
    /// the run ended before the five seconds were up.
    pub recovered: Option<bool>,
}

/// The run's pushes with their recoveries, in order.
#[must_use]
pub fn push_entries(driver: &PhysicsDriver) -> Vec<PushEntry> {
    driver
        .pushes()
        .iter()
        .map(|p| PushEntry {
            at_s: p.at_s,
            dv_mps: p.dv_mps,
            desired_mps: p.desired_mps,
            speed_after_mps: p.speed_after_mps,
            fell: p.fell,
            recovered: p.recovered(),
        })
        .collect()
}

/// One gait change as it took effect (`run --switch`, `run --json`'s
/// `gait_changes`; `gaitlab_physics::engine::gait_change`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GaitChangeEntry {
    /// Seconds into the whole run the new gait's controller took over.
    pub at_s: f64,
    /// The gait that ran before.
    pub from: &'static str,
    /// The gait that runs since.
    pub to: &'static str,
    /// `take_over` (the paper's, at a flight) or `own_start` (the lab's
    /// `switch_to_start`).
    pub entry: &'static str,
}

/// DESIGN.md's `always` and `physics` keys plus Table 2's extras.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PhysicsRunMetrics {
    /// Preset name.
    pub preset: String,
    /// `physics`.
    pub engine: &'static str,
    /// Frames stepped.
    pub frames: usize,
    /// Simulated seconds.
    pub sim_seconds: f64,
    /// Wall time of the run, milliseconds.
    pub wall_ms: f64,
    /// Gait name.
    pub gait: String,
    /// The gaits this creature has.
    pub gaits_available: &'static [&'static str],
    /// Dynamic scale (Table 1's L).
    pub scale: f64,
    /// Whether the creature fell (or was reset after a fall).
    pub fell: bool,
    /// The guard's message at the last put-back (a blow-up or a fall),
    /// its time on the clock of the attempt it ended.
    pub blow_up: Option<String>,
    /// Every put-back of the run, in order, each with the run's own time.
    pub put_backs: Vec<PutBackEntry>,
    /// Every push of the run (`--push`), in order, with its recovery.
    pub pushes: Vec<PushEntry>,
    /// Every gait change that took effect, in order, with when (left out
    /// without one).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub gait_changes: Vec<GaitChangeEntry>,
    /// Whether the creature recovered from every push: none without a
    /// push or while one has no verdict yet.
    pub recovered: Option<bool>,
    /// Each virtual leg's touchdown and lift-off gaps (the trot, bound and
    /// gallops; empty for one-legged gaits).
    pub pairs: Vec<PairTimingEntry>,
    /// Desired speed, m/s.
    pub speed_desired_mps: f64,
    /// Mean speed, m/s.
    pub speed_mean_mps: f64,
    /// Mean stride, metres.
    pub stride_length_m: f64,
    /// Mean stride, seconds.
    pub stride_duration_s: f64,
    /// Mean flight, seconds.
    pub flight_duration_s: f64,
    /// Mean stance, seconds.
    pub stance_duration_s: f64,
    /// Each leg's stance.
    pub legs: Vec<PhysicsLegMetrics>,
    /// Leg shortening in stance, metres.
    pub leg_length_change_m: f64,
    /// Pitch magnitude, degrees.
    pub pitch_magnitude_deg: f64,
    /// Roll magnitude, degrees.
    pub roll_magnitude_deg: f64,
    /// Peak vertical acceleration of the centre of mass, g.
    pub peak_vertical_accel_g: f64,
    /// Peak total vertical ground force, × body weight.
    pub peak_vertical_force_bw: f64,
    /// Mean per-stride peak-to-peak forward speed, m/s.
    pub speed_swing_mps: f64,
    /// Largest horizontal-to-vertical ground force ratio needed.
    pub friction_needed_max: f64,
    /// The same within the supports that ended, without their first and
    /// last 10 ms (Raibert & Hodgins 1991, "Modeling": about 0.5 would
    /// have held the quadruped's and kangaroo's feet there, the biped's
    /// "always less than 1").
    pub friction_needed_mid: f64,
    /// The same within the first and last 10 ms of those supports (the
    /// paper: "almost 2.0").
    pub friction_needed_edges: f64,
    /// Each leg's largest vertical ground force, × body weight, in leg order.
    pub peak_leg_force_bw: Vec<f64>,
    /// Cost of transport: positive actuator work over weight × distance
    /// (dimensionless; 0 before any travel).
    pub cost_of_transport: f64,
    /// Table 2's rows for this gait beside the run's figures (empty for a
    /// gait the paper does not tabulate).
    pub table2: Vec<Table2Entry>,
    /// The lab's additions to the paper's control this run used (empty:
    /// the paper's laws only).
    pub lab_additions: Vec<&'static str>,
    /// The state the run started from: `gait` (the gait's own start) or
    /// `on_cycle` (`scenario.physics.start`).
    pub start: &'static str,
    /// Why the start on the cycle asked for was not found, if it was not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub start_note: Option<String>,
    /// Integration steps.
    pub steps: u64,
    /// Integration steps per wall second.
    pub steps_per_second: f64,
    /// Simulated seconds per wall second.
    pub realtime_factor: f64,
    /// On ground that is not flat (`scenario.terrain`), what the run over
    /// it measured (`footholds_moved` is 0: the physics' feet land where
    /// the dynamics put them); absent on the floor.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub terrain: Option<TerrainRunMetrics>,
}

impl PhysicsRunMetrics {
    fn of(
        preset: &str,
        driver: &PhysicsDriver,
        timing: &Timing,
        lab_additions: Vec<&'static str>,
    ) -> Self {
        let s = driver.summary();
        let sim = driver.sim();
        let step_s = timing.step_ms / 1e3;
        let steps = sim.steps as f64;
        let legs = sim
            .creature
            .legs
            .iter()
            .zip(&s.leg_stance_s)
            .map(|(leg, &t)| PhysicsLegMetrics {
                name: leg.name.clone(),
                stance_duration_s: t,
            })
            .collect();
        let pushes = push_entries(driver);
        // Every push's verdict; none while one has none, or without a push.
        let verdicts: Option<Vec<bool>> = pushes.iter().map(|p| p.recovered).collect();
        let recovered = verdicts
            .filter(|v| !v.is_empty())
            .map(|v| v.iter().all(|&r| r));
        Self {
            preset: preset.to_owned(),
            engine: "physics",
            frames: timing.frames,
            sim_seconds: sim.time,
            wall_ms: timing.wall_ms,
            gait: driver.gait().to_owned(),
            gaits_available: gaitlab_physics::control::gaits::table::gait_names(
                sim.creature.species,
            ),
            scale: driver.params().scale,
            fell: s.fell || driver.resets() > 0,
            blow_up: driver
                .message()
                .filter(|m| Some(*m) != driver.start_note())
                .map(str::to_owned),
            pairs: gaitlab_physics::engine::pair_timing::pair_timing(
                &s.stances,
                driver.virtual_legs(),
            )
            .into_iter()
            .map(|t| PairTimingEntry {
                legs: t.legs.map(|i| {
                    sim.creature
                        .legs
                        .get(i)
                        .map_or_else(String::new, |leg| leg.name.clone())
                }),
                touchdown_gap_s: t.touchdown_gap_s,
                liftoff_gap_s: t.liftoff_gap_s,
                shared: t.shared,
                alone: t.alone,
            })
            .collect(),
            pushes,
            gait_changes: driver
                .gait_changes()
                .iter()
                .map(|c| GaitChangeEntry {
                    at_s: c.at_s,
                    from: c.from,
                    to: c.to,
                    entry: c.entry.name(),
                })
                .collect(),
            recovered,
            put_backs: driver
                .put_backs()
                .iter()
                .map(|p| PutBackEntry {
                    run_time_s: p.run_time_s,
                    why: p.why.clone(),
                })
                .collect(),
            speed_desired_mps: s.speed_desired_mps,
            speed_mean_mps: s.speed_mean_mps,
            stride_length_m: s.stride_length_m,
            stride_duration_s: s.stride_duration_s,
            flight_duration_s: s.flight_duration_s,
            stance_duration_s: s.stance_duration_s,
            legs,
            leg_length_change_m: s.leg_length_change_m,
            pitch_magnitude_deg: s.pitch_magnitude_deg,
            roll_magnitude_deg: s.roll_magnitude_deg,
            peak_vertical_accel_g: s.peak_vertical_accel_g,
            peak_vertical_force_bw: s.peak_vertical_force_bw,
            speed_swing_mps: s.speed_swing_mps,
            friction_needed_max: s.friction_needed_max,
            friction_needed_mid: s.friction_needed_mid,
            friction_needed_edges: s.friction_needed_edges,
            peak_leg_force_bw: s.peak_leg_force_bw.clone(),
            cost_of_transport: s.cost_of_transport,
            lab_additions,
            start: if driver.started_on_cycle() {
                "on_cycle"
            } else {
                "gait"
            },
            start_note: driver.start_note().map(str::to_owned),
            table2: {
                let names: Vec<&str> = sim.creature.legs.iter().map(|l| l.name.as_str()).collect();
                table2_entries(&s, driver.gait(), &names)
            },
            steps: sim.steps,
            steps_per_second: if step_s > 0.0 { steps / step_s } else { 0.0 },
            realtime_factor: if step_s > 0.0 { sim.time / step_s } else { 0.0 },
            terrain: physics_terrain_metrics(driver),
        }
    }
}

/// Table 2's rows for `gait` beside the run's figures in `summary` (`legs`
/// names the creature's legs, in leg order): `--json`'s `table2`, and the
/// page's through [`crate::catalog::table2`].
#[must_use]
pub fn table2_entries(
    summary: &gaitlab_physics::engine::metrics::GaitSummary,
    gait: &str,
    legs: &[&str],
) -> Vec<Table2Entry> {
    gaitlab_physics::engine::table2::compare(summary, gait, legs)
        .into_iter()
        .map(|c| Table2Entry {
            quantity: c.row.label,
            paper: c.row.animation,
            measured: c.measured,
            diff_pct: c.diff_pct(),
            input: c.row.quantity.is_input(),
        })
        .collect()
}
