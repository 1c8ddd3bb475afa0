//! The physics engine as a gaitlab driver (DESIGN.md "Data flow"): a preset's
//! creature simulated under its gait's controller on the fixed-step loop of
//! [`crate::world::sim`], read out as a [`Pose`] every frame, with the Table-2
//! figures of [`crate::engine::metrics`] and a guard that resets the creature and
//! says why when the simulation blows up (Raibert & Hodgins 1991, Figure 2).

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::physics::{PhysicsStart, check_hop_height_m, check_speed_mps};
use gaitlab_core::preset::{Creature as PresetCreature, PhysicsParams, PresetError};
use gaitlab_core::{Effector, Joint, JointKind, Pose, RootTransform, Skeleton};
use glam::{DMat3, DVec3};

use crate::control::additions::Additions;
use crate::control::gaits::controller::GaitController;
use crate::control::gaits::kangaroo_hop::jumps::QueuedJump;
use crate::control::gaits::kangaroo_hop::kangaroo_ground;
use crate::control::gaits::kangaroo_hop::{KangarooHop, KangarooHopParams};
use crate::control::gaits::make::make_controller;
use crate::control::gaits::table::gait_names;
use crate::control::laws::scale::Scale;
use crate::creatures::Species;
use crate::dynamics::model::Joint as BodyJoint;
use crate::engine::consistency;
use crate::engine::cycle_start::on_cycle;
use crate::engine::gait_change::{Entry, GaitChange, MAX_GAIT_CHANGES};
use crate::engine::gait_entry::enter_at_start;
use crate::engine::metrics::{GaitRecorder, GaitSummary};
use crate::engine::preset::creature_from_preset;
use crate::engine::probe::{self, PhysicsProbe};
use crate::engine::push::Push;
use crate::engine::steering::Steering;
use crate::world::commands::Commands;
use crate::world::ground::{GroundParams, Obstacle};
use crate::world::sim::{ControlInput, Controller, Sim, SimOptions};

/// Seconds after a fall before the creature is put back at the start.
pub const FALL_RESET_S: f64 = 1.5;

/// How many put-backs a run lists (a creature the app leaves failing for
/// hours must not grow the list without end); [`PhysicsDriver::resets`]
/// counts them all.
pub const MAX_PUT_BACKS: usize = 100;

/// How many pushes a run keeps with their recoveries.
pub const MAX_PUSHES: usize = 100;

/// The largest push [`PhysicsDriver::push`] takes, per axis (m/s).
pub const MAX_PUSH_MPS: f64 = 10.0;

/// One time the guard put the creature back at the start.
#[derive(Clone, Debug, PartialEq)]
pub struct PutBack {
    /// When, in seconds of the whole run (the simulation clock restarts
    /// with the creature; this one does not).
    pub run_time_s: f64,
    /// Why: the blow-up or the fall, with the time on the clock of the
    /// attempt it ended.
    pub why: String,
}

/// A physics creature running under control, seen as a [`Driver`].
#[derive(Clone, Debug)]
pub struct PhysicsDriver {
    skeleton: Skeleton,
    start_root: DVec3,
    params: PhysicsParams,
    /// The gait asked for last (a switch to it may still be waiting).
    gait: String,
    /// The gait of the controller that runs now.
    running_gait: String,
    /// The lab's additions resolved for `gait`.
    additions: Additions,
    sim: Sim,
    start: Sim,
    /// The controller a restart begins with, where the start carries its
    /// state (a start on the cycle); else a fresh one is made.
    start_controller: Option<GaitController>,
    /// Why a start on the cycle asked for was not found, if it was not.
    start_note: Option<String>,
    controller: GaitController,
    recorder: GaitRecorder,
    pose: Pose,
    effectors: Vec<DVec3>,
    fell_at: Option<f64>,
    /// The desired heading and the waypoint being steered to.
    steering: Steering,
    /// A controller waiting for the next flight to take over (a gait change).
    pending: Option<GaitController>,
    /// Whether a fall puts the creature back at the start after
    /// [`FALL_RESET_S`] (the app's choice; a measuring run turns it off).
    /// Meanwhile the fallen creature is held as it was when the fall was
    /// seen, so it never sinks through the ground it has no contact with.
    pub reset_after_fall: bool,
    /// Seconds (of `dt`) the fallen creature has been held, while
    /// `reset_after_fall`.
    held_s: f64,
    /// The desired speed (m/s at scale 1) and hop height (m) the run
    /// started with: a put-back restores them, so a speed that made the
    /// creature fall does not make it fall again at once.
    start_speed_mps: f64,
    start_hop_height_m: Option<f64>,
    message: Option<String>,
    resets: u32,
    /// The first [`MAX_PUT_BACKS`] put-backs since the run began or was
    /// reset, in order.
    put_backs: Vec<PutBack>,
    /// Seconds of the run before the current attempt began.
    attempt_start_s: f64,
    /// The pushes of the run, in order ([`PhysicsDriver::push`]).
    pushes: Vec<Push>,
    /// The gait changes that took effect, in order (the first
    /// [`MAX_GAIT_CHANGES`]).
    gait_changes: Vec<GaitChange>,
}

