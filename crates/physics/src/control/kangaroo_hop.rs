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

use gaitlab_core::portable::Portable;
use glam::{DVec2, DVec3};

use super::attitude::com_velocity;
use super::phase::Phase;
use super::posture::axis_torque;
use super::scale::Scale;
use super::speed_trim::{SpeedTrim, along_z};
use crate::creatures::PhysicalCreature;
use crate::dynamics::data::Data;
use crate::dynamics::model::GRAVITY_MPS2;
use crate::world::actuator::Stops;
use crate::world::ground::{GroundParams, PawPad};
use crate::world::sim::{ControlInput, Controller, Drive, Sim};

pub use super::kangaroo_hop_params::KangarooHopParams;

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

/// The leg's link lengths (m), read from the model.
#[derive(Clone, Copy, Debug, PartialEq)]
struct LegGeometry {
    thigh: f64,
    shin: f64,
    foot: f64,
}

fn leg_geometry(creature: &PhysicalCreature) -> Option<LegGeometry> {
    let leg = creature.legs.first()?;
    let bodies = creature.model.bodies();
    let shin_body = bodies.get(leg.foot_body)?.parent?;
    Some(LegGeometry {
        thigh: bodies.get(shin_body)?.placement.pos.length(),
        shin: bodies.get(leg.foot_body)?.placement.pos.length(),
        foot: leg.foot_point.length(),
    })
}

/// Unit direction (forward, up) of a link at absolute angle `a` (rad about +x,
/// 0 hanging down, positive swinging back).
fn dir(a: f64) -> DVec2 {
    DVec2::new(-a.psin(), -a.pcos())
}

/// Absolute angle of the direction `v` (forward, up).
fn angle_of(v: DVec2) -> f64 {
    (-v.x).patan2(-v.y)
}

/// A world point in the sagittal plane (forward, up).
fn planar(p: DVec3) -> DVec2 {
    DVec2::new(p.z, p.y)
}

