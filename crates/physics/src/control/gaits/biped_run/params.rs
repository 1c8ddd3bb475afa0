//! Parameters of biped running (Raibert & Hodgins 1991, Figure 4, eqs. 1–4),
//! at scale 1: gains, spring and thrust settings, and the lab's additions
//! this controller has.

use crate::control::gaits::hopper_params::HopperParams;

/// Parameters of biped running; lengths are leg-spring coordinates
/// (metres of extension, 0 = the leg at full length).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BipedRunParams {
    /// The run's own hop height when no command gives one (m): eq. 2's
    /// target rise of the centre of mass above the last lift-off — the
    /// prediction takes the leg as massless and lossless, and the hop
    /// reaches less (0.14 m asked: a 0.31 s flight, 0.12 m) — or, with the
    /// hop integrator, the hip's measured rise (0.10 m; see
    /// [`BipedRunParams::with_hop_integrator`]).
    pub hop_height_m: f64,
    /// The hopper's spring, thrust, placement and servo parameters.
    pub hopper: HopperParams,
    /// The lab's integral speed trim on (`lab_additions.speed_trim`; not
    /// in the paper), with gain `hopper.speed_integral_gain`.
    pub speed_trim: bool,
    /// Keep eq. 4's posture servo on in Unloading: the lab's addition
    /// (`lab_additions.unloading_posture`); Figure 4 zeroes the active hip's
    /// torque there.
    pub unloading_posture: bool,
    /// The lab's hop integrator (`lab_additions.hop_integrator`): the thrust
    /// corrected by `hopper.hop_gain` from each hop's measured apex, where
    /// the paper sets it by eq. 2's prediction at the bottom of each stance.
    pub hop_integrator: bool,
    /// The lab's ground ahead (`lab_additions.ground_ahead`; not in the
    /// paper): eq. 2's apex target taken above the ground plane under the
    /// next apex, where the paper's is above the last lift-off.
    pub ground_ahead: bool,
}

impl Default for BipedRunParams {
    fn default() -> Self {
        Self {
            hop_height_m: Self::EQ2_HOP_HEIGHT_M,
            hopper: HopperParams::default(),
            speed_trim: false,
            unloading_posture: true,
            hop_integrator: false,
            ground_ahead: false,
        }
    }
}

impl BipedRunParams {
    /// The hop height eq. 2 is asked for (m): it takes the leg as massless
    /// and lossless, and the hop reaches less.
    pub const EQ2_HOP_HEIGHT_M: f64 = 0.14;

    /// The hop height the hop integrator holds, measured (m), as every
    /// file ran with it until 2026-12-06.
    pub const MEASURED_HOP_HEIGHT_M: f64 = 0.10;

    /// These parameters with the lab's hop integrator `on` or off, and the
    /// hop height that goes with each.
    #[must_use]
    pub fn with_hop_integrator(self, on: bool) -> Self {
        let hop_height_m = if on {
            Self::MEASURED_HOP_HEIGHT_M
        } else {
            Self::EQ2_HOP_HEIGHT_M
        };
        Self {
            hop_integrator: on,
            hop_height_m,
            ..self
        }
    }

    /// The defaults before the lab's additions were optional (files without
    /// `lab_additions` run with these): eq. 3's gain 0.05 s, held to the
    /// desired speed by the speed trim at gain 0.3, posture servo on in
    /// Unloading, the hop integrator holding a 0.10 m apex rise. (With eq. 3's gain now 0.12 s, a trim at 0.3 makes the
    /// biped blow up at 2.5 m/s within a minute; its default is 0.1.)
    #[must_use]
    pub fn before_lab_additions() -> Self {
        let d = Self::default();
        Self {
            hopper: HopperParams {
                placement_gain_s: 0.05,
                speed_integral_gain: 0.3,
                ..d.hopper
            },
            hop_height_m: Self::MEASURED_HOP_HEIGHT_M,
            speed_trim: true,
            unloading_posture: true,
            hop_integrator: true,
            ground_ahead: false,
        }
    }
}
