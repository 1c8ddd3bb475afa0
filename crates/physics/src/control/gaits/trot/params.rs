//! Parameters of the quadruped trot on diagonal virtual legs (Raibert &
//! Hodgins 1991, "Gaits"), at scale 1.

/// The trot's tuning in [`QuadrupedRun`](crate::control::gaits::trot::QuadrupedRun) (values at scale 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaitTuning {
    /// Leg spring stiffness k of eq. 1 (N/m).
    pub leg_stiffness: f64,
    /// Leg spring damping b of eq. 1 in stance (N·s/m).
    pub leg_damping: f64,
    /// Leg damping while the foot is off the ground (N·s/m): the leg's
    /// length servo, damped so a lengthened leg does not ring before landing.
    pub leg_air_damping: f64,
    /// How far the telescoping leg can shorten from full length (m).
    pub leg_travel_m: f64,
    /// Spring rest for landing and standing (m of extension from full
    /// length, ≤ 0): the paper shortened it for the trot.
    pub landing_rest_m: f64,
    /// Rest of a shortened (idle) leg (m of extension, < `landing_rest_m`).
    pub idle_rest_m: f64,
    /// Initial thrust: extra rest length in the thrust state (m).
    pub thrust_m: f64,
    /// Desired flight duration after the lift-off of pair 0 and of pair 1
    /// (s): the trot's flight.
    pub flight_s: [f64; 2],
    /// The hop height eq. 2 is asked for when no command gives one (m of
    /// the centre of mass's rise above the last lift-off): eq. 2 takes the
    /// legs as massless and their springs as lossless, and the trot's
    /// damped legs reach less (0.11 m asked: Table 2's 0.18 s flight at
    /// 2.3 m/s, an apex of 0.04 m). Not used with the hop integrator,
    /// which holds `flight_s`.
    pub eq2_hop_m: f64,
    /// Initial guess of the stance duration T_s of eq. 3 (s).
    pub stance_s: f64,
    /// Foot placement gain k_ẋ of eq. 3 (s).
    pub placement_gain_s: f64,
    /// Posture servo stiffness of eq. 4 on pitch (N·m/rad).
    pub pitch_kp: f64,
    /// Posture servo damping of eq. 4 on pitch (N·m·s/rad).
    pub pitch_kv: f64,
    /// Posture servo stiffness of eq. 4 on roll (N·m/rad).
    pub roll_kp: f64,
    /// Posture servo damping of eq. 4 on roll (N·m·s/rad).
    pub roll_kv: f64,
    /// Desired trunk pitch in stance (rad, positive nose down).
    pub pitch_d: f64,
    /// Integral speed correction: change of the speed bias added to the
    /// desired speed of eq. 3 per stride, per m/s of the stride's mean
    /// speed error (dimensionless).
    pub speed_gain: f64,
    /// Pitch swing (rad): the desired pitch in the stance of pair 0 is
    /// `pitch_d + pitch_swing`, in that of pair 1 `pitch_d − pitch_swing`.
    pub pitch_swing: f64,
    /// Largest horizontal foot force the posture servo may ask for, as a
    /// fraction of the leg's spring force: the pitch torque of each stance
    /// leg is limited to this fraction of spring force × leg length, so the
    /// servo cannot swamp foot placement (∞ for no limit).
    pub posture_force_ratio: f64,
    /// Whether the landing pair lengthens only once its hips descend
    /// (else at once, as Figure 4's flight state does).
    pub wait_for_descent: bool,
    /// 1: the pair is one virtual leg at lift-off ("Gaits": its members
    /// "leave the ground in unison"): it unloads when its legs in stance
    /// have all reached thrust and are, on average, near full length, and
    /// both shorten together. 0: each leg unloads on its own spring, as
    /// the trot did before 2026-12-06, so one leg may carry the pair's
    /// posture torque alone at the end of the stance (`gaitlab-preset/1`
    /// files without the key).
    pub unison_liftoff: f64,
}

/// Parameters of [`QuadrupedRun`](crate::control::gaits::trot::QuadrupedRun); all at scale 1 (the controller scales
/// them by the creature's L), editable while running.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadrupedRunParams {
    /// Tuning of the trot.
    pub trot: GaitTuning,
    /// Thrust change per second of flight-duration error (m/s): the lab's
    /// hop integrator, regulating eq. 2's energy injection hop by hop.
    pub flight_gain: f64,
    /// The lab's hop integrator on (`lab_additions.hop_integrator`; not in
    /// the paper): each pair's thrust corrected by `flight_gain` from each
    /// flight's measured duration, where the paper sets it by eq. 2's
    /// prediction at the virtual leg's bottom.
    pub hop_integrator: bool,
    /// The lab's ground ahead (`lab_additions.ground_ahead`; not in the
    /// paper): eq. 3's touchdown point found over the ground plane under
    /// the body, where the paper's law takes the floor at height 0.
    pub ground_ahead: bool,
    /// Largest thrust (m).
    pub max_thrust_m: f64,
    /// Trunk yaw servo towards the heading in stance (N·m/rad).
    pub yaw_kp: f64,
    /// Trunk yaw damping in stance (N·m·s/rad).
    pub yaw_kv: f64,
    /// Hip servo stiffness for positioning legs (N·m/rad).
    pub swing_kp: f64,
    /// Hip servo damping for positioning legs (N·m·s/rad).
    pub swing_kv: f64,
    /// Share of the trunk's roll (0–1) eq. 3's leg aim takes in:
    /// 1 through the measured roll, as before; 0 in the trunk's sagittal
    /// plane ([`aim_frame`](crate::control::laws::placement::aim_frame)).
    pub swing_roll_follow: f64,
    /// Largest hip torque (N·m).
    pub max_hip_torque: f64,
}

impl Default for QuadrupedRunParams {
    fn default() -> Self {
        let trot = GaitTuning {
            leg_stiffness: 12_000.0,
            leg_damping: 30.0,
            leg_air_damping: 200.0,
            leg_travel_m: 0.36,
            landing_rest_m: -0.12,
            idle_rest_m: -0.30,
            thrust_m: 0.02,
            flight_s: [0.18, 0.18],
            eq2_hop_m: 0.11,
            stance_s: 0.09,
            placement_gain_s: 0.12,
            pitch_kp: 1500.0,
            pitch_kv: 100.0,
            roll_kp: 400.0,
            roll_kv: 70.0,
            pitch_d: 0.0,
            speed_gain: 0.0,
            pitch_swing: 0.0,
            posture_force_ratio: f64::INFINITY,
            wait_for_descent: true,
            unison_liftoff: 1.0,
        };
        Self {
            trot,
            flight_gain: 0.05,
            hop_integrator: true,
            ground_ahead: false,
            max_thrust_m: 0.10,
            yaw_kp: 300.0,
            yaw_kv: 30.0,
            swing_kp: 300.0,
            swing_kv: 15.0,
            swing_roll_follow: 1.0,
            max_hip_torque: 400.0,
        }
    }
}
