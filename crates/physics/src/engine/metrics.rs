//! The running figures of Raibert & Hodgins 1991, Table 2, measured from a
//! simulation as it runs: stride length and duration, flight and stance
//! durations, pitch and roll magnitudes, change of leg length during support,
//! speed and its swing within a stride, peak vertical acceleration, the
//! friction the motion needed ("Modeling": max |f_t|/f_n over stance; apart,
//! as the paper reads it, the first and last [`EDGE_S`] of each support
//! from the rest), the peak vertical force on each leg, and whether it fell.
//!
//! Feed it every step with [`GaitRecorder::record`]; read
//! [`GaitRecorder::summary`]. Everything before `settle_s` is ignored.

use glam::DVec3;

use crate::control::laws::attitude::{attitude_error, heading_forward};
use crate::world::sim::Sim;

/// The start and the end of a support the paper sets apart when it reads the
/// friction needed ("with the exception of the very beginning and end of
/// the support period … up to 10 ms"), seconds.
pub const EDGE_S: f64 = 0.010;

/// The friction the paper says its motions needed ("Modeling"), as
/// `(middle, edges)` bounds on [`GaitSummary::friction_needed_mid`] and
/// [`GaitSummary::friction_needed_edges`] for a creature with `legs` legs:
/// the biped's "always less than 1" (1.0 for both), the quadruped's and
/// the kangaroo's "about 0.5" apart from the edges' "almost 2.0" (read as
/// 0.6 and 2.0).
#[must_use]
pub fn paper_friction_bounds(legs: usize) -> (f64, f64) {
    if legs == 2 { (1.0, 1.0) } else { (0.6, 2.0) }
}

/// One support period of one leg.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stance {
    /// Touchdown time (s).
    pub start_s: f64,
    /// Lift-off time (s).
    pub end_s: f64,
    /// Hip-to-foot length at touchdown minus its minimum in stance (m).
    pub leg_shortening_m: f64,
}

/// One period with every foot off the ground.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlightPeriod {
    /// Start (s).
    pub start_s: f64,
    /// End (s).
    pub end_s: f64,
    /// The leg whose lift-off began it.
    pub last_leg: usize,
}

/// The Table-2 quantities of a run (means over the run after settling).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GaitSummary {
    /// Whether the creature fell (trunk tilted past 60° or dropped below
    /// 40 % of its leg length).
    pub fell: bool,
    /// Desired speed (m/s).
    pub speed_desired_mps: f64,
    /// Mean forward speed of the centre of mass along the heading (m/s).
    pub speed_mean_mps: f64,
    /// Mean time between successive touchdowns of the first leg (s).
    pub stride_duration_s: f64,
    /// Distance travelled in one stride (m).
    pub stride_length_m: f64,
    /// Mean duration of periods with no foot on the ground (s).
    pub flight_duration_s: f64,
    /// Mean stance duration over all legs (s).
    pub stance_duration_s: f64,
    /// Mean stance duration of each leg (s).
    pub leg_stance_s: Vec<f64>,
    /// Mean leg shortening during support over all legs (m).
    pub leg_length_change_m: f64,
    /// Mean per-stride peak-to-peak trunk pitch (deg).
    pub pitch_magnitude_deg: f64,
    /// Mean per-stride peak-to-peak trunk roll (deg).
    pub roll_magnitude_deg: f64,
    /// Largest vertical acceleration of the centre of mass (g): the total
    /// vertical ground force over body weight, less the 1 g that only holds
    /// the body up (Newton's law for the whole creature).
    pub peak_vertical_accel_g: f64,
    /// Largest total vertical ground force over body weight (× weight).
    pub peak_vertical_force_bw: f64,
    /// Mean per-stride peak-to-peak forward speed of the centre of mass
    /// (m/s): how much the body surges within a stride. Table 2's "error in
    /// running speed" as this lab reads it (docs/physics.md says why).
    pub speed_swing_mps: f64,
    /// Largest |f_t| / f_n at any foot carrying ≥ 10 % of body weight.
    pub friction_needed_max: f64,
    /// The same over the supports that ended after settling, without their
    /// first and last [`EDGE_S`].
    pub friction_needed_mid: f64,
    /// The same within the first and last [`EDGE_S`] of those supports.
    pub friction_needed_edges: f64,
    /// Each leg's largest vertical ground force, × body weight.
    pub peak_leg_force_bw: Vec<f64>,
    /// Cost of transport: the positive work of every joint's actuator
    /// (leg springs, hip servos, stops; Σ max(0, τ·q̇) dt) after settling,
    /// over body weight × distance travelled along the heading. The
    /// springs' elastic return counts as work, so it bounds from above what
    /// motors would supply. 0 before the creature has travelled.
    pub cost_of_transport: f64,
    /// Mean per-stride peak-to-peak angle of the tail's base joint relative
    /// to the trunk (deg), for creatures with a tail.
    pub tail_wag_deg: Option<f64>,
    /// Every flight period after settling.
    pub flights: Vec<FlightPeriod>,
    /// Every stance after settling, per leg.
    pub stances: Vec<Vec<Stance>>,
    /// The centre of mass when settled and now (world, m), if settled.
    pub com_first_last: Option<(DVec3, DVec3)>,
    /// Deepest any touching foot went below the ground under it after
    /// settling (m; the ground springs' penetration, 0 with none).
    pub foot_below_ground_max_m: f64,
    /// Lowest and highest trunk height above the ground under it after
    /// settling (m).
    pub trunk_height_range_m: (f64, f64),
}

