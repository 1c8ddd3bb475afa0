//! The thesis target script: She 2006 §5.2.2's sinusoidal end-effector targets
//! for walking and running (§5.2.1 cycles, §5.1.1 step, hand and speed
//! parameters), as a pure function of time, [`ThesisParams`] and [`ThesisMode`].
//!
//! # The script
//! With `ω = 2π·frequency_hz / slowdown` and the left limbs' phase `φ = ωt`
//! (the right limbs' phase is `φ − π`, half a cycle later), every target moves
//! between the two extremes of its stroke (thesis Fig. 5.2), in the body frame
//! (x toward the figure's left, y up from the ground, z forward, origin at the
//! root's ground projection):
//!
//! - foot: `mid + half·sin φ + ŷ·step_height·max(0, cos φ)²`, where
//!   `mid = (front + back)/2`, `half = (front − back)/2`. The foot is at the
//!   front at `φ = π/2`, sweeps back during stance (`cos φ < 0`) and is lifted
//!   only while it swings forward (`cos φ > 0`, highest at mid-swing `φ = 0`);
//!   the square keeps lift-off and touch-down velocity-continuous.
//! - hand: `mid − half·sin φ`, opposite to the same-side foot, riding up and
//!   down with the root's bounce (hands are given at the mean root height).
//! - root height: `root_height ± (bounce/2)·cos 2φ`, twice per cycle; `+` for
//!   walking (highest at mid-stance, the inverted pendulum), `−` for running
//!   (lowest at mid-stance, highest in the flight-like phase between stances).
//!
//! The right limbs mirror x. The left limbs are given in [`CycleShape`].
//!
//! # The listing
//! With `scenario.thesis.script` set to `listing`, the targets follow She
//! 2006 §5.2.2's code instead ([`ListingParams`]): each target is
//! `center + amplitude ⊙ sin(φ / ratio)` per axis, relative to the root, and
//! the root stays at the cycle's height (no bounce, no foot lift).
//!
//! # Speed
//! In the body frame the planted foot moves backward at `ω·|half.z|·|cos φ|`,
//! fastest at mid-stance. The stride-matched speed is that peak,
//! `ω·|front.z − back.z|/2 = π·|front.z − back.z|·frequency/slowdown`, so that the
//! planted foot is at rest in the world at mid-stance and never moves backward
//! (the foot traces a cycloid). The stroke's average speed
//! `2·|front.z − back.z|·frequency/slowdown` would leave it sliding backward at
//! mid-stance.

use gaitlab_core::portable::Portable;
use std::f64::consts::{PI, TAU};

use gaitlab_core::preset::thesis::{
    CycleShape, ListingCycle, ListingParams, TargetScript, ThesisMode, ThesisParams,
};
use glam::DVec3;

/// The limbs the script moves, in [`ScriptSample::targets`] order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Limb {
    /// Left foot (phase `φ`).
    LeftFoot,
    /// Right foot (phase `φ − π`).
    RightFoot,
    /// Left hand (opposite to the left foot).
    LeftHand,
    /// Right hand (opposite to the right foot).
    RightHand,
}

impl Limb {
    /// Every limb, in target order.
    pub const ALL: [Limb; 4] = [
        Limb::LeftFoot,
        Limb::RightFoot,
        Limb::LeftHand,
        Limb::RightHand,
    ];

    /// Index into [`ScriptSample::targets`].
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// Whether this is a foot.
    #[must_use]
    pub fn is_foot(self) -> bool {
        matches!(self, Limb::LeftFoot | Limb::RightFoot)
    }
}

/// The script's output at one instant, in the body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScriptSample {
    /// Target per limb, metres, in [`Limb::ALL`] order: relative to the root's
    /// ground projection, x toward the figure's left, y up from the ground, z forward.
    pub targets: [DVec3; 4],
    /// Root height above the ground, metres.
    pub root_height_m: f64,
}

impl ScriptSample {
    /// The sample `weight` of the way from `self` to `other` (0 gives `self`,
    /// 1 gives `other`), every target and the root height interpolated linearly
    /// (as `a + (b − a)·weight`, so equal samples blend to themselves exactly).
    #[must_use]
    pub fn lerp(&self, other: &ScriptSample, weight: f64) -> ScriptSample {
        let mut targets = self.targets;
        for (target, to) in targets.iter_mut().zip(&other.targets) {
            *target += (*to - *target) * weight;
        }
        ScriptSample {
            targets,
            root_height_m: self.root_height_m + (other.root_height_m - self.root_height_m) * weight,
        }
    }

    /// The target of `limb`.
    #[must_use]
    pub fn target(&self, limb: Limb) -> DVec3 {
        self.targets[limb.index()]
    }
}

/// The target script for one parameter set and mode (She 2006 §5.2.2).
#[derive(Clone, Copy, Debug)]
pub struct ThesisScript<'a> {
    /// The parameters (cycle shapes, slowdown, speed).
    pub params: &'a ThesisParams,
    /// The motion: walking modes use `params.walk`, running modes `params.run`.
    pub mode: ThesisMode,
}

impl<'a> ThesisScript<'a> {
    /// The script for `params` in `mode`.
    #[must_use]
    pub fn new(params: &'a ThesisParams, mode: ThesisMode) -> Self {
        Self { params, mode }
    }