/// Hip and knee angles (relative, rad) putting the toe at `toe` from the hip
/// (forward, up) with the ankle at `ankle` and the trunk at pitch `pitch`;
/// the knee bends forward.
fn leg_ik(g: &LegGeometry, toe: DVec2, ankle: f64, pitch: f64) -> (f64, f64) {
    // Knee-to-toe as one link in the shin's frame.
    let v = g.shin * dir(0.0) + g.foot * dir(ankle);
    let s = v.length();
    let delta = angle_of(v);
    let l1 = g.thigh;
    let d = toe
        .length()
        .clamp((l1 - s).abs() + 1e-6 * (l1 + s), 0.999 * (l1 + s));
    let gamma = angle_of(toe);
    let alpha = ((l1 * l1 + d * d - s * s) / (2.0 * l1 * d))
        .clamp(-1.0, 1.0)
        .pacos();
    let a1 = gamma - alpha;
    let knee = l1 * dir(a1);
    let toe_at = d * dir(gamma);
    let b = angle_of(toe_at - knee);
    let a2 = b - delta;
    (a1 - pitch, a2 - a1)
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
    /// Whether a jump is still to come.
    jump_pending: bool,
    started: bool,
    touchdown_time: f64,
    touchdown_toe: f64,
    liftoff_com_y: f64,
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
            started: false,
            touchdown_time: 0.0,
            touchdown_toe: 0.0,
            liftoff_com_y: f64::NAN,
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

    /// Set the desired forward speed (m/s at scale 1); the commanded speed
    /// ramps to it.
    pub fn set_speed(&mut self, mps: f64) {
        if mps.is_finite() {
            self.params.speed_mps = mps;
        }
    }

    /// Set the desired rise of the centre of mass from lift-off to apex (m at scale 1).
    pub fn set_hop_height(&mut self, m: f64) {
        if m.is_finite() {
            self.params.hop_rise_m = m.max(0.0);
        }
    }

    /// Ask for a jump over an obstacle whose near face is at `at_m` (m).
    pub fn jump_at(&mut self, at_m: f64) {
        self.params.jump_at_m = Some(at_m);
        self.jump_pending = true;
    }

    fn start(&mut self, l: f64, speed: f64) {
        if !self.started {
            self.started = true;
            self.stance_s = self.params.stance_guess_s * l.sqrt();
            self.stride_m = self.params.speed_mps * 0.35 * l;
            self.speed_command_mps = speed;
        }
    }

    /// Move the commanded speed toward the desired one, rate-limited.
    fn ramp_speed(&mut self, dt: f64, l: f64) {
        let target = self.params.speed_mps * l.sqrt();
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

    fn advance_phase(&mut self, input: &ControlInput<'_>, com: DVec3, com_v: DVec3) {
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
                if contact.touching && airborne > 0.03 * l.sqrt() && com_v.y < 0.0 {
                    self.phase = Phase::Loading;
                    self.touchdown_time = t;
                    self.touch_down(contact.position.z, t, com.z, l);
                    return;
                }
            }
            Phase::Loading if qd < 0.0 && q < self.ankle_rest - 0.02 => {
                self.phase = Phase::Compression;
            }
            Phase::Compression if qd >= 0.0 => {
                self.phase = Phase::Thrust;
                self.thrust(input, com, com_v);
            }
            Phase::Thrust if q >= self.ankle_rest - 0.05 => self.phase = Phase::Unloading,
            _ => {}
        }
        if self.phase != Phase::Flight
            && !contact.touching
            && t - self.touchdown_time > 0.02 * l.sqrt()
        {
            self.lift_off(t, com, l);
        }
    }

    fn touch_down(&mut self, toe_z: f64, t: f64, com_z: f64, l: f64) {
        let p = self.params;
        // Integral speed correction from the stride just finished.
        if self.jump == JumpStage::None
            && let Some(mean) = self.trim.mean_since(t, along_z(com_z), DVec3::Z, 0.0)
        {
            let limit = p.speed_integral_max_mps * l.sqrt();
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
        if self.jump == JumpStage::None
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
        if self.jump_pending
            && let Some(at) = p.jump_at_m
        {
            // Jump now if the next ordinary stride would land short of the
            // obstacle's far side but past its near face minus a margin.
            let next = toe_z + self.stride_m;
            if next > (at - 0.25 * l) * 1.0 && toe_z < at {
                self.jump = JumpStage::Takeoff;
                self.jump_pending = false;
            }
        }
    }

    fn lift_off(&mut self, t: f64, com: DVec3, l: f64) {
        let measured = t - self.touchdown_time;
        if self.jump == JumpStage::None {
            self.stance_s = measured.clamp(0.05 * l.sqrt(), 0.3 * l.sqrt());
        }
        self.liftoff_com_y = com.y;
        self.apex_com_y = f64::NEG_INFINITY;
        self.flight_start = t;
        self.phase = Phase::Flight;
        self.ankle_rest = self.params.ankle_rest_rad;
        if self.jump == JumpStage::Takeoff {
            self.jump = JumpStage::Airborne;
        }
    }

    fn ankle_gains(&self, l: f64) -> (f64, f64) {
        let p = &self.params;
        let (mut k, mut b) = Scale::new(l).torsional_gains(p.ankle_stiffness, p.ankle_damping);
        match self.jump {
            JumpStage::Takeoff => k *= p.jump_stiffness_factor,
            JumpStage::Landing if self.phase != Phase::Flight => b *= p.landing_damping_factor,
            _ => {}
        }
        (k, b)
    }

    /// Eq. 2 at the bottom of the stance: step the ankle rest so the
    /// predicted apex meets the target.
    fn thrust(&mut self, input: &ControlInput<'_>, com: DVec3, com_v: DVec3) {
        let l = input.creature.scale;
        let Some(leg) = input.creature.legs.first() else {
            return;
        };
        let p = self.params;
        let m = input.creature.model.total_mass();
        let g = GRAVITY_MPS2;
        let (k, _) = self.ankle_gains(l);
        let q = input.data.q[leg.spring];
        let strain = 0.5 * k * (q - self.ankle_rest).powi(2);
        let predicted = (strain + m * g * com.y + 0.5 * m * com_v.y * com_v.y) / (m * g);
        let base = if self.liftoff_com_y.is_finite() {
            self.liftoff_com_y
        } else {
            com.y
        };
        let mut target = base + p.hop_rise_m * l;
        if self.jump == JumpStage::Takeoff
            && let Some(at) = p.jump_at_m
        {
            // Long enough to carry the body past the obstacle, and high
            // enough for the tucked toe to clear it.
            let v = com_v.z.max(0.5 * l.sqrt());
            let far = at + p.obstacle_depth_m * l + 0.3 * l;
            let flight = ((far - com.z) / v - 0.5 * self.stance_s).max(0.1 * l.sqrt());
            let rise_time = 0.5 * flight;
            let by_time = 0.5 * g * rise_time * rise_time;
            let by_height = (p.obstacle_height_m + p.jump_clearance_m) * l + 0.1 * l;
            target = base + by_time.max(by_height);
        }
        self.target_apex_y = target;
        let wanted = (target + self.apex_correction_m - predicted) * m * g;
        let stored = (q - self.ankle_rest).powi(2) + 2.0 * wanted / k;
        let rest = q + stored.max(0.0).sqrt();
        let r0 = p.ankle_rest_rad;
        self.ankle_rest = rest.clamp(r0 - 0.5 * p.max_thrust_rad, r0 + p.max_thrust_rad);
    }
}

