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
//! pair separated: the second leg lands a little shorter (so some tens of
//! milliseconds later) and a few centimetres further forward, giving single,
//! double, single support within each pair's stance.
//!
//! All parameters are given at scale 1 and scaled by the creature's dynamic
//! scale L (Table 1).

use glam::DVec3;

use super::attitude::{com_velocity, heading_forward};
use super::hip_servo::HipServo;
use super::hop_height::{flight_for_height, height_for_flight};
use super::leg_spring::LegSpring;
use super::pair_posture::PairPosture;
use super::phase::Phase;
use super::placement::{foot_displacement, gimbal_angles, hip_at_touchdown, leg_direction};
use super::scale::Scale;
use super::speed_trim::{SpeedTrim, along_z};
use super::start::{first_leg_m, level_flight};
use crate::creatures::PhysicalCreature;
use crate::world::sim::{ControlInput, Controller, Drive, Sim};

/// The pairs: front then rear; within a pair the leg that lands first in
/// the gallop comes first (front-right 1, front-left 0, rear-right 3, rear-left 2).
pub const PAIRS: [[usize; 2]; 2] = [[1, 0], [3, 2]];

/// Index of the front pair in [`PAIRS`].
pub const FRONT: usize = 0;
/// Index of the rear pair in [`PAIRS`].
pub const REAR: usize = 1;

pub use super::quadruped_bound_params::{BoundStyle, QuadrupedBoundParams};

/// One pair's state machine (Figure 4).
#[derive(Clone, Copy, Debug)]
struct PairState {
    phase: Phase,
    /// Whether the other pair touched down since this pair's lift-off.
    armed: bool,
    touchdown_s: f64,
    liftoff_s: f64,
    /// Measured stance duration (s), T_s of eq. 3.
    stance_s: f64,
    /// Each leg's stance rest (m).
    rest: [f64; 2],
    /// Whether each leg has touched in this stance.
    touched: [bool; 2],
}

/// Put the quadruped of `sim` at the start of a bound at `speed_mps`
/// (scale-1, scaled by √L): trunk level at landing height, rear legs
/// extended for landing, front legs short, moving forward along +z.
pub fn bound_start(sim: &mut Sim, speed_mps: f64) {
    let l = sim.creature.scale;
    let p = QuadrupedBoundParams::default();
    let height = first_leg_m(sim) + p.landing_rest_m * l + 0.04 * l;
    level_flight(sim, speed_mps, height, |i| {
        let rest = if PAIRS[REAR].contains(&i) {
            p.landing_rest_m
        } else {
            p.short_rest_m
        };
        rest * l
    });
}

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
    hip_target: [[f64; 2]; 4],
    /// Eq. 4's servo as the last control call set it.
    posture: PairPosture,
    /// Each leg's hip-to-foot length at full extension (m, scaled).
    leg_m: [f64; 4],
    scale: Scale,
}

