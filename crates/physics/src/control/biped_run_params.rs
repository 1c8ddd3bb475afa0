//! Parameters of biped running (Raibert & Hodgins 1991, Figure 4, eqs. 1–4),
//! at scale 1: gains, spring and thrust settings, and the lab's additions
//! this controller has.

use super::additions::Offered;

/// Parameters of biped running; lengths are leg-spring coordinates
/// (metres of extension, 0 = the leg at full length).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BipedRunParams {
    /// Desired forward speed ẋ_d (m/s).
    pub speed_mps: f64,
    /// Desired heading (rad about +y; 0 = +z).
    pub heading: f64,
    /// Leg spring stiffness k (N/m) and damping b (N·s/m), eq. 1.
    pub leg_stiffness: f64,
    /// Leg spring damping (N·s/m).
    pub leg_damping: f64,
    /// How far the telescoping leg can shorten from full length (m).
    pub leg_travel_m: f64,
    /// Rest length for landing (m of extension).
    pub landing_rest_m: f64,
    /// Extra rest length during thrust (m).
    pub thrust_m: f64,
    /// Rest length of the shortened idle leg (m of extension).
    pub idle_rest_m: f64,
    /// Desired hop height: apex of the hip above its lift-off height (m).
    pub hop_height_m: f64,
    /// How much each hop's apex error changes the thrust (m of thrust per m).
    pub hop_gain: f64,
    /// Foot placement gain k_ẋ (s), eq. 3.
    pub placement_gain_s: f64,
    /// The lab's integral speed trim on (`lab_additions.speed_trim`; not
    /// in the paper), with gain `speed_integral_gain`.
    pub speed_trim: bool,
    /// Integral gain on each step's speed error (per step), while the speed
    /// trim is on.
    pub speed_integral_gain: f64,
    /// Keep eq. 4's posture servo on in Unloading: the lab's addition
    /// (`lab_additions.unloading_posture`); Figure 4 zeroes the active hip's
    /// torque there.
    pub unloading_posture: bool,
    /// Hip servo gains for positioning legs (N·m/rad, N·m·s/rad).
    pub swing_kp: f64,
    /// Hip swing damping (N·m·s/rad).
    pub swing_kv: f64,
    /// Posture servo gains of eq. 4 (N·m/rad, N·m·s/rad).
    pub posture_kp: f64,
    /// Posture damping (N·m·s/rad).
    pub posture_kv: f64,
    /// Trunk yaw servo in stance, through the hip's yaw joint (N·m/rad, N·m·s/rad).
    pub yaw_kp: f64,
    /// Trunk yaw damping in stance (N·m·s/rad).
    pub yaw_kv: f64,
    /// Servo of the leg's own yaw joint in flight; the leg spins on a tiny
    /// inertia, so these are small (N·m/rad, N·m·s/rad).
    pub leg_yaw_kp: f64,
    /// Leg yaw damping in flight (N·m·s/rad).
    pub leg_yaw_kv: f64,
    /// Largest hip torque (N·m).
    pub max_hip_torque: f64,
    /// Largest trunk-yaw torque through the stance leg's yaw joint (N·m).
    pub max_yaw_torque: f64,
    /// How fast a leg's rest length may change (m/s): a leg snapped short
    /// would jerk the trunk through the offset hips.
    pub leg_rate_mps: f64,
}

impl BipedRunParams {
    /// The lab's additions this controller has: the speed trim (off: eq. 3
    /// alone holds the speed) and Unloading's posture servo (on for a file
    /// that does not say, as files of 2026-12-02 ran).
    pub const LAB_ADDITIONS: Offered = Offered {
        speed_trim: Some(false),
        unloading_posture: Some(true),
        ..Offered::NONE
    };
}

impl Default for BipedRunParams {
    fn default() -> Self {
        Self {
            speed_mps: 1.5,
            heading: 0.0,
            leg_stiffness: 20_000.0,
            leg_damping: 20.0,
            leg_travel_m: 0.25,
            landing_rest_m: -0.03,
            thrust_m: 0.03,
            idle_rest_m: -0.18,
            hop_height_m: 0.10,
            hop_gain: 0.3,
            placement_gain_s: 0.12,
            speed_trim: false,
            speed_integral_gain: 0.1,
            unloading_posture: true,
            swing_kp: 150.0,
            swing_kv: 8.0,
            posture_kp: 1000.0,
            posture_kv: 160.0,
            yaw_kp: 200.0,
            yaw_kv: 20.0,
            leg_yaw_kp: 2.0,
            leg_yaw_kv: 0.1,
            max_hip_torque: 400.0,
            max_yaw_torque: 30.0,
            leg_rate_mps: 1.0,
        }
    }
}

impl BipedRunParams {
    /// The defaults before the lab's additions were optional (files without
    /// `lab_additions` run with these): eq. 3's gain 0.05 s, held to the
    /// desired speed by the speed trim at gain 0.3, posture servo on in
    /// Unloading. (With eq. 3's gain now 0.12 s, a trim at 0.3 makes the
    /// biped blow up at 2.5 m/s within a minute; its default is 0.1.)
    #[must_use]
    pub fn before_lab_additions() -> Self {
        Self {
            placement_gain_s: 0.05,
            speed_trim: true,
            speed_integral_gain: 0.3,
            unloading_posture: true,
            ..Self::default()
        }
    }
}