impl Controller for KangarooHop {
    crate::tunable_gains!(KangarooHopParams;
        ankle_stiffness => "N·m/rad", ankle_damping => "N·m·s/rad", posture_kp => "N·m/rad", posture_kv => "N·m·s/rad",
        placement_gain_s => "s", tail_stiffness => "N·m/rad", tail_damping => "N·m·s/rad");

    fn phase_name(&self) -> &'static str {
        KangarooHop::phase_name(self)
    }

    fn set_speed(&mut self, speed_mps: f64) {
        KangarooHop::set_speed(self, speed_mps);
    }

    fn set_hop_height(&mut self, height_m: f64) {
        KangarooHop::set_hop_height(self, height_m);
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
        self.start(l, com_v.z);
        self.ramp_speed(input.dt, l);
        self.advance_phase(input, com, com_v);
        let p = self.params;
        let s = Scale::new(l);
        let (t4, t45) = (s.torsional_stiffness(), s.torsional_damping());
        let max = p.max_torque * s.torque();
        let pitch = data.q[2];
        let pitch_rate = data.qd[2];

        // Ankle: the leg spring of eq. 1.
        let (ak, ab) = self.ankle_gains(l);
        let d = &mut drives[ankle];
        d.spring.stiffness = ak;
        d.spring.damping = ab;
        d.spring.rest = self.ankle_rest;
        d.spring.max_force = f64::INFINITY;
        d.feedforward = 0.0;
        d.stops = Some(Stops {
            min: p.ankle_rest_rad - 1.3,
            max: p.ankle_rest_rad + 1.2,
            stiffness: 50.0 * ak,
            damping: 20.0 * ab,
        });

        let hip_world = planar(data.point_world(creature.trunk, leg.hip_in_trunk));
        let stance = self.phase != Phase::Flight;
        if stance {
            // Hip: the knee onto the thrust line toe → centre of mass.
            let toe = planar(input.contacts.first().map_or(DVec3::ZERO, |c| c.position));
            let u = (planar(com) - toe).normalize_or(DVec2::Y);
            let th = toe - hip_world;
            let b = u.dot(th);
            let disc = b * b - (th.length_squared() - g.thigh * g.thigh);
            let a1_now = pitch + data.q[hip];
            let a1 = if disc >= 0.0 {
                let r = disc.sqrt();
                let k1 = toe + (-b + r) * u - hip_world;
                let k2 = toe + (-b - r) * u - hip_world;
                let (c1, c2) = (angle_of(k1), angle_of(k2));
                if (c1 - a1_now).abs() <= (c2 - a1_now).abs() {
                    c1
                } else {
                    c2
                }
            } else {
                angle_of(toe + (-b) * u - hip_world)
            };
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
                speed * self.stance_s / 2.0 + p.placement_gain_s * l.sqrt() * (speed - desired);
            let rising = (com_v.y / l.sqrt()).clamp(0.0, 1.0);
            let r0 = (p.landing_leg_m - p.flight_retract_m * rising) * l;
            let mut toe = if self.jump == JumpStage::Airborne
                && p.jump_at_m
                    .is_some_and(|at| com.z < at + p.obstacle_depth_m * l)
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

        // Tail: a step of the base spring's rest, down in stance, up in flight.
        let mut tail = creature.tail.iter().copied();
        if let Some(base) = tail.next() {
            let step = if stance {
                p.tail_mean_rad - 0.5 * p.tail_step_rad
            } else {
                p.tail_mean_rad + 0.5 * p.tail_step_rad
            };
            // The lab's tail feedback: the rest also follows the trunk's
            // pitch error and rate (the paper only steps it).
            let assist = if p.tail_feedback {
                p.tail_pitch_gain * (pitch - p.pitch_rad)
                    + p.tail_rate_gain_s * l.sqrt() * pitch_rate
            } else {
                0.0
            };
            let rest = step + assist.clamp(-1.0, 1.0);
            drives[base].servo(p.tail_stiffness * t4, p.tail_damping * t45, rest);
        }
        for j in tail {
            drives[j].servo(p.tail_tip_stiffness * t4, p.tail_tip_damping * t45, 0.0);
        }
        // Head level.
        if let Some(neck) = creature.neck {
            drives[neck].servo(p.neck_kp * t4, p.neck_kv * t45, -pitch);
        }
    }
}

