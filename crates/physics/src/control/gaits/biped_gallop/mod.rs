//! Biped galloping (Raibert & Hodgins 1991, "Gaits": "Biped galloping is
//! similar to quadruped galloping in that the two stance legs share a single
//! support phase"). Each stride is a flight, then the *trailing* leg's single
//! support, a double support, the *leading* leg's single support, and flight
//! again: the legs land separated in time and space and share the work of
//! rebounding. Two styles, as in the paper:
//!
//! - [`GallopStyle::TogetherSwing`]: the legs swing forward together during
//!   flight, "similar to the front half of a galloping horse";
//! - [`GallopStyle::AlternateSwing`]: each leg swings forward during the
//!   other leg's single support, "closer to the pattern used by galloping
//!   humans"; the stance leg's hip absorbs the swing's reaction, so the trunk
//!   pitches much less.
//!
//! The three running functions of "Control" act on each leg in its own
//! Figure-4 cycle (loading, compression, thrust, unloading): hopping height by
//! the leg spring's rest length and a thrust in stance (eq. 1–2), speed by
//! placing each foot about its neutral point (eq. 3, plus an integral
//! correction per stride), posture by eq. 4 through the hips of the legs in
//! support, shared in proportion to the load each carries. Everything scales
//! with the creature's L ("Dynamic Scaling", Table 1).

use glam::DVec3;

use crate::control::additions::speed_trim::SpeedTrim;
use crate::control::laws::attitude::{attitude_error, com_velocity, heading_forward, trunk_rate};
use crate::control::laws::body_plan::BodyPlan;
use crate::control::laws::hip_servo::{set_hip, zero_hip};
use crate::control::laws::leg_spring::LegSpring;
use crate::control::laws::phase::Phase;
use crate::control::laws::placement::{foot_displacement, hip_angles};
use crate::control::laws::posture::{through_hip, trunk_torque};
use crate::control::laws::scale::Scale;
use crate::creatures::PhysicalCreature;
use crate::world::sim::{ControlInput, Controller, Drive};

pub use crate::control::gaits::biped_gallop::params::{BipedGallopParams, GallopStyle};
pub use crate::control::gaits::biped_gallop::phase::GallopPhase;

pub mod build;
pub mod origins;
pub mod params;
pub mod phase;
mod stride;

/// One leg's part of the stride.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GallopLeg {
    /// The leg's own Figure-4 state; [`Phase::Flight`] while it is airborne.
    pub phase: Phase,
    /// Measured duration of its last stance (s), T_s of eq. 3 for this leg.
    pub stance_s: f64,
    /// When it last touched down (s).
    pub touchdown_s: f64,
    /// Hip roll and pitch (rad) at its last lift-off, held while it waits.
    hold: [f64; 2],
    /// Its rest length as it moves toward its target (m).
    rest: f64,
    /// Its rest length at touchdown, kept through the stance (m): a leg still
    /// lengthening when it lands would otherwise push like a thrust.
    landed_rest: f64,
}

/// The galloping state machine for a two-legged creature.
#[derive(Clone, Debug)]
pub struct BipedGallop {
    /// Parameters (editable while running: speed, heading, style, gains).
    pub params: BipedGallopParams,
    /// The stride's support state.
    pub phase: GallopPhase,
    /// Each leg's state.
    pub legs: [GallopLeg; 2],
    apex_height: f64,
    thrust: f64,
    descending: bool,
    /// Trunk pitch at the stride's last lift-off (rad).
    liftoff_pitch: f64,
    /// The centre of mass's height at the stride's last lift-off (m): eq.
    /// 2's apex target is measured from it.
    liftoff_com_y: f64,
    /// Desired trunk pitch in stance (rad), eq. 4's ϕ_d: set against the
    /// pitch the legs' swing in flight produces.
    pitch_d: f64,
    /// The lab's speed trim (zero unless `speed_trim`), per stride.
    trim: SpeedTrim,
    /// The creature's scale and leg lengths.
    plan: BodyPlan<2>,
}

