//! Parameters of She 2006's sinusoidal target script (§5.1.1 control module,
//! §5.2.2 target code, §5.2.3 wounded weights), in metres, hertz and radians.
//!
//! The thesis moves each target as `c + A·sin(ωT)` per axis; gaitlab names the
//! two extremes of each swing ("front/back leg maximum position", "front/back
//! hand maximum position", thesis Fig. 5.2) and adds a foot lift during the
//! forward swing so that feet leave the ground.

use glam::DVec3;
use serde::{Deserialize, Serialize};

pub use super::listing::{ListingCycle, ListingParams, ListingTarget, TargetScript, WoundForm};

/// The four thesis motions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "kebab-case")]
pub enum ThesisMode {
    /// Walking: double support, reachable foot targets.
    Walk,
    /// Running: flight phase, faster cycle, larger hand swing.
    Run,
    /// Walking with the wounded weights applied.
    WoundedWalk,
    /// Running with the wounded weights applied.
    WoundedRun,
}

impl ThesisMode {
    /// Every mode, in the thesis' order.
    pub const ALL: [ThesisMode; 4] = [
        ThesisMode::Walk,
        ThesisMode::Run,
        ThesisMode::WoundedWalk,
        ThesisMode::WoundedRun,
    ];

    /// The name used in presets, URLs and the CLI (`walk`, `run`, `wounded-walk`, `wounded-run`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ThesisMode::Walk => "walk",
            ThesisMode::Run => "run",
            ThesisMode::WoundedWalk => "wounded-walk",
            ThesisMode::WoundedRun => "wounded-run",
        }
    }

    /// Parses a mode name (also accepts `_` for `-`).
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        let name = name.to_ascii_lowercase().replace('_', "-");
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// Whether the wounded weights apply.
    #[must_use]
    pub fn wounded(self) -> bool {
        matches!(self, ThesisMode::WoundedWalk | ThesisMode::WoundedRun)
    }

    /// Whether this is a running mode.
    #[must_use]
    pub fn running(self) -> bool {
        matches!(self, ThesisMode::Run | ThesisMode::WoundedRun)
    }
}

/// Shape of one cyclic motion (walk or run). Positions are in the body frame
/// relative to the root's ground projection (x toward the figure's left, y up
/// from the ground, z forward) and are given for the LEFT limbs; the right limbs
/// mirror x and run half a cycle later.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct CycleShape {
    /// Gait cycles per second (the thesis' `walk_speed` / `run_speed` as ω = 2πf).
    pub frequency_hz: f64,
    /// Foot target at the front extreme of the stroke, metres.
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub front_foot: DVec3,
    /// Foot target at the back extreme of the stroke, metres.
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub back_foot: DVec3,
    /// Extra foot height at mid-swing, metres: the foot rises by
    /// `step_height_m · max(0, cos φ)²` only while it swings forward (0 keeps
    /// the thesis' flat y).
    pub step_height_m: f64,
    /// Hand target at the front extreme of the swing, metres (heights at the
    /// mean root height; hands ride up and down with the root's bob).
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub front_hand: DVec3,
    /// Hand target at the back extreme of the swing, metres.
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub back_hand: DVec3,
    /// Mean root height above the ground, metres.
    pub root_height_m: f64,
    /// Vertical bob of the root, peak to peak, metres (twice per cycle):
    /// walking peaks at mid-stance, running between stances.
    pub bounce_m: f64,
}

impl CycleShape {
    /// The default walking cycle for a 1.75 m human (presets/human.json): 0.9
    /// cycles/s, a 0.52 m stroke (stride-matched speed π·0.52·0.9 ≈ 1.47 m/s),
    /// 8 cm foot lift, hips 0.97 m up with a 2.5 cm bob, arms swinging
    /// mostly in front of the body. Tuned so that the knees stay bent (no
    /// straight-knee singularity) and the torso stays upright.
    #[must_use]
    pub fn walk() -> Self {
        Self {
            frequency_hz: 0.9,
            front_foot: DVec3::new(0.1, 0.0, 0.26),
            back_foot: DVec3::new(0.1, 0.0, -0.26),
            step_height_m: 0.08,
            front_hand: DVec3::new(0.22, 0.89, 0.26),
            back_hand: DVec3::new(0.22, 0.82, -0.14),
            root_height_m: 0.97,
            bounce_m: 0.025,
        }
    }

    /// The default running cycle for a 1.75 m human: 1.4 cycles/s, a 0.68 m
    /// stroke (≈ 3.0 m/s stride-matched), 20 cm foot lift (high heel kick),
    /// hips 0.9 m up with a 6 cm bob that peaks between stances, feet a few
    /// centimetres up at both ends of the stroke so that both are off the
    /// ground at the top of the bob (the thesis' "intermediate phase", §5.2.1).
    #[must_use]
    pub fn run() -> Self {
        Self {
            frequency_hz: 1.4,
            front_foot: DVec3::new(0.1, 0.02, 0.34),
            back_foot: DVec3::new(0.1, 0.05, -0.34),
            step_height_m: 0.2,
            front_hand: DVec3::new(0.22, 0.9, 0.3),
            back_hand: DVec3::new(0.23, 0.8, -0.16),
            root_height_m: 0.9,
            bounce_m: 0.06,
        }
    }
}

impl Default for CycleShape {
    fn default() -> Self {
        Self::walk()
    }
}