/// The kangaroo's paw-pad ground (eq. 6) at scale 1; scale it with
/// [`GroundParams::scaled`].
#[must_use]
pub fn kangaroo_ground() -> GroundParams {
    GroundParams {
        vertical_stiffness: 30_000.0,
        vertical_damping: 150.0,
        tangential_stiffness: 20_000.0,
        tangential_damping: 100.0,
        torsional_stiffness: 50.0,
        torsional_damping: 0.5,
        pad: Some(PawPad {
            stiffness_n: 600.0,
            thickness_m: 0.02,
        }),
    }
}

/// Put the kangaroo in flight just before landing, moving forward at
/// `speed_mps` (m/s at scale 1; scaled by √L), its leg set for a neutral
/// landing. Expects `sim.creature` to be the kangaroo.
pub fn kangaroo_start(sim: &mut Sim, speed_mps: f64) {
    let creature = &sim.creature;
    let l = creature.scale;
    let p = KangarooHopParams::default();
    let Some(g) = leg_geometry(creature) else {
        return;
    };
    let Some(leg) = creature.legs.first() else {
        return;
    };
    let (Some(&hip), Some(knee)) = (leg.hip.first(), leg.knee) else {
        return;
    };
    let ankle = leg.spring;
    let data: &mut Data = &mut sim.data;
    data.q.fill(0.0);
    data.qd.fill(0.0);
    let r0 = p.landing_leg_m * l;
    let dz = (0.5 * speed_mps * p.stance_guess_s * l).min(0.8 * r0);
    let toe = DVec2::new(dz, -(r0 * r0 - dz * dz).sqrt());
    let (qh, qk) = leg_ik(&g, toe, p.ankle_rest_rad, 0.0);
    data.q[hip] = qh;
    data.q[knee] = qk;
    data.q[ankle] = p.ankle_rest_rad;
    data.q[6] = p.tail_mean_rad;
    // Trunk height: the toe 1 cm (×L) above the ground.
    data.q[1] = -(leg.hip_in_trunk.y + toe.y) + 0.01 * l;
    data.qd[0] = speed_mps * l.sqrt();
    data.qd[1] = -0.5 * l.sqrt();
    crate::dynamics::kinematics::kinematics(&creature.model, data);
}
