//! Biped running (Raibert & Hodgins 1991, "Gaits" and Figure 4): one-legged
//! hopping control on the active leg while the idle leg is kept short and out
//! of the way. Hopping by the leg spring's rest length and a thrust in stance
//! (eq. 1–2), speed by foot placement (eq. 3), trunk attitude by the active
//! hip in stance (eq. 4).

use glam::DVec3;

use super::additions::Offered;
use super::attitude::{attitude_error, com_state, heading_forward, trunk_rate};
use super::hip_servo::set_hip;
use super::leg_spring::{LegSpring, toward};
use super::phase::Phase;
use super::placement::{foot_displacement, gimbal_angles, leg_direction};
use super::posture::{through_hip, trunk_torque};
use super::scale::Scale;
use super::speed_trim::SpeedTrim;
use crate::creatures::PhysicalCreature;
use crate::world::sim::{ControlInput, Controller, Drive};

/// Parameters of biped running; lengths are leg-spring coordinates
/// (metres of extension, 0 = the leg at full length).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BipedRunParams {
    /// Desired forward speed ẋ_d (m/s).
    pub speed_mps: f64,
    /// Desired heading (rad about +y; 0 = +z).
    pub heading: f64,
    /// Leg spring stiffness k (N/m) and damping b (N·s/m), eq. 1.
    pub leg_stiffness: f64,
    /// Leg spring damping (N·s/m).
    pub leg_damping: f64,
    /// How far the telescoping leg can shorten from full length (m).
    pub leg_travel_m: f64,
    /// Rest length for landing (m of extension).
    pub landing_rest_m: f64,
    /// Extra rest length during thrust (m).
    pub thrust_m: f64,
    /// Rest length of the shortened idle leg (m of extension).
    pub idle_rest_m: f64,
    /// Desired hop height: apex of the hip above its lift-off height (m).
    pub hop_height_m: f64,
    /// How much each hop's apex error changes the thrust (m of thrust per m).
    pub hop_gain: f64,
    /// Foot placement gain k_ẋ (s), eq. 3.
    pub placement_gain_s: f64,
    /// The lab's integral speed trim on (`lab_additions.speed_trim`; not
    /// in the paper), with gain `speed_integral_gain`.
    pub speed_trim: bool,
    /// Integral gain on each step's speed error (per step), while the speed
    /// trim is on.
    pub speed_integral_gain: f64,
    /// Keep eq. 4's posture servo on in Unloading: the lab's addition
    /// (`lab_additions.unloading_posture`); Figure 4 zeroes the active hip's
    /// torque there.
    pub unloading_posture: bool,
    /// Hip servo gains for positioning legs (N·m/rad, N·m·s/rad).
    pub swing_kp: f64,
    /// Hip swing damping (N·m·s/rad).
    pub swing_kv: f64,
    /// Posture servo gains of eq. 4 (N·m/rad, N·m·s/rad).
    pub posture_kp: f64,
    /// Posture damping (N·m·s/rad).
    pub posture_kv: f64,
    /// Trunk yaw servo in stance, through the hip's yaw joint (N·m/rad, N·m·s/rad).
    pub yaw_kp: f64,
    /// Trunk yaw damping in stance (N·m·s/rad).
    pub yaw_kv: f64,
    /// Servo of the leg's own yaw joint in flight; the leg spins on a tiny
    /// inertia, so these are small (N·m/rad, N·m·s/rad).
    pub leg_yaw_kp: f64,
    /// Leg yaw damping in flight (N·m·s/rad).
    pub leg_yaw_kv: f64,
    /// Largest hip torque (N·m).
    pub max_hip_torque: f64,
    /// Largest trunk-yaw torque through the stance leg's yaw joint (N·m).
    pub max_yaw_torque: f64,
    /// How fast a leg's rest length may change (m/s): a leg snapped short
    /// would jerk the trunk through the offset hips.
    pub leg_rate_mps: f64,
}

impl BipedRunParams {
    /// The lab's additions this controller has: the speed trim (off: eq. 3
    /// alone holds the speed) and Unloading's posture servo (on for a file
    /// that does not say, as files of 2026-12-02 ran).
    pub const LAB_ADDITIONS: Offered = Offered {
        speed_trim: Some(false),
        unloading_posture: Some(true),
        ..Offered::NONE
    };
}

impl Default for BipedRunParams {
    fn default() -> Self {
        Self {
            speed_mps: 1.5,
            heading: 0.0,
            leg_stiffness: 20_000.0,
            leg_damping: 20.0,
            leg_travel_m: 0.25,
            landing_rest_m: -0.03,
            thrust_m: 0.03,
            idle_rest_m: -0.18,
            hop_height_m: 0.10,
            hop_gain: 0.3,
            placement_gain_s: 0.12,
            speed_trim: false,
            speed_integral_gain: 0.1,
            unloading_posture: true,
            swing_kp: 150.0,
            swing_kv: 8.0,
            posture_kp: 1000.0,
            posture_kv: 160.0,
            yaw_kp: 200.0,
            yaw_kv: 20.0,
            leg_yaw_kp: 2.0,
            leg_yaw_kv: 0.1,
            max_hip_torque: 400.0,
            max_yaw_torque: 30.0,
            leg_rate_mps: 1.0,
        }
    }
}