impl QuadrupedBound {
    /// A controller for `creature` (its scale and leg lengths), in flight,
    /// either pair free to land first.
    #[must_use]
    pub fn new(params: QuadrupedBoundParams, creature: &PhysicalCreature) -> Self {
        let scale = creature.scale;
        let pair = PairState {
            phase: Phase::Flight,
            armed: false,
            touchdown_s: 0.0,
            liftoff_s: f64::NEG_INFINITY,
            stance_s: params.stance_s * scale.sqrt(),
            rest: [params.landing_rest_m * scale; 2],
            touched: [false; 2],
        };
        // The rear pair lands first; the front waits for it.
        let mut pairs = [pair; 2];
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
            hip_target: [[0.0; 2]; 4],
            posture: PairPosture::default(),
            leg_m: [0, 1, 2, 3].map(|i| creature.leg_length_m(i)),
            scale: Scale::new(scale),
        }
    }

    /// Bound or gallop.
    #[must_use]
    pub fn style(&self) -> BoundStyle {
        self.params.style
    }

    /// Change between bound and gallop while running.
    pub fn set_style(&mut self, style: BoundStyle) {
        self.params.style = style;
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

    fn pair_thrust(&self, pair: usize) -> f64 {
        let l = self.scale.length();
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
    fn regulate_pair(&mut self, k: usize, flight: f64) {
        let p = self.params;
        let l = self.scale.l;
        let target = if k == FRONT {
            p.gathered_flight_s
        } else {
            p.extended_flight_s
        } * l.sqrt();
        let max = p.max_thrust_m * l;
        self.trim[k] =
            (self.trim[k] + p.pair_flight_gain * l.sqrt() * (target - flight)).clamp(-max, max);
    }

    /// Advance both pairs' state machines on the contact and spring events.
    fn advance(&mut self, input: &ControlInput<'_>, com_forward: f64) {
        let l = self.scale.l;
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
                        .is_none_or(|(t0, _)| time - t0 >= p.min_stride_s * l.sqrt());
                    if k == REAR && stride_done {
                        // Eq. 2's energy per stride: one thrust for both pairs,
                        // regulated on the stride's total flight.
                        if self.stride_start.is_some() {
                            let error = p.stride_flight_s * l.sqrt() - self.stride_flight_s;
                            self.thrust = (self.thrust + p.flight_gain * l.sqrt() * error)
                                .clamp(p.min_thrust_m * l, p.max_thrust_m * l);
                        }
                        self.stride_flight_s = 0.0;
                        let vd = p.speed_mps * l.sqrt();
                        self.speed_trim.stride(
                            p.speed_trim,
                            p.speed_integral_gain,
                            vd,
                            p.speed_bias_cap * vd.abs().max(0.5 * l.sqrt()),
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
                Phase::Loading if !any && time - pair.touchdown_s > 0.01 * l.sqrt() => {
                    pair.phase = Phase::Flight;
                    pair.liftoff_s = time;
                }
                Phase::Loading if !any => {}
                Phase::Loading
                    if (qd < 0.0 && q < -0.002 * l)
                        || time - pair.touchdown_s > 0.015 * l.sqrt() =>
                {
                    pair.phase = Phase::Compression;
                }
                Phase::Compression if qd >= 0.0 => pair.phase = Phase::Thrust,
                Phase::Thrust if q >= p.thrust_end * thrusts[k] - 0.005 * l => {
                    pair.phase = Phase::Unloading;
                }
                _ => {}
            }
            if matches!(
                pair.phase,
                Phase::Compression | Phase::Thrust | Phase::Unloading
            ) && !any
            {
                pair.phase = Phase::Flight;
                pair.liftoff_s = time;
                pair.stance_s = (time - pair.touchdown_s).clamp(0.04 * l.sqrt(), 0.3 * l.sqrt());
                // The other pair landed during this stance: no flight.
                if other.phase != Phase::Flight && other.touchdown_s > pair.touchdown_s {
                    events[k] = Some((k, other.touchdown_s - time));
                }
            }
        }
        for (k, flight) in events.into_iter().flatten() {
            self.regulate_pair(k, flight);
        }
    }
}

impl Controller for QuadrupedBound {
    crate::tunable_gains!(QuadrupedBoundParams;
        leg_stiffness => "N/m", leg_damping => "N·s/m", placement_gain_s => "s", pitch_kp => "N·m/rad",
        pitch_kv => "N·m·s/rad", roll_kp => "N·m/rad", roll_kv => "N·m·s/rad");

    fn phase_name(&self) -> &'static str {
        self.phase().name()
    }

    fn leg_phase_name(&self, leg: usize) -> Option<&'static str> {
        let pair = PAIRS.iter().position(|legs| legs.contains(&leg))?;
        Some(self.pair_phase(pair).name())
    }

    fn set_speed(&mut self, speed_mps: f64) {
        self.params.speed_mps = speed_mps;
    }

    /// The bound regulates the flight in each stride: a hop height asks for
    /// the flight whose apex it is (eq. 2, [`super::hop_height`]).
    fn set_hop_height(&mut self, height_m: f64) {
        if height_m.is_finite() {
            self.params.stride_flight_s = flight_for_height(height_m);
        }
    }

    fn hop_height_m(&self) -> Option<f64> {
        Some(height_for_flight(self.params.stride_flight_s))
    }

    fn set_heading(&mut self, heading: f64) {
        self.params.heading = heading;
    }

    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let creature = input.creature;
        let data = input.data;
        if creature.legs.len() != 4 || creature.legs.iter().any(|leg| leg.hip.len() != 2) {
            return;
        }
        let s = self.scale;
        let l = s.length();
        let p = self.params;
        let fwd = heading_forward(p.heading);
        let com = crate::dynamics::energy::center_of_mass(&creature.model, data);
        self.advance(input, com.dot(fwd));

        let trunk = creature.trunk;
        let trunk_rot = data.world[trunk].rot;
        let trunk_pos = data.world[trunk].pos;
        let spring = LegSpring::new(p.leg_stiffness, p.leg_damping, p.leg_travel_m);
        let landing = p.landing_rest_m * l;
        let short = p.short_rest_m * l;
        let gallop = p.style == BoundStyle::Gallop;

        // Posture (eq. 4, weak on pitch) in stance: the servo's set-up here,
        // its torques every step ([`Controller::servo`]).
        let gains = |kp: f64, kv: f64| s.torsional_gains(kp, kv);
        let mut posture = PairPosture {
            heading: p.heading,
            pitch_d: p.pitch_bias,
            gains: [
                gains(p.pitch_kp, p.pitch_kv),
                gains(p.roll_kp, p.roll_kv),
                gains(p.yaw_kp, p.yaw_kv),
            ],
            max: p.max_hip_torque * s.torque(),
            force_ratio: p.posture_force_ratio,
            stiffness: p.leg_stiffness * s.stiffness(),
            leg_m: self.leg_m,
            ..PairPosture::default()
        };

        let velocity = com_velocity(creature, data);
        let desired = fwd * (p.speed_mps * s.velocity() + self.speed_trim.bias_mps);
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
            for (side, &i) in legs.iter().enumerate() {
                posture.sharing[i] = !in_flight
                    && pair.touched[side]
                    && input.contacts[i].touching
                    && servoing(pair.phase);
            }
            let sharing = legs.iter().any(|&i| posture.sharing[i]);
            for (side, &i) in legs.iter().enumerate() {
                let leg = &creature.legs[i];
                let reach = self.leg_m[i] + landing;
                let second = gallop && side == 1;
                let touching = input.contacts[i].touching;
                // Leg spring: eq. 1 with a programmable rest.
                let airborne_leg = in_flight || !pair.touched[side];
                let rest = if airborne_leg {
                    if in_flight && !extend {
                        short
                    } else if second {
                        landing - p.gallop_shorter_m * l
                    } else {
                        landing
                    }
                } else {
                    match pair.phase {
                        Phase::Thrust => pair.rest[side] + thrust,
                        Phase::Unloading => short,
                        _ if !touching && pair.phase != Phase::Loading => short,
                        _ => pair.rest[side],
                    }
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
                    let dir = leg_direction(trunk_rot, foot - hip_world, reach);
                    let (roll, pitch) = gimbal_angles(dir);
                    servo.set(drives, &leg.hip, [roll, pitch], &mut self.hip_target[i]);
                } else if touching && servoing(pair.phase) && sharing {
                    posture.applying[i] = true;
                    posture.rest[i] = rest;
                    self.hip_target[i] = [data.q[leg.hip[0]], data.q[leg.hip[1]]];
                } else {
                    for (&j, prev) in leg.hip.iter().zip(self.hip_target[i].iter_mut()) {
                        drives[j].torque(0.0);
                        *prev = data.q[j];
                    }
                }
            }
        }
        self.posture = posture;
    }

    fn servo(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.posture.apply(input, &PAIRS, drives);
    }
}
