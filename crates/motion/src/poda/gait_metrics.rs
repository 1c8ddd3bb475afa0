//! Gait figures measured from the motion, not echoed from the parameters
//! (DESIGN.md gait metrics): each leg's duty factor and relative phase (PODA
//! eq. 9's convention: a leg with phase R touches down at t ≡ −R·P), foot
//! slip and foot turn during support (the turn: the foot's orientation,
//! eq. 2's last three components, against the one it had when the gait put
//! it in support), the body's speed and stride length.
//!
//! Contact is read from the feet: a foot is on the ground while its height is
//! at most [`CONTACT_HEIGHT_M`]; touchdown and lift-off times are interpolated
//! between frames where the height crosses that threshold.

use glam::{DMat3, DQuat, DVec2, DVec3};

use super::foot_orientation::angle_between_rad;

/// Height above the ground at or below which a foot counts as in contact, metres.
pub const CONTACT_HEIGHT_M: f64 = 1e-3;

/// One leg's measured figures.
#[derive(Clone, Debug, Default)]
pub struct LegMetrics {
    /// Leg name.
    pub name: String,
    in_contact: bool,
    previous_height_m: f64,
    first_touchdown_s: Option<f64>,
    last_touchdown_s: f64,
    touchdowns: u32,
    stance_start_s: Option<f64>,
    stance_sum_s: f64,
    duty_stance_s: f64,
    duty_span_s: f64,
    slip_origin: Option<DVec2>,
    /// Largest horizontal drift of the foot during one support phase, metres.
    pub slip_max_m: f64,
    /// Whether the leg's IK holds the foot's orientation (eq. 2), as the
    /// driver's model decided it.
    pub holds_orientation: bool,
    turn_origin: Option<DQuat>,
    /// Largest turn of the foot during one support phase, radians: its
    /// orientation's angle from the one it had at the support's first frame.
    pub turn_max_rad: f64,
}

impl LegMetrics {
    fn new(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            ..Self::default()
        }
    }

    /// Measured duty factor: stance time over whole cycles between the first
    /// and the latest touchdown (`None` before two touchdowns).
    #[must_use]
    pub fn duty_factor(&self) -> Option<f64> {
        (self.duty_span_s > 0.0).then(|| self.duty_stance_s / self.duty_span_s)
    }

    /// Measured period: mean time between touchdowns (`None` before two).
    #[must_use]
    pub fn period_s(&self) -> Option<f64> {
        let first = self.first_touchdown_s?;
        (self.touchdowns >= 2)
            .then(|| (self.last_touchdown_s - first) / f64::from(self.touchdowns - 1))
    }

    /// Measured relative phase for period `period_s`: `(−t_touchdown / P) mod 1`
    /// of the first measured touchdown.
    #[must_use]
    pub fn relative_phase(&self, period_s: f64) -> Option<f64> {
        let first = self.first_touchdown_s?;
        (period_s > 0.0).then(|| (-first / period_s).rem_euclid(1.0))
    }

    /// Touchdowns seen.
    #[must_use]
    pub fn touchdowns(&self) -> u32 {
        self.touchdowns
    }

    fn record(&mut self, t_prev: f64, t: f64, foot: DVec3, gait_support: bool, first: bool) {
        let height = foot.y;
        let contact = height <= CONTACT_HEIGHT_M;
        if first {
            self.in_contact = contact;
        } else if contact != self.in_contact {
            let (above, below) = if contact {
                (self.previous_height_m, height)
            } else {
                (height, self.previous_height_m)
            };
            let span = above - below;
            let fraction = if span > 0.0 {
                ((above - CONTACT_HEIGHT_M) / span).clamp(0.0, 1.0)
            } else {
                1.0
            };
            let crossing = if contact {
                t_prev + fraction * (t - t_prev)
            } else {
                t - fraction * (t - t_prev)
            };
            if contact {
                self.touchdown(crossing);
            } else {
                self.liftoff(crossing);
            }
            self.in_contact = contact;
        }
        self.previous_height_m = height;
        let xz = DVec2::new(foot.x, foot.z);
        if gait_support {
            let origin = *self.slip_origin.get_or_insert(xz);
            self.slip_max_m = self.slip_max_m.max((xz - origin).length());
        } else {
            self.slip_origin = None;
        }
    }

    fn record_turn(&mut self, rotation: DMat3, gait_support: bool) {
        if gait_support {
            let rotation = DQuat::from_mat3(&rotation);
            let origin = *self.turn_origin.get_or_insert(rotation);
            self.turn_max_rad = self.turn_max_rad.max(angle_between_rad(origin, rotation));
        } else {
            self.turn_origin = None;
        }
    }

    fn touchdown(&mut self, t: f64) {
        match self.first_touchdown_s {
            None => self.first_touchdown_s = Some(t),
            Some(first) => {
                self.duty_stance_s = self.stance_sum_s;
                self.duty_span_s = t - first;
            }
        }
        self.touchdowns += 1;
        self.last_touchdown_s = t;
        self.stance_start_s = Some(t);
    }

    fn liftoff(&mut self, t: f64) {
        if let Some(start) = self.stance_start_s.take() {
            self.stance_sum_s += t - start;
        }
    }
}