/// Accumulates a run's events.
#[derive(Clone, Debug)]
pub struct GaitRecorder {
    /// Seconds ignored at the start.
    pub settle_s: f64,
    /// Desired speed (m/s) and heading (rad) the run is judged against.
    pub speed_desired_mps: f64,
    /// Desired heading (rad).
    pub heading: f64,
    touching: Vec<bool>,
    open_stance: Vec<Option<(f64, f64, f64)>>,
    stances: Vec<Vec<Stance>>,
    flights: Vec<FlightPeriod>,
    flight_start: Option<(f64, usize)>,
    touchdowns: Vec<(f64, DVec3)>,
    pitch_range: (f64, f64),
    roll_range: (f64, f64),
    pitch_spans: Vec<f64>,
    roll_spans: Vec<f64>,
    tail_range: (f64, f64),
    tail_spans: Vec<f64>,
    speed_range: (f64, f64),
    speed_spans: Vec<f64>,
    start: Option<(f64, DVec3)>,
    last: (f64, DVec3),
    fell: bool,
    peak_force: f64,
    friction: f64,
    /// Per leg, the open support's (time, |f_t|/f_n) samples; classified
    /// into `friction_mid` and `friction_edges` at its lift-off.
    friction_samples: Vec<Vec<(f64, f64)>>,
    friction_mid: f64,
    friction_edges: f64,
    peak_leg_force: Vec<f64>,
    /// Positive actuator work since settling (J) and the weight (N).
    positive_work_j: f64,
    weight_n: f64,
    below_ground: f64,
    trunk_height_range: (f64, f64),
}

impl GaitRecorder {
    /// A recorder for `legs` legs judged against a desired speed and heading.
    #[must_use]
    pub fn new(legs: usize, speed_desired_mps: f64, heading: f64, settle_s: f64) -> Self {
        Self {
            settle_s,
            speed_desired_mps,
            heading,
            touching: vec![false; legs],
            open_stance: vec![None; legs],
            stances: vec![Vec::new(); legs],
            flights: Vec::new(),
            flight_start: None,
            touchdowns: Vec::new(),
            pitch_range: (f64::INFINITY, f64::NEG_INFINITY),
            roll_range: (f64::INFINITY, f64::NEG_INFINITY),
            pitch_spans: Vec::new(),
            roll_spans: Vec::new(),
            tail_range: (f64::INFINITY, f64::NEG_INFINITY),
            tail_spans: Vec::new(),
            speed_range: (f64::INFINITY, f64::NEG_INFINITY),
            speed_spans: Vec::new(),
            start: None,
            last: (0.0, DVec3::ZERO),
            fell: false,
            peak_force: 0.0,
            friction: 0.0,
            friction_samples: vec![Vec::new(); legs],
            friction_mid: 0.0,
            friction_edges: 0.0,
            peak_leg_force: vec![0.0; legs],
            positive_work_j: 0.0,
            weight_n: 0.0,
            below_ground: 0.0,
            trunk_height_range: (f64::INFINITY, f64::NEG_INFINITY),
        }
    }

