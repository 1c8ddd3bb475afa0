//! The lab: one figure animated by a driver (She 2006's thesis motions for the
//! IK engine, PODA gaits for the `poda` engine), the settings a person changes, the 3-D scene and camera, the plot
//! history, and the last error to show. Front ends (eframe on the web, egui_kittest
//! natively) call [`Lab::ui`] once per frame.

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::Engine;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::preset::{Creature, load_bundled};
use gaitlab_core::{Kinematics, RootTransform};
use gaitlab_engine::{AnyDriver, Overrides, Take};
use gaitlab_motion::poda::GaitError;
use glam::DMat3;

use crate::history::History;
use crate::render::{Camera, Scene};
use crate::settings::Settings;

mod compare;
mod editor;

/// Longest real time one UI frame may advance the animation, seconds (a tab
/// that was hidden does not fast-forward).
const MAX_FRAME_ADVANCE_S: f64 = 0.1;

/// A monotonic clock in milliseconds, supplied by the platform (the core and the
/// lab read no clocks themselves).
pub type Clock = Box<dyn Fn() -> f64>;

/// The physics engine's body plot: trunk height (m), first leg's length (m),
/// vertical ground force (body weights) and the state machine's state (0 flight … 4 unloading).
pub const PHYSICS_BODY_SERIES: [&str; 4] = [
    "height (m)",
    "leg length (m)",
    "ground force (× weight)",
    "state (0–4)",
];

/// The physics engine's attitude plot, degrees.
pub const PHYSICS_ATTITUDE_SERIES: [&str; 2] = ["pitch (°)", "roll (°)"];

/// Most joints plotted at once.
pub const MAX_PLOT_JOINTS: usize = 8;

/// Joints plotted when the settings name none the creature has.
const DEFAULT_PLOT_JOINTS: [&str; 4] =
    ["left_hip_flex", "left_knee", "right_hip_flex", "right_knee"];

/// A file for the person: name, MIME type and contents.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Download {
    /// Suggested file name.
    pub file_name: String,
    /// MIME type.
    pub mime: &'static str,
    /// Contents.
    pub text: String,
}

/// The whole state of the lab.
pub struct Lab {
    /// What a person chose (persisted).
    pub settings: Settings,
    pub(crate) creature: Creature,
    pub(crate) driver: AnyDriver,
    pub(crate) camera: Camera,
    pub(crate) scene: Scene,
    pub(crate) kinematics: Kinematics,
    pub(crate) history: History,
    /// Frames advanced since the last reset.
    pub(crate) frame: u64,
    pub(crate) paused: bool,
    pending_steps: u32,
    accumulator_s: f64,
    /// The last problem to show (bad link, bad command, bad preset).
    pub(crate) last_error: Option<String>,
    /// Smoothed display frame rate, frames per second.
    pub(crate) fps: f64,
    /// Smoothed time spent advancing the driver per animation frame, µs.
    pub(crate) sim_us_per_frame: f64,
    clock: Option<Clock>,
    /// JSON of a preset loaded from a link or file rather than the bundle.
    pub(crate) custom_preset: Option<String>,
    /// Set when the state a link shows has changed (the web glue updates the URL).
    pub(crate) link_changed: bool,
    /// Set when the preset changed (the web glue pushes a history entry).
    pub(crate) preset_changed: bool,
    /// Joint-angle history for the plots (the joints in `plot_joints`).
    pub(crate) joint_history: History,
    /// Skeleton indices of the plotted joints.
    pub(crate) plot_joints: Vec<usize>,
    /// The motion take being recorded or last recorded.
    pub(crate) take: Option<Take>,
    /// Whether simulated frames are being appended to `take`.
    pub(crate) recording: bool,
    /// Whether the web glue should be recording video of the 3-D view.
    pub(crate) video_recording: bool,
    /// Frames the video recorder has copied (reported by the web front end).
    pub(crate) video_frames: u64,
    /// The encoder the video recorder uses (reported by the web front end;
    /// empty before the first recording).
    pub(crate) video_encoder: &'static str,
    /// Frames the video encoder skipped because it had fallen behind.
    pub(crate) video_skipped: u64,
    /// Seconds of video recorded so far (from the first recorded frame).
    pub(crate) video_seconds: f64,
    /// The 3-D view's rectangle on the canvas, physical pixels `[x, y, w, h]`.
    pub(crate) view_rect_px: [f32; 4],
    /// A file the front end should hand to the person (web: a download).
    pub(crate) pending_download: Option<Download>,
    /// The graphics path drawing the view ("webgpu (…)" or "webgl2 (…)"), when known.
    pub backend: Option<String>,
    /// What the last PODA gait edit derived, to say so in the gait panel.
    pub(crate) gait_derived: Vec<&'static str>,
    /// Recent PODA footprints (where supporting feet stood), oldest first.
    pub(crate) footprints: std::collections::VecDeque<glam::DVec3>,
    /// Each PODA leg's last recorded footprint.
    last_planted: Vec<glam::DVec3>,
    /// The side-by-side IK comparison, when one runs (it replaces the single view).
    pub(crate) compare: Option<crate::compare::Comparison>,
    /// The preset editor.
    pub(crate) editor: crate::editor::PresetEditor,
    /// The page's address without query or fragment (the web glue sets it;
    /// empty natively), the base of [`Lab::share_link`].
    pub page_url: String,
    /// The link "Copy link" made last, shown for copying by hand.
    pub(crate) shown_link: Option<String>,
    /// Set when the person asked to pick a preset file (the web glue opens the picker).
    pub(crate) file_pick_requested: bool,
    /// Forces the phone layout on or off (`None`: by the screen width).
    pub(crate) narrow_override: Option<bool>,
    /// Whether the last frame used the phone layout (controls in a drawer).
    pub(crate) narrow: bool,
    /// Whether the phone layout's controls drawer is open.
    pub(crate) controls_open: bool,
    /// The phone layout's "Controls" button, points (CSS pixels) `[x, y, w, h]`
    /// (zeros in the wide layout), for tests that tap it.
    pub(crate) controls_button_pt: [f32; 4],
    /// Whether the last frame was drawn with dark visuals.
    pub(crate) dark_mode: bool,
}

