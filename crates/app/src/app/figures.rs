//! What the figures on screen go through together: a new creature, a reset,
//! a frame, a redraw. During a comparison its views replace the single view's
//! figure, so each of these reaches the comparison, the Jacobian panel's
//! probe and the history scrubber as well as the lab.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::preset::{Creature, Engine};
use gaitlab_engine::{Applied, EngineCommand};

use super::App;
use crate::lab::Effect;
use crate::lab::session;

impl App {
    /// Switches to a bundled preset (its own default scenario, keeping the chosen mode and method).
    ///
    /// # Errors
    /// If no bundled preset has that name or it cannot drive the thesis motions;
    /// the current preset stays.
    pub fn set_preset(&mut self, name: &str) -> Result<(), String> {
        let creature = session::bundled(name)?;
        self.install(creature, None)?;
        self.session.settings.preset = name.to_owned();
        Ok(())
    }

    /// Switches to a preset given as JSON (a `#p=` link or a pasted file).
    ///
    /// # Errors
    /// The preset's `path: reason`; the current preset stays.
    pub fn set_custom_preset(&mut self, json: &str) -> Result<(), String> {
        let creature = Creature::from_json(json).map_err(|e| format!("preset: {e}"))?;
        self.install(creature, Some(json.to_owned()))
    }

    /// Sets the thesis motion.
    pub fn set_mode(&mut self, mode: ThesisMode) {
        self.session.settings.mode = mode;
        // Other engines keep the mode for when a thesis preset runs.
        drop(self.stage.driver.apply(EngineCommand::Mode(mode)));
        if let Some(compare) = self.compare.as_mut() {
            compare.set_mode(mode);
        }
        self.outbox.push(Effect::LinkChanged);
    }

    /// Applies a new figure heading (restarts the motion facing that way).
    pub fn set_heading_deg(&mut self, degrees: f64) {
        let heading_deg = degrees.clamp(-180.0, 180.0);
        self.session.settings.heading_deg = heading_deg;
        // A running physics creature turns toward the new heading; the
        // others start again facing it.
        if let Ok(Applied::Restart) = self
            .stage
            .driver
            .apply(EngineCommand::Heading(heading_deg.to_radians()))
        {
            self.reset();
        }
    }

    /// The address bar's query for what is on screen ([`crate::link::query`]):
    /// the preset; for the IK engine its mode; and the method when one view
    /// runs (a comparison runs several).
    #[must_use]
    pub fn address_query(&self) -> String {
        let settings = &self.session.settings;
        let ik = self.engine() == Engine::Ik;
        crate::link::query(
            &settings.preset,
            ik.then(|| settings.mode.name()),
            (ik && self.compare.is_none()).then(|| settings.method.name()),
        )
    }

    /// Switches engine by loading the matching bundled creature (the engine
    /// layer's [`gaitlab_engine::bundled_for_engine`]).
    ///
    /// # Errors
    /// If the matching preset cannot be loaded; nothing changes.
    pub fn set_engine(&mut self, engine: Engine) -> Result<(), String> {
        if engine == self.engine() {
            return Ok(());
        }
        let name = gaitlab_engine::bundled_for_engine(engine, &self.session.creature.name);
        self.set_preset(name)
    }

    /// Back to time 0 and the rest pose.
    pub fn reset(&mut self) {
        self.stage.driver.reset();
        if let Some(compare) = self.compare.as_mut() {
            compare.reset();
        }
        self.after_reset();
    }

    /// Advances the animation by `real_dt` seconds of wall time in fixed frames
    /// of [`Lab::frame_seconds`](crate::Lab::frame_seconds); paused labs only take requested single steps.
    pub fn advance(&mut self, real_dt: f64) {
        let dt = self.frame_seconds();
        let steps = self.playback.steps_for(real_dt, dt);
        if steps == 0 {
            return;
        }
        let started = self.playback.now_ms();
        for _ in 0..steps {
            self.step_frame(dt);
        }
        self.playback.note_sim_time(started, steps);
        self.refresh_scene();
    }

    /// One frame of `dt` seconds: the single view or, in lock step, every
    /// comparison view; then the plots, take and footprints and the history
    /// scrubber's record.
    pub(crate) fn step_frame(&mut self, dt: f64) {
        if let Some(compare) = self.compare.as_mut() {
            // The views replace the single figure, in lock step.
            compare.step(dt, self.lab.playback.clock.as_deref());
            self.lab.stage.frame += 1;
        } else {
            self.stage.step(dt);
            self.record_frame();
        }
        self.rewind_note();
        self.probe_jacobian();
    }

    /// Rebuilds the 3-D scenes from the drivers' current poses, with overlays.
    pub(crate) fn refresh_scene(&mut self) {
        let lab = &mut self.lab;
        let view = &lab.session.settings.view;
        if let Some(compare) = self.compare.as_mut() {
            compare.refresh_scenes(view);
        }
        lab.stage.refresh_scene(view);
        lab.overlays
            .add_to(&mut lab.stage.scene, &lab.stage.driver, view);
    }

    /// Runs `creature` ([`crate::lab::Lab::load_creature`]), then starts the
    /// features over on it: the probe, the scene, the history and a running
    /// comparison (rebuilt on the new figure).
    fn install(&mut self, creature: Creature, custom: Option<String>) -> Result<(), String> {
        self.lab.load_creature(creature, custom)?;
        self.after_reset();
        self.rebuild_compare();
        Ok(())
    }

    /// Frame 0: the lab's records ([`crate::lab::Lab::restart_records`]), the
    /// Jacobian probe, the scene and the history scrubber start again.
    pub(crate) fn after_reset(&mut self) {
        self.lab.restart_records();
        self.jacobian.probe.clear();
        self.probe_jacobian();
        self.refresh_scene();
        self.rewind_restart();
    }
}
