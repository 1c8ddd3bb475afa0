//! The thesis' own target script, She 2006 §5.2.2's code listing: each target
//! is `center + amplitude ⊙ sin(ω·T)` per axis, in metres, in a frame whose
//! origin is the root (x toward the figure's left, y up, z forward).
//!
//! The listing moves only z:
//!
//! ```text
//! target[0].Set( 0.35, back_y_leg,   back_z_leg·sin(walk_speed·T));
//! target[1].Set(-0.35, front_y_leg,  front_z_leg·sin(walk_speed·T));
//! target[2].Set(-0.8,  back_y_hand, -0.3·sin(walk_speed·T));
//! target[3].Set( 0.8,  front_y_hand, 0.3·sin(walk_speed·T));
//! ```
//!
//! and running the same with `run_speed`, hands at y = 0 and amplitude 1.0.
//! The thesis leaves its frame, units and several constants unnamed; the
//! reading gaitlab uses (documented in `docs/she-2006.md`) is:
//!
//! - units are metres on gaitlab's 1.75 m human and the frame's origin is the
//!   root (pelvis), so the running hands' literal `y = 0` is hip height;
//! - `target[0]` is the left foot (x = +0.35 is the figure's left), so
//!   `back_z_leg = −front_z_leg` makes the two feet move in antiphase and each
//!   foot in phase with the opposite hand, as in a human gait;
//! - `back_y_leg = front_y_leg` put the feet on the ground, the root's height
//!   above the ground being chosen per motion so that §5.3's reachability holds:
//!   walking, the foot targets lie within the legs' reach and the hands' do not;
//!   running, none do;
//! - walking, `back_y_hand = front_y_hand = −0.2` (20 cm below the hip), so that
//!   the hand targets stay beyond the arms' reach even when a method bends the
//!   spine fully sideways toward them (at hip height, y = 0, pinv does reach
//!   them in up to 8 % of the frames); running, the listing's y = 0.
//!
//! §5.2 and §5.3 also say that "each component [moves] with its own period":
//! [`ListingParams::axis_period_ratio`] sets each axis' period as a fraction of
//! the cycle, and a target's x and y amplitudes make those axes move (both 0 in
//! the listing).

use glam::DVec3;
use serde::{Deserialize, Serialize};

/// One target of the listing: `center + amplitude ⊙ sin(ω·T / ratio)` per axis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct ListingTarget {
    /// Centre of the motion, metres, relative to the root (x left, y up, z forward).
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub center: DVec3,
    /// Amplitude per axis, metres (the listing's sine coefficients; its x and y are 0).
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub amplitude: DVec3,
}

impl Default for ListingTarget {
    fn default() -> Self {
        Self {
            center: DVec3::ZERO,
            amplitude: DVec3::ZERO,
        }
    }
}

impl ListingTarget {
    fn new(center: [f64; 3], amplitude_z: f64) -> Self {
        Self {
            center: DVec3::from_array(center),
            amplitude: DVec3::new(0.0, 0.0, amplitude_z),
        }
    }
}

/// One motion of the listing (walking or running).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct ListingCycle {
    /// Cycles per second: the listing's `walk_speed` / `run_speed` is ω = 2π·frequency_hz.
    pub frequency_hz: f64,
    /// Height of the root (the frame's origin) above the ground, metres.
    pub root_height_m: f64,
    /// `target[0]`: the left foot.
    pub left_foot: ListingTarget,
    /// `target[1]`: the right foot.
    pub right_foot: ListingTarget,
    /// `target[2]`: the right hand (x = −0.8).
    pub right_hand: ListingTarget,
    /// `target[3]`: the left hand (x = +0.8).
    pub left_hand: ListingTarget,
}

impl ListingCycle {
    /// The walking listing. Feet on the ground with the root 0.90 m up and a
    /// 0.3 m stroke amplitude: the farthest foot target is 0.94 m from its hip
    /// joint, inside the leg's 0.987 m reach. Hands 0.8 m out and 0.2 m below
    /// the hip: 0.91 m or more from the upright shoulder and still about 0.71 m
    /// with the spine bent fully sideways, beyond the arm's 0.64 m reach.
    /// 0.9 cycles per second (gaitlab's walking frequency; the thesis leaves
    /// `walk_speed` to the user).
    #[must_use]
    pub fn walk() -> Self {
        let height = 0.9;
        let foot_z = 0.3;
        Self {
            frequency_hz: 0.9,
            root_height_m: height,
            left_foot: ListingTarget::new([0.35, -height, 0.0], -foot_z),
            right_foot: ListingTarget::new([-0.35, -height, 0.0], foot_z),
            right_hand: ListingTarget::new([-0.8, -0.2, 0.0], -0.3),
            left_hand: ListingTarget::new([0.8, -0.2, 0.0], 0.3),
        }
    }