    /// The cycle shape this mode uses.
    #[must_use]
    pub fn shape(&self) -> &'a CycleShape {
        if self.mode.running() {
            &self.params.run
        } else {
            &self.params.walk
        }
    }

    /// The listing's cycle this mode uses (script `listing`).
    #[must_use]
    pub fn listing(&self) -> &'a ListingCycle {
        if self.mode.running() {
            &self.params.listing.run
        } else {
            &self.params.listing.walk
        }
    }

    /// Effective cycle frequency, `frequency_hz / slowdown`, hertz, of the
    /// script in use. A slowdown that is not a positive finite number counts as 1.
    #[must_use]
    pub fn frequency_hz(&self) -> f64 {
        let slowdown = self.params.slowdown;
        let slowdown = if slowdown.is_finite() && slowdown > 0.0 {
            slowdown
        } else {
            1.0
        };
        let frequency = match self.params.script {
            TargetScript::Lab => self.shape().frequency_hz,
            TargetScript::Listing => self.listing().frequency_hz,
        };
        frequency / slowdown
    }

    /// The phase after which the script repeats, radians: 2π, or infinite when
    /// the listing's axes have periods other than the cycle's (the driver then
    /// keeps the phase unwrapped).
    #[must_use]
    pub fn phase_period(&self) -> f64 {
        match self.params.script {
            TargetScript::Listing if self.params.listing.axis_period_ratio != DVec3::ONE => {
                f64::INFINITY
            }
            _ => TAU,
        }
    }

    /// Angular frequency `ω = 2π·frequency_hz / slowdown`, radians per second.
    #[must_use]
    pub fn angular_frequency(&self) -> f64 {
        TAU * self.frequency_hz()
    }

    /// Duration of one cycle, seconds (infinite at zero frequency).
    #[must_use]
    pub fn period_s(&self) -> f64 {
        1.0 / self.frequency_hz()
    }

    /// Speed at which the planted foot is at rest at mid-stance:
    /// `ω·|front.z − back.z|/2`, metres per second (see the module docs).
    #[must_use]
    pub fn stride_matched_speed_mps(&self) -> f64 {
        match self.params.script {
            TargetScript::Lab => {
                let shape = self.shape();
                0.5 * self.angular_frequency() * (shape.front_foot.z - shape.back_foot.z).abs()
            }
            TargetScript::Listing => {
                let cycle = self.listing();
                let amplitude = cycle
                    .left_foot
                    .amplitude
                    .z
                    .abs()
                    .max(cycle.right_foot.amplitude.z.abs());
                self.angular_frequency() * amplitude / self.params.listing.axis_period_ratio.z
            }
        }
    }

    /// Forward speed of the root: 0 unless `moving_forward`, else `speed_mps`
    /// or, when that is `None`, the stride-matched speed.
    #[must_use]
    pub fn speed_mps(&self) -> f64 {
        if !self.params.moving_forward {
            return 0.0;
        }
        self.params
            .speed_mps
            .unwrap_or_else(|| self.stride_matched_speed_mps())
    }

    /// The targets and root height at left-limb phase `phase`, radians.
    #[must_use]
    pub fn at_phase(&self, phase: f64) -> ScriptSample {
        match self.params.script {
            TargetScript::Lab => self.lab_at_phase(phase),
            TargetScript::Listing => listing_at_phase(self.listing(), &self.params.listing, phase),
        }
    }

    /// gaitlab's own script at phase `phase` (see the module docs).
    fn lab_at_phase(&self, phase: f64) -> ScriptSample {
        let shape = self.shape();
        let right_phase = phase - PI;
        let mirror = DVec3::new(-1.0, 1.0, 1.0);
        let bounce = 0.5 * shape.bounce_m * (2.0 * phase).pcos();
        let bounce = if self.mode.running() { -bounce } else { bounce };
        let ride = DVec3::new(0.0, bounce, 0.0);
        ScriptSample {
            targets: [
                foot(shape, phase),
                foot(shape, right_phase) * mirror,
                hand(shape, phase) + ride,
                hand(shape, right_phase) * mirror + ride,
            ],
            root_height_m: shape.root_height_m + bounce,
        }
    }

    /// The targets and root height at time `t`, seconds (phase `ωt`).
    #[must_use]
    pub fn at_time(&self, t: f64) -> ScriptSample {
        self.at_phase(self.angular_frequency() * t)
    }
}

/// The listing at phase `phase`: each target `center + amplitude ⊙ sin(φ/ratio)`
/// raised by the root height (targets are relative to the root's ground projection).
fn listing_at_phase(cycle: &ListingCycle, listing: &ListingParams, phase: f64) -> ScriptSample {
    let ratio = listing.axis_period_ratio;
    let wave = DVec3::new(
        (phase / ratio.x).psin(),
        (phase / ratio.y).psin(),
        (phase / ratio.z).psin(),
    );
    let root = DVec3::new(0.0, cycle.root_height_m, 0.0);
    ScriptSample {
        targets: cycle
            .targets()
            .map(|target| root + target.center + target.amplitude * wave),
        root_height_m: cycle.root_height_m,
    }
}

/// Left foot target at phase `phase`.
fn foot(shape: &CycleShape, phase: f64) -> DVec3 {
    let (sin, cos) = phase.psin_cos();
    let mid = 0.5 * (shape.front_foot + shape.back_foot);
    let half = 0.5 * (shape.front_foot - shape.back_foot);
    let lift = cos.max(0.0);
    mid + half * sin + DVec3::Y * (shape.step_height_m * lift * lift)
}

/// Left hand target at left-foot phase `phase`: opposite to the foot.
fn hand(shape: &CycleShape, phase: f64) -> DVec3 {
    let mid = 0.5 * (shape.front_hand + shape.back_hand);
    let half = 0.5 * (shape.front_hand - shape.back_hand);
    mid - half * phase.psin()
}