impl BipedRunParams {
    /// The defaults before the lab's additions were optional (files without
    /// `lab_additions` run with these): eq. 3's gain 0.05 s, held to the
    /// desired speed by the speed trim at gain 0.3, posture servo on in
    /// Unloading. (With eq. 3's gain now 0.12 s, a trim at 0.3 makes the
    /// biped blow up at 2.5 m/s within a minute; its default is 0.1.)
    #[must_use]
    pub fn before_lab_additions() -> Self {
        Self {
            placement_gain_s: 0.05,
            speed_trim: true,
            speed_integral_gain: 0.3,
            unloading_posture: true,
            ..Self::default()
        }
    }
}

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
    apex_height: f64,
    thrust: f64,
    descending: bool,
    /// The lab's speed trim (zero unless `speed_trim`), measured from one
    /// lift-off to the next.
    trim: SpeedTrim,
    /// Each leg's rest length as it moves toward its target (m).
    rest: [f64; 2],
    /// Each leg's hip-to-foot length at full extension (m, scaled).
    leg_m: [f64; 2],
    /// Table 1's factors for the creature's L.
    scale: Scale,
}

impl BipedRun {
    /// A controller for `creature` (its scale and leg lengths), starting in
    /// flight with leg 0 active.
    #[must_use]
    pub fn new(params: BipedRunParams, creature: &PhysicalCreature) -> Self {
        let scale = creature.scale;
        let leg_m = [0, 1].map(|i| creature.leg_length_m(i));
        Self {
            params,
            phase: Phase::Flight,
            active: 0,
            stance_s: 0.18 * scale.sqrt(),
            touchdown_time: 0.0,
            liftoff_height: 0.0,
            apex_height: f64::NEG_INFINITY,
            thrust: params.thrust_m * scale,
            descending: true,
            trim: SpeedTrim::default(),
            rest: [params.landing_rest_m * scale, params.idle_rest_m * scale],
            leg_m,
            scale: Scale::new(scale),
        }
    }

    fn advance_phase(&mut self, input: &ControlInput<'_>) {
        let leg = &input.creature.legs[self.active];
        let contact = input.contacts[self.active];
        let q = input.data.q[leg.spring];
        let qd = input.data.qd[leg.spring];
        let trunk_y = input.data.world[input.creature.trunk].pos.y;
        let p = &self.params;
        let (l, t) = (self.scale.length(), self.scale.time());
        match self.phase {
            Phase::Flight => {
                self.apex_height = self.apex_height.max(trunk_y);
                self.descending = self.descending
                    || input.data.world[input.creature.trunk].pos.y < self.apex_height - 0.002 * l;
                if contact.touching && self.descending {
                    self.phase = Phase::Loading;
                    self.touchdown_time = input.time;
                }
            }
            Phase::Loading if q < (p.landing_rest_m - 0.005) * l => self.phase = Phase::Compression,
            Phase::Compression if qd >= 0.0 => self.phase = Phase::Thrust,
            Phase::Thrust
                if q >= p.landing_rest_m * l + self.thrust - 0.01 * l || q >= -0.005 * l =>
            {
                self.phase = Phase::Unloading;
            }
            _ => {}
        }
        // Lift-off ends a stance only once the leg has thrust; a foot that
        // bounces off the ground at impact is still landing.
        if matches!(self.phase, Phase::Thrust | Phase::Unloading) && !contact.touching {
            // Lift-off: the legs swap, the hop's apex adjusts the thrust (eq. 2).
            self.stance_s = (input.time - self.touchdown_time).clamp(0.05 * t, 0.5 * t);
            if self.apex_height.is_finite() {
                let error = p.hop_height_m * l - (self.apex_height - self.liftoff_height);
                self.thrust = (self.thrust + p.hop_gain * error).clamp(0.0, 0.12 * l);
            }
            self.liftoff_height = trunk_y;
            // Speed over the last step against the desired speed.
            let com = crate::dynamics::energy::center_of_mass(&input.creature.model, input.data);
            let (on, gain) = (p.speed_trim, p.speed_integral_gain);
            let v = self.scale.velocity();
            (self.trim).stride_at_heading(on, gain, p.speed_mps, v, input.time, com, p.heading);
            self.apex_height = f64::NEG_INFINITY;
            self.active = 1 - self.active;
            self.phase = Phase::Flight;
            self.descending = false;
        }
    }
}