fn scaled_skeleton(skeleton: &Skeleton, l: f64) -> Result<Skeleton, PresetError> {
    let joints: Vec<Joint> = skeleton
        .joints()
        .iter()
        .map(|j| {
            let mut j = j.clone();
            j.offset *= l;
            j.size *= l;
            if j.kind == JointKind::Prismatic {
                j.limits = j.limits.map(|(a, b)| (a * l, b * l));
                j.rest *= l;
                j.center *= l;
            }
            j
        })
        .collect();
    let effectors: Vec<Effector> = skeleton
        .effectors()
        .iter()
        .map(|e| Effector {
            offset: e.offset * l,
            ..e.clone()
        })
        .collect();
    Skeleton::new(joints, effectors).map_err(|e| PresetError::new("skeleton", e.to_string()))
}

impl PhysicsDriver {
    /// The driver of a preset whose engine is `physics`, with the preset's gait.
    ///
    /// # Errors
    /// A [`PresetError`] when the physics section is missing or wrong, or the
    /// gait is not one of the model's.
    pub fn new(preset: &PresetCreature) -> Result<Self, PresetError> {
        let params = preset.scenario.physics.clone().ok_or_else(|| {
            PresetError::new(
                "scenario.physics",
                "engine \"physics\" needs the creature's physical model",
            )
        })?;
        Self::with_params(preset, params)
    }

    /// The driver with `params` in place of the preset's physics section.
    ///
    /// # Errors
    /// As [`PhysicsDriver::new`].
    pub fn with_params(
        preset: &PresetCreature,
        params: PhysicsParams,
    ) -> Result<Self, PresetError> {
        let mut with = preset.clone();
        with.scenario.physics = Some(params.clone());
        let creature = creature_from_preset(&with)?;
        consistency::check_structure(&with, &params)?;
        let l = params.scale;
        let names = gait_names(creature.species);
        let gait = params
            .gait
            .clone()
            .or_else(|| names.first().map(|s| (*s).to_owned()))
            .unwrap_or_default();
        let controller = make_controller(&creature, &gait, &params)?;
        let skeleton = scaled_skeleton(&preset.skeleton, l)?;
        let start_q: Vec<f64> = skeleton.rest_values();
        let start_root = preset.root_position * l;
        let options = SimOptions {
            dt: params.dt_s * Scale::new(l).time(),
            control_every: params.control_every,
            ..SimOptions::default()
        };
        let mut ground = match creature.species {
            Species::Kangaroo => kangaroo_ground(),
            _ => GroundParams::default(),
        };
        if let Some(spec) = &params.ground {
            let set = |slot: &mut f64, value: Option<f64>| *slot = value.unwrap_or(*slot);
            set(&mut ground.vertical_stiffness, spec.vertical_stiffness);
            set(&mut ground.vertical_damping, spec.vertical_damping);
            set(&mut ground.tangential_stiffness, spec.tangential_stiffness);
            set(&mut ground.tangential_damping, spec.tangential_damping);
        }
        let ground = ground.scaled(l);
        let mut sim = Sim::new(creature, ground, options);
        sim.commands = starting_commands(&params);
        // The ground's shape (issue 45): the springs act along its normal;
        // the engine layer's `driver_for` lets the gaits made for it onto it.
        sim.terrain.surface = preset.scenario.terrain.clone();
        for o in &params.obstacles {
            sim.terrain.obstacles.push(Obstacle {
                min_xz: [-10.0 * l, o.at_m * l],
                max_xz: [10.0 * l, (o.at_m + o.depth_m) * l],
                height_m: o.height_m * l,
            });
        }
        if sim.creature.model.free_base() {
            sim.data.base_position = start_root;
            sim.data.base_velocity.linear =
                DVec3::new(0.0, 0.0, params.speed_mps * Scale::new(l).velocity());
        } else if let Some(v) = sim.data.qd.first_mut() {
            *v = params.speed_mps * Scale::new(l).velocity();
        }
        sim.data.q.copy_from_slice(&start_q);
        controller.start(&mut sim, params.speed_mps);
        crate::dynamics::kinematics::kinematics(&sim.creature.model, &mut sim.data);
        lift_above_ground(&mut sim);
        consistency::check_start(&sim.creature, &sim.data, &sim.terrain)?;
        let mut controller = controller;
        let mut start_controller = None;
        let mut message = None;
        if params.start == PhysicsStart::OnCycle {
            match on_cycle(&sim, &controller, params.speed_mps) {
                Some(Ok((settled, resumed))) => {
                    sim = settled;
                    controller = resumed;
                    start_controller = Some(controller.clone());
                }
                Some(Err(why)) => {
                    message = Some(format!(
                        "start: no start on the gait's cycle ({why}); the gait's own start instead"
                    ));
                }
                None => {}
            }
        }
        let legs = sim.creature.legs.len();
        let (start_speed_mps, start_hop_height_m) = (params.speed_mps, params.hop_height_m);
        let mut driver = Self {
            pose: Pose {
                root: RootTransform {
                    position: start_root,
                    rotation: DMat3::IDENTITY,
                },
                joints: start_q.clone(),
            },
            effectors: vec![DVec3::ZERO; skeleton.effector_count()],
            skeleton,
            start_root,

            recorder: GaitRecorder::new(
                legs,
                params.speed_mps * Scale::new(l).velocity(),
                0.0,
                3.0 * Scale::new(l).time(),
            ),
            additions: controller.additions(),
            params,
            running_gait: gait.clone(),
            gait,
            start: sim.clone(),
            start_controller,
            start_note: message.clone(),
            sim,
            controller,
            fell_at: None,
            steering: Steering::default(),
            pending: None,
            reset_after_fall: true,
            held_s: 0.0,
            start_speed_mps,
            start_hop_height_m,
            message,
            resets: 0,
            put_backs: Vec::new(),
            attempt_start_s: 0.0,
            pushes: Vec::new(),
            gait_changes: Vec::new(),
        };
        driver.update_pose();
        Ok(driver)
    }

