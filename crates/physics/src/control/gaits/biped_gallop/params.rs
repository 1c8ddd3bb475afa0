//! Parameters of biped galloping (Raibert & Hodgins 1991, "Gaits"), at scale
//! 1, and the two swing styles.

use crate::control::gaits::hopper_params::HopperParams;

/// How the legs swing forward (Raibert & Hodgins 1991, "Gaits").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GallopStyle {
    /// Both legs swing forward together during flight (the front half of a
    /// galloping horse).
    #[default]
    TogetherSwing,
    /// Each leg swings forward during the other leg's single support (the
    /// galloping human).
    AlternateSwing,
}

impl GallopStyle {
    /// A short name for people.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            GallopStyle::TogetherSwing => "together swing",
            GallopStyle::AlternateSwing => "alternate swing",
        }
    }
}

/// Parameters of biped galloping; leg lengths are leg-spring coordinates
/// (metres of extension, 0 = the leg at full length), all given at the
/// paper's size (L = 1) and scaled by the creature's L.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BipedGallopParams {
    /// How the legs swing forward.
    pub style: GallopStyle,
    /// The leading leg (0 or 1): it lands second, ahead of the trailing leg,
    /// and leaves the ground last.
    pub lead_leg: usize,
    /// The gallop's own hop height, regulated when no command gives one:
    /// apex of the trunk in flight above the height of
    /// a hip over a vertical leg at landing length (m).
    pub hop_height_m: f64,
    /// The hopper's spring, thrust, placement and servo parameters.
    pub hopper: HopperParams,
    /// The lab's integral speed trim on (`lab_additions.speed_trim`; not
    /// in the paper), with gain `hopper.speed_integral_gain`: removes the
    /// steady error eq. 3 alone leaves.
    pub speed_trim: bool,
    /// The lab's hop integrator on (`lab_additions.hop_integrator`; not in
    /// the paper): the thrust corrected by `hopper.hop_gain` from each
    /// flight's measured apex, where the paper sets it by eq. 2's
    /// prediction at the leading leg's bottom.
    pub hop_integrator: bool,
    /// Extra forward placement of the trailing foot beyond its neutral point (m).
    pub trail_offset_m: f64,
    /// Extra forward placement of the leading foot beyond its neutral point (m).
    pub lead_offset_m: f64,
    /// How much shorter than for landing the leading leg is held while the
    /// body falls toward the trailing leg's touchdown (m).
    pub lead_retract_m: f64,
    /// Delay from the trailing leg's touchdown until the leading leg starts
    /// to lengthen for its landing (s): spaces the two touchdowns in time.
    pub lead_delay_s: f64,
    /// How fast the leading leg lengthens for its landing (m/s).
    pub lead_extend_mps: f64,
    /// How fast the trailing leg lengthens for landing in flight (m/s).
    pub trail_extend_mps: f64,
    /// How fast the trailing leg shortens in unloading while the leading
    /// leg supports (m/s).
    pub trail_unload_mps: f64,
    /// Fraction of the trunk's pitching in flight that the posture servo
    /// anticipates in stance (0 = level in stance, 0.5 = pitch about level).
    pub pitch_feedforward: f64,
}

impl Default for BipedGallopParams {
    fn default() -> Self {
        Self {
            style: GallopStyle::TogetherSwing,
            lead_leg: 0,
            hop_height_m: 0.12,
            hopper: HopperParams {
                leg_stiffness: 12_000.0,
                hop_gain: 0.15,
                placement_gain_s: 0.06,
                speed_integral_gain: 0.3,
                swing_kp: 400.0,
                swing_kv: 15.0,
                posture_kp: 1500.0,
                posture_kv: 100.0,
                ..HopperParams::default()
            },
            speed_trim: true,
            hop_integrator: true,
            trail_offset_m: 0.0,
            lead_offset_m: 0.0,
            lead_retract_m: 0.08,
            lead_delay_s: 0.03,
            lead_extend_mps: 4.0,
            trail_extend_mps: 1.0,
            trail_unload_mps: 2.0,
            pitch_feedforward: 0.5,
        }
    }
}