impl BipedGallop {
    /// A controller for `creature` (its scale and leg lengths), starting in
    /// flight, falling toward the trailing leg's landing.
    #[must_use]
    pub fn new(params: BipedGallopParams, creature: &PhysicalCreature) -> Self {
        let scale = creature.scale;
        let leg = |rest: f64| GallopLeg {
            phase: Phase::Flight,
            stance_s: 0.2 * Scale::new(scale).time(),
            touchdown_s: f64::NEG_INFINITY,
            hold: [0.0; 2],
            rest: rest * scale,
            landed_rest: params.hopper.landing_rest_m * scale,
        };
        let lead = params.lead_leg.min(1);
        let mut legs = [leg(params.hopper.landing_rest_m); 2];
        legs[lead].rest = params.hopper.idle_rest_m * scale;
        Self {
            params,
            phase: GallopPhase::Flight,
            legs,
            apex_height: f64::NEG_INFINITY,
            thrust: params.hopper.thrust_m * scale,
            descending: true,
            liftoff_pitch: f64::NAN,
            liftoff_com_y: f64::NAN,
            pitch_d: 0.0,
            trim: SpeedTrim::default(),
            plan: BodyPlan::of(creature),
        }
    }

    /// The leading leg (lands second, leaves last).
    #[must_use]
    pub fn lead(&self) -> usize {
        self.params.lead_leg.min(1)
    }

    /// The trailing leg (lands first, leaves first).
    #[must_use]
    pub fn trail(&self) -> usize {
        1 - self.lead()
    }

    /// The thrust now added to the rest length in thrust (m).
    #[must_use]
    pub fn thrust_m(&self) -> f64 {
        self.thrust
    }
}

impl Controller for BipedGallop {
    crate::family_gains!(biped BipedGallopParams);