/// A wounded joint (She 2006 §5.1.1 "weighted parameters", §5.2.3).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct WoundedJoint {
    /// Joint name.
    pub joint: String,
    /// Multiply form, 0 to 10: with `wound_form` `step` the joint's IK step is
    /// scaled by this (0 freezes it); with `angle` the angle shown on the body
    /// is (θ_shown = w·θ). Default 1.
    #[serde(default = "one")]
    pub multiply: f64,
    /// Add form, −0.5 to 0.5 radians: with `wound_form` `step` added to the
    /// joint's step each iteration; with `angle` added to the angle shown
    /// (θ_shown = θ + w). Default 0.
    #[serde(default)]
    pub add: f64,
}

fn one() -> f64 {
    1.0
}

/// Which effector plays which limb in the thesis script.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct EffectorRoles {
    /// Effector that follows the left foot target.
    pub left_foot: String,
    /// Effector that follows the right foot target.
    pub right_foot: String,
    /// Effector that follows the left hand target.
    pub left_hand: String,
    /// Effector that follows the right hand target.
    pub right_hand: String,
}

impl Default for EffectorRoles {
    fn default() -> Self {
        Self {
            left_foot: "left_foot".into(),
            right_foot: "right_foot".into(),
            left_hand: "left_hand".into(),
            right_hand: "right_hand".into(),
        }
    }
}

/// Everything the thesis' control module exposes (§5.1.1, §6.2 panels).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct ThesisParams {
    /// Which script moves the targets: She 2006 §5.2.2's listing
    /// (`listing`, default) or gaitlab's own (`lab`: the `walk`/`run` cycle
    /// shapes; what a `gaitlab-preset/1` file without the key runs).
    pub script: TargetScript,
    /// The listing's targets (used when `script` is `listing`).
    pub listing: ListingParams,
    /// How the wounded weights act: on the angle shown on the body (`angle`,
    /// She 2006 §5.1.1, default) or on the IK step (`step`, the lab's
    /// reading; what a `gaitlab-preset/1` file without the key runs).
    pub wound_form: WoundForm,
    /// Walking cycle (script `lab`).
    pub walk: CycleShape,
    /// Running cycle (script `lab`).
    pub run: CycleShape,
    /// Time is divided by this (≥ 1 slows the motion down). Default 1.
    pub slowdown: f64,
    /// Whether the root advances and the targets go with it ("moving forward"). Default true.
    pub moving_forward: bool,
    /// Forward speed when moving forward, m/s; `None` matches the stride:
    /// π × |front_foot.z − back_foot.z| × frequency / slowdown, the body-frame
    /// speed of the planted foot at mid-stance, so that it is at rest in the
    /// world there. Default `None`.
    pub speed_mps: Option<f64>,
    /// IK iterations per animation frame. Default 4.
    pub iterations_per_frame: usize,
    /// Posture relaxation per frame, 0 to 1: before the frame's IK iterations
    /// every joint moves toward its PODA center angle by
    /// `posture_gain · gain_j · (center_j − θ_j)` (the joint's `center` and
    /// `gain`), and the iterations then restore the targets. This keeps
    /// redundant joints (torso, ankles, elbows) from drifting for every method,
    /// like PODA eq. 6's null-space term, which the solver applies only for
    /// pinv and DLS. 0 turns it off. The lab's addition: default 0 (the
    /// thesis has no posture term); 0.1 in a `gaitlab-preset/1` file without
    /// the key.
    pub posture_gain: f64,
    /// Seconds over which, after a reset, the targets blend (smoothstep) from
    /// the rest pose's effector positions into the cycle and the speed rises
    /// from 0, so the figure starts from standing instead of snapping to the
    /// first targets; a running mode then starts as a walk and blends into the
    /// run over the next `start_ramp_s` (running straight from standing asks
    /// the legs to shorten by up to 30 cm at once, which can drive a knee that
    /// starts nearly straight into its limit). Live mode changes blend over the
    /// same time. 0 starts the cycle at once, as the thesis does. The lab's
    /// addition: default 0; 1 s in a `gaitlab-preset/1` file without the key.
    pub start_ramp_s: f64,
    /// Joints weighted in the wounded modes.
    pub wounded: Vec<WoundedJoint>,
    /// Effector roles.
    pub roles: EffectorRoles,
}

/// What a `gaitlab-preset/1` file meant by leaving out `script`,
/// `wound_form`, `posture_gain` and `start_ramp_s`: the lab's script, step
/// wounds, a 0.1 posture pull and a 1 s start ramp (the code's defaults
/// until 2026-12-06).
pub const V1_THESIS: (TargetScript, WoundForm, f64, f64) =
    (TargetScript::Lab, WoundForm::Step, 0.1, 1.0);

impl ThesisParams {
    /// The thesis' control module with the lab's script, posture pull,
    /// start ramp and step wounds ([`V1_THESIS`]): what a
    /// `gaitlab-preset/1` file without those keys runs.
    #[must_use]
    pub fn lab() -> Self {
        let (script, wound_form, posture_gain, start_ramp_s) = V1_THESIS;
        Self {
            script,
            wound_form,
            posture_gain,
            start_ramp_s,
            ..Self::default()
        }
    }
}

/// The thesis as printed: §5.2.2's listing, §5.1.1's weights on the angle
/// shown, no posture pull and no start ramp.
impl Default for ThesisParams {
    fn default() -> Self {
        Self {
            script: TargetScript::Listing,
            listing: ListingParams::default(),
            wound_form: WoundForm::Angle,
            walk: CycleShape::walk(),
            run: CycleShape::run(),
            slowdown: 1.0,
            moving_forward: true,
            speed_mps: None,
            iterations_per_frame: 4,
            posture_gain: 0.0,
            start_ramp_s: 0.0,
            wounded: Vec::new(),
            roles: EffectorRoles::default(),
        }
    }
}
