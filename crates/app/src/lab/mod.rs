//! The lab: one figure animated by a driver (She 2006's thesis motions for the
//! IK engine, PODA gaits for `poda`, Raibert & Hodgins 1991 for `physics`),
//! composed of parts, one file each: the [`Session`] (creature, settings,
//! custom preset, last error), the [`Stage`] (driver, kinematics, scene, error
//! history, frame), the [`Plots`], the [`Overlays`], the [`TakeRecorder`] and
//! an [`Outbox`] of effects the web glue drains. The lab holds no feature's
//! state: the comparison, the hand, the Jacobian panel, the λ trade-off and
//! the history scrubber sit beside it in the [`crate::app::App`], which is
//! what front ends drive and which keeps every figure on screen in step.

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::Creature;
use gaitlab_core::preset::Engine;
use gaitlab_engine::{AnyDriver, EngineCommand, Take};

use crate::history::History;
use crate::render::Camera;
use crate::settings::Settings;

pub(crate) mod gait_shape;
pub(crate) mod layout;
mod outbox;
mod overlays;
mod playback;
mod plots;
pub(crate) mod session;
mod take;
mod video;

use crate::stage::Stage;
pub use gait_shape::GaitShapeEdit;
pub use layout::Layout;
pub use outbox::{Download, Effect, Outbox};
pub use overlays::Overlays;
pub use playback::{Clock, MAX_FRAME_ADVANCE_S, PLAYBACK_RATES, Playback};
pub use plots::{MAX_PLOT_JOINTS, PHYSICS_ATTITUDE_SERIES, PHYSICS_BODY_SERIES, Plots};
pub use session::Session;
pub use take::TakeRecorder;
pub use video::VideoStatus;

/// The single figure's lab, by part (the features are the [`crate::App`]'s).
pub struct Lab {
    /// What a person chose and what runs.
    pub(crate) session: Session,
    /// The single view: driver, kinematics, scene, error history, frame.
    pub(crate) stage: Stage,
    /// The 3-D view's camera (shared by the side-by-side views).
    pub(crate) camera: Camera,
    /// Pause, single steps and timings.
    pub(crate) playback: Playback,
    /// The joint plot.
    pub(crate) plots: Plots,
    /// Footprints and the other scene overlays.
    pub(crate) overlays: Overlays,
    /// The motion take.
    pub(crate) take: TakeRecorder,
    /// Effects for the front end.
    pub(crate) outbox: Outbox,
    /// The video recording as the front end reports it.
    pub(crate) video: VideoStatus,
    /// The layout as last drawn.
    pub(crate) layout: Layout,
    /// A drag on the physics creature's trunk, pushing it.
    pub(crate) push_drag: crate::render::push_drag::PushDrag,
    /// The preset editor.
    pub(crate) editor: crate::editor::PresetEditor,
    /// What the last PODA gait edit derived, to say so in the gait panel.
    pub(crate) gait_derived: Vec<&'static str>,
    /// The link "Copy link" made last, shown for copying by hand.
    pub(crate) shown_link: Option<String>,
    /// The graphics path drawing the view ("webgpu (…)" or "webgl2 (…)"), when known.
    pub backend: Option<String>,
    /// The page's address without query or fragment (the web glue sets it;
    /// empty natively), the base of [`crate::App::share_link`].
    pub page_url: String,
}

impl Lab {
    /// A lab with `settings`; an unknown preset falls back to the default one and
    /// leaves a message.
    #[must_use]
    pub fn new(settings: Settings) -> Self {
        let (session, driver) = Session::start(settings);
        let mut lab = Self {
            session,
            stage: Stage::on_ground(driver),
            camera: Camera::default(),
            playback: Playback::default(),
            plots: Plots::default(),
            overlays: Overlays::default(),
            take: TakeRecorder::default(),
            outbox: Outbox::default(),
            video: VideoStatus::default(),
            layout: Layout::default(),
            push_drag: crate::render::push_drag::PushDrag::default(),
            editor: crate::editor::PresetEditor::default(),
            gait_derived: Vec::new(),
            shown_link: None,
            backend: None,
            page_url: String::new(),
        };
        lab.restart_records();
        lab
    }

    /// Supplies the platform clock used to time the simulation.
    pub fn set_clock(&mut self, clock: Clock) {
        self.playback.clock = Some(clock);
    }

    /// What a person chose.
    #[must_use]
    pub fn settings(&self) -> &Settings {
        &self.session.settings
    }

