//! The simulation loop of Raibert & Hodgins 1991, Figure 2: every
//! integration interval (0.4 ms by default) the model computes contact and
//! actuator forces and integrates the equations of motion; every control
//! interval the controller updates the actuators' set points. A fixed-step
//! accumulator decouples the physics from the display's frame rate.
//!
//! Stages per step: `kinematics → contacts → control (when due) → actuators
//! → dynamics → integrate → guard`. The guard stops a run whose state turned
//! non-finite or ran away, so the caller can reset and say why.

use crate::creatures::PhysicalCreature;
use crate::dynamics::data::Data;
use crate::dynamics::spatial::Force;
use crate::world::actuator::{SpringDamper, Stops};
use crate::world::commands::{Commands, ScaledCommands};
use crate::world::ground::{FootContact, GroundParams, Terrain, contact_forces};
use crate::world::ground_view::GroundView;

/// One joint's actuator: a spring-damper / servo (eq. 1, eq. 5) plus a
/// feed-forward torque from the controller (eq. 4's posture torque) and the
/// joint's mechanical stops.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drive {
    /// Spring-damper or servo; zero stiffness and damping make it limp.
    pub spring: SpringDamper,
    /// Added torque or force (N·m or N).
    pub feedforward: f64,
    /// Travel limits, if any.
    pub stops: Option<Stops>,
}

impl Default for Drive {
    fn default() -> Self {
        Self {
            spring: SpringDamper {
                stiffness: 0.0,
                damping: 0.0,
                rest: 0.0,
                max_force: f64::INFINITY,
            },
            feedforward: 0.0,
            stops: None,
        }
    }
}

impl Drive {
    /// Servo this joint to `target` with gains `kp`, `kv` (eq. 5), no feed-forward.
    pub fn servo(&mut self, kp: f64, kv: f64, target: f64) {
        self.spring.stiffness = kp;
        self.spring.damping = kv;
        self.spring.rest = target;
        self.feedforward = 0.0;
    }

    /// Apply only `torque`: the servo goes limp.
    pub fn torque(&mut self, torque: f64) {
        self.spring.stiffness = 0.0;
        self.spring.damping = 0.0;
        self.feedforward = torque;
    }

    /// The generalized force at coordinate `q` moving at `qd`.
    #[must_use]
    pub fn force(&self, q: f64, qd: f64) -> f64 {
        let stops = self.stops.map_or(0.0, |s| s.force(q, qd));
        (self.spring.force(q, qd) + self.feedforward)
            .clamp(-self.spring.max_force, self.spring.max_force)
            + stops
    }
}

/// What the controller sees each control interval.
pub struct ControlInput<'a> {
    /// The creature.
    pub creature: &'a PhysicalCreature,
    /// The state, kinematics up to date.
    pub data: &'a Data,
    /// Each leg's contact.
    pub contacts: &'a [FootContact],
    /// Simulated time (s).
    pub time: f64,
    /// Time since the last control call (s).
    pub dt: f64,
    /// The commands, at the creature's scale.
    pub commands: ScaledCommands,
    /// The ground plane under the trunk, from the terrain at the last
    /// control interval (issue 45 item 3): all a controller learns of the
    /// terrain.
    pub ground: GroundView,
}

/// A running controller: sets actuator set points from the state.
pub trait Controller {
    /// Update `drives` (one per joint coordinate).
    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]);

    /// The servos the paper models with the actuators (eq. 4's posture
    /// servo), run every integration step after [`Controller::control`]
    /// with the set points `control` left: between control intervals they
    /// keep acting on the fresh state. Default: none.
    fn servo(&mut self, _input: &ControlInput<'_>, _drives: &mut [Drive]) {}

    /// The state machine's current state, for people and plots.
    fn phase_name(&self) -> &'static str {
        ""
    }

    /// The state of leg `leg`'s own state machine, for a controller that runs
    /// one per leg or per pair of legs; `None` where the controller's one
    /// state is all there is.
    fn leg_phase_name(&self, _leg: usize) -> Option<&'static str> {
        None
    }

    /// The hop height the gait regulates when no command gives one (m at
    /// scale 1), if it regulates one.
    fn hop_height_m(&self) -> Option<f64> {
        None
    }

    /// The gains a person may tune while it runs.
    fn gains(&self) -> Vec<Gain> {
        Vec::new()
    }

    /// Set a gain by name; `false` when there is no such gain or the value is
    /// negative or not finite.
    fn set_gain(&mut self, _name: &str, _value: f64) -> bool {
        false
    }

    /// Any of its parameters by name (the preset's `controller` keys, at
    /// scale 1), gains included; `None` when it has no such parameter.
    fn parameter(&self, _name: &str) -> Option<f64> {
        None
    }

    /// The names [`Controller::parameter`] takes.
    fn parameter_names(&self) -> &'static [&'static str] {
        &[]
    }
}

