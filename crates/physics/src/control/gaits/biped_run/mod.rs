//! Biped running (Raibert & Hodgins 1991, "Gaits" and Figure 4): one-legged
//! hopping control on the active leg while the idle leg is kept short and out
//! of the way. Hopping by the leg spring's rest length and a thrust in stance
//! (eq. 1–2), speed by foot placement (eq. 3), trunk attitude by the active
//! hip in stance (eq. 4).

pub mod build;
pub mod origins;
pub mod params;

use glam::DVec3;

use crate::control::additions::ground_ahead::{Liftoff, apex_target_m};
use crate::control::additions::speed_trim::SpeedTrim;
use crate::control::laws::attitude::{attitude_error, com_state, heading_forward, trunk_rate};
use crate::control::laws::body_plan::BodyPlan;
use crate::control::laws::hip_servo::{set_hip, zero_hip};
use crate::control::laws::leg_spring::{LegSpring, toward};
use crate::control::laws::phase::{Phase, StanceEvents};
use crate::control::laws::placement::{foot_displacement, hip_angles};
use crate::control::laws::posture::{through_hip, trunk_torque};
use crate::control::laws::scale::Scale;
use crate::creatures::PhysicalCreature;
use crate::world::sim::{ControlInput, Controller, Drive};

pub use crate::control::gaits::biped_run::params::BipedRunParams;

/// The running state machine of Figure 4 for a two-legged creature.
#[derive(Clone, Debug)]
pub struct BipedRun {
    /// Parameters (editable while running).
    pub params: BipedRunParams,
    /// Current state.
    pub phase: Phase,
    /// Which leg supports (0 or 1).
    pub active: usize,
    /// Measured duration of the last stance (s), T_s of eq. 3.
    pub stance_s: f64,
    touchdown_time: f64,
    liftoff_height: f64,
    /// The centre of mass's height at the last lift-off, or at touchdown
    /// before the first (m): eq. 2's apex target is measured from it.
    liftoff_com_y: f64,
    /// The ground plane's height under the centre of mass then (m; used
    /// only with the lab's `ground_ahead`).
    liftoff_ground_y: f64,
    apex_height: f64,
    thrust: f64,
    descending: bool,
    /// The lab's speed trim (zero unless `speed_trim`), measured from one
    /// lift-off to the next.
    trim: SpeedTrim,
    /// Each leg's rest length as it moves toward its target (m).
    rest: [f64; 2],
    /// The creature's scale and leg lengths.
    plan: BodyPlan<2>,
}

impl BipedRun {
    /// A controller for `creature` (its scale and leg lengths), starting in
    /// flight with leg 0 active.
    #[must_use]
    pub fn new(params: BipedRunParams, creature: &PhysicalCreature) -> Self {
        let scale = creature.scale;
        Self {
            params,
            phase: Phase::Flight,
            active: 0,
            stance_s: 0.18 * Scale::new(scale).time(),
            touchdown_time: 0.0,
            liftoff_height: 0.0,
            liftoff_com_y: f64::NAN,
            liftoff_ground_y: 0.0,
            apex_height: f64::NEG_INFINITY,
            thrust: params.hopper.thrust_m * scale,
            descending: true,
            trim: SpeedTrim::default(),
            rest: [
                params.hopper.landing_rest_m * scale,
                params.hopper.idle_rest_m * scale,
            ],
            plan: BodyPlan::of(creature),
        }
    }

