//! Kangaroo hopping and jumping (Raibert & Hodgins 1991, "Kangaroo control",
//! with "Hopping Control", "Speed Control", "Posture Control", "Modeling" and
//! "Dynamic Scaling").
//!
//! * Hopping: the ankle is the leg's energy store, a torsional spring-damper
//!   with adjustable rest angle (eq. 1). At the bottom of each stance the rest
//!   angle steps so that the predicted apex of eq. 2,
//!   `h = (PE_strain + PE_elevation + KE)/Mg`, meets the desired one; a slow
//!   correction learns the losses from each measured apex.
//! * Speed: in flight the toe is placed at eq. 3's
//!   `x_fh,d = ẋ·T_s/2 + k_ẋ·(ẋ − ẋ_d)` from the projection of the centre of
//!   mass, through a two-link inverse kinematics of hip and knee with the
//!   ankle held at its rest angle by its spring. The ẋ_d used is a commanded
//!   speed that ramps toward the desired one at a bounded rate (the fast gaits
//!   are reached by accelerating through the slower ones; a start at 5 m/s
//!   tumbles), plus an integral correction from each stride's mean speed.
//!   While the body still rises the toe is drawn in, so the leg swinging
//!   forward does not scuff the ground after a low hop (the scuff's pitching
//!   impulse was what tipped the fast gaits over).
//! * Posture: in stance the hip is servoed to keep the knee on the thrust line
//!   from the toe through the system centre of mass, so the knee carries
//!   little load and applies eq. 4 on the trunk pitch.
//! * Tail and head: the tail-base spring's rest angle steps down in stance and
//!   up in flight; its stiffness makes the tail's natural frequency about the
//!   hopping frequency, so it counter-oscillates with the leg. The distal tail
//!   joints are spring-dampers at a fixed rest; the neck is servoed level.
//! * Jump ("Results"): extra states — a stiffer, harder thrust on the stance
//!   before the obstacle, a tucked leg over it, and more dissipation in the
//!   landing stance.
//!
//! Every gain is given at dynamic scale 1 and scaled by the creature's L
//! (Table 1): lengths ×L, times ×√L, speeds ×√L, torsional stiffness ×L⁴,
//! torsional damping ×L^4.5.

use glam::{DVec2, DVec3};

use crate::control::additions::speed_trim::SpeedTrim;
use crate::control::gaits::kangaroo_hop::leg::{
    leg_geometry, leg_ik, planar, thigh_on_thrust_line,
};
use crate::control::laws::attitude::com_velocity;
use crate::control::laws::phase::Phase;
use crate::control::laws::posture::axis_torque;
use crate::control::laws::scale::Scale;
use crate::world::sim::{ControlInput, Controller, Drive};

mod ankle;
pub mod build;
mod cycle_start;
pub mod jumps;
pub mod leg;
pub mod origins;
pub mod params;
pub mod start;
mod stride;
mod tail;

pub use crate::control::gaits::kangaroo_hop::params::KangarooHopParams;
pub use crate::control::laws::ground::kangaroo_ground;

/// The extra states of a jump over an obstacle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum JumpStage {
    /// Ordinary hopping.
    #[default]
    None,
    /// The stance that throws the jump: stiffer ankle, larger thrust.
    Takeoff,
    /// Flying over the obstacle with the leg tucked.
    Airborne,
    /// The stance after the jump: extra ankle damping.
    Landing,
}

/// The kangaroo hopping controller: the state machine of Figure 4 plus the
/// jump states.
#[derive(Clone, Debug)]
pub struct KangarooHop {
    /// Parameters (editable while running).
    pub params: KangarooHopParams,
    /// Current state of Figure 4.
    pub phase: Phase,
    /// Current jump state.
    pub jump: JumpStage,
    /// Measured duration of the last stance (s), T_s of eq. 3.
    pub stance_s: f64,
    /// Current ankle rest angle (rad).
    pub ankle_rest: f64,
    /// Learned correction of the apex target (m), from measured apexes.
    pub apex_correction_m: f64,
    /// Commanded forward speed (m/s, scaled), ramping toward the desired one.
    pub speed_command_mps: f64,
    /// The lab's speed trim added to the commanded speed in eq. 3 (zero
    /// unless `speed_trim`), from one touchdown to the next.
    pub trim: SpeedTrim,
    /// Whether the jump in the parameters' `jump_at_m` is still to come.
    jump_pending: bool,
    /// The boxes to jump after it, nearest first (jumps.rs).
    queued: Vec<jumps::QueuedJump>,
    started: bool,
    touchdown_time: f64,
    touchdown_toe: f64,
    liftoff_com_y: f64,
    /// The ground plane's height under the centre of mass then (m; used
    /// only with the lab's `ground_ahead`).
    liftoff_ground_y: f64,
    apex_com_y: f64,
    target_apex_y: f64,
    flight_start: f64,
    stride_m: f64,
    /// The knee whose posture servo acts in this stance, if any.
    knee_servo: Option<usize>,
}

impl KangarooHop {
    /// A controller starting in flight.
    #[must_use]
    pub fn new(params: KangarooHopParams) -> Self {
        Self {
            params,
            phase: Phase::Flight,
            jump: JumpStage::None,
            stance_s: params.stance_guess_s,
            ankle_rest: params.ankle_rest_rad,
            apex_correction_m: 0.0,
            speed_command_mps: f64::NAN,
            trim: SpeedTrim::default(),
            jump_pending: params.jump_at_m.is_some(),
            queued: Vec::new(),
            started: false,
            touchdown_time: 0.0,
            touchdown_toe: 0.0,
            liftoff_com_y: f64::NAN,
            liftoff_ground_y: 0.0,
            apex_com_y: f64::NEG_INFINITY,
            target_apex_y: f64::NAN,
            flight_start: 0.0,
            stride_m: 0.0,
            knee_servo: None,
        }
    }