/// One gain a person may tune while a controller runs (the app's sliders,
/// the `gain` command), at scale 1 in the paper's units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gain {
    /// Parameter name (`posture_kp`, `leg_stiffness`, …), the wire key.
    pub name: &'static str,
    /// The gain in words for people ("Leg spring stiffness k (eq. 1)").
    pub label: &'static str,
    /// Unit, for labels.
    pub unit: &'static str,
    /// Current value.
    pub value: f64,
    /// The controller's default value.
    pub default: f64,
}

impl Gain {
    /// A gain from its parts.
    #[must_use]
    pub const fn new(
        name: &'static str,
        label: &'static str,
        unit: &'static str,
        value: f64,
        default: f64,
    ) -> Self {
        Self {
            name,
            label,
            unit,
            value,
            default,
        }
    }
}

/// Options of the simulation loop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimOptions {
    /// Integration interval (s); the paper's 0.4 ms by default.
    pub dt: f64,
    /// Run the controller every this many steps (1 = every step).
    pub control_every: u32,
    /// Most steps one [`Sim::advance`] may take, so a slow frame cannot
    /// snowball; the remainder is dropped (the display slows down instead).
    pub max_steps_per_advance: u32,
    /// Speeds above this (m/s, or rad/s for joints) count as a blow-up.
    pub max_speed: f64,
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            dt: 0.0004,
            control_every: 1,
            max_steps_per_advance: 400,
            max_speed: 200.0,
        }
    }
}

/// Why a simulation stopped.
#[derive(Clone, Debug, PartialEq)]
pub struct BlowUp {
    /// Simulated time (s).
    pub time: f64,
    /// What went wrong, for people.
    pub reason: String,
}

impl std::fmt::Display for BlowUp {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "simulation blew up at t = {:.3} s: {}",
            self.time, self.reason
        )
    }
}

impl std::error::Error for BlowUp {}

/// A creature in the world, with its actuators, contacts and clock.
#[derive(Clone, Debug)]
pub struct Sim {
    /// The creature simulated.
    pub creature: PhysicalCreature,
    /// Its state.
    pub data: Data,
    /// One actuator per joint coordinate.
    pub drives: Vec<Drive>,
    /// One contact per leg.
    pub contacts: Vec<FootContact>,
    /// Ground springs.
    pub ground: GroundParams,
    /// Ground shape.
    pub terrain: Terrain,
    /// Loop options.
    pub options: SimOptions,
    /// Simulated time (s).
    pub time: f64,
    /// Steps taken.
    pub steps: u64,
    /// What a person asks of the running creature, at scale 1; the
    /// controller reads them each control interval.
    pub commands: Commands,
    /// The ground plane under the trunk at the last control interval.
    ground_view: GroundView,
    accumulator: f64,
}

impl Sim {
    /// A simulation of `creature` at rest at the zero state.
    #[must_use]
    pub fn new(creature: PhysicalCreature, ground: GroundParams, options: SimOptions) -> Self {
        let data = Data::new(&creature.model);
        let drives = vec![Drive::default(); creature.model.joint_count()];
        let contacts = vec![FootContact::default(); creature.legs.len()];
        Self {
            creature,
            data,
            drives,
            contacts,
            ground,
            terrain: Terrain::default(),
            options,
            time: 0.0,
            steps: 0,
            commands: Commands::default(),
            ground_view: GroundView::FLAT,
            accumulator: 0.0,
        }
    }

    /// The ground plane under the trunk now, from [`Sim::terrain`]: what a
    /// controller is handed of the terrain ([`ControlInput::ground`]).
    #[must_use]
    pub fn ground_view(&self) -> GroundView {
        let trunk = self.data.world[self.creature.trunk].pos;
        GroundView::of(&self.terrain, trunk, self.creature.scale)
    }