    /// What a person chose, mutably (panels edit view flags in place).
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.session.settings
    }

    /// The creature being animated.
    #[must_use]
    pub fn creature(&self) -> &Creature {
        &self.session.creature
    }

    /// The driver animating it.
    #[must_use]
    pub fn driver(&self) -> &AnyDriver {
        &self.stage.driver
    }

    /// The 3-D view's camera as last moved.
    #[must_use]
    pub fn camera(&self) -> crate::render::Camera {
        self.camera
    }

    /// The single view.
    #[must_use]
    pub fn stage(&self) -> &Stage {
        &self.stage
    }

    /// Frames advanced since the last reset.
    #[must_use]
    pub fn frame(&self) -> u64 {
        self.stage.frame
    }

    /// Whether the animation is paused.
    #[must_use]
    pub fn paused(&self) -> bool {
        self.playback.paused
    }

    /// The last error message, if any.
    #[must_use]
    pub fn last_error(&self) -> Option<&str> {
        self.session.last_error.as_deref()
    }

    /// The note about the running preset (its deprecated values), if any.
    #[must_use]
    pub fn notice(&self) -> Option<&str> {
        self.session.notice.as_deref()
    }

    /// Hides the note about the running preset.
    pub fn clear_notice(&mut self) {
        self.session.notice = None;
    }

    /// Records a problem to show.
    pub fn report_error(&mut self, message: impl Into<String>) {
        self.session.last_error = Some(message.into());
    }

    /// Clears the shown problem.
    pub fn clear_error(&mut self) {
        self.session.last_error = None;
    }

    /// Smoothed µs per animation frame spent in the driver (needs a clock).
    #[must_use]
    pub fn sim_us_per_frame(&self) -> f64 {
        self.playback.sim_us_per_frame
    }

    /// Takes every effect queued for the front end, oldest first.
    pub fn drain_effects(&mut self) -> Vec<Effect> {
        self.outbox.drain()
    }

    /// Runs `creature`. Where its IK options (`scenario.ik`) differ from the
    /// running preset's, it runs with its own, as the CLI does (she-2006's
    /// clamp-only joint limits); otherwise the person's options stay (an
    /// editor apply keeps a λ set in the panel). The method stays either way.
    pub(crate) fn load_creature(
        &mut self,
        creature: Creature,
        custom: Option<String>,
    ) -> Result<(), String> {
        let mut settings = self.session.settings.clone();
        if creature.scenario.ik != self.session.creature.scenario.ik {
            settings.ik = IkOptions {
                method: settings.method,
                ..creature.scenario.ik.clone()
            };
        }
        let driver = session::driver_for(&creature, &settings)?;
        self.session.settings.ik = settings.ik;
        let deprecations: Vec<String> = creature
            .deprecations()
            .iter()
            .map(ToString::to_string)
            .collect();
        self.session.notice = (!deprecations.is_empty()).then(|| deprecations.join("; "));
        self.stage = Stage::on_ground(driver);
        self.session.creature = creature;
        self.session.custom_preset = custom;
        // A problem shown belonged to the run this one replaces (a fall, a
        // blow-up and put-back): it does not stay over the new one.
        self.session.last_error = None;
        // A recording belongs to its skeleton.
        self.session.track = None;
        self.editor.preset_changed();
        // A take belongs to its skeleton.
        self.take.clear();
        // Frame the new creature from the home view, whatever the last one's.
        self.camera.home();
        self.outbox.push(Effect::PresetChanged);
        self.outbox.push(Effect::LinkChanged);
        self.restart_records();
        Ok(())
    }

    /// Sets the IK method.
    pub fn set_method(&mut self, method: Method) {
        self.session.settings.method = method;
        self.session.settings.ik.method = method;
        self.stage.driver.set_ik_method(method);
        self.outbox.push(Effect::LinkChanged);
    }

    /// Replaces the thesis parameters (speed, shapes, wounded weights) live.
    ///
    /// # Errors
    /// The parameter's `path: reason`; the driver keeps its parameters.
    pub fn set_params(
        &mut self,
        params: gaitlab_core::preset::thesis::ThesisParams,
    ) -> Result<(), String> {
        self.stage
            .driver
            .apply(EngineCommand::Thesis(Box::new(params)))
            .map(drop)
    }

    /// Applies the IK options in the settings (after a panel edit).
    pub fn apply_ik_options(&mut self) {
        let mut options = self.session.settings.ik.clone();
        options.method = self.session.settings.method;
        self.stage.driver.set_ik_options(options);
    }

    /// The engine of the creature being animated.
    #[must_use]
    pub fn engine(&self) -> Engine {
        self.session.creature.scenario.engine
    }

    /// Pauses or resumes.
    pub fn set_paused(&mut self, paused: bool) {
        self.playback.paused = paused;
    }

    /// Advances exactly one animation frame on the next update, even when paused.
    pub fn single_step(&mut self) {
        self.playback.single_step();
    }

    /// Frame 0 of the stage's driver: empty histories, no footprints, the
    /// plotted joints resolved again (the app redraws the scene and restarts
    /// its features after it).
    pub(crate) fn restart_records(&mut self) {
        self.stage.frame = 0;
        self.overlays.clear();
        self.playback.clear_accumulator();
        let creature = &self.session.creature;
        self.plots
            .resolve(creature, &self.session.settings.plot_joints);
        self.stage.history = if self.engine() == Engine::Physics {
            self.plots.show_physics_attitude();
            History::new(PHYSICS_BODY_SERIES.map(str::to_owned).to_vec())
        } else {
            History::new(
                creature
                    .skeleton
                    .effectors()
                    .iter()
                    .map(|e| e.name.clone())
                    .collect(),
            )
        };
    }

    /// Frame length of the animation, seconds (the preset's fps).
    #[must_use]
    pub fn frame_seconds(&self) -> f64 {
        self.session.creature.scenario.frame_seconds()
    }

    /// After a step of the single view: the plots, the take and the footprints.
    pub(crate) fn record_frame(&mut self) {
        let stage = &mut self.stage;
        if let Some(probe) = stage.driver.physics_probe() {
            let message = stage.driver.take_message();
            let t = probe.time_s;
            stage.history.push(
                t,
                [
                    probe.height_m,
                    probe.leg_length_m,
                    probe.ground_force_bw,
                    probe.phase_index as f64,
                ]
                .into_iter(),
            );
            self.plots
                .joint_history
                .push(t, [probe.pitch_deg, probe.roll_deg].into_iter());
            if let Some(message) = message.filter(|m| !m.is_empty()) {
                self.report_error(message);
            }
            self.record_take();
            return;
        }
        let driver = &stage.driver;
        let errors = driver
            .ik_report()
            .map(|r| &r.effector_error_m[..])
            .unwrap_or(&[]);
        stage.history.push(driver.time(), errors.iter().copied());
        self.plots.record_joints(
            driver.time(),
            &self.session.creature.skeleton,
            &driver.pose().joints,
        );
        self.record_take();
        self.overlays.note_footprints(&self.stage.driver);
    }

    fn record_take(&mut self) {
        if let Some(message) = self.take.record(&self.stage.driver) {
            self.report_error(message);
        }
    }

    /// Starts a new motion take (the previous one is dropped).
    pub fn start_recording(&mut self) {
        let fps = 1.0 / self.frame_seconds();
        self.take.start(&self.stage.driver, fps);
    }

    /// Stops appending to the take (it stays available to save).
    pub fn stop_recording(&mut self) {
        self.take.stop();
    }

    /// Whether a motion take is being recorded.
    #[must_use]
    pub fn recording(&self) -> bool {
        self.take.recording()
    }

    /// The current or last take.
    #[must_use]
    pub fn take(&self) -> Option<&Take> {
        self.take.take()
    }

    /// Queues the take as a `bvh` or `csv` file for the person: its last
    /// `last_s` seconds, or the whole take for `None`.
    ///
    /// # Errors
    /// An unknown format, no take, a bad `last_s`, or the writer's reason.
    pub fn save_take(&mut self, format: &str, last_s: Option<f64>) -> Result<(), String> {
        let settings = &self.session.settings;
        let stem = format!(
            "{}-{}-{}",
            self.session.creature.name,
            settings.mode.name(),
            settings.method.name()
        );
        let download = self.take.save(&self.stage.driver, format, last_s, &stem)?;
        self.outbox.push(Effect::Download(download));
        Ok(())
    }

    /// Queues the take as a file with the panel's "last N seconds" setting
    /// ([`Settings::export_last_s`]; 0 means the whole take).
    ///
    /// # Errors
    /// As [`Lab::save_take`].
    pub fn save_take_as_set(&mut self, format: &str) -> Result<(), String> {
        let last_s = self.session.settings.export_last_s;
        self.save_take(format, (last_s > 0.0).then_some(last_s))
    }

    /// Takes the oldest file queued for the person, if any.
    pub fn take_download(&mut self) -> Option<Download> {
        self.outbox.take_download()
    }

    /// Starts or stops the video recording of the 3-D view (carried out by the
    /// web front end, through [`Effect::StartVideo`] and [`Effect::StopVideo`]).
    pub fn set_video_recording(&mut self, on: bool) {
        if on == self.video.recording {
            return;
        }
        self.video.recording = on;
        self.outbox.push(if on {
            Effect::StartVideo
        } else {
            Effect::StopVideo
        });
    }

    /// Whether video of the 3-D view should be recording.
    #[must_use]
    pub fn video_recording(&self) -> bool {
        self.video.recording
    }

    /// The 3-D view's rectangle on the canvas, physical pixels `[x, y, w, h]`.
    #[must_use]
    pub fn view_rect_px(&self) -> [f32; 4] {
        self.layout.view_rect_px
    }

    /// Sets the plotted joints by name.
    ///
    /// # Errors
    /// A name the creature lacks, or more than [`MAX_PLOT_JOINTS`]; nothing changes then.
    pub fn set_plot_joints(&mut self, names: &[String]) -> Result<(), String> {
        plots::check_plot_joints(&self.session.creature, names)?;
        self.session.settings.plot_joints = names.to_vec();
        self.plots
            .resolve(&self.session.creature, &self.session.settings.plot_joints);
        Ok(())
    }

    /// Records the display frame rate from the UI's frame time.
    pub(crate) fn note_frame_time(&mut self, dt: f64) {
        self.playback.note_frame_time(dt);
    }
}
