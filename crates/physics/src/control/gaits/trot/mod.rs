//! Quadruped trotting (Raibert & Hodgins 1991, "Control" — hopping, speed
//! and posture — Figure 4, "Gaits", "Modeling", Tables 2 and 3).
//!
//! The trot is a *virtual biped* gait: the legs work in diagonal pairs and
//! each pair acts as one virtual leg run by the state machine of Figure 4.
//! The active pair's leg springs get a programmable rest length and a thrust
//! in stance (eq. 1–2); the pair's feet are placed about the neutral point
//! with the speed correction of eq. 3, each relative to its own hip; the hips
//! servo the trunk's pitch and roll in stance (eq. 4) and steer its yaw
//! towards the commanded heading; the idle pair is kept short and swung
//! forward. (The bound and the gallop are [`crate::control::gaits::bound`].)
//!
//! The hop is regulated by the duration of the flight that follows each
//! pair's lift-off (the Table-2 quantity), each pair's thrust adjusted after
//! every flight. As in the paper, the standing length of the legs is reduced
//! for the trot. Every parameter is given for the creature at scale 1 and
//! scaled by its dynamic scale L (Table 1).

use gaitlab_core::portable::Portable;

use crate::control::additions::speed_trim::SpeedTrim;
use crate::control::laws::attitude::{com_velocity, heading_forward};
use crate::control::laws::body_plan::BodyPlan;
use crate::control::laws::hip_servo::{HipServo, release};
use crate::control::laws::hop_height::height_for_flight;
use crate::control::laws::lift_share::lift_share;
use crate::control::laws::pair_posture::PairPosture;
use crate::control::laws::phase::Phase;
use crate::control::laws::placement::{
    aim_frame, foot_displacement, hip_angles, hip_at_touchdown_over,
};
use crate::control::laws::scale::Scale;
use crate::creatures::PhysicalCreature;
use crate::world::ground_view::GroundView;
use crate::world::sim::{ControlInput, Controller, Drive};

/// The trot's two virtual legs, diagonal pairs of leg indices (front-left
/// 0, front-right 1, rear-left 2, rear-right 3): front-left + rear-right,
/// front-right + rear-left.
pub const TROT_PAIRS: [[usize; 2]; 2] = [[0, 3], [1, 2]];

pub mod build;
mod cycle;
pub mod origins;
pub mod params;
pub mod start;
pub mod take_over;

pub use crate::control::gaits::trot::params::{GaitTuning, QuadrupedRunParams};
pub use crate::control::laws::ground::quadruped_ground;

/// The quadruped running controller, the trot: a virtual biped on diagonal
/// pairs of legs.
#[derive(Clone, Debug)]
pub struct QuadrupedRun {
    /// Parameters (editable while running).
    pub params: QuadrupedRunParams,
    /// The two virtual legs, pairs of leg indices, the first to land first:
    /// the trot's diagonals ([`TROT_PAIRS`]) unless made
    /// [`on_pairs`](QuadrupedRun::on_pairs).
    pub pairs: [[usize; 2]; 2],
    /// The active (supporting or landing) pair, 0 or 1 of `pairs`.
    pub active: usize,
    /// Each leg's state; the idle pair's legs stay in [`Phase::Flight`].
    pub leg_phase: [Phase; 4],
    /// Measured duration of each pair's last stance (s), T_s of eq. 3.
    pub stance_s: [f64; 2],
    /// Each pair's current thrust (m).
    pub thrust: [f64; 2],
    /// The last measured flight after each pair's lift-off (s).
    pub flight_s: [f64; 2],
    in_stance: bool,
    done: [bool; 4],
    touchdown_time: f64,
    /// Each leg's touchdown time (s).
    leg_touchdown: [f64; 4],
    /// Each leg's spring rest at its touchdown (m): its stance rest.
    stance_rest: [f64; 4],
    /// Each leg's hip servo target last call (rad), for the servo's rate feed-forward.
    hip_target: [[f64; 2]; 4],
    /// Eq. 4's servo as the last control call set it.
    posture: PairPosture,
    liftoff_time: f64,
    liftoff_pair: Option<usize>,
    /// The centre of mass's height at the last lift-off, or at the first
    /// touchdown before one (m): eq. 2's apex target is measured from it.
    liftoff_com_y: f64,
    /// The ground plane's height under the centre of mass then (m; used
    /// only with the lab's `ground_ahead`).
    liftoff_ground_y: f64,
    /// Eq. 2 has set this stance's thrust.
    eq2_set: bool,
    /// A per-step speed correction by the tuning's `speed_gain` (0 unless a
    /// preset sets it: the trot holds its speed by eq. 3 alone).
    pub trim: SpeedTrim,
    /// The share of each pair's spring work that lifts the centre of mass
    /// ([`lift_share`]; 1 for the trot's diagonals): eq. 2 counts that
    /// share of its springs' strain.
    lift_share: [f64; 2],
    /// The creature's scale and leg lengths.
    plan: BodyPlan<4>,
}