    /// One integration step of `options.dt`.
    ///
    /// # Errors
    /// [`BlowUp`] when the dynamics are singular or the state turns
    /// non-finite or runs away; the state is then not to be trusted.
    pub fn step(&mut self, controller: &mut dyn Controller) -> Result<(), BlowUp> {
        let model = &self.creature.model;
        let dt = self.options.dt;
        crate::dynamics::kinematics::kinematics(model, &mut self.data);
        self.data.external.fill(Force::ZERO);
        contact_forces(
            &self.creature,
            &mut self.data,
            &self.ground,
            &self.terrain,
            &mut self.contacts,
        );
        let every = u64::from(self.options.control_every.max(1));
        let control_due = self.steps.is_multiple_of(every);
        if control_due {
            self.ground_view = self.ground_view();
        }
        let input = ControlInput {
            creature: &self.creature,
            data: &self.data,
            contacts: &self.contacts,
            time: self.time,
            dt: dt * every as f64,
            commands: self.commands.at_scale(self.creature.scale),
            ground: self.ground_view,
        };
        if control_due {
            controller.control(&input, &mut self.drives);
        }
        controller.servo(&input, &mut self.drives);
        for (k, drive) in self.drives.iter().enumerate() {
            self.data.tau[k] = drive.force(self.data.q[k], self.data.qd[k]);
        }
        crate::dynamics::aba::accelerations(model, &mut self.data).map_err(|e| BlowUp {
            time: self.time,
            reason: e.to_string(),
        })?;
        crate::dynamics::integrate::integrate(model, &mut self.data, dt);
        self.time += dt;
        self.steps += 1;
        self.accumulator = (self.accumulator - dt).max(0.0);
        self.guard()
    }

    fn guard(&self) -> Result<(), BlowUp> {
        let d = &self.data;
        let fail = |reason: String| {
            Err(BlowUp {
                time: self.time,
                reason,
            })
        };
        if !d.is_finite() {
            return fail("the state became NaN or infinite".into());
        }
        let max = self.options.max_speed;
        let base = d.base_velocity;
        if base.linear.length() > max || base.angular.length() > max {
            return fail(format!("the body moved faster than {max} m/s or rad/s"));
        }
        if let Some(k) = d.qd.iter().position(|v| v.abs() > max) {
            let model = &self.creature.model;
            let name = (0..model.bodies().len())
                .find(|&i| model.dof_of(i) == Some(k))
                .map_or("?", |i| model.bodies()[i].name.as_str());
            return fail(format!("joint {name} moved faster than {max} rad/s or m/s"));
        }
        Ok(())
    }

    /// Add `frame_dt` seconds of display time to the accumulator.
    pub fn accumulate(&mut self, frame_dt: f64) {
        self.accumulator += frame_dt.max(0.0);
    }

    /// Whether the accumulator holds at least one step; taking the step is
    /// the caller's, who then takes [`Sim::options`]`.dt` off with
    /// [`Sim::step`] — see [`Sim::advance`] for the whole loop.
    #[must_use]
    pub fn due(&self) -> bool {
        self.accumulator >= self.options.dt
    }

    /// After a caller-driven loop: drop what could not be stepped when the
    /// step budget ran out, so a slow frame cannot snowball.
    pub fn settle_accumulator(&mut self) {
        if self.accumulator >= self.options.dt * f64::from(self.options.max_steps_per_advance) {
            self.accumulator = 0.0;
        }
    }

    /// Advance by `frame_dt` seconds of display time on the fixed-step
    /// accumulator; returns the number of steps taken.
    ///
    /// # Errors
    /// As [`Sim::step`].
    pub fn advance(
        &mut self,
        frame_dt: f64,
        controller: &mut dyn Controller,
    ) -> Result<u32, BlowUp> {
        self.accumulator += frame_dt.max(0.0);
        let mut taken = 0;
        while self.due() && taken < self.options.max_steps_per_advance {
            self.step(controller)?;
            taken += 1;
        }
        if taken == self.options.max_steps_per_advance {
            self.accumulator = 0.0;
        }
        Ok(taken)
    }
}
