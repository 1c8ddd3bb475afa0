//! The kangaroo's hop cycle (Raibert & Hodgins 1991, Figure 4 and
//! "Kangaroo control"): the states' events, eq. 2's thrust as a step of the
//! ankle spring's rest at the bottom of the stance, and what each touchdown
//! and lift-off measures (stance time, stride, apex, the jump's stages).

use glam::DVec3;

use super::{JumpStage, KangarooHop};
use crate::control::additions::ground_ahead::{Liftoff, apex_target_m};
use crate::control::additions::speed_trim::along_z;
use crate::control::laws::hop_height::{Compressed, rest_for_apex};
use crate::control::laws::phase::{Phase, StanceEvents};
use crate::control::laws::scale::Scale;
use crate::dynamics::model::GRAVITY_MPS2;
use crate::world::sim::ControlInput;

impl KangarooHop {
    pub(super) fn advance_phase(&mut self, input: &ControlInput<'_>, com: DVec3, com_v: DVec3) {
        let l = input.creature.scale;
        let Some(leg) = input.creature.legs.first() else {
            return;
        };
        let Some(contact) = input.contacts.first() else {
            return;
        };
        let q = input.data.q[leg.spring];
        let qd = input.data.qd[leg.spring];
        let t = input.time;
        match self.phase {
            Phase::Flight => {
                self.apex_com_y = self.apex_com_y.max(com.y);
                let airborne = t - self.flight_start;
                if contact.touching && airborne > 0.03 * Scale::new(l).time() && com_v.y < 0.0 {
                    self.phase = Phase::Loading;
                    self.touchdown_time = t;
                    self.touch_down(contact.position.z, t, com.z, l);
                    return;
                }
            }
            stance => {
                self.phase = stance.after(StanceEvents {
                    shortened: qd < 0.0 && q < self.ankle_rest - 0.02,
                    lengthening: qd >= 0.0,
                    extended: q >= self.ankle_rest - 0.05,
                });
                // Eq. 2's thrust, once, at the bottom of the stance.
                if stance == Phase::Compression && self.phase == Phase::Thrust {
                    self.thrust(input, com, com_v);
                }
            }
        }
        if self.phase != Phase::Flight
            && !contact.touching
            && t - self.touchdown_time > 0.02 * Scale::new(l).time()
        {
            let ground_y = input.ground.height_at(com.x, com.z);
            self.lift_off(t, com, l, ground_y);
        }
    }

    pub(super) fn touch_down(&mut self, toe_z: f64, t: f64, com_z: f64, l: f64) {
        let p = self.params;
        // Integral speed correction from the stride just finished.
        if self.jump == JumpStage::None
            && let Some(mean) = self.trim.mean_since(t, along_z(com_z), DVec3::Z, 0.0)
        {
            let limit = p.speed_integral_max_mps * Scale::new(l).velocity();
            let error = self.speed_command_mps - mean;
            self.trim
                .correct(p.speed_trim, p.speed_integral_gain, error, limit);
        }
        self.trim.mark(t, along_z(com_z));
        if self.touchdown_toe != 0.0 {
            let stride = toe_z - self.touchdown_toe;
            if stride > 0.0 {
                self.stride_m = 0.5 * self.stride_m + 0.5 * stride;
            }
        }
        self.touchdown_toe = toe_z;
        // Hop-height learning from the apex just flown (eq. 2's losses).
        if p.hop_integrator
            && self.jump == JumpStage::None
            && self.target_apex_y.is_finite()
            && self.apex_com_y.is_finite()
        {
            let err = self.target_apex_y - self.apex_com_y;
            self.apex_correction_m =
                (self.apex_correction_m + p.hop_gain * err).clamp(-0.1 * l, 0.2 * l);
        }
        self.jump = match self.jump {
            JumpStage::Airborne => JumpStage::Landing,
            JumpStage::Landing => JumpStage::None,
            s => s,
        };
        self.next_jump(toe_z, l);
        let p = self.params;
        if self.jump_pending
            && let Some(at) = p.jump_at_m
        {
            // Jump now if the next ordinary stride would land past the
            // obstacle's near face minus a margin (positions at scale 1).
            let next = toe_z + self.stride_m;
            if next > (at - 0.25) * l && toe_z < at * l {
                self.jump = JumpStage::Takeoff;
                self.jump_pending = false;
            }
        }
    }

