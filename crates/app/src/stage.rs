//! A stage: one figure's driver, its forward kinematics, the 3-D scene drawn
//! from them, its error history and its frame counter. The lab's single view
//! is a stage over any engine's driver; each side-by-side view of an IK
//! comparison ([`crate::compare`]) is a stage over its own thesis driver.

use gaitlab_core::Kinematics;
use gaitlab_core::driver::Driver;
use gaitlab_engine::AnyDriver;

use crate::history::History;
use crate::render::Scene;
use crate::view::ViewOptions;

/// One animated figure and what is drawn and plotted of it.
pub struct Stage<D = AnyDriver> {
    /// The driver animating the figure.
    pub(crate) driver: D,
    /// World transforms of the driver's skeleton at its current pose.
    pub(crate) kinematics: Kinematics,
    /// What the 3-D view draws.
    pub(crate) scene: Scene,
    /// The error plot's history (per effector, the largest error, or the
    /// physics engine's body series).
    pub(crate) history: History,
    /// Frames advanced since the last reset.
    pub(crate) frame: u64,
}

impl<D: Driver> Stage<D> {
    /// A stage over `driver` at frame 0 with an empty `history` (the scene is
    /// filled by the first [`Stage::refresh_scene`]).
    #[must_use]
    pub fn new(driver: D, history: History) -> Self {
        let kinematics = Kinematics::new(driver.skeleton());
        Self {
            driver,
            kinematics,
            scene: Scene::default(),
            history,
            frame: 0,
        }
    }

    /// The driver.
    #[must_use]
    pub fn driver(&self) -> &D {
        &self.driver
    }

    /// The driver, mutably.
    pub fn driver_mut(&mut self) -> &mut D {
        &mut self.driver
    }

    /// The 3-D scene as last refreshed.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The error plot's history.
    #[must_use]
    pub fn history(&self) -> &History {
        &self.history
    }

    /// Frames advanced since the last reset.
    #[must_use]
    pub fn frame(&self) -> u64 {
        self.frame
    }

    /// Advances the driver one frame of `dt` seconds.
    pub fn step(&mut self, dt: f64) {
        self.driver.step(dt);
        self.frame += 1;
    }

    /// Back to time 0 and the rest pose, with an empty history.
    pub fn reset(&mut self) {
        self.driver.reset();
        self.frame = 0;
        self.history.clear();
    }

    /// Rebuilds the scene from the driver's current pose (a physics
    /// creature's skeleton is the driver's, scaled by L, Table 1).
    pub fn refresh_scene(&mut self, view: &ViewOptions) {
        let skeleton = self.driver.skeleton();
        let pose = self.driver.pose();
        self.kinematics.update(skeleton, &pose.root, &pose.joints);
        self.scene.fill(
            skeleton,
            &self.kinematics,
            pose.root.position,
            self.driver.targets(),
            view,
        );
    }
}

impl Stage<AnyDriver> {
    /// A stage over `driver` at frame 0 with an empty history, drawing the
    /// ground the driver's figure stands on ([`AnyDriver::terrain`]).
    #[must_use]
    pub fn on_ground(driver: AnyDriver) -> Self {
        let mut stage = Self::new(driver, History::default());
        stage.scene.set_terrain(stage.driver.terrain());
        stage
    }

    /// One IK iteration ([`AnyDriver::step_iteration`]); the frame counter
    /// moves when the iteration closes its frame. `None` when the driver
    /// cannot step by iteration.
    pub fn step_iteration(&mut self, dt: f64) -> Option<gaitlab_engine::IterationStep> {
        let step = self.driver.step_iteration(dt)?;
        if step.done >= step.of {
            self.frame += 1;
        }
        Some(step)
    }
}