impl QuadrupedRun {
    /// A trot controller for `creature` (its scale and leg lengths),
    /// starting in flight with pair 0 about to land.
    #[must_use]
    pub fn new(params: QuadrupedRunParams, creature: &PhysicalCreature) -> Self {
        Self::on_pairs(params, creature, TROT_PAIRS)
    }

    /// The same controller on other virtual legs (`pairs`, two pairs of leg
    /// indices, the first to land first): the pace's lateral pairs.
    #[must_use]
    pub fn on_pairs(
        params: QuadrupedRunParams,
        creature: &PhysicalCreature,
        pairs: [[usize; 2]; 2],
    ) -> Self {
        let scale = creature.scale;
        let t = params.trot;
        Self {
            params,
            pairs,
            active: 0,
            leg_phase: [Phase::Flight; 4],
            stance_s: [t.stance_s * Scale::new(scale).time(); 2],
            thrust: [t.thrust_m * scale; 2],
            flight_s: [0.0; 2],
            in_stance: false,
            done: [false; 4],
            touchdown_time: 0.0,
            leg_touchdown: [0.0; 4],
            stance_rest: [params.trot.landing_rest_m * scale; 4],
            hip_target: [[0.0; 2]; 4],
            posture: PairPosture::default(),
            liftoff_time: 0.0,
            liftoff_pair: None,
            liftoff_com_y: f64::NAN,
            liftoff_ground_y: 0.0,
            eq2_set: false,
            trim: SpeedTrim::default(),
            lift_share: pairs.map(|pair| lift_share(creature, pair)),
            plan: BodyPlan::of(creature),
        }
    }

    /// The state of the active virtual leg (Figure 4): flight until a leg
    /// of the active pair lands, then the state of its first leg in stance.
    #[must_use]
    pub fn phase(&self) -> Phase {
        if !self.in_stance {
            return Phase::Flight;
        }
        let pair = self.pairs[self.active];
        pair.iter()
            .map(|&i| self.leg_phase[i])
            .find(|&p| p != Phase::Flight)
            .unwrap_or(Phase::Unloading)
    }

    fn tuning(&self) -> GaitTuning {
        self.params.trot
    }
}

impl Controller for QuadrupedRun {
    crate::family_gains!(quadruped params.trot = QuadrupedRunParams::default().trot);

