//! Any engine's driver, by the preset's engine: She 2006's thesis motions
//! ([`ThesisDriver`]), Girard & Maciejewski 1985's PODA gaits
//! ([`PodaDriver`]), Raibert & Hodgins 1991's simulated runners
//! ([`PhysicsDriver`]), or recorded targets followed by the thesis IK
//! ([`TrackDriver`], `gaitlab track`). Everything generic goes through
//! [`Driver`]; front ends ask for the concrete driver they edit. Built by
//! [`crate::driver_for()`] only.

use gaitlab_core::Skeleton;
use gaitlab_core::driver::{Driver, IkFrameReport, IkMetrics};
use gaitlab_core::export::TargetTrack;
use gaitlab_core::ik::{IkOptions, IkSolver, Method, Targets};
use gaitlab_core::pose::Pose;
use gaitlab_core::preset::{
    LabAddition, ik_lab_additions, poda_lab_additions, thesis_lab_additions,
};
use gaitlab_motion::held::HeldTargets;
use gaitlab_motion::{IterationRecord, IterationStep, PodaDriver, ThesisDriver, TrackDriver};
use gaitlab_physics::PhysicsDriver;
use glam::DVec3;

/// The driver of one figure, whatever its engine.
#[derive(Clone, Debug)]
pub enum AnyDriver {
    /// Sinusoidal targets tracked by Jacobian IK (engine `ik`).
    Thesis(Box<ThesisDriver>),
    /// PODA gait synthesis (engine `poda`).
    Poda(Box<PodaDriver>),
    /// Physical simulation under control (engine `physics`).
    Physics(Box<PhysicsDriver>),
    /// Recorded effector targets followed by IK (`gaitlab track`).
    Track(Box<TrackDriver<TargetTrack>>),
}

impl AnyDriver {
    fn inner(&self) -> &dyn Driver {
        match self {
            AnyDriver::Thesis(driver) => driver.as_ref(),
            AnyDriver::Poda(driver) => driver.as_ref(),
            AnyDriver::Physics(driver) => driver.as_ref(),
            AnyDriver::Track(driver) => driver.as_ref(),
        }
    }

    fn inner_mut(&mut self) -> &mut dyn Driver {
        match self {
            AnyDriver::Thesis(driver) => driver.as_mut(),
            AnyDriver::Poda(driver) => driver.as_mut(),
            AnyDriver::Physics(driver) => driver.as_mut(),
            AnyDriver::Track(driver) => driver.as_mut(),
        }
    }

    /// Whether a physics creature that falls or blows up is put back at the
    /// start (the page) or left lying (a headless run reports the fall);
    /// other engines do not fall.
    pub fn set_reset_after_fall(&mut self, on: bool) {
        if let AnyDriver::Physics(physics) = self {
            physics.reset_after_fall = on;
        }
    }

    /// The physics creature as a MuJoCo MJCF model named `name`; `None` for
    /// other engines.
    #[must_use]
    pub fn mjcf(&self, name: &str) -> Option<String> {
        match self {
            AnyDriver::Physics(physics) => Some(physics.mjcf(name)),
            _ => None,
        }
    }

    /// Whether the driver follows a recording of targets (`gaitlab track`,
    /// the page's recorded targets) rather than a script or a gait.
    #[must_use]
    pub fn is_recording(&self) -> bool {
        matches!(self, AnyDriver::Track(_))
    }

    /// The thesis motion running, when the driver runs the thesis' script.
    #[must_use]
    pub fn thesis_mode(&self) -> Option<gaitlab_core::preset::thesis::ThesisMode> {
        match self {
            AnyDriver::Thesis(driver) => Some(driver.mode()),
            _ => None,
        }
    }

    /// The thesis driver, when the engine is `ik`.
    #[must_use]
    pub fn thesis(&self) -> Option<&ThesisDriver> {
        match self {
            AnyDriver::Thesis(driver) => Some(driver),
            _ => None,
        }
    }

    /// The thesis driver, mutably.
    pub fn thesis_mut(&mut self) -> Option<&mut ThesisDriver> {
        match self {
            AnyDriver::Thesis(driver) => Some(driver),
            _ => None,
        }
    }

    /// The recorded-target driver, when it follows a recording.
    #[must_use]
    pub fn track(&self) -> Option<&TrackDriver<TargetTrack>> {
        match self {
            AnyDriver::Track(driver) => Some(driver),
            _ => None,
        }
    }

    /// Whether the figure is posed by Jacobian IK toward targets of its own
    /// (the thesis motions or a recording): the drivers whose IK method and
    /// options a front end sets, and that an IK comparison can run.
    #[must_use]
    pub fn is_ik(&self) -> bool {
        matches!(self, AnyDriver::Thesis(_) | AnyDriver::Track(_))
    }

    /// The lab's additions in force for what runs, each with its reason
    /// (empty: the paper alone): what `--json`, `state()` and the page's
    /// readout list. IK and PODA from `gaitlab_core::preset`'s lists, physics
    /// from the gait controller and `switch_to_start`.
    #[must_use]
    pub fn lab_additions(&self) -> Vec<LabAddition> {
        const PHYSICS: &str = "The lab's addition to Raibert & Hodgins' control for this gait (the physics panel and docs/physics.md, \"The lab's additions\")";
        const SWITCH: &str = "A switch enters the new gait at its own start where the creature is, not the paper's take-over at the next falling flight";
        match self {
            AnyDriver::Thesis(driver) => {
                thesis_lab_additions(driver.params(), driver.options(), driver.mode())
            }
            AnyDriver::Track(driver) => ik_lab_additions(driver.options()).collect(),
            AnyDriver::Poda(driver) => poda_lab_additions(driver.params(), driver.terrain()),
            AnyDriver::Physics(driver) => driver
                .lab_additions_in_force()
                .map(|name| LabAddition {
                    name,
                    reason: if name == "switch_to_start" {
                        SWITCH
                    } else {
                        PHYSICS
                    },
                })
                .collect(),
        }
    }