    /// Record the state after a step.
    pub fn record(&mut self, sim: &Sim) {
        let t = sim.time;
        let c = &sim.creature;
        let d = &sim.data;
        let com = crate::dynamics::energy::center_of_mass(&c.model, d);
        let err = attitude_error(c, d, self.heading, 0.0);
        let fwd = heading_forward(self.heading);
        let lateral = DVec3::Y.cross(fwd);
        let pitch = err.dot(lateral).to_degrees();
        let roll = err.dot(fwd).to_degrees();
        let reach = c
            .legs
            .first()
            .map_or(1.0, |l| l.foot_point.length() + l.hip_in_trunk.length());
        // The trunk's height above the ground under it (the floor's 0, or
        // the terrain's there).
        let trunk = d.world[c.trunk].pos;
        let trunk_y = trunk.y - sim.terrain.height(trunk.x, trunk.z);
        if pitch.abs() > 60.0 || roll.abs() > 60.0 || trunk_y < 0.4 * reach.min(1.0 * c.scale) {
            self.fell = true;
        }
        let settled = t >= self.settle_s;
        if settled && self.start.is_none() {
            self.start = Some((t, com));
        }
        // Forward speed by the centre of mass's travel since the last step.
        let (t_last, com_last) = self.last;
        if settled && t > t_last && self.start.is_some_and(|(t0, _)| t0 < t) {
            let v = (com - com_last).dot(fwd) / (t - t_last);
            self.speed_range = (self.speed_range.0.min(v), self.speed_range.1.max(v));
        }
        self.last = (t, com);
        let weight = c.model.total_mass() * crate::dynamics::model::GRAVITY_MPS2;
        if self.start.is_some_and(|(t0, _)| t0 < t) && t > t_last {
            let power: f64 = d.tau.iter().zip(&d.qd).map(|(f, v)| (f * v).max(0.0)).sum();
            self.positive_work_j += power * (t - t_last);
            self.weight_n = weight;
        }
        let mut vertical = 0.0;
        let flat = sim.terrain.surface.is_flat() && sim.terrain.obstacles.is_empty();
        for (i, (leg, contact)) in c.legs.iter().zip(&sim.contacts).enumerate() {
            vertical += contact.force.y;
            let hip = d.world[c.trunk].rot * leg.hip_in_trunk + d.world[c.trunk].pos;
            let length = (contact.position - hip).length();
            if settled && weight > 0.0 {
                self.peak_leg_force[i] = self.peak_leg_force[i].max(contact.force.y / weight);
            }
            // The touchdown's sample belongs to the support it starts: the
            // samples are cleared at the touchdown (below) before it is kept.
            // Tangential over normal force, in the surface's frame at the
            // foot (on the floor: horizontal over vertical).
            let normal = if flat {
                DVec3::Y
            } else {
                let p = contact.position;
                sim.terrain.surface_at(p.x, p.z).1
            };
            if contact.touching && settled {
                let p = contact.position;
                let depth = if flat {
                    -p.y
                } else {
                    sim.terrain.height(p.x, p.z) - p.y
                };
                self.below_ground = self.below_ground.max(depth);
            }
            let pressing = contact.force.dot(normal);
            let friction = (contact.touching && pressing > 0.1 * weight && settled)
                .then(|| (contact.force - pressing * normal).length() / pressing);
            if let Some(ratio) = friction {
                self.friction = self.friction.max(ratio);
            }
            match (self.touching[i], contact.touching) {
                (false, true) => {
                    self.friction_samples[i].clear();
                    self.open_stance[i] = Some((t, length, length));
                    if i == 0 {
                        self.close_stride(t, com, settled);
                    }
                }
                (true, true) => {
                    if let Some(s) = &mut self.open_stance[i] {
                        s.2 = s.2.min(length);
                    }
                }
                (true, false) => {
                    if let Some((start, _, _)) = self.open_stance[i]
                        && settled
                        && start >= self.settle_s
                    {
                        self.classify_friction(i, start, t);
                    }
                    if let Some((start, at_td, min)) = self.open_stance[i].take()
                        && settled
                        && start >= self.settle_s
                    {
                        self.stances[i].push(Stance {
                            start_s: start,
                            end_s: t,
                            leg_shortening_m: at_td - min,
                        });
                    }
                    if sim.contacts.iter().all(|c| !c.touching) {
                        self.flight_start = Some((t, i));
                    }
                }
                (false, false) => {}
            }
            if let Some(ratio) = friction {
                self.friction_samples[i].push((t, ratio));
            }
            self.touching[i] = contact.touching;
        }
        if sim.contacts.iter().any(|c| c.touching)
            && let Some((start, leg)) = self.flight_start.take()
            && start >= self.settle_s
        {
            self.flights.push(FlightPeriod {
                start_s: start,
                end_s: t,
                last_leg: leg,
            });
        }
        if settled {
            let (low, high) = self.trunk_height_range;
            self.trunk_height_range = (low.min(trunk_y), high.max(trunk_y));
            self.peak_force = self.peak_force.max(vertical / weight);
            self.pitch_range = (self.pitch_range.0.min(pitch), self.pitch_range.1.max(pitch));
            self.roll_range = (self.roll_range.0.min(roll), self.roll_range.1.max(roll));
            if let Some(&k) = c.tail.first() {
                let tail = d.q[k].to_degrees();
                self.tail_range = (self.tail_range.0.min(tail), self.tail_range.1.max(tail));
            }
        }
    }