    fn update_pose(&mut self) {
        let data = &self.sim.data;
        let model = &self.sim.creature.model;
        self.pose.joints.copy_from_slice(&data.q);
        if model.free_base() {
            self.pose.root.position = data.base_position;
            self.pose.root.rotation = DMat3::from_quat(data.base_orientation.normalize());
        } else {
            // A planar base's leading slides move the whole creature: shown as
            // root motion (the same world positions, and BVH root channels).
            self.pose.root.position = self.start_root;
            self.pose.root.rotation = DMat3::IDENTITY;
            for (i, body) in model.bodies().iter().enumerate() {
                let (BodyJoint::Prismatic(axis), Some(k)) = (body.joint, model.dof_of(i)) else {
                    break;
                };
                let chained = body.parent.is_none_or(|p| p + 1 == i);
                if !chained || body.mass > 0.0 || body.placement.rot != DMat3::IDENTITY {
                    break;
                }
                self.pose.root.position += axis * data.q[k];
                self.pose.joints[k] = 0.0;
            }
        }
        let offset = usize::from(model.free_base());
        for (e, out) in self.skeleton.effectors().iter().zip(&mut self.effectors) {
            *out = data.point_world(e.joint + offset, e.offset);
        }
    }

    /// The simulation (state, creature, contacts).
    #[must_use]
    pub fn sim(&self) -> &Sim {
        &self.sim
    }

    /// The creature's legs by name, in leg order (Table 2's per-pair rows
    /// and the gait metrics name them).
    pub fn leg_names(&self) -> impl Iterator<Item = &str> + Clone {
        self.sim.creature.legs.iter().map(|l| l.name.as_str())
    }

    /// The gait asked for last (a take-over may still be waiting for it).
    #[must_use]
    pub fn gait(&self) -> &str {
        &self.gait
    }

    /// The gaits a switch enters at their own start where the creature is
    /// (`scenario.physics.switch_to_start`, the lab's); the others are taken
    /// over at the next flight, as the paper's.
    #[must_use]
    pub fn switch_to_start(&self) -> &[String] {
        &self.params.switch_to_start
    }

    /// The gait whose controller runs now.
    #[must_use]
    pub fn running_gait(&self) -> &str {
        &self.running_gait
    }

    /// The physics parameters in use.
    #[must_use]
    pub fn params(&self) -> &PhysicsParams {
        &self.params
    }