    /// The ground the figure stands on: its preset's `scenario.terrain` for
    /// PODA and physics creatures, the floor for IK figures (which walk on
    /// flat ground only).
    #[must_use]
    pub fn terrain(&self) -> &gaitlab_core::terrain::Terrain {
        static FLOOR: gaitlab_core::terrain::Terrain = gaitlab_core::terrain::Terrain::Flat;
        match self {
            AnyDriver::Poda(driver) => driver.terrain(),
            AnyDriver::Physics(driver) => &driver.sim().terrain.surface,
            AnyDriver::Thesis(_) | AnyDriver::Track(_) => &FLOOR,
        }
    }

    /// The IK options of an IK driver ([`AnyDriver::is_ik`]).
    #[must_use]
    pub fn ik_options(&self) -> Option<&IkOptions> {
        match self {
            AnyDriver::Thesis(driver) => Some(driver.options()),
            AnyDriver::Track(driver) => Some(driver.options()),
            _ => None,
        }
    }

    /// Replaces an IK driver's options (others have none: nothing happens).
    pub fn set_ik_options(&mut self, options: IkOptions) {
        match self {
            AnyDriver::Thesis(driver) => driver.set_options(options),
            AnyDriver::Track(driver) => driver.set_options(options),
            _ => {}
        }
    }

    /// Switches an IK driver's method (others have none: nothing happens).
    pub fn set_ik_method(&mut self, method: Method) {
        match self {
            AnyDriver::Thesis(driver) => driver.set_method(method),
            AnyDriver::Track(driver) => driver.set_method(method),
            _ => {}
        }
    }

    /// Holds effector `e`'s target at the world point `at` (`Some`) or lets
    /// go of it (`None`) — the lab's grab and pull, for the thesis' script
    /// ([`ThesisDriver::hold_target`]). `false` when the driver has no
    /// script targets to hold (PODA, physics, a recording) or `e` or `at`
    /// is unusable.
    pub fn hold_target(&mut self, e: usize, at: Option<DVec3>) -> bool {
        self.thesis_mut()
            .is_some_and(|driver| driver.hold_target(e, at))
    }

    /// Pins or unpins effector `e`'s target ([`ThesisDriver::pin_target`]);
    /// `false` without the thesis' script or for an unknown effector.
    pub fn pin_target(&mut self, e: usize, on: bool) -> bool {
        match self.thesis_mut() {
            Some(driver) if e < driver.skeleton().effector_count() => {
                driver.pin_target(e, on);
                true
            }
            _ => false,
        }
    }

    /// The held and pinned targets, for the thesis' script.
    #[must_use]
    pub fn held_targets(&self) -> Option<&HeldTargets> {
        self.thesis().map(ThesisDriver::held)
    }

    /// One IK iteration of the frame to come ([`ThesisDriver::step_iteration`]);
    /// `None` for other drivers or a bad `dt`.
    pub fn step_iteration(&mut self, dt: f64) -> Option<IterationStep> {
        self.thesis_mut()?.step_iteration(dt)
    }

    /// One frame's IK iterations without advancing time ([`ThesisDriver::settle`]);
    /// `false` for other drivers.
    pub fn settle(&mut self) -> bool {
        self.thesis_mut().map(ThesisDriver::settle).is_some()
    }

    /// The iterations of the frame last run, for the thesis' script (empty
    /// for other drivers).
    #[must_use]
    pub fn iteration_log(&self) -> &[IterationRecord] {
        self.thesis().map_or(&[], ThesisDriver::iteration_log)
    }

    /// The IK solver of the thesis' script, as its last iteration left it.
    #[must_use]
    pub fn ik_solver(&self) -> Option<&IkSolver> {
        self.thesis().map(ThesisDriver::solver)
    }

    /// The PODA driver, when the engine is `poda`.
    #[must_use]
    pub fn poda(&self) -> Option<&PodaDriver> {
        match self {
            AnyDriver::Poda(driver) => Some(driver),
            _ => None,
        }
    }

    /// The PODA driver, mutably.
    pub fn poda_mut(&mut self) -> Option<&mut PodaDriver> {
        match self {
            AnyDriver::Poda(driver) => Some(driver),
            _ => None,
        }
    }

    /// The physics driver, when the engine is `physics`.
    #[must_use]
    pub fn physics(&self) -> Option<&PhysicsDriver> {
        match self {
            AnyDriver::Physics(driver) => Some(driver),
            _ => None,
        }
    }

    /// The physics driver, mutably.
    pub fn physics_mut(&mut self) -> Option<&mut PhysicsDriver> {
        match self {
            AnyDriver::Physics(driver) => Some(driver),
            _ => None,
        }
    }
}

impl Driver for AnyDriver {
    fn step(&mut self, dt: f64) {
        self.inner_mut().step(dt);
    }

    fn time(&self) -> f64 {
        self.inner().time()
    }

    fn reset(&mut self) {
        self.inner_mut().reset();
    }

    fn skeleton(&self) -> &Skeleton {
        self.inner().skeleton()
    }

    fn pose(&self) -> &Pose {
        self.inner().pose()
    }

    fn effector_positions(&self) -> &[DVec3] {
        self.inner().effector_positions()
    }

    fn targets(&self) -> Option<&Targets> {
        self.inner().targets()
    }

    fn ik_report(&self) -> Option<&IkFrameReport> {
        self.inner().ik_report()
    }

    fn ik_metrics(&self) -> Option<&IkMetrics> {
        self.inner().ik_metrics()
    }
}
