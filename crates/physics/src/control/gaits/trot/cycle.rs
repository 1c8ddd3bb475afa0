//! The trot's leg cycle (Raibert & Hodgins 1991, Figure 4 on a virtual leg):
//! each leg of the active diagonal pair lands, compresses and thrusts on
//! its own spring's events; the pair unloads as one virtual leg when its
//! legs are near full length on average (`unison_liftoff`), and lifts off
//! when both feet have left the ground. Eq. 2 sets the pair's thrust at the
//! virtual leg's bottom, or — the lab's hop integrator — each flight
//! corrects it from the Table-2 flight time.

use super::QuadrupedRun;
use crate::control::additions::ground_ahead::{Liftoff, apex_target_m};
use crate::control::additions::speed_trim::along_z;
use crate::control::laws::attitude::com_state;
use crate::control::laws::hop_height::{
    Release, flight_for_height, pair_springs, thrust_for_apex_released,
};
use crate::control::laws::leg_spring::LegSpring;
use crate::control::laws::phase::{Phase, StanceEvents};
use crate::world::sim::{ControlInput, Drive};

impl QuadrupedRun {
    /// Advance the active pair's legs through Figure 4 on their springs'
    /// and feet's events; the pairs swap when the virtual leg lifts off.
    pub(super) fn advance_phase(
        &mut self,
        input: &ControlInput<'_>,
        drives: &[Drive],
        descending: bool,
        com_forward: f64,
    ) {
        let t = self.tuning();
        let l = self.plan.scale.length();
        let time_s = self.plan.scale.time();
        let pair = self.pairs[self.active];
        let landing = t.landing_rest_m * l;
        let unison = t.unison_liftoff > 0.5;
        // Flight time of the pair that lifted off last ends at the first touch
        // of any foot.
        if let Some(p) = self.liftoff_pair
            && input.contacts.iter().any(|c| c.touching)
        {
            let flight = input.time - self.liftoff_time;
            self.flight_s[p] = flight;
            let target =
                (input.commands.hop_height_m).map_or(t.flight_s[p] * time_s, flight_for_height);
            let error = target - flight;
            if self.params.hop_integrator {
                self.thrust[p] = (self.thrust[p] + self.params.flight_gain * time_s * error)
                    .clamp(0.0, self.params.max_thrust_m * l);
            }
            self.liftoff_pair = None;
        }
        for &i in &pair {
            if self.done[i] {
                continue;
            }
            let leg = &input.creature.legs[i];
            let touching = input.contacts[i].touching;
            let q = input.data.q[leg.spring];
            let qd = input.data.qd[leg.spring];
            let phase = &mut self.leg_phase[i];
            match *phase {
                Phase::Flight => {
                    let armed = descending || self.in_stance || !t.wait_for_descent;
                    if touching && armed {
                        *phase = Phase::Loading;
                        self.leg_touchdown[i] = input.time;
                        // A leg caught short stands at the length it landed with.
                        self.stance_rest[i] = drives[leg.spring]
                            .spring
                            .rest
                            .min(q + 0.02 * l)
                            .max(landing - 0.08 * l);
                        if !self.in_stance {
                            self.in_stance = true;
                            self.touchdown_time = input.time;
                            self.eq2_set = false;
                            if !self.liftoff_com_y.is_finite() {
                                let com = com_state(input.creature, input.data).0;
                                let liftoff = Liftoff::at(com, &input.ground);
                                self.liftoff_com_y = liftoff.com_y;
                                self.liftoff_ground_y = liftoff.ground_y;
                            }
                        }
                    }
                }
                stance => {
                    *phase = stance.after(StanceEvents {
                        shortened: (qd < 0.0 && q < self.stance_rest[i] - 0.002 * l)
                            || input.time - self.leg_touchdown[i] > 0.015 * time_s,
                        lengthening: qd >= 0.0,
                        extended: !unison && q >= self.stance_rest[i] - 0.005 * l,
                    });
                }
            }
            if *phase != Phase::Flight && !touching {
                // A foot bouncing off at once may land again.
                self.done[i] =
                    *phase != Phase::Loading || input.time - self.leg_touchdown[i] > 0.01 * time_s;
                *phase = Phase::Flight;
            }
        }
        // Eq. 2 at the virtual leg's bottom: the first of its legs to turn
        // from Compression to Thrust sets the pair's thrust.
        if !self.params.hop_integrator
            && !self.eq2_set
            && pair
                .iter()
                .any(|&i| !self.done[i] && self.leg_phase[i] == Phase::Thrust)
        {
            self.eq2_set = true;
            self.thrust[self.active] = self.eq2_thrust(input);
        }
        // The pair is one virtual leg ("Gaits": its members "strike the
        // ground in unison and leave the ground in unison"): it unloads
        // when its legs in stance are all in thrust and, on average, near
        // full length. Leg by leg, the first leg off left the other to
        // carry the pair's posture torque alone: a trot needing friction
        // 3.7 mid-support and 12.4 at its end (docs/physics.md).
        let (mut qm, mut n, mut thrusting) = (0.0, 0.0, unison);
        for &i in &pair {
            if self.done[i] || self.leg_phase[i] == Phase::Flight {
                continue;
            }
            thrusting &= self.leg_phase[i] == Phase::Thrust;
            qm += input.data.q[input.creature.legs[i].spring] - self.stance_rest[i];
            n += 1.0;
        }
        if n > 0.0 && thrusting && qm / n >= -0.005 * l {
            for &i in &pair {
                if self.leg_phase[i] == Phase::Thrust {
                    self.leg_phase[i] = Phase::Unloading;
                }
            }
        }
        if self.in_stance
            && pair.iter().all(|&i| !input.contacts[i].touching)
            && pair.iter().any(|&i| self.done[i])
        {
            // Lift-off of the virtual leg: the pairs swap (Figure 4, flight).
            let measured = input.time - self.touchdown_time;
            self.stance_s[self.active] = measured.clamp(0.04 * time_s, 0.4 * time_s);
            self.liftoff_time = input.time;
            self.liftoff_pair = Some(self.active);
            let com = com_state(input.creature, input.data).0;
            self.set_liftoff(Liftoff::at(com, &input.ground));
            // Integral speed correction from the step's mean speed.
            let vd = input.commands.speed_mps;
            self.trim.stride(
                true,
                t.speed_gain,
                vd,
                0.5 * vd.abs(),
                input.time,
                along_z(com_forward),
                glam::DVec3::Z,
                1e-3,
            );
            self.in_stance = false;
            self.done = [false; 4];
            self.leg_phase = [Phase::Flight; 4];
            self.active = 1 - self.active;
        }
    }