    fn advance_phase(&mut self, input: &ControlInput<'_>) {
        let leg = &input.creature.legs[self.active];
        let contact = input.contacts[self.active];
        let q = input.data.q[leg.spring];
        let qd = input.data.qd[leg.spring];
        let trunk_y = input.data.world[input.creature.trunk].pos.y;
        let p = self.params;
        let (l, t) = (self.plan.scale.length(), self.plan.scale.time());
        match self.phase {
            Phase::Flight => {
                self.apex_height = self.apex_height.max(trunk_y);
                self.descending = self.descending
                    || input.data.world[input.creature.trunk].pos.y < self.apex_height - 0.002 * l;
                if contact.touching && self.descending {
                    self.phase = Phase::Loading;
                    self.touchdown_time = input.time;
                    if !self.liftoff_com_y.is_finite() {
                        let com = com_state(input.creature, input.data).0;
                        self.set_liftoff(Liftoff::at(com, &input.ground));
                    }
                }
            }
            stance => {
                self.phase = stance.after(StanceEvents {
                    shortened: q < (p.hopper.landing_rest_m - 0.005) * l,
                    lengthening: qd >= 0.0,
                    extended: q >= p.hopper.landing_rest_m * l + self.thrust - 0.01 * l
                        || q >= -0.005 * l,
                });
                // Eq. 2 at the bottom of the stance: the thrust whose
                // predicted apex is the target (Figure 4, "extend leg").
                if stance == Phase::Compression && self.phase == Phase::Thrust && !p.hop_integrator
                {
                    self.thrust = self.eq2_thrust(input, q);
                }
            }
        }
        // Lift-off ends a stance only once the leg has thrust; a foot that
        // bounces off the ground at impact is still landing.
        if matches!(self.phase, Phase::Thrust | Phase::Unloading) && !contact.touching {
            // Lift-off: the legs swap, the hop's apex adjusts the thrust (eq. 2).
            self.stance_s = (input.time - self.touchdown_time).clamp(0.05 * t, 0.5 * t);
            if p.hop_integrator && self.apex_height.is_finite() {
                let target = input.commands.hop_height_m.unwrap_or(p.hop_height_m * l);
                let error = target - (self.apex_height - self.liftoff_height);
                self.thrust = (self.thrust + p.hopper.hop_gain * error).clamp(0.0, 0.12 * l);
            }
            self.liftoff_height = trunk_y;
            let com = com_state(input.creature, input.data).0;
            self.set_liftoff(Liftoff::at(com, &input.ground));
            // Speed over the last step against the desired speed.
            let (on, gain) = (p.speed_trim, p.hopper.speed_integral_gain);
            (self.trim).stride_at_input(on, gain, self.plan.scale.velocity(), input);
            self.apex_height = f64::NEG_INFINITY;
            self.active = 1 - self.active;
            self.phase = Phase::Flight;
            self.descending = false;
        }
    }

    /// Eq. 2 for the active leg at spring length `q` (m): the extension of
    /// its rest beyond the landing rest that makes the predicted apex the
    /// target, between none and the leg's full length (a rest past the stop
    /// would push the leg's light bodies against it, not the body up).
    fn eq2_thrust(&self, input: &ControlInput<'_>, q: f64) -> f64 {
        let p = &self.params;
        let s = self.plan.scale;
        let l = s.length();
        let rise = input.commands.hop_height_m.unwrap_or(p.hop_height_m * l);
        let rest = self.rest[self.active];
        let landing = p.hopper.landing_rest_m * l;
        let liftoff = Liftoff {
            com_y: self.liftoff_com_y,
            ground_y: self.liftoff_ground_y,
        };
        let now = com_state(input.creature, input.data);
        let half_stance = self.stance_s / 2.0;
        let target = apex_target_m(
            p.ground_ahead,
            &input.ground,
            liftoff,
            now,
            half_stance,
            rise,
        );
        p.hopper.eq2_thrust(input, s, (rest, q), landing, target)
    }

    /// Keep the lift-off eq. 2's next target is measured from.
    fn set_liftoff(&mut self, liftoff: Liftoff) {
        self.liftoff_com_y = liftoff.com_y;
        self.liftoff_ground_y = liftoff.ground_y;
    }
}

impl Controller for BipedRun {
    crate::family_gains!(biped BipedRunParams);