impl Controller for BipedRun {
    crate::tunable_gains!(BipedRunParams;
        leg_stiffness => "N/m", leg_damping => "N·s/m", posture_kp => "N·m/rad", posture_kv => "N·m·s/rad",
        placement_gain_s => "s", swing_kp => "N·m/rad", swing_kv => "N·m·s/rad");

    fn phase_name(&self) -> &'static str {
        self.phase.name()
    }

    fn set_speed(&mut self, speed_mps: f64) {
        self.params.speed_mps = speed_mps;
    }

    fn set_heading(&mut self, heading: f64) {
        self.params.heading = heading;
    }

    fn set_hop_height(&mut self, height_m: f64) {
        self.params.hop_height_m = height_m;
    }

    fn hop_height_m(&self) -> Option<f64> {
        Some(self.params.hop_height_m)
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
            let (ykp, ykv) = self.scale.torsional_gains(p.leg_yaw_kp, p.leg_yaw_kv);
            zero_hip(drives, &input.creature.legs[self.active].hip, ykp, ykv);
        }
    }

    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.advance_phase(input);
        let p = self.params;
        let s = self.scale;
        let l = s.l;
        let creature = input.creature;
        let data = input.data;
        let trunk_rot = data.world[creature.trunk].rot;
        let (com, velocity) = com_state(creature, data);
        let desired =
            heading_forward(p.heading) * (p.speed_mps * s.velocity() + self.trim.bias_mps);
        let spring = LegSpring::new(p.leg_stiffness, p.leg_damping, p.leg_travel_m);
        // Leg lengths: the spring of eq. 1 with a programmable rest.
        let step = p.leg_rate_mps * s.velocity() * input.dt;
        for (i, leg) in creature.legs.iter().enumerate().take(2) {
            let target = if i != self.active {
                p.idle_rest_m * l
            } else {
                match self.phase {
                    Phase::Thrust => p.landing_rest_m * l + self.thrust,
                    Phase::Unloading => p.idle_rest_m * l,
                    // Lengthen for landing once the body falls, so the new
                    // active leg does not scuff the ground at lift-off.
                    Phase::Flight if !self.descending => p.idle_rest_m * l,
                    _ => p.landing_rest_m * l,
                }
            };
            self.rest[i] = toward(self.rest[i], target, step);
            spring.apply(&mut drives[leg.spring], self.rest[i], s);
        }
        // The active leg: placed for landing in flight, posture servo in stance.
        let active = &creature.legs[self.active];
        let idle = &creature.legs[1 - self.active];
        let reach = self.leg_m[self.active] + p.landing_rest_m * l;
        let (kp, kv) = s.torsional_gains(p.swing_kp, p.swing_kv);
        let (ykp, ykv) = s.torsional_gains(p.leg_yaw_kp, p.leg_yaw_kv);
        let max = p.max_hip_torque * s.torque();
        match self.phase {
            Phase::Flight => {
                let hip_world = data.world[creature.trunk].rot * active.hip_in_trunk
                    + data.world[creature.trunk].pos;
                let foot = DVec3::new(com.x, 0.0, com.z)
                    + foot_displacement(
                        velocity,
                        desired,
                        self.stance_s,
                        p.placement_gain_s * s.time(),
                    );
                let dir = leg_direction(trunk_rot, foot - hip_world, reach);
                let (roll, pitch) = gimbal_angles(dir);
                set_hip(drives, &active.hip[..2], [roll, pitch], kp, kv, max);
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
        let s = self.scale;
        let creature = input.creature;
        let data = input.data;
        let active = &creature.legs[self.active];
        let trunk_rot = data.world[creature.trunk].rot;
        let max = p.max_hip_torque * s.torque();
        let err = attitude_error(creature, data, p.heading, 0.0);
        let rate = trunk_rate(creature, data);
        let (pkp, pkv) = s.torsional_gains(p.posture_kp, p.posture_kv);
        let torque = trunk_torque(err, rate, pkp, pkv);
        let roll_q = data.q[active.hip[0]];
        through_hip(drives, &active.hip, roll_q, trunk_rot, torque, max);
        // The leg turns on a tiny inertia: only a torque the loaded foot's
        // torsional grip can hold.
        let (ypkp, ypkv) = s.torsional_gains(p.yaw_kp, p.yaw_kv);
        let yaw = -err.y * ypkp - rate.y * ypkv;
        let grip = p.max_yaw_torque * s.torque();
        drives[active.hip[2]].torque((-yaw).clamp(-grip, grip));
    }
}

/// Zero the roll and pitch torques of a ball hip; its yaw joint keeps the
/// leg's own orientation (gains `ykp`, `ykv`).
fn zero_hip(drives: &mut [Drive], hip: &[usize], ykp: f64, ykv: f64) {
    for &j in &hip[..2] {
        drives[j].torque(0.0);
    }
    drives[hip[2]].servo(ykp, ykv, 0.0);
}