    /// Eq. 2 for the active pair: the thrust added to its legs' stance rests
    /// that makes the predicted apex the hop height above the last lift-off
    /// — the commanded one, else the apex of the pair's Table-2 flight —
    /// between none and the pair's `max_thrust_m`.
    fn eq2_thrust(&self, input: &ControlInput<'_>) -> f64 {
        let t = self.tuning();
        let s = self.plan.scale;
        let l = s.length();
        let pair = self.pairs[self.active];
        let (com, v) = com_state(input.creature, input.data);
        let springs = pair_springs(
            &input.data.q,
            pair.map(|i| input.creature.legs[i].spring),
            pair.map(|i| self.stance_rest[i]),
            pair.map(|i| !self.done[i] && self.leg_phase[i] != Phase::Flight),
            t.leg_stiffness * s.stiffness() * self.lift_share[self.active],
        );
        let rise = (input.commands.hop_height_m).unwrap_or(t.eq2_hop_m * l);
        let mass = input.creature.model.total_mass();
        // The pair unloads 0.005 L short of its stance rest (above): the
        // strain eq. 2 counts is what the springs give back until then.
        let released = Release {
            of_step: 1.0,
            beyond_m: 0.005 * l,
        };
        let step = thrust_for_apex_released(
            &springs,
            released,
            mass,
            com.y,
            v.y,
            apex_target_m(
                self.params.ground_ahead,
                &input.ground,
                Liftoff {
                    com_y: self.liftoff_com_y,
                    ground_y: self.liftoff_ground_y,
                },
                (com, v),
                self.stance_s[self.active] / 2.0,
                rise,
            ),
        );
        step.clamp(0.0, self.params.max_thrust_m * l)
    }

    /// Keep the lift-off eq. 2's next target is measured from.
    fn set_liftoff(&mut self, liftoff: Liftoff) {
        self.liftoff_com_y = liftoff.com_y;
        self.liftoff_ground_y = liftoff.ground_y;
    }

    /// The leg springs of eq. 1 with a programmable rest: the idle pair and
    /// the legs done with their stance short, the active pair's per state.
    pub(super) fn set_springs(
        &self,
        input: &ControlInput<'_>,
        drives: &mut [Drive],
        descending: bool,
    ) {
        let creature = input.creature;
        let s = self.plan.scale;
        let l = s.length();
        let t = self.tuning();
        let pair = self.pairs[self.active];
        let trunk_rot = input.data.world[creature.trunk].rot;
        let spring = LegSpring::new(t.leg_stiffness, t.leg_damping, t.leg_travel_m);
        let landing = t.landing_rest_m * l;
        let short = t.idle_rest_m * l;
        let thrust = self.thrust[self.active];
        // The active pair lands as one virtual leg: each leg's landing length
        // makes up for its hip's height above the pair's mean, so the feet
        // reach the ground together although the trunk pitches and rolls.
        // With the lab's `ground_ahead`, each hip's height is taken above
        // the ground plane under it, so on a slope the feet still reach
        // the ground together; the paper's floor is level.
        let trunk_pos = input.data.world[creature.trunk].pos;
        let ground_ahead = self.params.ground_ahead;
        let hip_y = |i: usize| {
            let hip = trunk_rot * creature.legs[i].hip_in_trunk;
            if ground_ahead {
                let at = hip + trunk_pos;
                hip.y - (input.ground.height_at(at.x, at.z) - input.ground.at.y)
            } else {
                hip.y
            }
        };
        let mean_hip_y = (hip_y(pair[0]) + hip_y(pair[1])) / 2.0;
        let level = |i: usize| (hip_y(i) - mean_hip_y).clamp(-0.08 * l, 0.08 * l);
        // Leg springs: eq. 1 with a programmable rest.
        for (i, leg) in creature.legs.iter().enumerate() {
            let damping = if input.contacts[i].touching {
                t.leg_damping
            } else {
                t.leg_air_damping
            };
            let rest = if !pair.contains(&i) || self.done[i] {
                short
            } else {
                match self.leg_phase[i] {
                    Phase::Thrust => self.stance_rest[i] + thrust,
                    Phase::Unloading => short,
                    Phase::Flight if !descending && !self.in_stance && t.wait_for_descent => short,
                    Phase::Flight => (landing + level(i)).min(0.0),
                    _ => self.stance_rest[i],
                }
            };
            spring.apply_with_damping(&mut drives[leg.spring], rest, damping, s);
        }
    }
}