    /// The running listing. The root 1.06 m up with the foot targets on the
    /// ground: the nearest is 1.04 m from its hip joint, beyond the leg's
    /// reach; a 0.45 m stroke amplitude. Hands at y = 0 (hip height) with the
    /// listing's amplitude 1.0. 1.4 cycles per second.
    #[must_use]
    pub fn run() -> Self {
        let height = 1.06;
        let foot_z = 0.45;
        Self {
            frequency_hz: 1.4,
            root_height_m: height,
            left_foot: ListingTarget::new([0.35, -height, 0.0], -foot_z),
            right_foot: ListingTarget::new([-0.35, -height, 0.0], foot_z),
            right_hand: ListingTarget::new([-0.8, 0.0, 0.0], -1.0),
            left_hand: ListingTarget::new([0.8, 0.0, 0.0], 1.0),
        }
    }

    /// The targets in [`EffectorRoles`](super::thesis::EffectorRoles) order:
    /// left foot, right foot, left hand, right hand.
    #[must_use]
    pub fn targets(&self) -> [&ListingTarget; 4] {
        [
            &self.left_foot,
            &self.right_foot,
            &self.left_hand,
            &self.right_hand,
        ]
    }
}

impl Default for ListingCycle {
    fn default() -> Self {
        Self::walk()
    }
}

/// The listing's parameters (`scenario.thesis.listing`), used when
/// `scenario.thesis.script` is `listing`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct ListingParams {
    /// Walking targets.
    pub walk: ListingCycle,
    /// Running targets.
    pub run: ListingCycle,
    /// Period of the x, y and z motion as a fraction of the cycle's: axis `a`
    /// moves as `sin(ω·T / ratio[a])`. Default `[1, 1, 1]` (one period, the
    /// listing). With x or y amplitudes, other ratios give §5.3's "each
    /// component with its own period".
    #[cfg_attr(feature = "schema", schemars(with = "[f64; 3]"))]
    pub axis_period_ratio: DVec3,
}

impl Default for ListingParams {
    fn default() -> Self {
        Self {
            walk: ListingCycle::walk(),
            run: ListingCycle::run(),
            axis_period_ratio: DVec3::ONE,
        }
    }
}

/// Which script moves the four targets (`scenario.thesis.script`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum TargetScript {
    /// gaitlab's own script (`walk`/`run` cycle shapes): reachable foot strokes
    /// with a foot lift, hands swinging in front, a bouncing root. The lab's
    /// addition; the default of presets written before `she-2006`.
    #[default]
    Lab,
    /// She 2006 §5.2.2's listing ([`ListingParams`]): only z moves, sinusoidally.
    Listing,
}

impl TargetScript {
    /// Every script.
    pub const ALL: [TargetScript; 2] = [TargetScript::Lab, TargetScript::Listing];

    /// The name used in presets and commands.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            TargetScript::Lab => "lab",
            TargetScript::Listing => "listing",
        }
    }
}

/// How a wounded weight acts (She 2006 §5.1.1 "weighted parameters",
/// `scenario.thesis.wound_form`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum WoundForm {
    /// The lab's reading: the weight acts on the IK step, `Δθ ← w·Δθ` or
    /// `Δθ + w` each iteration, so the other joints make up for the stiff one.
    /// The default of presets written before `she-2006`.
    #[default]
    Step,
    /// The thesis' reading: the weight acts on the angle mapped onto the body,
    /// `θ_shown = w·θ` or `θ + w` (within the joint's limits), "before mapping
    /// rotation angles to joints in the rigid body" (§5.1.1, §5.2.3). The IK
    /// keeps its own unweighted angles.
    Angle,
}

impl WoundForm {
    /// Every form.
    pub const ALL: [WoundForm; 2] = [WoundForm::Step, WoundForm::Angle];

    /// The name used in presets and commands.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            WoundForm::Step => "step",
            WoundForm::Angle => "angle",
        }
    }
}