    fn phase_name(&self) -> &'static str {
        self.phase.name()
    }

    fn leg_phase_name(&self, leg: usize) -> Option<&'static str> {
        self.legs.get(leg).map(|l| l.phase.name())
    }

    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let creature = input.creature;
        if creature.legs.len() < 2 || creature.legs.iter().any(|g| g.hip.len() < 3) {
            return;
        }
        self.advance_phase(input);
        let p = self.params;
        let l = self.plan.scale.l;
        let data = input.data;
        let trunk_rot = data.world[creature.trunk].rot;
        let trunk_pos = data.world[creature.trunk].pos;
        let velocity = com_velocity(creature, data);
        let forward = heading_forward(input.commands.heading_rad);
        let s = self.plan.scale;
        let desired = forward * (input.commands.speed_mps + self.trim.bias_mps);
        let spring = LegSpring::new(
            p.hopper.leg_stiffness,
            p.hopper.leg_damping,
            p.hopper.leg_travel_m,
        );

        let com = crate::dynamics::energy::center_of_mass(&creature.model, data);
        let (kp, kv) = s.torsional_gains(p.hopper.swing_kp, p.hopper.swing_kv);
        let (ykp, ykv) = s.torsional_gains(p.hopper.leg_yaw_kp, p.hopper.leg_yaw_kv);
        let max = p.hopper.max_hip_torque * s.torque();

        let time = input.time;
        let step = p.hopper.leg_rate_mps * s.velocity() * input.dt;
        let extend = p.lead_extend_mps * s.velocity() * input.dt;
        let flight_extend = p.trail_extend_mps * s.velocity() * input.dt;
        let unload = p.trail_unload_mps * s.velocity() * input.dt;
        for (i, leg) in creature.legs.iter().enumerate().take(2) {
            // Leg length: the spring of eq. 1 with a programmable rest.
            let target = self.rest_target(i, time);
            let (down, up) = match self.legs[i].phase {
                // The leading leg lengthens briskly for its landing.
                Phase::Flight if i == self.lead() => (step, extend.max(step)),
                Phase::Flight if self.phase == GallopPhase::Flight => {
                    (step, flight_extend.max(step))
                }
                // The trailing leg pulls up briskly while the leading leg
                // carries the body.
                Phase::Unloading if i == self.trail() && self.in_support(self.lead()) => {
                    (unload.max(step), step)
                }
                _ => (step, step),
            };
            let state = &mut self.legs[i];
            state.rest += (target - state.rest).clamp(-down, up);
            spring.apply(&mut drives[leg.spring], state.rest, s);

            match self.legs[i].phase {
                Phase::Flight => {
                    let targets = if self.holds(i) {
                        self.legs[i].hold
                    } else {
                        // Eq. 3 about this leg's own neutral point.
                        let offset = if i == self.lead() {
                            p.lead_offset_m
                        } else {
                            p.trail_offset_m
                        };
                        let foot = DVec3::new(com.x, 0.0, com.z)
                            + forward * (offset * l)
                            + foot_displacement(
                                velocity,
                                desired,
                                self.legs[i].stance_s,
                                p.hopper.placement_gain_s * s.time(),
                            );
                        let hip_world = trunk_rot * leg.hip_in_trunk + trunk_pos;
                        let reach = self.plan.leg_m[i] + p.hopper.landing_rest_m * l;
                        hip_angles(trunk_rot, hip_world, foot, reach)
                    };
                    set_hip(drives, &leg.hip[..2], targets, kp, kv, max);
                    drives[leg.hip[2]].servo(ykp, ykv, 0.0);
                }
                // Figure 4: "zero active hip torque" on landing.
                Phase::Loading => zero_hip(drives, &leg.hip, ykp, ykv),
                // Eq. 4: [`Controller::servo`], every integration step.
                Phase::Compression | Phase::Thrust | Phase::Unloading => {}
            }
        }
    }

    /// Eq. 4 on pitch and roll (and a yaw servo): the torque the trunk
    /// needs, shared by the legs in support in proportion to their load.
    fn servo(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        let creature = input.creature;
        let servoing = |s: &GallopLeg| {
            matches!(
                s.phase,
                Phase::Compression | Phase::Thrust | Phase::Unloading
            )
        };
        if creature.legs.len() < 2
            || creature.legs.iter().any(|g| g.hip.len() < 3)
            || !self.legs.iter().any(servoing)
        {
            return;
        }
        let p = self.params;
        let s = self.plan.scale;
        let data = input.data;
        let trunk_rot = data.world[creature.trunk].rot;
        let max = p.hopper.max_hip_torque * s.torque();
        let err = attitude_error(creature, data, input.commands.heading_rad, self.pitch_d);
        let rate = trunk_rate(creature, data);
        let (pkp, pkv) = s.torsional_gains(p.hopper.posture_kp, p.hopper.posture_kv);
        let posture = trunk_torque(err, rate, pkp, pkv);
        let (ypkp, ypkv) = s.torsional_gains(p.hopper.yaw_kp, p.hopper.yaw_kv);
        let yaw = -err.y * ypkp - rate.y * ypkv;
        let load = [0, 1].map(|i| {
            if servoing(&self.legs[i]) {
                input.contacts.get(i).map_or(0.0, |c| c.force.y.max(0.0)) + 1e-6
            } else {
                0.0
            }
        });
        let total_load = load[0] + load[1];
        for (i, leg) in creature.legs.iter().enumerate().take(2) {
            if !servoing(&self.legs[i]) {
                continue;
            }
            let share = if total_load > 0.0 {
                load[i] / total_load
            } else {
                0.0
            };
            let roll_q = data.q[leg.hip[0]];
            through_hip(drives, &leg.hip, roll_q, trunk_rot, posture * share, max);
            // The leg turns on a tiny inertia: only a torque the loaded
            // foot's torsional grip can hold.
            let grip = p.hopper.max_yaw_torque * s.torque() * share;
            drives[leg.hip[2]].torque((-yaw * share).clamp(-grip, grip));
        }
    }
}