/// Figures of a whole run.
#[derive(Clone, Debug, Default)]
pub struct GaitMetrics {
    /// Per leg, in leg order.
    pub legs: Vec<LegMetrics>,
    /// Frames recorded.
    pub frames: u64,
    /// Simulated seconds recorded.
    pub sim_seconds: f64,
    /// Horizontal distance the body travelled, metres.
    pub body_distance_m: f64,
    /// Highest and lowest root height seen, metres.
    pub body_height_range_m: (f64, f64),
    /// Lowest and highest body pitch seen, radians (positive: nose up).
    pub body_pitch_range_rad: (f64, f64),
    /// Most the body fell behind and ran ahead of its even motion along the
    /// path (the fore-aft surge), metres; `(0, 0)` without surge.
    pub body_surge_range_m: (f64, f64),
    /// Longest time with no foot in contact, seconds (a flight phase).
    pub flight_max_s: f64,
    /// Deepest any foot went below the ground under it, metres (the feet
    /// are recorded as heights above the ground; 0 or less: never below).
    pub below_ground_max_m: f64,
    /// The root where the run started and where it is now, metres.
    pub root_first_last: Option<(DVec3, DVec3)>,
    flight_start_s: Option<f64>,
    last_body: Option<DVec2>,
}

impl GaitMetrics {
    /// Empty metrics for legs named `names`.
    #[must_use]
    pub fn new<'a>(names: impl IntoIterator<Item = &'a str>) -> Self {
        Self {
            legs: names.into_iter().map(LegMetrics::new).collect(),
            body_height_range_m: (f64::INFINITY, f64::NEG_INFINITY),
            body_pitch_range_rad: (f64::INFINITY, f64::NEG_INFINITY),
            below_ground_max_m: f64::NEG_INFINITY,
            ..Self::default()
        }
    }

    /// Records the frame ending at `t` (the previous one ended at `t_prev`):
    /// each leg's foot position (its height above the ground under it) and
    /// whether the gait has it in support, the
    /// root position and the body's pitch (radians). The first call after [`GaitMetrics::new`] only sets
    /// the starting state.
    pub fn record(
        &mut self,
        t_prev: f64,
        t: f64,
        feet: impl Iterator<Item = (DVec3, bool)>,
        root: DVec3,
        pitch_rad: f64,
    ) {
        let first = self.last_body.is_none();
        let mut any_contact = false;
        for (leg, (foot, support)) in self.legs.iter_mut().zip(feet) {
            leg.record(t_prev, t, foot, support, first);
            any_contact |= leg.in_contact;
            self.below_ground_max_m = self.below_ground_max_m.max(-foot.y);
        }
        self.root_first_last = Some((self.root_first_last.map_or(root, |(first, _)| first), root));
        let body = DVec2::new(root.x, root.z);
        if let Some(last) = self.last_body {
            self.body_distance_m += (body - last).length();
            self.frames += 1;
            self.sim_seconds += t - t_prev;
        }
        self.last_body = Some(body);
        let (low, high) = self.body_height_range_m;
        self.body_height_range_m = (low.min(root.y), high.max(root.y));
        let (low, high) = self.body_pitch_range_rad;
        self.body_pitch_range_rad = (low.min(pitch_rad), high.max(pitch_rad));
        if any_contact {
            self.flight_start_s = None;
        } else {
            let start = *self.flight_start_s.get_or_insert(t_prev);
            self.flight_max_s = self.flight_max_s.max(t - start);
        }
    }

    /// The same metrics with `held[i]` saying whether leg `i`'s IK holds its
    /// foot's orientation (eq. 2).
    #[must_use]
    pub fn holding_orientation(mut self, held: impl IntoIterator<Item = bool>) -> Self {
        for (leg, held) in self.legs.iter_mut().zip(held) {
            leg.holds_orientation = held;
        }
        self
    }

    /// Records this frame's foot orientations (rotation matrices from each
    /// foot's frame to the world, in leg order) with whether the gait has
    /// each foot in support: the turn of a foot in support is measured from
    /// its orientation at the support's first frame, as its slip is from its
    /// position then.
    pub fn record_turns(&mut self, feet: impl Iterator<Item = (DMat3, bool)>) {
        for (leg, (rotation, support)) in self.legs.iter_mut().zip(feet) {
            leg.record_turn(rotation, support);
        }
    }

    /// Largest turn of any planted foot during its support, radians.
    #[must_use]
    pub fn foot_turn_max_rad(&self) -> f64 {
        self.legs.iter().map(|l| l.turn_max_rad).fold(0.0, f64::max)
    }

    /// The names of the legs whose IK holds their foot's orientation, in leg order.
    pub fn orientation_legs(&self) -> impl Iterator<Item = &str> {
        self.legs
            .iter()
            .filter(|l| l.holds_orientation)
            .map(|l| l.name.as_str())
    }

    /// Records this frame's fore-aft surge, metres forward of the body's even
    /// motion along its path.
    pub fn record_surge(&mut self, surge_m: f64) {
        let (low, high) = self.body_surge_range_m;
        self.body_surge_range_m = (low.min(surge_m), high.max(surge_m));
    }

    /// Largest foot slip of any leg, metres.
    #[must_use]
    pub fn foot_slip_max_m(&self) -> f64 {
        self.legs.iter().map(|l| l.slip_max_m).fold(0.0, f64::max)
    }

    /// Mean measured period over the legs with one, seconds.
    #[must_use]
    pub fn period_s(&self) -> Option<f64> {
        let periods: (f64, u32) = self
            .legs
            .iter()
            .filter_map(LegMetrics::period_s)
            .fold((0.0, 0), |(sum, n), p| (sum + p, n + 1));
        (periods.1 > 0).then(|| periods.0 / f64::from(periods.1))
    }

    /// Mean horizontal body speed, m/s.
    #[must_use]
    pub fn body_speed_mps(&self) -> f64 {
        if self.sim_seconds > 0.0 {
            self.body_distance_m / self.sim_seconds
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gaitlab_core::portable::Portable;

    #[test]
    fn interpolated_contacts_give_duty_period_and_phase() {
        // One foot: on the ground for 0.6 s of every 1 s cycle, touching down at t ≡ 0.25.
        let mut metrics = GaitMetrics::new(["leg"]);
        let dt = 1.0 / 60.0;
        let height = |t: f64| {
            let s = (t - 0.25).rem_euclid(1.0);
            if s < 0.6 {
                0.0
            } else {
                0.05 * (std::f64::consts::PI * (s - 0.6) / 0.4).psin()
            }
        };
        let mut t_prev = 0.0;
        for k in 0..=600 {
            let t = f64::from(k) * dt;
            let support = (t - 0.25).rem_euclid(1.0) < 0.6;
            metrics.record(
                t_prev,
                t,
                std::iter::once((DVec3::new(0.0, height(t), 0.0), support)),
                DVec3::ZERO,
                0.0,
            );
            t_prev = t;
        }
        let leg = &metrics.legs[0];
        let period = leg.period_s().unwrap_or(0.0);
        assert!((period - 1.0).abs() < 1e-3, "period {period}");
        let duty = leg.duty_factor().unwrap_or(0.0);
        assert!((duty - 0.6).abs() < 0.01, "duty {duty}");
        let phase = leg.relative_phase(period).unwrap_or(-1.0);
        assert!((phase - 0.75).abs() < 0.01, "phase {phase}");
        assert!(leg.slip_max_m < 1e-12);
    }

    #[test]
    fn a_foots_turn_is_measured_from_the_start_of_each_support() {
        let mut metrics = GaitMetrics::new(["leg"]).holding_orientation([true]);
        let turned = |rad: f64| DMat3::from_rotation_x(rad) * DMat3::from_rotation_y(0.4);
        // Support: 0.01 rad, then 0.03 rad from where it touched down.
        for rad in [0.0, 0.01, 0.03] {
            metrics.record_turns(std::iter::once((turned(rad), true)));
        }
        // Transfer: any turn; the next support starts where it lands.
        for rad in [0.5, 0.9] {
            metrics.record_turns(std::iter::once((turned(rad), false)));
        }
        for rad in [0.9, 0.91] {
            metrics.record_turns(std::iter::once((turned(rad), true)));
        }
        assert!((metrics.foot_turn_max_rad() - 0.03).abs() < 1e-12);
        assert_eq!(metrics.orientation_legs().collect::<Vec<_>>(), ["leg"]);
        let without = GaitMetrics::new(["leg"]);
        assert_eq!(without.orientation_legs().count(), 0);
    }
}