    /// Leg `i`'s support from `start_s` to its lift-off at `end_s`: each
    /// friction sample within [`EDGE_S`] of either end counts for the
    /// edges, the rest for the middle.
    fn classify_friction(&mut self, i: usize, start_s: f64, end_s: f64) {
        for &(t, ratio) in &self.friction_samples[i] {
            if t - start_s < EDGE_S || end_s - t < EDGE_S {
                self.friction_edges = self.friction_edges.max(ratio);
            } else {
                self.friction_mid = self.friction_mid.max(ratio);
            }
        }
        self.friction_samples[i].clear();
    }

    fn close_stride(&mut self, t: f64, com: DVec3, settled: bool) {
        if settled {
            self.touchdowns.push((t, com));
            if self.pitch_range.0.is_finite() && self.touchdowns.len() > 1 {
                self.pitch_spans
                    .push(self.pitch_range.1 - self.pitch_range.0);
                self.roll_spans.push(self.roll_range.1 - self.roll_range.0);
                if self.tail_range.0.is_finite() {
                    self.tail_spans.push(self.tail_range.1 - self.tail_range.0);
                }
                if self.speed_range.0.is_finite() {
                    self.speed_spans
                        .push(self.speed_range.1 - self.speed_range.0);
                }
            }
        }
        self.speed_range = (f64::INFINITY, f64::NEG_INFINITY);
        self.tail_range = (f64::INFINITY, f64::NEG_INFINITY);
        self.pitch_range = (f64::INFINITY, f64::NEG_INFINITY);
        self.roll_range = (f64::INFINITY, f64::NEG_INFINITY);
    }

    /// Whether the creature has fallen since the recorder started.
    #[must_use]
    pub fn fell(&self) -> bool {
        self.fell
    }

