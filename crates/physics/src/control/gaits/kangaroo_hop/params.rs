//! Parameters of the kangaroo's hop and jump (Raibert & Hodgins 1991,
//! "Kangaroo", Figure 5), at scale 1.

/// Parameters of kangaroo hopping, at dynamic scale 1 (the controller scales
/// them by the creature's L).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KangarooHopParams {
    /// Largest rate of change of the commanded speed (m/s²): a fast gait is
    /// reached by accelerating through the slower ones.
    pub speed_ramp_mps2: f64,
    /// The lab's speed ramp on (`lab_additions.speed_ramp`; not in the
    /// paper): start at most 2 m/s and ramp at `speed_ramp_mps2`.
    pub speed_ramp: bool,
    /// The lab's integral speed trim on (`lab_additions.speed_trim`; not
    /// in the paper), with gain `speed_integral_gain`.
    pub speed_trim: bool,
    /// Integral gain of the speed correction (m/s of placement target per
    /// m/s of a stride's mean speed error): eq. 3 alone leaves a steady
    /// shortfall that grows with speed.
    pub speed_integral_gain: f64,
    /// Largest integral speed correction (m/s).
    pub speed_integral_max_mps: f64,
    /// The hop's own rise of the centre of mass from lift-off to apex,
    /// regulated when no command gives one (m).
    pub hop_rise_m: f64,
    /// Integral gain of the apex correction (m of target per m of error per hop).
    pub hop_gain: f64,
    /// Ankle spring stiffness (N·m/rad), eq. 1.
    pub ankle_stiffness: f64,
    /// Ankle spring damping (N·m·s/rad), eq. 1.
    pub ankle_damping: f64,
    /// Ankle rest angle for landing (rad, foot relative to shin).
    pub ankle_rest_rad: f64,
    /// Largest step of the ankle rest angle for thrust (rad).
    pub max_thrust_rad: f64,
    /// Foot placement gain k_ẋ (s), eq. 3.
    pub placement_gain_s: f64,
    /// Hip-to-toe distance at touchdown (m).
    pub landing_leg_m: f64,
    /// Shortening of the hip-to-toe distance while the body still rises in
    /// flight (m), so the toe swinging forward clears the ground; it fades
    /// out by the apex.
    pub flight_retract_m: f64,
    /// First guess of the stance duration T_s (s), before one is measured.
    pub stance_guess_s: f64,
    /// Hip servo stiffness in flight (N·m/rad), eq. 5.
    pub hip_kp: f64,
    /// Hip servo damping in flight (N·m·s/rad).
    pub hip_kv: f64,
    /// Hip servo stiffness in stance, knee onto the thrust line (N·m/rad).
    pub stance_hip_kp: f64,
    /// Hip servo damping in stance (N·m·s/rad).
    pub stance_hip_kv: f64,
    /// Knee servo stiffness in flight (N·m/rad).
    pub knee_kp: f64,
    /// Knee servo damping in flight (N·m·s/rad).
    pub knee_kv: f64,
    /// Posture gain k_p of eq. 4 at the knee (N·m/rad).
    pub posture_kp: f64,
    /// Posture gain k_v of eq. 4 at the knee (N·m·s/rad).
    pub posture_kv: f64,
    /// Apply eq. 4 at the knee in loading and unloading too, not only in
    /// compression and thrust.
    pub posture_always: bool,
    /// Desired trunk pitch ϕ_d (rad, positive nose down).
    pub pitch_rad: f64,
    /// Tail-base spring stiffness (N·m/rad).
    pub tail_stiffness: f64,
    /// Tail-base spring damping (N·m·s/rad).
    pub tail_damping: f64,
    /// Mean rest angle of the tail base (rad, positive raises the tail).
    pub tail_mean_rad: f64,
    /// Step of the tail-base rest angle between flight (up) and stance (down) (rad).
    pub tail_step_rad: f64,
    /// Pitch feedback added to the tail-base rest angle (rad of rest per rad
    /// of trunk pitch): the tail as an inertial appendage keeps the trunk level.
    pub tail_pitch_gain: f64,
    /// The lab's tail feedback on (`lab_additions.tail_feedback`; not in
    /// the paper, which steps the tail's rest angle and tunes its natural
    /// frequency to the hop): the rest follows pitch error and rate with
    /// `tail_pitch_gain` and `tail_rate_gain_s`.
    pub tail_feedback: bool,
    /// The lab's hop integrator on (`lab_additions.hop_integrator`; not in
    /// the paper): each measured apex corrects eq. 2's target by
    /// `hop_gain`, learning the losses eq. 2 leaves out.
    pub hop_integrator: bool,
    /// The lab's ground ahead (`lab_additions.ground_ahead`; not in the
    /// paper): eq. 2's apex target taken above the ground plane under the
    /// next apex, where the paper's is above the last lift-off.
    pub ground_ahead: bool,
    /// Pitch-rate feedback added to the tail-base rest angle (s).
    pub tail_rate_gain_s: f64,
    /// Stiffness of the two distal tail joints (N·m/rad).
    pub tail_tip_stiffness: f64,
    /// Damping of the two distal tail joints (N·m·s/rad).
    pub tail_tip_damping: f64,
    /// Neck servo stiffness, head kept level (N·m/rad).
    pub neck_kp: f64,
    /// Neck servo damping (N·m·s/rad).
    pub neck_kv: f64,
    /// Largest torque of hip and knee (N·m).
    pub max_torque: f64,
    /// Forward position of the obstacle's near face to jump (m), if any.
    pub jump_at_m: Option<f64>,
    /// Depth of the obstacle along the direction of travel (m).
    pub obstacle_depth_m: f64,
    /// Height of the obstacle (m).
    pub obstacle_height_m: f64,
    /// Clearance wanted between the toe and the obstacle (m).
    pub jump_clearance_m: f64,
    /// Ankle stiffness multiplier for the jump's take-off stance.
    pub jump_stiffness_factor: f64,
    /// Ankle damping multiplier for the landing stance after a jump.
    pub landing_damping_factor: f64,
}