    /// The current state's name: the jump states while jumping, else Figure 4's.
    #[must_use]
    pub fn phase_name(&self) -> &'static str {
        match self.jump {
            JumpStage::None => self.phase.name(),
            JumpStage::Takeoff => "jump take-off",
            JumpStage::Airborne => "jump flight",
            JumpStage::Landing => "jump landing",
        }
    }

    /// At the first control call: the stance-time and stride guesses for
    /// the desired speed `desired_mps` and the speed command from the body's
    /// own `speed_mps` (both m/s at the creature's scale).
    fn start(&mut self, l: f64, desired_mps: f64, speed_mps: f64) {
        if !self.started {
            self.started = true;
            self.stance_s = self.params.stance_guess_s * Scale::new(l).time();
            self.stride_m = desired_mps * 0.35 * Scale::new(l).time();
            self.speed_command_mps = speed_mps;
        }
    }
}

impl Controller for KangarooHop {
    crate::tunable_gains!(KangarooHopParams;
        ankle_stiffness => "N·m/rad", ankle_damping => "N·m·s/rad", posture_kp => "N·m/rad", posture_kv => "N·m·s/rad",
        placement_gain_s => "s", tail_stiffness => "N·m/rad", tail_damping => "N·m·s/rad");

    fn phase_name(&self) -> &'static str {
        KangarooHop::phase_name(self)
    }

    fn hop_height_m(&self) -> Option<f64> {
        Some(self.params.hop_rise_m)
    }

    /// The knee in stance: posture (eq. 4) in compression and thrust, the
    /// reaction of the torque the trunk needs; limp in the other states.
    fn servo(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let Some(knee) = self.knee_servo else {
            return;
        };
        let p = &self.params;
        let s = Scale::new(input.creature.scale);
        let posture = matches!(self.phase, Phase::Compression | Phase::Thrust) || p.posture_always;
        let torque = if posture {
            let (pitch, pitch_rate) = (input.data.q[2], input.data.qd[2]);
            let (kp, kv) = s.torsional_gains(p.posture_kp, p.posture_kv);
            -axis_torque(pitch - p.pitch_rad, pitch_rate, kp, kv)
        } else {
            0.0
        };
        let max = p.max_torque * s.torque();
        drives[knee].torque(torque.clamp(-max, max));
    }

    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let creature = input.creature;
        let data = input.data;
        let l = creature.scale;
        let (Some(leg), Some(g)) = (creature.legs.first(), leg_geometry(creature)) else {
            return;
        };
        let Some(&hip) = leg.hip.first() else {
            return;
        };
        let Some(knee) = leg.knee else {
            return;
        };
        let ankle = leg.spring;
        let com = crate::dynamics::energy::center_of_mass(&creature.model, data);
        let com_v = com_velocity(creature, data);
        self.start(l, input.commands.speed_mps, com_v.z);
        self.ramp_speed(input.dt, input.commands.speed_mps);
        self.advance_phase(input, com, com_v);
        let p = self.params;
        let s = Scale::new(l);
        let (t4, t45) = (s.torsional_stiffness(), s.torsional_damping());
        let max = p.max_torque * s.torque();
        let pitch = data.q[2];
        let pitch_rate = data.qd[2];

        self.drive_ankle(&mut drives[ankle], l);

        let hip_world = planar(data.point_world(creature.trunk, leg.hip_in_trunk));
        let stance = self.phase != Phase::Flight;
        if stance {
            // Hip: the knee onto the thrust line toe → centre of mass.
            let toe = planar(input.contacts.first().map_or(DVec3::ZERO, |c| c.position));
            let a1 = thigh_on_thrust_line(&g, hip_world, toe, planar(com), pitch + data.q[hip]);
            drives[hip].servo(p.stance_hip_kp * t4, p.stance_hip_kv * t45, a1 - pitch);
            drives[hip].spring.max_force = max;
            // Knee: posture (eq. 4), every integration step ([`Controller::servo`]).
            self.knee_servo = Some(knee);
        } else {
            self.knee_servo = None;
            // Flight: place the toe for landing by eq. 3.
            let speed = com_v.z;
            let desired = self.speed_command_mps + self.trim.bias_mps;
            let x_fh =
                speed * self.stance_s / 2.0 + p.placement_gain_s * s.time() * (speed - desired);
            let rising = (com_v.y / s.velocity()).clamp(0.0, 1.0);
            let r0 = (p.landing_leg_m - p.flight_retract_m * rising) * l;
            let mut toe = if self.jump == JumpStage::Airborne
                && p.jump_at_m
                    .is_some_and(|at| com.z < (at + p.obstacle_depth_m) * l)
            {
                // Tucked over the obstacle.
                DVec2::new(0.05 * l, -0.22 * l)
            } else {
                let dz = (com.z + x_fh - hip_world.x).clamp(-0.9 * r0, 0.9 * r0);
                DVec2::new(dz, -(r0 * r0 - dz * dz).sqrt())
            };
            if self.jump == JumpStage::Takeoff {
                toe.y = -r0;
            }
            let (qh, qk) = leg_ik(&g, toe, self.ankle_rest, pitch);
            drives[hip].servo(p.hip_kp * t4, p.hip_kv * t45, qh);
            drives[hip].spring.max_force = max;
            drives[knee].servo(p.knee_kp * t4, p.knee_kv * t45, qk);
            drives[knee].spring.max_force = max;
        }

        self.tail_and_neck(creature, pitch, pitch_rate, stance, drives);
    }
}