    /// Lift-off at `t` (s) of the centre of mass at `com` over ground
    /// `ground_y` (m) high, at scale `l`.
    pub(super) fn lift_off(&mut self, t: f64, com: DVec3, l: f64, ground_y: f64) {
        let measured = t - self.touchdown_time;
        if self.jump == JumpStage::None {
            self.stance_s = measured.clamp(0.05 * Scale::new(l).time(), 0.3 * Scale::new(l).time());
        }
        self.liftoff_com_y = com.y;
        self.liftoff_ground_y = ground_y;
        self.apex_com_y = f64::NEG_INFINITY;
        self.flight_start = t;
        self.phase = Phase::Flight;
        self.ankle_rest = self.params.ankle_rest_rad;
        if self.jump == JumpStage::Takeoff {
            self.jump = JumpStage::Airborne;
        }
    }

    /// Eq. 2 at the bottom of the stance: step the ankle rest so the
    /// predicted apex meets the target.
    pub(super) fn thrust(&mut self, input: &ControlInput<'_>, com: DVec3, com_v: DVec3) {
        let l = input.creature.scale;
        let Some(leg) = input.creature.legs.first() else {
            return;
        };
        let p = self.params;
        let m = input.creature.model.total_mass();
        let g = GRAVITY_MPS2;
        let (k, _) = self.ankle_gains(l);
        let q = input.data.q[leg.spring];
        let base = if self.liftoff_com_y.is_finite() {
            self.liftoff_com_y
        } else {
            com.y
        };
        let rise = input.commands.hop_height_m.unwrap_or(p.hop_rise_m * l);
        let liftoff = Liftoff {
            com_y: base,
            ground_y: self.liftoff_ground_y,
        };
        let half_stance = self.stance_s / 2.0;
        let on = p.ground_ahead && self.liftoff_com_y.is_finite();
        let mut target = apex_target_m(on, &input.ground, liftoff, (com, com_v), half_stance, rise);
        if self.jump == JumpStage::Takeoff
            && let Some(at) = p.jump_at_m
        {
            // Long enough to carry the body past the obstacle, and high
            // enough for the tucked toe to clear it.
            let v = com_v.z.max(0.5 * Scale::new(l).velocity());
            let far = (at + p.obstacle_depth_m + 0.3) * l;
            let flight = ((far - com.z) / v - 0.5 * self.stance_s).max(0.1 * Scale::new(l).time());
            let rise_time = 0.5 * flight;
            let by_time = 0.5 * g * rise_time * rise_time;
            let by_height = (p.obstacle_height_m + p.jump_clearance_m) * l + 0.1 * l;
            target = base + by_time.max(by_height);
        }
        self.target_apex_y = target;
        let learned = if p.hop_integrator {
            self.apex_correction_m
        } else {
            0.0
        };
        let ankle = Compressed {
            stiffness: k,
            compression: self.ankle_rest - q,
        };
        let rest = rest_for_apex(q, ankle, m, com.y, com_v.y, target + learned);
        let r0 = p.ankle_rest_rad;
        self.ankle_rest = rest.clamp(r0 - 0.5 * p.max_thrust_rad, r0 + p.max_thrust_rad);
    }
}

impl KangarooHop {
    /// Move the commanded speed toward the desired `target` (m/s, at the
    /// creature's scale), rate-limited when the lab's ramp is on.
    pub(super) fn ramp_speed(&mut self, dt: f64, target: f64) {
        let step = if self.params.speed_ramp {
            self.params.speed_ramp_mps2.max(0.0) * dt
        } else {
            f64::INFINITY
        };
        let cmd = if self.speed_command_mps.is_finite() {
            self.speed_command_mps
        } else {
            target
        };
        self.speed_command_mps = cmd + (target - cmd).clamp(-step, step);
    }
}