    /// The run's figures so far.
    #[must_use]
    pub fn summary(&self) -> GaitSummary {
        let mean = |xs: &mut dyn Iterator<Item = f64>| {
            let (s, n) = xs.fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
            if n == 0 { 0.0 } else { s / n as f64 }
        };
        let fwd = heading_forward(self.heading);
        let speed = match self.start {
            Some((t0, c0)) if self.last.0 > t0 => (self.last.1 - c0).dot(fwd) / (self.last.0 - t0),
            _ => 0.0,
        };
        let strides: Vec<(f64, f64)> = self
            .touchdowns
            .windows(2)
            .map(|w| (w[1].0 - w[0].0, (w[1].1 - w[0].1).dot(fwd)))
            .collect();
        let all_stances = || self.stances.iter().flatten();
        GaitSummary {
            fell: self.fell,
            speed_desired_mps: self.speed_desired_mps,
            speed_mean_mps: speed,
            stride_duration_s: mean(&mut strides.iter().map(|s| s.0)),
            stride_length_m: mean(&mut strides.iter().map(|s| s.1)),
            flight_duration_s: mean(&mut self.flights.iter().map(|f| f.end_s - f.start_s)),
            stance_duration_s: mean(&mut all_stances().map(|s| s.end_s - s.start_s)),
            leg_stance_s: self
                .stances
                .iter()
                .map(|v| mean(&mut v.iter().map(|s| s.end_s - s.start_s)))
                .collect(),
            leg_length_change_m: mean(&mut all_stances().map(|s| s.leg_shortening_m)),
            pitch_magnitude_deg: mean(&mut self.pitch_spans.iter().copied()),
            roll_magnitude_deg: mean(&mut self.roll_spans.iter().copied()),
            peak_vertical_accel_g: (self.peak_force - 1.0).max(0.0),
            peak_vertical_force_bw: self.peak_force,
            speed_swing_mps: mean(&mut self.speed_spans.iter().copied()),
            friction_needed_max: self.friction,
            friction_needed_mid: self.friction_mid,
            friction_needed_edges: self.friction_edges,
            peak_leg_force_bw: self.peak_leg_force.clone(),
            cost_of_transport: match self.start {
                Some((_, c0)) if (self.last.1 - c0).dot(fwd) > 1e-3 && self.weight_n > 0.0 => {
                    self.positive_work_j / (self.weight_n * (self.last.1 - c0).dot(fwd))
                }
                _ => 0.0,
            },
            tail_wag_deg: (!self.tail_spans.is_empty())
                .then(|| mean(&mut self.tail_spans.iter().copied())),
            flights: self.flights.clone(),
            stances: self.stances.clone(),
            com_first_last: self.start.map(|(_, c0)| (c0, self.last.1)),
            foot_below_ground_max_m: self.below_ground,
            trunk_height_range_m: self.trunk_height_range,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_supports_first_and_last_ten_ms_count_for_the_edges() {
        let mut recorder = GaitRecorder::new(1, 1.0, 0.0, 0.0);
        // A support from 1.000 s to 1.100 s: a spike 4 ms in, one 3 ms
        // before lift-off, and 0.4 in the middle.
        recorder.friction_samples[0] = vec![
            (1.004, 1.9),
            (1.012, 0.3),
            (1.050, 0.4),
            (1.088, 0.2),
            (1.097, 1.2),
        ];
        recorder.classify_friction(0, 1.0, 1.1);
        assert_eq!(recorder.friction_edges, 1.9);
        assert_eq!(recorder.friction_mid, 0.4);
        assert!(recorder.friction_samples[0].is_empty());
        // A later support's middle raises the middle's figure only.
        recorder.friction_samples[0] = vec![(2.05, 0.7)];
        recorder.classify_friction(0, 2.0, 2.1);
        assert_eq!((recorder.friction_mid, recorder.friction_edges), (0.7, 1.9));
    }
}