    /// The lab's additions the gait's controller uses, by their preset
    /// names (`scenario.physics.lab_additions`), resolved when the gait was
    /// chosen; none when it runs the paper's laws only.
    pub fn lab_additions(&self) -> impl Iterator<Item = &'static str> + Clone + use<> {
        self.additions.names()
    }

    /// Every lab addition in force for the run: the gait controller's
    /// ([`Self::lab_additions`]) and `switch_to_start` where the preset
    /// enters some gait at its own start on a switch (not the paper's
    /// take-over at the next flight). What `--json` and the page list.
    pub fn lab_additions_in_force(&self) -> impl Iterator<Item = &'static str> + Clone + use<> {
        let switch = (!self.params.switch_to_start.is_empty()).then_some("switch_to_start");
        self.additions.names().chain(switch)
    }

    /// The state machine's state.
    #[must_use]
    pub fn phase_name(&self) -> &'static str {
        self.controller.phase_name()
    }

    /// The state of leg `leg`'s own state machine where the controller runs
    /// one per leg (the biped gallop, the trot) or per pair (the bound and
    /// quadruped gallop); else the controller's state ([`Self::phase_name`]).
    #[must_use]
    pub fn leg_phase_name(&self, leg: usize) -> &'static str {
        self.controller
            .leg_phase_name(leg)
            .unwrap_or_else(|| self.controller.phase_name())
    }

    /// The whole creature's centre of mass in the world, metres.
    #[must_use]
    pub fn centre_of_mass(&self) -> DVec3 {
        crate::dynamics::energy::center_of_mass(&self.sim.creature.model, &self.sim.data)
    }

    /// The trunk of a free-floating creature as a capsule `(a, b, radius)` in
    /// the world (see [`probe::trunk_capsule`]).
    #[must_use]
    pub fn trunk_capsule(&self) -> Option<(DVec3, DVec3, f64)> {
        probe::trunk_capsule(&self.sim)
    }

    /// A snapshot of the trunk, first leg, ground force and state for plots.
    #[must_use]
    pub fn probe(&self) -> PhysicsProbe {
        probe::probe(&self.sim, self.controller.phase_name())
    }

    /// The Table-2 figures since the last reset.
    #[must_use]
    pub fn summary(&self) -> GaitSummary {
        self.recorder.summary()
    }

    /// Whether the creature has fallen since the figures started (the
    /// recorder's flag: cheap, where [`Self::summary`] computes every figure).
    #[must_use]
    pub fn fell(&self) -> bool {
        self.recorder.fell()
    }

    /// Start the Table-2 figures afresh from now (no settling time): for
    /// measuring after a speed change has settled.
    pub fn clear_metrics(&mut self) {
        let legs = self.sim.creature.legs.len();
        self.recorder = GaitRecorder::new(
            legs,
            self.params.speed_mps * Scale::new(self.params.scale).velocity(),
            0.0,
            self.sim.time,
        );
    }

    /// Why the creature was last put back at the start (a blow-up or a fall),
    /// until the next [`PhysicsDriver::take_message`].
    #[must_use]
    pub fn message(&self) -> Option<&str> {
        self.message.as_deref()
    }

    /// Read and clear the message.
    pub fn take_message(&mut self) -> Option<String> {
        self.message.take()
    }

    /// Whether the run started on the gait's cycle
    /// ([`crate::engine::cycle_start`]).
    #[must_use]
    pub fn started_on_cycle(&self) -> bool {
        self.start_controller.is_some()
    }

    /// Why the start on the cycle the preset asks for was not found (the
    /// run then starts from the gait's own start); `None` when it was, or
    /// was not asked for.
    #[must_use]
    pub fn start_note(&self) -> Option<&str> {
        self.start_note.as_deref()
    }

    /// The controller running now (after a gait change, the new one's once
    /// it has taken over).
    #[must_use]
    pub fn controller(&self) -> &GaitController {
        &self.controller
    }

    /// The running gait's virtual legs ([`GaitController::virtual_legs`]).
    #[must_use]
    pub fn virtual_legs(&self) -> &'static [[usize; 2]] {
        self.controller.virtual_legs()
    }

    /// How many times the creature was put back after a blow-up or a fall.
    #[must_use]
    pub fn resets(&self) -> u32 {
        self.resets
    }

    /// The put-backs since the run began (or was last reset), each with
    /// the run's own time: the first [`MAX_PUT_BACKS`] of them.
    #[must_use]
    pub fn put_backs(&self) -> &[PutBack] {
        &self.put_backs
    }

    /// Seconds since the run began or was last reset, across put-backs.
    #[must_use]
    pub fn run_time_s(&self) -> f64 {
        self.attempt_start_s + self.sim.time
    }

    /// Push the creature: change its trunk's horizontal velocity by
    /// `dv_mps` = [x (sideways), z (forward at heading 0)] m/s, in the world
    /// frame, now — the whole creature's velocity, as an impulse on its body
    /// gives it at once ([`super::push`]). The recovery is judged over the
    /// next [`RECOVERY_S`](super::push::RECOVERY_S) seconds ([`Self::pushes`]).
    ///
    /// # Errors
    /// `push: reason` for a change that is not finite or above 10 m/s, or
    /// a sideways one on a planar creature (the kangaroo); nothing changes.
    pub fn push(&mut self, dv_mps: [f64; 2]) -> Result<(), String> {
        if !dv_mps
            .iter()
            .all(|v| v.is_finite() && v.abs() <= MAX_PUSH_MPS)
        {
            return Err(format!(
                "push: {dv_mps:?} must be two finite speeds within ±{MAX_PUSH_MPS} m/s"
            ));
        }
        let data = &mut self.sim.data;
        if self.sim.creature.model.free_base() {
            let world = DVec3::new(dv_mps[0], 0.0, dv_mps[1]);
            data.base_velocity.linear += data.base_orientation.inverse() * world;
        } else if dv_mps[0] != 0.0 {
            return Err(format!(
                "push: this creature is planar (forward and up only): a sideways push ({} m/s) has nowhere to go",
                dv_mps[0]
            ));
        } else if let Some(v) = data.qd.first_mut() {
            *v += dv_mps[1];
        }
        if self.pushes.len() < MAX_PUSHES {
            let desired = self.params.speed_mps * Scale::new(self.params.scale).velocity();
            let forward = crate::control::laws::attitude::heading_forward(self.heading());
            self.pushes
                .push(Push::new(self.run_time_s(), dv_mps, desired, forward));
        }
        Ok(())
    }

    /// The run's pushes with their recoveries, in order (the first
    /// [`MAX_PUSHES`]).
    #[must_use]
    pub fn pushes(&self) -> &[Push] {
        &self.pushes
    }

    fn watch_pushes(&mut self) {
        let now = self.run_time_s();
        if !self.pushes.iter().any(|p| p.open(now)) {
            return;
        }
        let fell = self
            .fell_at
            .map(|t| self.attempt_start_s + t)
            .or_else(|| self.put_backs.last().map(|p| p.run_time_s));
        let com = self.centre_of_mass();
        for p in &mut self.pushes {
            p.observe(now, com, fell);
        }
    }

    /// Put the creature back at the start after a blow-up or a fall,
    /// recording when and why, with the speed and hop height the run
    /// started with.
    fn put_back(&mut self, mut why: String) {
        let run_time_s = self.run_time_s();
        if self.params.speed_mps != self.start_speed_mps
            || self.params.hop_height_m != self.start_hop_height_m
        {
            self.params.speed_mps = self.start_speed_mps;
            self.params.hop_height_m = self.start_hop_height_m;
            why.push_str(&format!(
                ", at its starting speed of {:.2} m/s",
                self.start_speed_mps
            ));
        }
        self.attempt_start_s = run_time_s;
        if self.put_backs.len() < MAX_PUT_BACKS {
            self.put_backs.push(PutBack {
                run_time_s,
                why: why.clone(),
            });
        }
        self.restart(why);
    }

    /// Whether no step has run since the start (or a reset): a command now
    /// is the run's starting command.
    fn at_start(&self) -> bool {
        self.sim.time == 0.0
    }

    /// Change the desired speed (m/s at scale 1) while running.
    ///
    /// # Errors
    /// `speed_mps: reason` outside the preset's range
    /// ([`gaitlab_core::preset::physics::check_speed_mps`]); nothing changes.
    pub fn set_speed(&mut self, speed_mps: f64) -> Result<(), PresetError> {
        check_speed_mps("speed_mps", speed_mps)?;
        if self.at_start() {
            self.start_speed_mps = speed_mps;
        }
        self.params.speed_mps = speed_mps;
        self.sim.commands.speed_mps = speed_mps;
        self.recorder.speed_desired_mps = speed_mps * Scale::new(self.params.scale).velocity();
        Ok(())
    }

    /// Change the desired hop height (m at scale 1) while running.
    ///
    /// # Errors
    /// `hop_height_m: reason` outside the preset's range
    /// ([`gaitlab_core::preset::physics::HOP_HEIGHT_RANGE_M`]); nothing changes.
    pub fn set_hop_height(&mut self, height_m: f64) -> Result<(), PresetError> {
        check_hop_height_m("hop_height_m", height_m)?;
        if self.at_start() {
            self.start_hop_height_m = Some(height_m);
        }
        self.params.hop_height_m = Some(height_m);
        self.sim.commands.hop_height_m = Some(height_m);
        Ok(())
    }

    /// The hop height the controller regulates now (m at scale 1): the
    /// command's, else the gait's own — the biped's and kangaroo's apex
    /// rise, the trot's and bound's flight as the apex it reaches (eq. 2).
    #[must_use]
    pub fn hop_height_m(&self) -> Option<f64> {
        (self.sim.commands.hop_height_m).or_else(|| self.controller.hop_height_m())
    }

    /// The creature as a MuJoCo model (see [`crate::engine::mjcf`]): its springs and
    /// hip torque limits as the controller sets them at the start.
    #[must_use]
    pub fn mjcf(&self, name: &str) -> String {
        let mut probe = self.start.clone();
        let mut controller = self.controller.clone();
        // One step lets the controller set its springs and servos.
        let _ = probe.step(&mut controller);
        let creature = &probe.creature;
        let mut spring_joints: Vec<usize> = creature.legs.iter().map(|l| l.spring).collect();
        spring_joints.extend(&creature.tail);
        let springs = spring_joints
            .iter()
            .map(|&k| {
                let s = probe.drives[k].spring;
                (k, s.stiffness, s.damping, s.rest)
            })
            .collect();
        let hip_torque_limit = creature
            .legs
            .iter()
            .flat_map(|l| l.hip.iter())
            .map(|&k| probe.drives[k].spring.max_force)
            .filter(|m| m.is_finite())
            .fold(0.0, f64::max);
        let options = crate::engine::mjcf::MjcfOptions {
            name: name.to_owned(),
            timestep_s: self.sim.options.dt,
            root_position: if creature.model.free_base() {
                self.start.data.base_position
            } else {
                DVec3::ZERO
            },
            springs,
            hip_torque_limit: if hip_torque_limit > 0.0 {
                hip_torque_limit
            } else {
                400.0 * self.params.scale.powi(4)
            },
            ground: self.sim.ground,
            terrain: self.sim.terrain.surface.clone(),
        };
        crate::engine::mjcf::to_mjcf(creature, &options)
    }

    /// The running controller's tunable gains.
    #[must_use]
    pub fn gains(&self) -> Vec<crate::world::sim::Gain> {
        self.controller.gains()
    }

    /// The running controller's parameter `name` (a `controller` key of the
    /// preset, at scale 1); `None` when it has none of that name.
    #[must_use]
    pub fn parameter(&self, name: &str) -> Option<f64> {
        self.controller.parameter(name)
    }

    /// The names [`PhysicsDriver::parameter`] takes.
    #[must_use]
    pub fn parameter_names(&self) -> &'static [&'static str] {
        self.controller.parameter_names()
    }

    /// Set one of [`PhysicsDriver::gains`] by name (finite, ≥ 0; no upper
    /// limit: an absurd gain blows up and the guard resets the creature).
    ///
    /// # Errors
    /// `gain.NAME: reason` for an unknown gain or a negative or non-finite value.
    pub fn set_gain(&mut self, name: &str, value: f64) -> Result<(), String> {
        if self.controller.set_gain(name, value) {
            Ok(())
        } else if self.controller.gains().iter().any(|g| g.name == name) {
            Err(format!("gain.{name}: must be a finite number ≥ 0"))
        } else {
            let names: Vec<&str> = self.controller.gains().iter().map(|g| g.name).collect();
            Err(format!(
                "gain.{name}: no such gain (this controller has: {})",
                names.join(", ")
            ))
        }
    }

    /// Put a box on the ground `distance_m` (m at scale 1) ahead of the
    /// kangaroo and have it jump it: the paper's animator input "when and how
    /// high to jump" (Figure 2), taken by the jump's extra states. Returns
    /// where the box's near face is (m along the way, at scale 1).
    ///
    /// # Errors
    /// `obstacle: …` when the gait has no jump (only the kangaroo's hop does)
    /// or the distance is not in [1, 20] m.
    pub fn place_obstacle_ahead(&mut self, distance_m: f64) -> Result<f64, String> {
        if !(distance_m.is_finite() && (1.0..=20.0).contains(&distance_m)) {
            return Err(format!(
                "obstacle: {distance_m} m ahead is not in [1, 20] m"
            ));
        }
        let Some(kangaroo) = self.controller.get_mut::<KangarooHop>() else {
            return Err(format!(
                "obstacle: the {} has no jump (the paper adds jump states to the kangaroo's hop only)",
                self.gait
            ));
        };
        let l = self.params.scale;
        let com = crate::dynamics::energy::center_of_mass(&self.sim.creature.model, &self.sim.data);
        let at_m = com.z / l + distance_m;
        // The box of the controller's own size (0.25 m high, 0.3 m deep),
        // whatever box a file gave before it.
        let size = KangarooHopParams::default();
        let jump = QueuedJump {
            at_m,
            depth_m: size.obstacle_depth_m,
            height_m: size.obstacle_height_m,
        };
        self.sim.terrain.obstacles.push(Obstacle {
            min_xz: [-10.0 * l, at_m * l],
            max_xz: [10.0 * l, (at_m + jump.depth_m) * l],
            height_m: jump.height_m * l,
        });
        kangaroo.jump_over(jump);
        Ok(at_m)
    }

    /// Follow `waypoints` (`[x, z]`, m at scale 1) from the first: the
    /// steering aims at each in turn (Raibert & Hodgins 1991, "simple
    /// paths"); an empty path keeps the present heading.
    ///
    /// # Errors
    /// `waypoints: at most 64 waypoints` or `waypoints[i]: …` for a point out
    /// of range; nothing changes.
    pub fn set_waypoints(&mut self, waypoints: &[[f64; 2]]) -> Result<(), PresetError> {
        gaitlab_core::preset::physics::check_waypoints("waypoints", waypoints)?;
        self.params.waypoints = waypoints.to_vec();
        self.steering.waypoint = 0;
        Ok(())
    }

    /// The path being followed (`[x, z]`, m at scale 1).
    #[must_use]
    pub fn waypoints(&self) -> &[[f64; 2]] {
        &self.params.waypoints
    }

    /// Change gait while running: the new controller takes over at the next
    /// falling flight, or, for a gait `switch_to_start` names, at once from
    /// that gait's own start where the creature is. The gait already
    /// running, asked for again, runs on with its
    /// state: a fresh controller would forget what the running one has
    /// learned (the kangaroo's apex correction and measured stance, with
    /// which it holds 5 m/s; taken over by a fresh one it tumbles within
    /// 3–6 s).
    ///
    /// # Errors
    /// The gait is not one of this model's.
    pub fn set_gait(&mut self, gait: &str) -> Result<(), PresetError> {
        let mut params = self.params.clone();
        params.gait = Some(gait.to_owned());
        let next = make_controller(&self.sim.creature, gait, &params)?;
        self.additions = next.additions();
        let to_start = params.switch_to_start.iter().any(|g| g == gait);
        if gait == self.running_gait {
            // The running gait runs on, and a switch still waiting is dropped.
            self.pending = None;
        } else if to_start {
            // The lab's entry at the gait's own start, now.
            let heading = self.steering.heading;
            enter_at_start(&mut self.sim, &next, params.speed_mps, heading);
            self.record_change(next.gait(), Entry::OwnStart);
            self.controller = next;
            self.running_gait = gait.to_owned();
            self.pending = None;
        } else {
            // Another state machine takes over at the next flight, when no
            // foot is loaded and the body is falling toward a landing — the
            // state every controller starts from — and takes over from the
            // state it finds. Bound and gallop too: the other style's
            // controller, with its own gains, starts from the running one's
            // measured stance (handed its thrust, tuned on the other style's
            // springs, it tumbled).
            self.pending = Some(next);
        }
        self.params = params;
        self.gait = gait.to_owned();
        Ok(())
    }

    /// Turn the desired heading toward `heading` (rad about +y; 0 = +z) at
    /// [`TURN_RATE_RAD_S`](crate::engine::steering::TURN_RATE_RAD_S). Waypoints, if any,
    /// take over again at the next frame.
    pub fn set_heading(&mut self, heading: f64) {
        if heading.is_finite() {
            self.steering.heading_goal = heading;
            self.params.waypoints.clear();
        }
    }

    /// The desired heading now (rad).
    #[must_use]
    pub fn heading(&self) -> f64 {
        self.steering.heading
    }

    /// The next waypoint's index (equal to the count once all are reached).
    #[must_use]
    pub fn waypoint(&self) -> usize {
        self.steering.waypoint
    }

    /// Steer: aim at the next waypoint, and turn the heading toward its goal.
    fn steer(&mut self, dt: f64) {
        let (model, data) = (&self.sim.creature.model, &self.sim.data);
        let com = || crate::dynamics::energy::center_of_mass(model, data);
        if let Some(heading) = self.steering.steer(com, &self.params, dt) {
            self.sim.commands.heading_rad = heading;
        }
    }

    /// Hand over to a pending controller once the creature is in flight and
    /// falling, in a flight the new gait can start in; it takes over from
    /// the state it finds and what the running gait measured.
    fn take_over(&mut self) {
        if self.pending.is_none() || self.sim.contacts.iter().any(|c| c.touching) {
            return;
        }
        let sim = &self.sim;
        let vy = (sim.data)
            .point_velocity_world(sim.creature.trunk, DVec3::ZERO)
            .y;
        let input = ControlInput {
            creature: &sim.creature,
            data: &sim.data,
            contacts: &sim.contacts,
            time: sim.time,
            dt: sim.options.dt,
            commands: sim.commands.at_scale(sim.creature.scale),
            ground: sim.ground_view(),
        };
        if vy < 0.0
            && let Some(next) = self.pending.as_mut()
            && next.can_take_over(&input)
        {
            next.take_over_from(&input, &self.controller.handover());
            if let Some(next) = self.pending.take() {
                self.record_change(next.gait(), Entry::TakeOver);
                self.controller = next;
                self.running_gait.clone_from(&self.gait);
            }
        }
    }

    /// Note that `to` now runs, entered by `entry`.
    fn record_change(&mut self, to: &'static str, entry: Entry) {
        if self.gait_changes.len() < MAX_GAIT_CHANGES {
            self.gait_changes.push(GaitChange {
                at_s: self.run_time_s(),
                from: self.controller.gait(),
                to,
                entry,
            });
        }
    }

    /// The gait changes that took effect, in order: when each new gait's
    /// controller took over (a switch asked for waits for a flight it can
    /// start in), from which gait, and how it was entered.
    #[must_use]
    pub fn gait_changes(&self) -> &[GaitChange] {
        &self.gait_changes
    }

    /// Take `steps` integration steps with nothing recorded — the work a
    /// benchmark times (contacts, control, actuators, dynamics, integration).
    ///
    /// # Errors
    /// The blow-up, if one happens; the state is then not to be trusted.
    pub fn run_steps(&mut self, steps: u32) -> Result<(), crate::world::sim::BlowUp> {
        for _ in 0..steps {
            self.sim.step(&mut self.controller)?;
            self.take_over();
        }
        Ok(())
    }

    fn restart(&mut self, why: String) {
        self.sim = self.start.clone();
        let legs = self.sim.creature.legs.len();
        self.recorder = GaitRecorder::new(
            legs,
            self.params.speed_mps * Scale::new(self.params.scale).velocity(),
            0.0,
            3.0 * Scale::new(self.params.scale).time(),
        );
        // Only the kangaroo's hop starts on its cycle, and it is the
        // kangaroo's one gait: the stored controller is the gait's.
        if let Some(c) = &self.start_controller {
            self.controller = c.clone();
        } else if let Ok(c) = make_controller(&self.sim.creature, &self.gait, &self.params) {
            self.controller = c;
        }
        self.pending = None;
        self.running_gait.clone_from(&self.gait);
        self.steering = Steering::default();
        self.sim.commands = starting_commands(&self.params);
        self.fell_at = None;
        self.held_s = 0.0;
        self.message = Some(why);
        self.resets += 1;
        self.update_pose();
    }
}