    fn phase_name(&self) -> &'static str {
        self.phase().name()
    }

    fn leg_phase_name(&self, leg: usize) -> Option<&'static str> {
        self.leg_phase.get(leg).map(|p| p.name())
    }

    /// The trot regulates each pair's flight time: its own hop height is
    /// the apex of its mean flight (eq. 2, [`crate::control::laws::hop_height`]).
    fn hop_height_m(&self) -> Option<f64> {
        let f = self.params.trot.flight_s;
        Some(height_for_flight((f[0] + f[1]) / 2.0))
    }

    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let creature = input.creature;
        let data = input.data;
        if creature.legs.len() != 4 {
            return;
        }
        let s = self.plan.scale;
        let l = s.length();
        let trunk = creature.trunk;
        let trunk_rot = data.world[trunk].rot;
        let trunk_pos = data.world[trunk].pos;
        // The frame the positioning legs are aimed in (eq. 3's kinematic transformation).
        let aim = aim_frame(trunk_rot, self.params.swing_roll_follow);
        let pair = self.pairs[self.active];
        let descending = pair
            .iter()
            .map(|&i| {
                data.point_velocity_world(trunk, creature.legs[i].hip_in_trunk)
                    .y
            })
            .sum::<f64>()
            < 0.0;
        let com = crate::dynamics::energy::center_of_mass(&creature.model, data);
        let fwd = heading_forward(input.commands.heading_rad);
        self.advance_phase(input, drives, descending, com.dot(fwd));
        let pair = self.pairs[self.active];
        let idle = self.pairs[1 - self.active];
        let p = self.params;
        let t = self.tuning();
        let landing = t.landing_rest_m * l;
        self.set_springs(input, drives, descending);
        // Foot placement (eq. 3) for the active pair's legs in the air.
        let velocity = com_velocity(creature, data);
        let desired = fwd * (input.commands.speed_mps + self.trim.bias_mps);
        let max = p.max_hip_torque * s.torque();
        let (kp, kv) = s.torsional_gains(p.swing_kp, p.swing_kv);
        let servo = HipServo {
            kp,
            kv,
            max,
            dt: input.dt,
        };
        let displacement = foot_displacement(
            velocity,
            desired,
            self.stance_s[self.active],
            t.placement_gain_s * s.time(),
        );
        // Posture (eq. 4) and heading in stance: the servo's set-up here, its
        // torques every step ([`Controller::servo`]).
        let swing = if self.active == 0 {
            t.pitch_swing
        } else {
            -t.pitch_swing
        };
        let gains = |kp: f64, kv: f64| s.torsional_gains(kp, kv);
        let servoing = |ph: Phase| matches!(ph, Phase::Compression | Phase::Thrust);
        // With the lab's `ground_ahead` the trunk pitches with the ground
        // along the heading (nose up uphill), so the front and rear hips
        // stand as high above their ground; the paper holds it level.
        let slope_pitch = if p.ground_ahead {
            input.ground.grade_along(fwd).patan2(1.0)
        } else {
            0.0
        };
        let mut posture = PairPosture {
            heading: input.commands.heading_rad,
            pitch_d: t.pitch_d + swing - slope_pitch,
            gains: [
                gains(t.pitch_kp, t.pitch_kv),
                gains(t.roll_kp, t.roll_kv),
                gains(p.yaw_kp, p.yaw_kv),
            ],
            max,
            force_ratio: t.posture_force_ratio,
            stiffness: t.leg_stiffness * s.stiffness(),
            leg_m: self.plan.leg_m,
            at_least_one: true,
            ..PairPosture::default()
        };
        for &i in &pair {
            posture.sharing[i] = !self.done[i] && servoing(self.leg_phase[i]);
        }
        let mut active_pitch = 0.0;
        for &i in &pair {
            let leg = &creature.legs[i];
            let hip_world = trunk_rot * leg.hip_in_trunk + trunk_pos;
            let reach = self.plan.leg_m[i] + landing;
            active_pitch += data.q[leg.hip[1]] / 2.0;
            let phase = self.leg_phase[i];
            if self.done[i] {
                servo.set(drives, &leg.hip, [0.0, 0.0], &mut self.hip_target[i]);
                continue;
            }
            match phase {
                Phase::Flight => {
                    // Aim at where the hip will be at touchdown, so the
                    // target stays put on the ground and the leg sweeps
                    // back as the body travels (ground speed matching).
                    let hip_v = data.point_velocity_world(trunk, leg.hip_in_trunk);
                    // The paper's floor, or with the lab's `ground_ahead`
                    // the ground plane under the body.
                    let ground = if p.ground_ahead {
                        input.ground
                    } else {
                        GroundView::FLAT
                    };
                    let lookahead = 0.5 * s.time();
                    let foot = hip_at_touchdown_over(
                        &ground,
                        hip_world,
                        hip_v,
                        reach,
                        displacement,
                        lookahead,
                    ) + displacement;
                    let angles = hip_angles(aim, hip_world, foot, reach);
                    servo.set(drives, &leg.hip, angles, &mut self.hip_target[i]);
                }
                Phase::Loading | Phase::Unloading => {
                    release(drives, &leg.hip, &data.q, &mut self.hip_target[i]);
                }
                Phase::Compression | Phase::Thrust => {
                    posture.applying_rest_m[i] = Some(self.stance_rest[i]);
                    self.hip_target[i] = [data.q[leg.hip[0]], data.q[leg.hip[1]]];
                }
            }
        }
        // The idle pair swings forward, mirroring the active pair's sweep.
        for &i in &idle {
            let leg = &creature.legs[i];
            servo.set(
                drives,
                &leg.hip,
                [0.0, -active_pitch],
                &mut self.hip_target[i],
            );
        }
        self.posture = posture;
    }

    fn servo(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.posture.apply(input, &self.pairs, drives);
    }
}
