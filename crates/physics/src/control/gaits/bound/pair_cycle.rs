//! The bound's pairs stepped through their cycle each control interval
//! (Raibert & Hodgins 1991, Figure 4 on the front and the rear pair): each
//! pair's events, eq. 2's thrust regulated on the stride's flight, eq. 3's
//! stance time measured.

use glam::DVec3;

use super::gallop_legs::{BOUNCE_S, LegSense, spring_events};
use super::{FRONT, PAIRS, QuadrupedBound, REAR};
use crate::control::additions::speed_trim::along_z;
use crate::control::gaits::bound::params::BoundStyle;
use crate::control::laws::attitude::com_state;
use crate::control::laws::hop_height::{
    flight_for_height, height_for_flight, pair_springs, thrust_for_apex,
};
use crate::control::laws::phase::Phase;
use crate::world::sim::ControlInput;

impl QuadrupedBound {
    /// Bound or gallop.
    #[must_use]
    pub fn style(&self) -> BoundStyle {
        self.params.style
    }

    /// The state of the pair `pair` (0 front, 1 rear).
    #[must_use]
    pub fn pair_phase(&self, pair: usize) -> Phase {
        self.pairs[pair.min(1)].phase
    }

    /// The state shown for the creature: the rear pair's in its stance,
    /// else the front pair's, else flight.
    #[must_use]
    pub fn phase(&self) -> Phase {
        if self.pairs[REAR].phase != Phase::Flight {
            self.pairs[REAR].phase
        } else {
            self.pairs[FRONT].phase
        }
    }

    pub(super) fn pair_thrust(&self, pair: usize) -> f64 {
        let l = self.plan.scale.length();
        if !self.params.hop_integrator && self.eq2_thrust[pair].is_finite() {
            return self.eq2_thrust[pair];
        }
        let extra = if pair == REAR {
            self.params.rear_extra_thrust_m * l
        } else {
            0.0
        };
        (self.thrust + extra + self.trim[pair])
            .clamp(self.params.min_thrust_m * l, self.params.max_thrust_m * l)
    }

    /// Regulate pair `k`'s trim on the flight `flight` (s) that followed
    /// its lift-off (negative: overlap with the other pair's stance).
    pub(super) fn regulate_pair(&mut self, k: usize, flight: f64) {
        let p = self.params;
        if !p.hop_integrator {
            return;
        }
        let scale = self.plan.scale;
        let l = scale.l;
        let target = if k == FRONT {
            p.gathered_flight_s
        } else {
            p.extended_flight_s
        } * scale.time();
        let max = p.max_thrust_m * l;
        self.trim[k] = (self.trim[k] + p.pair_flight_gain * scale.velocity() * (target - flight))
            .clamp(-max, max);
    }

    /// Eq. 2 for pair `k` with feet `touching`: the step of its legs' rests
    /// that makes the predicted apex the height of the flight that follows
    /// its lift-off (gathered after the front pair, extended after the
    /// rear; none for an overlap) above the last lift-off, between the
    /// bound's smallest and largest thrust.
    fn pair_eq2(&self, input: &ControlInput<'_>, k: usize, touching: [bool; 2]) -> f64 {
        let p = &self.params;
        let s = self.plan.scale;
        let l = s.length();
        let (com, v) = com_state(input.creature, input.data);
        let springs = pair_springs(
            &input.data.q,
            PAIRS[k].map(|i| input.creature.legs[i].spring),
            self.pairs[k].rest,
            touching,
            p.leg_stiffness * s.stiffness(),
        );
        let flight = if k == FRONT {
            p.gathered_flight_s
        } else {
            p.extended_flight_s
        } * s.time();
        let rise =
            (input.commands.hop_height_m).unwrap_or_else(|| height_for_flight(flight.max(0.0)));
        let mass = input.creature.model.total_mass();
        let step = thrust_for_apex(&springs, mass, com.y, v.y, self.liftoff_com_y + rise);
        step.clamp(p.min_thrust_m * l, p.max_thrust_m * l)
    }

