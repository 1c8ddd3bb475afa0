//! Quadruped bounding and galloping as a planar two-legged runner
//! (Raibert & Hodgins 1991, "Control" — eqs. 1–4 — Figure 4, "Gaits",
//! Tables 2 and 3; after Raibert's 1990 trotting, pacing and bounding
//! quadruped and Murphy & Raibert's planar bounding).
//!
//! In the sagittal plane the bounding quadruped is a biped whose "legs" are
//! its front and rear pairs. The two feet of a pair move together (same hip
//! angles), and each pair runs its own state machine of Figure 4: it lands,
//! compresses, thrusts and lifts off on its own events. Both pairs get the
//! same thrust (eq. 2's energy injection, one value regulated on the
//! stride's total flight time), so their vertical impulses balance and the
//! trunk's pitch oscillation is the gait's natural mode rather than
//! something the hips fight. The only coordination is that a pair lengthens
//! for landing only after the other pair has touched down since its own
//! lift-off, so the pairs alternate (rear, extended flight, front, gathered
//! flight).
//!
//! Each pair places its feet about its own hip's neutral point with eq. 3's
//! speed correction, which also governs pitch: front feet placed further
//! forward raise the nose. In stance the hips only damp the pitch rate
//! weakly and pull the trunk toward a small pitch bias (eq. 4 with small
//! gains); roll is servoed level by the hip roll joints, the torque split
//! across the pair's feet; yaw toward the heading by differential fore–aft
//! foot forces.
//!
//! The gallop ([`BoundStyle::Gallop`]) is the bound with the two legs of each
//! pair separated in time and space (`quadruped_bound/gallop_legs.rs`).
//!
//! All parameters are given at scale 1 and scaled by the creature's dynamic
//! scale L (Table 1).

use glam::DVec3;

use crate::control::additions::speed_trim::SpeedTrim;
use crate::control::laws::attitude::{com_velocity, heading_forward};
use crate::control::laws::body_plan::BodyPlan;
use crate::control::laws::hip_servo::{HipServo, release};
use crate::control::laws::hop_height::height_for_flight;
use crate::control::laws::leg_spring::LegSpring;
use crate::control::laws::pair_posture::PairPosture;
use crate::control::laws::phase::Phase;
use crate::control::laws::placement::{aim_frame, foot_displacement, hip_angles, hip_at_touchdown};
use crate::creatures::PhysicalCreature;
use crate::world::sim::{ControlInput, Controller, Drive};

pub use crate::control::gaits::bound::params::{
    BoundStyle, FRONT, PAIRS, QuadrupedBoundParams, REAR,
};

pub mod build;
mod gallop_legs;
pub mod origins;
mod pair_cycle;
mod pairs;
pub mod params;
pub mod start;
pub mod take_over;

use gallop_legs::stance_rest;
use pairs::PairState;

/// The bounding / galloping controller.
#[derive(Clone, Debug)]
pub struct QuadrupedBound {
    /// Parameters (editable while running).
    pub params: QuadrupedBoundParams,
    pairs: [PairState; 2],
    /// The common thrust (m).
    pub thrust: f64,
    /// Each pair's own thrust trim added to the common thrust (m).
    pub trim: [f64; 2],
    /// The lab's speed trim added to the desired speed (zero unless
    /// `speed_trim`), from one rear touchdown to the next.
    pub speed_trim: SpeedTrim,
    /// Last measured flight after each pair's lift-off (s): gathered
    /// (after the front pair) and extended (after the rear pair).
    pub flight_s: [f64; 2],
    /// Start of the current all-feet-off period and the pair that lifted last.
    flight_start: Option<(f64, usize)>,
    /// Flight accumulated since the last rear touchdown (s).
    stride_flight_s: f64,
    /// Time and forward position of the centre of mass at the last rear touchdown.
    stride_start: Option<(f64, f64)>,
    /// Each pair's thrust as eq. 2 set it at the pair's last bottom (m;
    /// NaN before one), without the hop integrator.
    eq2_thrust: [f64; 2],
    /// The centre of mass's height at the last lift-off of a pair, or at
    /// the first touchdown before one (m): eq. 2's apex target is measured
    /// from it.
    liftoff_com_y: f64,
    hip_target: [[f64; 2]; 4],
    /// Eq. 4's servo as the last control call set it.
    posture: PairPosture,
    /// The creature's scale and leg lengths.
    plan: BodyPlan<4>,
}