impl PhysicsDriver {
    /// [`Driver::step`] calling `after_step` with the driver after every
    /// integration step that succeeded (what a per-step trace,
    /// [`crate::engine::trace`], reads); the motion is exactly that of
    /// [`Driver::step`].
    pub fn step_observed(&mut self, dt: f64, mut after_step: impl FnMut(&Self)) {
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        if self.reset_after_fall
            && let Some(t) = self.fell_at
        {
            // Held where it fell, then put back.
            self.held_s += dt;
            if self.held_s > FALL_RESET_S * Scale::new(self.params.scale).time() {
                self.put_back(format!(
                    "the creature fell at t = {t:.2} s and was put back at the start"
                ));
            }
            return;
        }
        self.steer(dt);
        let mut stepped = 0;
        let budget =
            ((dt / self.sim.options.dt).ceil() as u32).min(self.sim.options.max_steps_per_advance);
        let mut result = Ok(());
        // The fixed-step loop, recording every step for the Table-2 figures.
        self.sim.accumulate(dt);
        while stepped < budget && self.sim.due() {
            result = self.sim.step(&mut self.controller);
            if result.is_err() {
                break;
            }
            self.recorder.record(&self.sim);
            self.take_over();
            self.watch_pushes();
            after_step(self);
            stepped += 1;
        }
        self.sim.settle_accumulator();
        if let Err(blow_up) = result {
            self.put_back(format!("{blow_up}; the creature was put back at the start"));
            return;
        }
        let summary_fell = self.recorder.fell();
        if summary_fell && self.fell_at.is_none() {
            self.fell_at = Some(self.sim.time);
        }
        self.update_pose();
    }
}