/// An edit of the PODA gait's shape (see [`Lab::edit_gait_shape`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GaitShapeEdit<'a> {
    /// Relative phase of one leg, a fraction of the period.
    Phase {
        /// Leg index.
        leg: usize,
        /// New relative phase.
        phase: f64,
    },
    /// Highest point of the transfer trajectory, metres.
    StepHeight(f64),
    /// Key leg positions `[along, height]` of the transfer trajectory.
    TransferKeys(&'a [[f64; 2]]),
}

/// Footprints kept for the ground overlay.
const MAX_FOOTPRINTS: usize = 48;
/// Length of body path drawn ahead of the figure, metres.
const PATH_AHEAD_M: f64 = 4.0;

/// A joint value as plotted: degrees for revolute joints, millimetres for prismatic ones.
fn display_value(skeleton: &gaitlab_core::Skeleton, joint: usize, value: f64) -> f64 {
    match skeleton.joints()[joint].kind {
        gaitlab_core::JointKind::Revolute => value.to_degrees(),
        gaitlab_core::JointKind::Prismatic => value * 1e3,
    }
}

/// A plotted joint's legend label with its unit.
fn plot_label(skeleton: &gaitlab_core::Skeleton, joint: usize) -> String {
    let j = &skeleton.joints()[joint];
    match j.kind {
        gaitlab_core::JointKind::Revolute => format!("{} (°)", j.name),
        gaitlab_core::JointKind::Prismatic => format!("{} (mm)", j.name),
    }
}

fn bundled_or_default(name: &str) -> Result<Creature, String> {
    match load_bundled(name) {
        Some(Ok(creature)) => Ok(creature),
        Some(Err(error)) => Err(format!("bundled preset {name}: {error}")),
        None => Err(format!("no bundled preset named {name:?}")),
    }
}

fn default_creature() -> Creature {
    match bundled_or_default(gaitlab_core::preset::DEFAULT_PRESET) {
        Ok(creature) => creature,
        // The bundled default is checked by the core's tests; this cannot happen.
        Err(error) => unreachable!("{error}"),
    }
}