    fn phase_name(&self) -> &'static str {
        self.phase.name()
    }

    /// Eq. 4 through the active hip while its foot is loaded ("vertical
    /// loading on the feet keeps the leg from slipping when the torque is
    /// applied"); a foot that left the ground between control calls goes
    /// limp until the state machine sees the lift-off.
    fn servo(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let touching = input.contacts[self.active].touching;
        let landed = self.phase == Phase::Flight && self.descending && touching;
        if self.posture_on() && touching {
            self.posture(input, drives);
        } else if landed || self.posture_on() {
            // Landed, or lifted off, since the last control call: Figure
            // 4's zero hip torque until the state machine sees it.
            let p = &self.params;
            let (ykp, ykv) = self
                .plan
                .scale
                .torsional_gains(p.hopper.leg_yaw_kp, p.hopper.leg_yaw_kv);
            zero_hip(drives, &input.creature.legs[self.active].hip, ykp, ykv);
        }
    }

    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.advance_phase(input);
        let p = self.params;
        let s = self.plan.scale;
        let l = s.l;
        let creature = input.creature;
        let data = input.data;
        let trunk_rot = data.world[creature.trunk].rot;
        let (com, velocity) = com_state(creature, data);
        let c = input.commands;
        let desired = heading_forward(c.heading_rad) * (c.speed_mps + self.trim.bias_mps);
        let spring = LegSpring::new(
            p.hopper.leg_stiffness,
            p.hopper.leg_damping,
            p.hopper.leg_travel_m,
        );
        // Leg lengths: the spring of eq. 1 with a programmable rest.
        let step = p.hopper.leg_rate_mps * s.velocity() * input.dt;
        for (i, leg) in creature.legs.iter().enumerate().take(2) {
            let target = if i != self.active {
                p.hopper.idle_rest_m * l
            } else {
                match self.phase {
                    Phase::Thrust => p.hopper.landing_rest_m * l + self.thrust,
                    Phase::Unloading => p.hopper.idle_rest_m * l,
                    // Lengthen for landing once the body falls, so the new
                    // active leg does not scuff the ground at lift-off.
                    Phase::Flight if !self.descending => p.hopper.idle_rest_m * l,
                    _ => p.hopper.landing_rest_m * l,
                }
            };
            self.rest[i] = toward(self.rest[i], target, step);
            spring.apply(&mut drives[leg.spring], self.rest[i], s);
        }
        // The active leg: placed for landing in flight, posture servo in stance.
        let active = &creature.legs[self.active];
        let idle = &creature.legs[1 - self.active];
        let reach = self.plan.leg_m[self.active] + p.hopper.landing_rest_m * l;
        let (kp, kv) = s.torsional_gains(p.hopper.swing_kp, p.hopper.swing_kv);
        let (ykp, ykv) = s.torsional_gains(p.hopper.leg_yaw_kp, p.hopper.leg_yaw_kv);
        let max = p.hopper.max_hip_torque * s.torque();
        match self.phase {
            Phase::Flight => {
                let hip_world = data.world[creature.trunk].rot * active.hip_in_trunk
                    + data.world[creature.trunk].pos;
                let foot = DVec3::new(com.x, 0.0, com.z)
                    + foot_displacement(
                        velocity,
                        desired,
                        self.stance_s,
                        p.hopper.placement_gain_s * s.time(),
                    );
                let angles = hip_angles(trunk_rot, hip_world, foot, reach);
                set_hip(drives, &active.hip[..2], angles, kp, kv, max);
                drives[active.hip[2]].servo(ykp, ykv, 0.0);
            }
            // Figure 4: "zero active hip torque" on landing and unloading.
            Phase::Loading => zero_hip(drives, &active.hip, ykp, ykv),
            Phase::Unloading if !p.unloading_posture => zero_hip(drives, &active.hip, ykp, ykv),
            // Eq. 4: [`Controller::servo`], every integration step.
            Phase::Compression | Phase::Thrust | Phase::Unloading => {}
        }
        // The idle leg mirrors the active one, so the two legs' swings react
        // on the trunk with opposite torques and cancel.
        let mirror = [-data.q[active.hip[0]], -data.q[active.hip[1]]];
        set_hip(drives, &idle.hip[..2], mirror, kp, kv, max);
        drives[idle.hip[2]].servo(ykp, ykv, 0.0);
    }
}

impl BipedRun {
    /// Whether eq. 4's posture servo acts now: in Compression and Thrust,
    /// and in Unloading with the lab's `unloading_posture`.
    fn posture_on(&self) -> bool {
        match self.phase {
            Phase::Compression | Phase::Thrust => true,
            Phase::Unloading => self.params.unloading_posture,
            Phase::Flight | Phase::Loading => false,
        }
    }

    /// Eq. 4 on pitch and roll: the torque the trunk needs, applied by the
    /// active hip's joints as its reaction; yaw by the foot's grip.
    fn posture(&self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let p = &self.params;
        let s = self.plan.scale;
        let creature = input.creature;
        let data = input.data;
        let active = &creature.legs[self.active];
        let trunk_rot = data.world[creature.trunk].rot;
        let max = p.hopper.max_hip_torque * s.torque();
        let err = attitude_error(creature, data, input.commands.heading_rad, 0.0);
        let rate = trunk_rate(creature, data);
        let (pkp, pkv) = s.torsional_gains(p.hopper.posture_kp, p.hopper.posture_kv);
        let torque = trunk_torque(err, rate, pkp, pkv);
        let roll_q = data.q[active.hip[0]];
        through_hip(drives, &active.hip, roll_q, trunk_rot, torque, max);
        // The leg turns on a tiny inertia: only a torque the loaded foot's
        // torsional grip can hold.
        let (ypkp, ypkv) = s.torsional_gains(p.hopper.yaw_kp, p.hopper.yaw_kv);
        let yaw = -err.y * ypkp - rate.y * ypkv;
        let grip = p.hopper.max_yaw_torque * s.torque();
        drives[active.hip[2]].torque((-yaw).clamp(-grip, grip));
    }
}