    /// Advance both pairs' state machines on the contact and spring events.
    pub(super) fn advance(&mut self, input: &ControlInput<'_>, com_forward: f64) {
        let scale = self.plan.scale;
        let l = scale.l;
        let p = self.params;
        let any_touch = input.contacts.iter().any(|c| c.touching);
        // Flights (every foot off) and the thrust regulation on the stride's
        // total flight, updated when the gathered flight ends.
        match (self.flight_start, any_touch) {
            (Some((t0, last)), true) => {
                self.flight_s[last] = input.time - t0;
                self.stride_flight_s += input.time - t0;
                self.flight_start = None;
            }
            (None, false) => {
                let last = if self.pairs[FRONT].liftoff_s >= self.pairs[REAR].liftoff_s {
                    FRONT
                } else {
                    REAR
                };
                self.flight_start = Some((input.time, last));
            }
            _ => {}
        }
        let thrusts = [self.pair_thrust(FRONT), self.pair_thrust(REAR)];
        // Flights to regulate each pair's trim on: (pair, flight).
        let mut events: [Option<(usize, f64)>; 2] = [None; 2];
        for (k, &legs) in PAIRS.iter().enumerate() {
            let other = self.pairs[1 - k];
            let touching = [
                input.contacts[legs[0]].touching,
                input.contacts[legs[1]].touching,
            ];
            let any = touching[0] || touching[1];
            let (mut q, mut qd, mut n) = (0.0, 0.0, 0.0);
            for (s, &i) in legs.iter().enumerate() {
                if touching[s] {
                    let spring = input.creature.legs[i].spring;
                    q += input.data.q[spring] - self.pairs[k].rest[s];
                    qd += input.data.qd[spring];
                    n += 1.0;
                }
            }
            if n > 0.0 {
                q /= n;
                qd /= n;
            }
            let time = input.time;
            let pair = &mut self.pairs[k];
            for s in 0..2 {
                if touching[s] && pair.phase != Phase::Flight && !pair.touched[s] {
                    pair.touched[s] = true;
                    pair.rest[s] = input.data.q[input.creature.legs[legs[s]].spring]
                        .clamp(p.short_rest_m * l, 0.0)
                        .max(p.landing_rest_m * l - 0.1 * l)
                        .min(p.landing_rest_m * l + 0.02 * l);
                }
            }
            match pair.phase {
                Phase::Flight if any => {
                    if !self.liftoff_com_y.is_finite() {
                        self.liftoff_com_y = com_state(input.creature, input.data).0.y;
                    }
                    let pair = &mut self.pairs[k];
                    pair.phase = Phase::Loading;
                    pair.touchdown_s = time;
                    pair.armed = false;
                    for s in 0..2 {
                        pair.touched[s] = touching[s];
                        let q = input.data.q[input.creature.legs[legs[s]].spring];
                        pair.rest[s] = q
                            .max(p.landing_rest_m * l - 0.1 * l)
                            .min(p.landing_rest_m * l + 0.02 * l);
                    }
                    // The other pair's flight ends with this touchdown.
                    if other.phase == Phase::Flight && other.liftoff_s > pair.liftoff_s {
                        events[k] = Some((1 - k, time - other.liftoff_s));
                    }
                    self.pairs[1 - k].armed = true;
                    // A stride runs from one rear touchdown to the next; a
                    // rear bounce sooner than `min_stride_s` is the same stride.
                    let stride_done = self
                        .stride_start
                        .is_none_or(|(t0, _)| time - t0 >= p.min_stride_s * scale.time());
                    if k == REAR && stride_done {
                        // Eq. 2's energy per stride: one thrust for both pairs,
                        // regulated on the stride's total flight.
                        if p.hop_integrator && self.stride_start.is_some() {
                            let target = (input.commands.hop_height_m)
                                .map_or(p.stride_flight_s * scale.time(), flight_for_height);
                            let error = target - self.stride_flight_s;
                            self.thrust = (self.thrust + p.flight_gain * scale.velocity() * error)
                                .clamp(p.min_thrust_m * l, p.max_thrust_m * l);
                        }
                        self.stride_flight_s = 0.0;
                        let vd = input.commands.speed_mps;
                        self.speed_trim.stride(
                            p.speed_trim,
                            p.speed_integral_gain,
                            vd,
                            p.speed_bias_cap * vd.abs().max(0.5 * scale.velocity()),
                            time,
                            along_z(com_forward),
                            DVec3::Z,
                            1e-3,
                        );
                        self.stride_start = Some((time, com_forward));
                    }
                    continue;
                }
                // A foot bouncing off at impact is still landing.
                Phase::Loading if !any && time - pair.touchdown_s > BOUNCE_S * scale.time() => {
                    pair.phase = Phase::Flight;
                    pair.liftoff_s = time;
                }
                Phase::Loading if !any => {}
                stance => {
                    let extended = p.thrust_end * thrusts[k] - 0.005 * l;
                    let since = time - pair.touchdown_s;
                    pair.phase = stance.after(spring_events(q, qd, since, extended, l));
                    // Eq. 2 at the pair's bottom (Figure 4, "extend leg").
                    if !p.hop_integrator
                        && stance == Phase::Compression
                        && pair.phase == Phase::Thrust
                    {
                        self.eq2_thrust[k] = self.pair_eq2(input, k, touching);
                    }
                }
            }
            let pair = &mut self.pairs[k];
            if matches!(
                pair.phase,
                Phase::Compression | Phase::Thrust | Phase::Unloading
            ) && !any
            {
                self.liftoff_com_y = com_state(input.creature, input.data).0.y;
                let pair = &mut self.pairs[k];
                pair.phase = Phase::Flight;
                pair.liftoff_s = time;
                pair.stance_s =
                    (time - pair.touchdown_s).clamp(0.04 * scale.time(), 0.3 * scale.time());
                // The other pair landed during this stance: no flight.
                if other.phase != Phase::Flight && other.touchdown_s > pair.touchdown_s {
                    events[k] = Some((k, other.touchdown_s - time));
                }
            }
        }
        for (k, flight) in events.into_iter().flatten() {
            self.regulate_pair(k, flight);
        }
        if p.style == BoundStyle::Gallop && p.gallop_lag_s > 0.0 {
            self.advance_legs(input, thrusts);
        }
    }

    /// Each leg's own stance within its pair (the gallop with a lag).
    fn advance_legs(&mut self, input: &ControlInput<'_>, thrusts: [f64; 2]) {
        let l = self.plan.scale.l;
        for (k, &legs) in PAIRS.iter().enumerate() {
            let pair = &mut self.pairs[k];
            for (s, &i) in legs.iter().enumerate() {
                let spring = input.creature.legs[i].spring;
                let sense = LegSense {
                    touching: input.contacts[i].touching,
                    q_m: input.data.q[spring] - pair.rest[s],
                    qd_mps: input.data.qd[spring],
                    extended_m: self.params.thrust_end * thrusts[k] - 0.005 * l,
                    time_s: input.time,
                    l,
                };
                pair.legs[s].advance(pair.phase, &sense);
            }
        }
    }
}