impl Driver for PhysicsDriver {
    fn step(&mut self, dt: f64) {
        self.step_observed(dt, |_| {});
    }

    fn time(&self) -> f64 {
        self.sim.time
    }

    fn reset(&mut self) {
        self.restart(String::new());
        self.message = None;
        self.resets = 0;
        self.put_backs.clear();
        self.attempt_start_s = 0.0;
        self.pushes.clear();
        self.gait_changes.clear();
    }

    fn skeleton(&self) -> &Skeleton {
        &self.skeleton
    }

    fn pose(&self) -> &Pose {
        &self.pose
    }

    fn effector_positions(&self) -> &[DVec3] {
        &self.effectors
    }
}

/// The commands a run starts with: the preset's speed and hop height, the
/// heading straight ahead (+z) where the steering starts.
fn starting_commands(params: &PhysicsParams) -> Commands {
    Commands {
        speed_mps: params.speed_mps,
        heading_rad: Steering::default().heading,
        hop_height_m: params.hop_height_m,
    }
}

/// On ground that is not flat, a creature whose start would put a foot
/// below the ground under it is raised (its free base, or the planar
/// kangaroo's `base-up` slide; kinematics refreshed) until that foot is on
/// it: the start the gait gives on the floor, over the ground where it
/// stands (rough ground's bumps under the start). Nothing moves where every
/// foot starts above the ground, the floor included.
fn lift_above_ground(sim: &mut Sim) {
    if sim.terrain.surface.is_flat() {
        return;
    }
    let lift = sim
        .creature
        .legs
        .iter()
        .map(|leg| {
            let p = sim.data.point_world(leg.foot_body, leg.foot_point);
            sim.terrain.height(p.x, p.z) - p.y
        })
        .fold(0.0, f64::max);
    if lift <= 0.0 {
        return;
    }
    let model = &sim.creature.model;
    if model.free_base() {
        sim.data.base_position.y += lift;
    } else if let Some(k) = model.body_index("base-up").and_then(|b| model.dof_of(b)) {
        sim.data.q[k] += lift;
    } else {
        return;
    }
    crate::dynamics::kinematics::kinematics(&sim.creature.model, &mut sim.data);
}