/// The lab's driver for `creature` with the person's settings, through the
/// engine layer's one `driver_for`.
fn driver_for(creature: &Creature, settings: &Settings) -> Result<AnyDriver, String> {
    let overrides = Overrides {
        mode: Some(settings.mode),
        method: Some(settings.method),
        ik: Some(settings.ik.clone()),
        heading_deg: Some(settings.heading_deg),
        ..Overrides::default()
    };
    gaitlab_engine::driver_for(creature, &overrides).map_err(|e| {
        if e.path.starts_with("ik") || e.path == "heading_deg" {
            format!("settings.{e}")
        } else {
            format!("preset {}: {e}", creature.name)
        }
    })
}

impl Lab {
    /// A lab with `settings`; an unknown preset falls back to the default one and
    /// leaves a message.
    #[must_use]
    pub fn new(settings: Settings) -> Self {
        let mut settings = settings;
        let mut last_error = None;
        let creature = match bundled_or_default(&settings.preset) {
            Ok(creature) => creature,
            Err(error) => {
                last_error = Some(error);
                settings.preset = gaitlab_core::preset::DEFAULT_PRESET.to_owned();
                default_creature()
            }
        };
        let driver = match driver_for(&creature, &settings) {
            Ok(driver) => driver,
            Err(error) => {
                last_error = Some(error);
                settings = Settings::default();
                match driver_for(&default_creature(), &settings) {
                    Ok(driver) => driver,
                    Err(error) => unreachable!("the default preset drives: {error}"),
                }
            }
        };
        let kinematics = Kinematics::new(driver.skeleton());
        let mut lab = Self {
            settings,
            history: History::default(),
            creature,
            driver,
            camera: Camera::default(),
            scene: Scene::default(),
            kinematics,
            frame: 0,
            paused: false,
            pending_steps: 0,
            accumulator_s: 0.0,
            last_error,
            fps: 0.0,
            sim_us_per_frame: 0.0,
            clock: None,
            custom_preset: None,
            link_changed: false,
            preset_changed: false,
            backend: None,
            joint_history: History::default(),
            plot_joints: Vec::new(),
            take: None,
            recording: false,
            video_recording: false,
            video_frames: 0,
            video_encoder: "",
            video_skipped: 0,
            video_seconds: 0.0,
            view_rect_px: [0.0; 4],
            pending_download: None,
            gait_derived: Vec::new(),
            footprints: std::collections::VecDeque::with_capacity(MAX_FOOTPRINTS),
            last_planted: Vec::new(),
            compare: None,
            editor: crate::editor::PresetEditor::default(),
            page_url: String::new(),
            shown_link: None,
            file_pick_requested: false,
            narrow_override: None,
            narrow: false,
            controls_open: false,
            controls_button_pt: [0.0; 4],
            dark_mode: true,
        };
        lab.after_reset();
        lab
    }

    /// Supplies the platform clock used to time the simulation.
    pub fn set_clock(&mut self, clock: Clock) {
        self.clock = Some(clock);
    }

    /// The creature being animated.
    #[must_use]
    pub fn creature(&self) -> &Creature {
        &self.creature
    }

    /// The driver animating it.
    #[must_use]
    pub fn driver(&self) -> &AnyDriver {
        &self.driver
    }

    /// Frames advanced since the last reset.
    #[must_use]
    pub fn frame(&self) -> u64 {
        self.frame
    }

    /// Whether the animation is paused.
    #[must_use]
    pub fn paused(&self) -> bool {
        self.paused
    }

    /// The last error message, if any.
    #[must_use]
    pub fn last_error(&self) -> Option<&str> {
        self.last_error.as_deref()
    }

    /// Records a problem to show.
    pub fn report_error(&mut self, message: impl Into<String>) {
        self.last_error = Some(message.into());
    }

    /// Clears the shown problem.
    pub fn clear_error(&mut self) {
        self.last_error = None;
    }

    /// Smoothed µs per animation frame spent in the driver (needs a clock).
    #[must_use]
    pub fn sim_us_per_frame(&self) -> f64 {
        self.sim_us_per_frame
    }