impl Default for KangarooHopParams {
    fn default() -> Self {
        Self {
            speed_ramp_mps2: 0.25,
            speed_ramp: true,
            speed_trim: false,
            speed_integral_gain: 0.2,
            speed_integral_max_mps: 1.0,
            hop_rise_m: 0.07,
            hop_gain: 0.5,
            ankle_stiffness: 250.0,
            ankle_damping: 0.3,
            ankle_rest_rad: -1.2,
            max_thrust_rad: 0.8,
            placement_gain_s: 0.1,
            landing_leg_m: 0.46,
            flight_retract_m: 0.06,
            stance_guess_s: 0.11,
            hip_kp: 150.0,
            hip_kv: 4.0,
            stance_hip_kp: 200.0,
            stance_hip_kv: 5.0,
            knee_kp: 60.0,
            knee_kv: 2.0,
            posture_kp: 200.0,
            posture_kv: 30.0,
            posture_always: false,
            pitch_rad: 0.0,
            tail_stiffness: 7.0,
            tail_damping: 0.4,
            tail_mean_rad: 0.1,
            tail_step_rad: 0.15,
            tail_pitch_gain: 4.0,
            tail_feedback: true,
            hop_integrator: true,
            ground_ahead: false,
            tail_rate_gain_s: 0.3,
            tail_tip_stiffness: 4.0,
            tail_tip_damping: 0.05,
            neck_kp: 3.0,
            neck_kv: 0.08,
            max_torque: 200.0,
            jump_at_m: None,
            obstacle_depth_m: 0.3,
            obstacle_height_m: 0.25,
            jump_clearance_m: 0.08,
            jump_stiffness_factor: 1.5,
            landing_damping_factor: 4.0,
        }
    }
}
