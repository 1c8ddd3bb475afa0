//! The biped gallop's stride (Raibert & Hodgins 1991, "Gaits" and Figure
//! 4 per leg): each leg's states on its own events, the trailing leg handing
//! the load to the leading one, eq. 2's thrust and the flight's pitching
//! measured at the stride's last lift-off, and the rest length each leg
//! heads for.

use glam::DVec3;

use super::{BipedGallop, GallopPhase, GallopStyle};
use crate::control::laws::attitude::{attitude_error, com_state, heading_forward};
use crate::control::laws::phase::{Phase, StanceEvents};
use crate::world::sim::ControlInput;

impl BipedGallop {
    /// Whether leg `i` is in support (any state but flight).
    pub(super) fn in_support(&self, i: usize) -> bool {
        self.legs[i].phase != Phase::Flight
    }

    /// Advance each leg's Figure-4 state on its spring's and foot's events,
    /// and the stride's support state from both.
    pub(super) fn advance_phase(&mut self, input: &ControlInput<'_>) {
        let p = self.params;
        let l = self.plan.scale.l;
        let trunk_y = input.data.world[input.creature.trunk].pos.y;
        let pitch = self.pitch(input);
        if self.phase == GallopPhase::Flight {
            self.apex_height = self.apex_height.max(trunk_y);
            self.descending = self.descending || trunk_y < self.apex_height - 0.002 * l;
        }
        let (lead, trail) = (self.lead(), self.trail());
        let lead_rebounds = self.legs[lead].phase == Phase::Thrust;
        for i in [trail, lead] {
            let Some(leg) = input.creature.legs.get(i) else {
                continue;
            };
            let touching = input.contacts.get(i).is_some_and(|c| c.touching);
            let q = input.data.q[leg.spring];
            let qd = input.data.qd[leg.spring];
            let other_down = self.in_support(1 - i);
            // A landing counts from a falling flight or beside the other leg,
            // not as a scuff just after lift-off.
            if self.legs[i].phase == Phase::Flight && touching && (other_down || self.descending) {
                if i == trail && self.liftoff_pitch.is_finite() {
                    // The flight's pitching: aim the stance's posture servo
                    // at the opposite side, so the trunk swings about level.
                    let change = pitch - self.liftoff_pitch;
                    let goal = (-p.pitch_feedforward * change).clamp(-0.3, 0.3);
                    self.pitch_d += 0.5 * (goal - self.pitch_d);
                }
                let state = &mut self.legs[i];
                state.phase = Phase::Loading;
                state.touchdown_s = input.time;
                state.landed_rest = state.rest.min(p.hopper.landing_rest_m * l);
            }
            let bottom = i == lead && self.legs[i].phase == Phase::Compression;
            let state = &mut self.legs[i];
            let since_touchdown = input.time - state.touchdown_s;
            state.phase = state.phase.after(StanceEvents {
                // Compression once the spring shortens; a leg that landed
                // still lengthening may not shorten past its rest at once.
                shortened: q < state.landed_rest - 0.005 * l
                    || since_touchdown >= 0.02 * self.plan.scale.time(),
                // Thrust once the spring lengthens again after a real
                // compression, not on the first jitter of a landing.
                lengthening: qd >= 0.0 && since_touchdown >= 0.03 * self.plan.scale.time(),
                extended: q >= state.landed_rest + self.thrust - 0.01 * l || q >= -0.005 * l,
            });
            // Eq. 2 at the leading leg's bottom: the thrust whose predicted
            // apex is the target (Figure 4, "extend leg").
            if bottom && !p.hop_integrator && self.legs[i].phase == Phase::Thrust {
                self.thrust = self.eq2_thrust(input, i, q);
            }
            let state = &mut self.legs[i];
            // The trailing leg hands the load over: it shortens once the
            // leading leg rebounds, so it leaves the ground first.
            if i == trail
                && lead_rebounds
                && matches!(state.phase, Phase::Compression | Phase::Thrust)
            {
                state.phase = Phase::Unloading;
            }
            // Lift-off ends a stance only once the leg has thrust; a foot that
            // bounces off the ground at impact is still landing.
            if matches!(state.phase, Phase::Thrust | Phase::Unloading) && !touching {
                state.stance_s = (input.time - state.touchdown_s)
                    .clamp(0.05 * self.plan.scale.time(), 0.5 * self.plan.scale.time());
                state.phase = Phase::Flight;
                state.hold = [input.data.q[leg.hip[0]], input.data.q[leg.hip[1]]];
                if !other_down {
                    self.start_flight(input);
                    self.liftoff_pitch = pitch;
                    self.liftoff_com_y = com_state(input.creature, input.data).0.y;
                }
            }
        }
        self.phase = match (self.in_support(trail), self.in_support(lead)) {
            (false, false) => GallopPhase::Flight,
            (true, false) => GallopPhase::TrailSupport,
            (true, true) => GallopPhase::DoubleSupport,
            (false, true) => GallopPhase::LeadSupport,
        };
    }