    /// Switches to a bundled preset (its own default scenario, keeping the chosen mode and method).
    ///
    /// # Errors
    /// If no bundled preset has that name or it cannot drive the thesis motions;
    /// the current preset stays.
    pub fn set_preset(&mut self, name: &str) -> Result<(), String> {
        let creature = bundled_or_default(name)?;
        self.install(creature, None)?;
        self.settings.preset = name.to_owned();
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

    fn install(&mut self, creature: Creature, custom: Option<String>) -> Result<(), String> {
        let driver = driver_for(&creature, &self.settings)?;
        self.kinematics = Kinematics::new(driver.skeleton());
        self.creature = creature;
        self.driver = driver;
        self.custom_preset = custom;
        self.editor.preset_changed();
        // A take belongs to its skeleton.
        self.take = None;
        self.recording = false;
        // Frame the new creature from scratch.
        self.camera.framed = false;
        self.preset_changed = true;
        self.link_changed = true;
        self.after_reset();
        self.rebuild_compare();
        Ok(())
    }

    /// Sets the thesis motion.
    pub fn set_mode(&mut self, mode: ThesisMode) {
        self.settings.mode = mode;
        if let Some(driver) = self.driver.thesis_mut() {
            driver.set_mode(mode);
        }
        if let Some(compare) = self.compare.as_mut() {
            compare.set_mode(mode);
        }
        self.link_changed = true;
    }

    /// Sets the IK method.
    pub fn set_method(&mut self, method: Method) {
        self.settings.method = method;
        self.settings.ik.method = method;
        if let Some(driver) = self.driver.thesis_mut() {
            driver.set_method(method);
        }
        self.link_changed = true;
    }

    /// Replaces the thesis parameters (speed, shapes, wounded weights) live.
    ///
    /// # Errors
    /// The parameter's `path: reason`; the driver keeps its parameters.
    pub fn set_params(
        &mut self,
        params: gaitlab_core::preset::thesis::ThesisParams,
    ) -> Result<(), String> {
        let Some(driver) = self.driver.thesis_mut() else {
            return Err("scenario.thesis: engine poda has no thesis parameters".to_owned());
        };
        driver
            .set_params(params)
            .map_err(|e| format!("scenario.thesis.{e}"))
    }

    /// Applies the IK options in the settings (after a panel edit).
    pub fn apply_ik_options(&mut self) {
        let mut options = self.settings.ik.clone();
        options.method = self.settings.method;
        if let Some(driver) = self.driver.thesis_mut() {
            driver.set_options(options);
        }
    }

    /// Applies a new figure heading (restarts the motion facing that way).
    pub fn set_heading_deg(&mut self, degrees: f64) {
        self.settings.heading_deg = degrees.clamp(-180.0, 180.0);
        if let Some(driver) = self.driver.physics_mut() {
            // A running creature turns toward the new heading (no reset).
            driver.set_heading(self.settings.heading_deg.to_radians());
            return;
        }
        if let Some(driver) = self.driver.thesis_mut() {
            driver.set_origin(RootTransform {
                rotation: DMat3::from_rotation_y(self.settings.heading_deg.to_radians()),
                ..RootTransform::default()
            });
        }
        self.reset();
    }

    /// The engine of the creature being animated.
    #[must_use]
    pub fn engine(&self) -> Engine {
        self.creature.scenario.engine
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
        let name = gaitlab_engine::bundled_for_engine(engine, &self.creature.name);
        self.set_preset(name)
    }

    /// Switches the PODA gait (blending over one cycle).
    ///
    /// # Errors
    /// `gait: reason` when the engine has no gaits or the name is unknown for
    /// the creature's leg count; nothing changes.
    pub fn set_gait(&mut self, name: &str) -> Result<(), String> {
        if let Some(driver) = self.driver.physics_mut() {
            driver
                .set_gait(name)
                .map_err(|e| format!("gait: {}", e.reason))?;
            self.link_changed = true;
            return Ok(());
        }
        let Some(driver) = self.driver.poda_mut() else {
            return Err(format!(
                "gait: engine {} has no gaits (use mode)",
                self.creature.scenario.engine.name()
            ));
        };
        driver.set_gait(name).map_err(|e| e.to_string())?;
        self.link_changed = true;
        Ok(())
    }

    /// Sets one PODA gait value (`period_s`, `duty_factor`, `speed_mps`,
    /// `stroke_m`, or `leg_force_n`, each leg's upward force during support,
    /// eq. 12–13); the gait model derives the others so that eq. 7–8 (and
    /// eq. 13 for the force) stay true, and [`Lab::gait_derived`] names what it
    /// derived.
    ///
    /// # Errors
    /// `key: reason` when the engine has no gait, the key is unknown, or the
    /// value (or a value derived from it) is out of range; nothing changes.
    pub fn edit_gait(&mut self, key: &str, value: f64) -> Result<(), String> {
        if let Some(driver) = self.driver.physics_mut() {
            return match key {
                "speed_mps" => driver.set_speed(value).map_err(|e| e.to_string()),
                "hop_height_m" => driver.set_hop_height(value).map_err(|e| e.to_string()),
                _ => Err(format!(
                    "{key}: engine physics has no such gait value (speed_mps, hop_height_m)"
                )),
            };
        }
        let Some(driver) = self.driver.poda_mut() else {
            return Err(format!(
                "{key}: engine {} has no gait",
                self.creature.scenario.engine.name()
            ));
        };
        if key == "leg_force_n" {
            let derived = driver
                .set_leg_force_n(value)
                .map_err(|e| GaitError::new(key, e.reason).to_string())?;
            self.gait_derived = derived.derived.to_vec();
            return Ok(());
        }
        let gait = driver.gait_mut();
        let derived = match key {
            "period_s" => gait.set_period(value),
            "duty_factor" => gait.set_duty_factor(value),
            "speed_mps" => gait.set_speed(value),
            "stroke_m" => gait.set_stroke(value),
            _ => return Err(format!("{key}: not a gait value")),
        }
        .map_err(|e| e.to_string())?;
        self.gait_derived = derived.derived.to_vec();
        Ok(())
    }

    /// Sets a physics controller gain by name (the Gains sliders and the
    /// `gain` command).
    ///
    /// # Errors
    /// `gain: …` when the engine is not physics, `gain.NAME: reason` for an
    /// unknown gain or a negative or non-finite value; nothing changes.
    pub fn set_gain(&mut self, name: &str, value: f64) -> Result<(), String> {
        let engine = self.creature.scenario.engine.name();
        let Some(driver) = self.driver.physics_mut() else {
            return Err(format!("gain: engine {engine} has no controller gains"));
        };
        driver.set_gain(name, value)
    }

    /// Sets leg `leg`'s relative phase (eq. 9), the step height or the
    /// transfer key positions of the PODA gait.
    ///
    /// # Errors
    /// `key: reason` when the engine has no gait or the value is out of
    /// range; nothing changes.
    pub fn edit_gait_shape(&mut self, edit: GaitShapeEdit<'_>) -> Result<(), String> {
        let engine = self.creature.scenario.engine.name();
        let Some(driver) = self.driver.poda_mut() else {
            return Err(format!("gait: engine {engine} has no gait"));
        };
        match edit {
            GaitShapeEdit::Phase { leg, phase } => driver
                .gait_mut()
                .set_phase(leg, phase)
                .map(drop)
                .map_err(|e| format!("phases[{leg}]: {}", e.reason)),
            GaitShapeEdit::StepHeight(height) => {
                driver.set_step_height(height).map_err(|e| e.to_string())
            }
            GaitShapeEdit::TransferKeys(keys) => {
                driver.set_transfer_keys(keys).map_err(|e| e.to_string())
            }
        }
    }

    /// Sets a PODA leg joint's center angle (radians, or metres for prismatic
    /// joints) and gain (eq. 6).
    ///
    /// # Errors
    /// `center.…: reason`; nothing changes.
    pub fn set_center(&mut self, joint: &str, center: f64, gain: f64) -> Result<(), String> {
        let engine = self.creature.scenario.engine.name();
        let Some(driver) = self.driver.poda_mut() else {
            return Err(format!(
                "center: engine {engine} sets centers in its IK panel"
            ));
        };
        driver
            .set_center(joint, center, gain)
            .map_err(|e| e.to_string())
    }

    /// Replaces the PODA body path (the body joins it where it is closest).
    ///
    /// # Errors
    /// `path.…: reason`; nothing changes.
    pub fn set_path(&mut self, spec: &gaitlab_core::preset::PathSpec) -> Result<(), String> {
        let engine = self.creature.scenario.engine.name();
        let Some(driver) = self.driver.poda_mut() else {
            return Err(format!("path: engine {engine} has no body path"));
        };
        driver.set_path(spec).map_err(|e| e.to_string())?;
        self.refresh_scene();
        Ok(())
    }

    /// What the last gait edit derived (e.g. `support_s`, `period_s`).
    #[must_use]
    pub fn gait_derived(&self) -> &[&'static str] {
        &self.gait_derived
    }

    /// Pauses or resumes.
    pub fn set_paused(&mut self, paused: bool) {
        self.paused = paused;
    }

    /// Advances exactly one animation frame on the next update, even when paused.
    pub fn single_step(&mut self) {
        self.pending_steps = self.pending_steps.saturating_add(1).min(600);
    }

    /// Back to time 0 and the rest pose.
    pub fn reset(&mut self) {
        self.driver.reset();
        if let Some(compare) = self.compare.as_mut() {
            compare.reset();
        }
        self.after_reset();
    }

    fn after_reset(&mut self) {
        self.frame = 0;
        self.footprints.clear();
        self.last_planted.clear();
        self.accumulator_s = 0.0;
        let names = self
            .creature
            .skeleton
            .effectors()
            .iter()
            .map(|e| e.name.clone())
            .collect();
        self.history = History::new(names);
        self.resolve_plot_joints();
        if self.driver.physics().is_some() {
            self.history = History::new(PHYSICS_BODY_SERIES.map(str::to_owned).to_vec());
            self.joint_history = History::new(PHYSICS_ATTITUDE_SERIES.map(str::to_owned).to_vec());
        }
        self.refresh_scene();
    }

    /// Frame length of the animation, seconds (the preset's fps).
    #[must_use]
    pub fn frame_seconds(&self) -> f64 {
        self.creature.scenario.frame_seconds()
    }

    /// Advances the animation by `real_dt` seconds of wall time in fixed frames
    /// of [`Lab::frame_seconds`]; paused labs only take requested single steps.
    pub fn advance(&mut self, real_dt: f64) {
        let dt = self.frame_seconds();
        let mut steps = 0;
        if self.paused {
            steps = self.pending_steps;
            self.accumulator_s = 0.0;
        } else if real_dt.is_finite() && real_dt > 0.0 {
            self.accumulator_s += real_dt.min(MAX_FRAME_ADVANCE_S);
            while self.accumulator_s >= dt {
                self.accumulator_s -= dt;
                steps += 1;
            }
            steps += self.pending_steps;
        }
        self.pending_steps = 0;
        if steps == 0 {
            return;
        }
        let started = self.clock.as_ref().map(|clock| clock());
        for _ in 0..steps {
            if let Some(compare) = self.compare.as_mut() {
                // The views replace the single figure, in lock step.
                compare.step(dt, self.clock.as_deref());
                self.frame += 1;
                continue;
            }
            self.driver.step(dt);
            self.frame += 1;
            if let Some(physics) = self.driver.physics_mut() {
                let message = physics.take_message();
                let probe = physics.probe();
                let t = physics.time();
                self.history.push(
                    t,
                    [
                        probe.height_m,
                        probe.leg_length_m,
                        probe.ground_force_bw,
                        probe.phase_index as f64,
                    ]
                    .into_iter(),
                );
                self.joint_history
                    .push(t, [probe.pitch_deg, probe.roll_deg].into_iter());
                if let Some(message) = message.filter(|m| !m.is_empty()) {
                    self.report_error(message);
                }
                if self.recording {
                    self.record_frame();
                }
                continue;
            }
            let errors = self
                .driver
                .ik_report()
                .map(|r| &r.effector_error_m[..])
                .unwrap_or(&[]);
            self.history
                .push(self.driver.time(), errors.iter().copied());
            let joints = &self.driver.pose().joints;
            let skeleton = &self.creature.skeleton;
            self.joint_history.push(
                self.driver.time(),
                self.plot_joints
                    .iter()
                    .map(|&j| display_value(skeleton, j, joints[j])),
            );
            if self.recording {
                self.record_frame();
            }
            self.note_footprints();
        }
        if let (Some(started), Some(clock)) = (started, self.clock.as_ref()) {
            let per_frame_us = (clock() - started) * 1e3 / f64::from(steps);
            self.sim_us_per_frame = if self.sim_us_per_frame == 0.0 {
                per_frame_us
            } else {
                0.9 * self.sim_us_per_frame + 0.1 * per_frame_us
            };
        }
        self.refresh_scene();
    }

    fn record_frame(&mut self) {
        let Some(take) = self.take.as_mut() else {
            self.recording = false;
            return;
        };
        let targets = self
            .driver
            .targets()
            .map(|t| &t.position[..])
            .unwrap_or(&[]);
        let pushed = take.push(
            self.driver.time(),
            self.driver.pose(),
            self.driver.effector_positions(),
            targets,
        );
        if !pushed {
            self.recording = false;
            if take.is_full() {
                self.last_error = Some(format!(
                    "recording: stopped at the {:.0} s limit",
                    gaitlab_engine::MAX_TAKE_S
                ));
            }
        }
    }

    /// Starts a new motion take (the previous one is dropped).
    pub fn start_recording(&mut self) {
        // The driver's skeleton is the one drawn (a physics creature's is scaled by L).
        self.take = Some(Take::new(
            self.driver.skeleton(),
            1.0 / self.frame_seconds(),
            self.driver.targets().is_some(),
        ));
        self.recording = true;
    }

    /// Stops appending to the take (it stays available to save).
    pub fn stop_recording(&mut self) {
        self.recording = false;
    }

    /// Whether a motion take is being recorded.
    #[must_use]
    pub fn recording(&self) -> bool {
        self.recording
    }

    /// The current or last take.
    #[must_use]
    pub fn take(&self) -> Option<&Take> {
        self.take.as_ref()
    }

    /// Queues the take as a `bvh` or `csv` file for the person: its last
    /// `last_s` seconds, or the whole take for `None`.
    ///
    /// # Errors
    /// An unknown format, no take, a bad `last_s`, or the writer's reason.
    pub fn save_take(&mut self, format: &str, last_s: Option<f64>) -> Result<(), String> {
        let take = self
            .take
            .as_ref()
            .ok_or("save: nothing recorded yet (start a recording first)")?;
        let skeleton = self.driver.skeleton();
        let (text, mime) = match format {
            "bvh" => (take.to_bvh(skeleton, last_s)?, "text/plain"),
            "csv" => (take.to_csv(skeleton, last_s)?, "text/csv"),
            other => return Err(format!("save: unknown format {other:?} (bvh, csv)")),
        };
        let file_name = format!(
            "gaitlab-{}-{}-{}.{format}",
            self.creature.name,
            self.settings.mode.name(),
            self.settings.method.name()
        );
        self.pending_download = Some(Download {
            file_name,
            mime,
            text,
        });
        Ok(())
    }

    /// Queues the take as a file with the panel's "last N seconds" setting
    /// ([`Settings::export_last_s`]; 0 means the whole take).
    ///
    /// # Errors
    /// As [`Lab::save_take`].
    pub fn save_take_as_set(&mut self, format: &str) -> Result<(), String> {
        let last_s = self.settings.export_last_s;
        self.save_take(format, (last_s > 0.0).then_some(last_s))
    }

    /// Takes the file queued for the person, if any.
    pub fn take_download(&mut self) -> Option<Download> {
        self.pending_download.take()
    }

    /// Starts or stops the video recording of the 3-D view (carried out by the
    /// web front end).
    pub fn set_video_recording(&mut self, on: bool) {
        self.video_recording = on;
    }

    /// Whether video of the 3-D view should be recording.
    #[must_use]
    pub fn video_recording(&self) -> bool {
        self.video_recording
    }

    /// The 3-D view's rectangle on the canvas, physical pixels `[x, y, w, h]`.
    #[must_use]
    pub fn view_rect_px(&self) -> [f32; 4] {
        self.view_rect_px
    }

    /// Sets the plotted joints by name.
    ///
    /// # Errors
    /// A name the creature lacks, or more than [`MAX_PLOT_JOINTS`]; nothing changes then.
    pub fn set_plot_joints(&mut self, names: &[String]) -> Result<(), String> {
        if names.len() > MAX_PLOT_JOINTS {
            return Err(format!(
                "plot_joints: at most {MAX_PLOT_JOINTS} joints, got {}",
                names.len()
            ));
        }
        for (i, name) in names.iter().enumerate() {
            if self.creature.skeleton.joint_index(name).is_none() {
                return Err(format!(
                    "plot_joints[{i}]: {} has no joint named {name:?}",
                    self.creature.name
                ));
            }
        }
        self.settings.plot_joints = names.to_vec();
        self.resolve_plot_joints();
        Ok(())
    }

    /// The plotted joints' indices from the settings' names; falls back to the
    /// hips and knees, or the first joints, when none of the names exist.
    fn resolve_plot_joints(&mut self) {
        let skeleton = &self.creature.skeleton;
        let find = |names: Vec<&str>| -> Vec<usize> {
            let mut found: Vec<usize> = names
                .into_iter()
                .filter_map(|n| skeleton.joint_index(n))
                .collect();
            found.dedup();
            found.truncate(MAX_PLOT_JOINTS);
            found
        };
        let mut joints = find(
            self.settings
                .plot_joints
                .iter()
                .map(String::as_str)
                .collect(),
        );
        if joints.is_empty() {
            joints = find(DEFAULT_PLOT_JOINTS.to_vec());
        }
        if joints.is_empty()
            && let Some(poda) = &self.creature.scenario.poda
        {
            // Each leg's hip, up to four legs.
            joints = find(poda.legs.iter().take(4).map(|l| l.hip.as_str()).collect());
        }
        if joints.is_empty() {
            joints = (0..skeleton.joint_count().min(4)).collect();
        }
        let names = joints.iter().map(|&j| plot_label(skeleton, j)).collect();
        self.plot_joints = joints;
        self.joint_history = History::new(names);
    }

    /// Rebuilds the 3-D scene from the driver's current pose.
    /// Records a footprint for every PODA foot that landed since the last frame.
    fn note_footprints(&mut self) {
        let Some(driver) = self.driver.poda() else {
            return;
        };
        for (leg, (target, support)) in driver.foot_targets().enumerate() {
            if leg >= self.last_planted.len() {
                self.last_planted.resize(leg + 1, glam::DVec3::NAN);
            }
            if support && self.last_planted[leg].distance_squared(target) > 1e-12 {
                self.last_planted[leg] = target;
                if self.footprints.len() == MAX_FOOTPRINTS {
                    self.footprints.pop_front();
                }
                self.footprints.push_back(target);
            }
        }
    }

    fn refresh_scene(&mut self) {
        if let Some(compare) = self.compare.as_mut() {
            compare.refresh_scenes(&self.settings.view);
        }
        // The driver's skeleton: a physics creature's is scaled by L (Table 1).
        let skeleton = self.driver.skeleton();
        let pose = self.driver.pose();
        self.kinematics.update(skeleton, &pose.root, &pose.joints);
        self.scene.fill(
            skeleton,
            &self.kinematics,
            pose.root.position,
            self.driver.targets(),
            &self.settings.view,
        );
        if let Some(driver) = self.driver.physics() {
            let boxes = driver.sim().terrain.obstacles.iter().map(|o| {
                (
                    glam::DVec3::new(o.min_xz[0], 0.0, o.min_xz[1]),
                    glam::DVec3::new(o.max_xz[0], o.height_m, o.max_xz[1]),
                )
            });
            self.scene
                .add_physics_overlay(driver.trunk_capsule(), boxes);
        }
        if let Some(driver) = self.driver.poda()
            && self.settings.view.targets
        {
            let path = driver.path();
            let start = driver.path_distance_m();
            let steps = 40;
            self.scene.add_gait_overlay(
                self.footprints.iter().copied(),
                driver.footholds(),
                (0..=steps).map(|k| {
                    path.sample(start + PATH_AHEAD_M * f64::from(k) / f64::from(steps))
                        .position
                }),
            );
        }
    }

    /// Records the display frame rate from the UI's frame time.
    pub(crate) fn note_frame_time(&mut self, dt: f64) {
        if dt > 0.0 && dt.is_finite() {
            let fps = 1.0 / dt;
            self.fps = if self.fps == 0.0 {
                fps
            } else {
                0.95 * self.fps + 0.05 * fps
            };
        }
    }
}
