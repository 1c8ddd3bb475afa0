//! Parameters of the quadruped bound and gallop (Raibert & Hodgins 1991,
//! "Gaits", Table 2), at scale 1, and the two styles.

/// The pairs: front then rear; within a pair the leg that lands first in
/// the gallop comes first (front-right 1, front-left 0, rear-right 3, rear-left 2).
pub const PAIRS: [[usize; 2]; 2] = [[1, 0], [3, 2]];

/// Index of the front pair in [`PAIRS`].
pub const FRONT: usize = 0;
/// Index of the rear pair in [`PAIRS`].
pub const REAR: usize = 1;

/// Bound or gallop.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BoundStyle {
    /// The legs of each pair strike and leave together.
    #[default]
    Bound,
    /// The legs of each pair strike separated in time and space.
    Gallop,
}

impl BoundStyle {
    /// The gait's name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Bound => "bound",
            Self::Gallop => "gallop",
        }
    }
}

/// Parameters of [`QuadrupedBound`](crate::control::gaits::bound::QuadrupedBound) at scale 1 (scaled by L while running).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadrupedBoundParams {
    /// Bound or gallop.
    pub style: BoundStyle,
    /// Leg spring stiffness k of eq. 1, per leg (N/m).
    pub leg_stiffness: f64,
    /// How far the telescoping leg can shorten from full length (m).
    pub leg_travel_m: f64,
    /// Leg spring damping b of eq. 1 in stance (N·s/m).
    pub leg_damping: f64,
    /// Leg damping while the foot is in the air (N·s/m).
    pub leg_air_damping: f64,
    /// Spring rest for landing (m of extension from full length, ≤ 0).
    pub landing_rest_m: f64,
    /// Spring rest of a shortened leg (m of extension).
    pub short_rest_m: f64,
    /// Initial thrust: extra rest length in the thrust state (m), the same
    /// for both pairs.
    pub thrust_m: f64,
    /// Extra thrust of the rear pair over the front (m); 0 for equal thrusts.
    pub rear_extra_thrust_m: f64,
    /// Largest thrust (m).
    pub max_thrust_m: f64,
    /// Smallest thrust (m); below 0 the thrust state shortens the leg and
    /// takes energy out when the flights are too long.
    pub min_thrust_m: f64,
    /// Desired total flight per stride, gathered plus extended (s).
    pub stride_flight_s: f64,
    /// Thrust change per second of stride-flight error (m/s).
    pub flight_gain: f64,
    /// Desired gathered flight, after the front pair's lift-off (s).
    pub gathered_flight_s: f64,
    /// Desired extended flight, after the rear pair's lift-off (s); negative
    /// for an overlap of the two stances.
    pub extended_flight_s: f64,
    /// Change of a pair's own thrust trim per second of error in the flight
    /// that follows its lift-off (m/s); 0 for the common thrust only.
    pub pair_flight_gain: f64,
    /// The thrust state ends once the leg has extended this fraction of
    /// the thrust past its landing rest (0: as soon as it is back at rest).
    pub thrust_end: f64,
    /// A pair stays short at least this long after its lift-off (s).
    pub min_short_s: f64,
    /// Initial guess of the stance duration T_s of eq. 3 (s).
    pub stance_s: f64,
    /// Foot placement gain k_ẋ of eq. 3 (s).
    pub placement_gain_s: f64,
    /// The lab's integral speed trim on (`lab_additions.speed_trim`; not
    /// in the paper), with gain `speed_integral_gain`.
    pub speed_trim: bool,
    /// The lab's hop integrator on (`lab_additions.hop_integrator`; not in
    /// the paper): the common thrust corrected by `flight_gain` from each
    /// stride's flight and each pair's trim by `pair_flight_gain`, where the
    /// paper sets each pair's thrust by eq. 2's prediction at its bottom.
    pub hop_integrator: bool,
    /// Change of the speed bias per stride per m/s of the stride's mean
    /// speed error (dimensionless): removes eq. 3's steady speed error.
    pub speed_integral_gain: f64,
    /// Largest speed bias as a fraction of the desired speed.
    pub speed_bias_cap: f64,
    /// Shortest stride (s): a rear touchdown sooner than this after the
    /// last one (a bounce) does not end the stride.
    pub min_stride_s: f64,
    /// Extra forward placement of the front feet (m): raises the nose.
    pub front_offset_m: f64,
    /// Pitch the stance hips pull the trunk toward (rad, positive nose down).
    pub pitch_bias: f64,
    /// Stance pitch stiffness toward the bias (N·m/rad), weak.
    pub pitch_kp: f64,
    /// Stance pitch-rate damping (N·m·s/rad).
    pub pitch_kv: f64,
    /// Stance roll servo stiffness (N·m/rad).
    pub roll_kp: f64,
    /// Stance roll damping (N·m·s/rad).
    pub roll_kv: f64,
    /// Stance yaw servo toward the heading (N·m/rad).
    pub yaw_kp: f64,
    /// Stance yaw damping (N·m·s/rad).
    pub yaw_kv: f64,
    /// Largest horizontal foot force the stance hips may ask for, as a
    /// fraction of the leg's spring force (friction-safe posture torques).
    pub posture_force_ratio: f64,
    /// Longest look-ahead of the landing foot target (s): the leg sweeps
    /// back over this last part of the flight to match ground speed.
    pub sweep_s: f64,
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
    /// Gallop: how much shorter the second leg of a pair lands (m), which
    /// delays its touchdown.
    pub gallop_shorter_m: f64,
    /// Gallop: how much further forward the second foot lands (m).
    pub gallop_spread_m: f64,
    /// Gallop: how long after the pair's first touchdown the second leg
    /// lengthens for landing (s); above 0 each leg also runs its own stance
    /// (`quadruped_bound/gallop_legs.rs`). 0: both legs follow the pair's
    /// stance, as files made before it ran.
    pub gallop_lag_s: f64,
}

impl Default for QuadrupedBoundParams {
    fn default() -> Self {
        Self {
            style: BoundStyle::Bound,
            leg_stiffness: 6_660.0,
            leg_travel_m: 0.36,
            leg_damping: 9.6,
            leg_air_damping: 120.0,
            landing_rest_m: -0.116,
            short_rest_m: -0.28,
            thrust_m: 0.03,
            rear_extra_thrust_m: 0.0,
            max_thrust_m: 0.068,
            min_thrust_m: 0.0,
            stride_flight_s: 0.12,
            flight_gain: 0.121,
            gathered_flight_s: 0.15,
            extended_flight_s: 0.03,
            pair_flight_gain: 0.0,
            thrust_end: 0.67,
            min_short_s: 0.05,
            stance_s: 0.09,
            placement_gain_s: 0.138,
            speed_trim: true,
            hop_integrator: true,
            speed_integral_gain: 0.11,
            speed_bias_cap: 1.0,
            min_stride_s: 0.12,
            front_offset_m: 0.0,
            pitch_bias: 0.0,
            pitch_kp: 160.0,
            pitch_kv: 20.0,
            roll_kp: 400.0,
            roll_kv: 60.0,
            yaw_kp: 200.0,
            yaw_kv: 20.0,
            posture_force_ratio: 0.43,
            sweep_s: 0.05,
            swing_kp: 300.0,
            swing_kv: 15.0,
            swing_roll_follow: 1.0,
            max_hip_torque: 400.0,
            gallop_shorter_m: 0.025,
            gallop_spread_m: 0.03,
            gallop_lag_s: 0.0,
        }
    }
}