    /// The trunk's pitch about the heading's lateral axis (rad).
    pub(super) fn pitch(&self, input: &ControlInput<'_>) -> f64 {
        let heading = input.commands.heading_rad;
        let err = attitude_error(input.creature, input.data, heading, 0.0);
        let lateral = DVec3::Y.cross(heading_forward(heading));
        err.dot(lateral)
    }

    /// The stride's last lift-off: the hop's apex adjusts the thrust (eq. 2)
    /// and the stride's speed the integral correction.
    pub(super) fn start_flight(&mut self, input: &ControlInput<'_>) {
        let p = self.params;
        let l = self.plan.scale.l;
        if p.hop_integrator && self.apex_height.is_finite() {
            let landing_height = self.plan.leg_m[self.trail()] + p.hopper.landing_rest_m * l;
            let hop = input.commands.hop_height_m.unwrap_or(p.hop_height_m * l);
            let error = (landing_height + hop) - self.apex_height;
            self.thrust = (self.thrust + p.hopper.hop_gain * error).clamp(0.0, 0.12 * l);
        }
        let (on, gain) = (p.speed_trim, p.hopper.speed_integral_gain);
        (self.trim).stride_at_input(on, gain, self.plan.scale.velocity(), input);
        self.apex_height = f64::NEG_INFINITY;
        self.descending = false;
    }

    /// Eq. 2 for leg `i` at spring length `q` (m): the extension of its rest
    /// beyond its landed rest that makes the predicted apex the hop height
    /// above the stride's last lift-off (before the first, the trunk
    /// `hop_height_m` above a hip over a vertical leg at landing length),
    /// between none and the leg's full length.
    fn eq2_thrust(&self, input: &ControlInput<'_>, i: usize, q: f64) -> f64 {
        let p = &self.params;
        let s = self.plan.scale;
        let l = s.length();
        let hop = input.commands.hop_height_m.unwrap_or(p.hop_height_m * l);
        let target = if self.liftoff_com_y.is_finite() {
            self.liftoff_com_y + hop
        } else {
            let com_y = com_state(input.creature, input.data).0.y;
            let trunk_y = input.data.world[input.creature.trunk].pos.y;
            let landing_height = self.plan.leg_m[self.trail()] + p.hopper.landing_rest_m * l;
            com_y + (landing_height + hop - trunk_y)
        };
        let state = &self.legs[i];
        p.hopper
            .eq2_thrust(input, s, (state.rest, q), state.landed_rest, target)
    }

    /// Whether airborne leg `i` holds its lift-off angles rather than
    /// swinging to its landing place.
    pub(super) fn holds(&self, i: usize) -> bool {
        match self.params.style {
            // The trailing leg waits behind while the leading leg supports;
            // both swing forward together in flight.
            GallopStyle::TogetherSwing => i == self.trail() && self.in_support(self.lead()),
            // The leading leg waits through flight and swings forward in the
            // trailing leg's single support; the trailing leg swings in the
            // leading leg's.
            GallopStyle::AlternateSwing => i == self.lead() && self.phase == GallopPhase::Flight,
        }
    }

    /// The rest length leg `i` heads for (m).
    pub(super) fn rest_target(&self, i: usize, time: f64) -> f64 {
        let p = &self.params;
        let l = self.plan.scale.l;
        let state = &self.legs[i];
        match state.phase {
            Phase::Thrust => state.landed_rest + self.thrust,
            Phase::Unloading => p.hopper.idle_rest_m * l,
            Phase::Loading | Phase::Compression => state.landed_rest,
            Phase::Flight if i == self.trail() => {
                // Lengthen for landing in flight; not while the leading leg
                // still supports, so the foot does not scuff the ground.
                if self.phase == GallopPhase::Flight {
                    p.hopper.landing_rest_m * l
                } else {
                    p.hopper.idle_rest_m * l
                }
            }
            Phase::Flight => {
                let trail = &self.legs[self.trail()];
                let waited = time - trail.touchdown_s >= p.lead_delay_s * self.plan.scale.time();
                if self.in_support(self.trail()) && waited {
                    p.hopper.landing_rest_m * l
                } else if self.phase == GallopPhase::Flight && self.descending {
                    (p.hopper.landing_rest_m - p.lead_retract_m) * l
                } else {
                    p.hopper.idle_rest_m * l
                }
            }
        }
    }
}