impl QuadrupedBound {
    /// A controller for `creature` (its scale and leg lengths), in flight,
    /// either pair free to land first.
    #[must_use]
    pub fn new(params: QuadrupedBoundParams, creature: &PhysicalCreature) -> Self {
        let scale = creature.scale;
        // The rear pair lands first; the front waits for it.
        let mut pairs = [PairState::in_flight(&params, scale); 2];
        pairs[REAR].armed = true;
        Self {
            params,
            pairs,
            thrust: params.thrust_m * scale,
            trim: [0.0; 2],
            speed_trim: SpeedTrim::default(),
            flight_s: [0.0; 2],
            flight_start: None,
            stride_flight_s: 0.0,
            stride_start: None,
            eq2_thrust: [f64::NAN; 2],
            liftoff_com_y: f64::NAN,
            hip_target: [[0.0; 2]; 4],
            posture: PairPosture::default(),
            plan: BodyPlan::of(creature),
        }
    }
}

impl Controller for QuadrupedBound {
    crate::family_gains!(quadruped QuadrupedBoundParams);

    fn phase_name(&self) -> &'static str {
        self.phase().name()
    }

    fn leg_phase_name(&self, leg: usize) -> Option<&'static str> {
        let pair = PAIRS.iter().position(|legs| legs.contains(&leg))?;
        Some(self.pair_phase(pair).name())
    }

    /// The bound regulates the flight in each stride: its own is that of
    /// this apex height (eq. 2, [`crate::control::laws::hop_height`]).
    fn hop_height_m(&self) -> Option<f64> {
        Some(height_for_flight(self.params.stride_flight_s))
    }

    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let creature = input.creature;
        let data = input.data;
        if creature.legs.len() != 4 || creature.legs.iter().any(|leg| leg.hip.len() != 2) {
            return;
        }
        let s = self.plan.scale;
        let l = s.length();
        let p = self.params;
        let fwd = heading_forward(input.commands.heading_rad);
        let com = crate::dynamics::energy::center_of_mass(&creature.model, data);
        self.advance(input, com.dot(fwd));

        let trunk = creature.trunk;
        let trunk_rot = data.world[trunk].rot;
        let trunk_pos = data.world[trunk].pos;
        // The frame the positioning legs are aimed in (eq. 3's kinematic transformation).
        let aim = aim_frame(trunk_rot, p.swing_roll_follow);
        let spring = LegSpring::new(p.leg_stiffness, p.leg_damping, p.leg_travel_m);
        let landing = p.landing_rest_m * l;
        let short = p.short_rest_m * l;
        let gallop = p.style == BoundStyle::Gallop;
        let own_legs = gallop && p.gallop_lag_s > 0.0;

        // Posture (eq. 4, weak on pitch) in stance: the servo's set-up here,
        // its torques every step ([`Controller::servo`]).
        let gains = |kp: f64, kv: f64| s.torsional_gains(kp, kv);
        let mut posture = PairPosture {
            heading: input.commands.heading_rad,
            pitch_d: p.pitch_bias,
            gains: [
                gains(p.pitch_kp, p.pitch_kv),
                gains(p.roll_kp, p.roll_kv),
                gains(p.yaw_kp, p.yaw_kv),
            ],
            max: p.max_hip_torque * s.torque(),
            force_ratio: p.posture_force_ratio,
            stiffness: p.leg_stiffness * s.stiffness(),
            leg_m: self.plan.leg_m,
            ..PairPosture::default()
        };

        let velocity = com_velocity(creature, data);
        let desired = fwd * (input.commands.speed_mps + self.speed_trim.bias_mps);
        let max = p.max_hip_torque * s.torque();
        let (kp, kv) = gains(p.swing_kp, p.swing_kv);
        let servo = HipServo {
            kp,
            kv,
            max,
            dt: input.dt,
        };
        let servoing = |ph: Phase| matches!(ph, Phase::Compression | Phase::Thrust);

        for (k, &legs) in PAIRS.iter().enumerate() {
            let pair = self.pairs[k];
            let thrust = self.pair_thrust(k);
            let in_flight = pair.phase == Phase::Flight;
            // Lengthen for landing once armed and clear of the ground.
            let extend = pair.armed && input.time - pair.liftoff_s > p.min_short_s * s.time();
            let displacement = foot_displacement(
                velocity,
                desired,
                pair.stance_s,
                p.placement_gain_s * s.time(),
            ) + if k == FRONT {
                fwd * (p.front_offset_m * l)
            } else {
                DVec3::ZERO
            };
            // Stance legs of the pair sharing the posture torque.
            let phase = |side: usize| pair.leg_phase(side, own_legs);
            for (side, &i) in legs.iter().enumerate() {
                posture.sharing[i] = !in_flight
                    && pair.touched[side]
                    && input.contacts[i].touching
                    && servoing(phase(side));
            }
            let sharing = legs.iter().any(|&i| posture.sharing[i]);
            for (side, &i) in legs.iter().enumerate() {
                let leg = &creature.legs[i];
                let reach = self.plan.leg_m[i] + landing;
                let second = gallop && side == 1;
                let touching = input.contacts[i].touching;
                // Leg spring: eq. 1 with a programmable rest.
                let airborne_leg = in_flight || !pair.touched[side];
                let rest = if airborne_leg {
                    if in_flight && !extend {
                        short
                    } else if second
                        && (!own_legs
                            || in_flight
                            || input.time - pair.touchdown_s < p.gallop_lag_s * s.time())
                    {
                        landing - p.gallop_shorter_m * l
                    } else {
                        landing
                    }
                } else {
                    stance_rest(phase(side), touching, pair.rest[side], thrust, short)
                };
                let damping = if touching {
                    p.leg_damping
                } else {
                    p.leg_air_damping
                };
                spring.apply_with_damping(&mut drives[leg.spring], rest.min(0.0), damping, s);
                let hip_world = trunk_rot * leg.hip_in_trunk + trunk_pos;
                if airborne_leg && !touching {
                    // Foot placement (eq. 3) about the hip's neutral point, aimed
                    // where the hip will be at touchdown but looking at most
                    // `sweep_s` ahead: the leg waits at its landing angle and,
                    // in the last moments, sweeps back so the heavy foot meets
                    // the ground at little speed (ground speed matching).
                    let hip_v = data.point_velocity_world(trunk, leg.hip_in_trunk);
                    let spread = if second {
                        fwd * (p.gallop_spread_m * l)
                    } else {
                        DVec3::ZERO
                    };
                    let lookahead = p.sweep_s * s.time();
                    let foot = hip_at_touchdown(hip_world, hip_v, reach, displacement, lookahead)
                        + displacement
                        + spread;
                    let angles = hip_angles(aim, hip_world, foot, reach);
                    servo.set(drives, &leg.hip, angles, &mut self.hip_target[i]);
                } else if touching && servoing(phase(side)) && sharing {
                    posture.applying_rest_m[i] = Some(rest);
                    self.hip_target[i] = [data.q[leg.hip[0]], data.q[leg.hip[1]]];
                } else {
                    release(drives, &leg.hip, &data.q, &mut self.hip_target[i]);
                }
            }
        }
        self.posture = posture;
    }

    fn servo(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.posture.apply(input, &PAIRS, drives);
    }
}
