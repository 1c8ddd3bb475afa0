//! The `command(json)` API (DESIGN.md "Browser", docs/app.md): the typed
//! [`Command`] — every key optional, unknown keys refused — and
//! [`App::command`], which reads it whole and then applies its keys in a fixed
//! order. Commands are plain data; nothing in them is evaluated.

use std::collections::BTreeMap;

use serde::Deserialize;
use serde::de::{Deserializer, MapAccess, Visitor};

use super::camera::CameraCommand;
use super::error::{from_value, object, present};
use super::names::{
    EngineName, JacobianAtName, MethodName, ModeName, SaveFormatName, ThemeName,
    TransposeAlphaName, VideoSizeName,
};
use crate::app::App;
use crate::compare::CompareValue;
use crate::lab::GaitShapeEdit;

/// Longest command text accepted, bytes (a custom preset rides in `preset_json`).
pub const MAX_COMMAND_BYTES: usize = 300 * 1024;

/// `gain`: one physics controller gain.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct GainCommand {
    /// The gain's name (`state().physics.gains` lists them).
    pub name: String,
    /// Its new value.
    pub value: f64,
}

/// `center`: a PODA leg joint's eq. 6 center and gain.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct CenterCommand {
    /// A leg joint's name.
    pub joint: String,
    /// The joint angle the leg is pulled toward, radians.
    pub center: f64,
    /// How hard, 0–1.
    pub gain: f64,
}

/// `views`: view flags to set (the others stay).
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ViewsCommand {
    /// World axes at the origin.
    pub world_axes: Option<bool>,
    /// Joint frames.
    pub joint_axes: Option<bool>,
    /// IK targets.
    pub targets: Option<bool>,
    /// Perspective (true) or orthographic projection.
    pub perspective: Option<bool>,
    /// The camera follows the figure.
    pub follow: Option<bool>,
    /// The ground grid.
    pub grid: Option<bool>,
    /// The figure's shadow.
    pub shadow: Option<bool>,
    /// Each effector's manipulability ellipsoid.
    pub ellipsoids: Option<bool>,
    /// Each limb's reach shell.
    pub reach_shells: Option<bool>,
}

/// `save`'s object form.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct SaveObject {
    /// The file format.
    pub format: SaveFormatName,
    /// Seconds at the take's end to write; 0 or null for all.
    pub last_s: Option<f64>,
}

/// `save`: a format (the panel's "last N seconds" apply) or `{format, last_s}`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "schema", schemars(untagged))]
pub enum SaveCommand {
    /// `"bvh"` or `"csv"`.
    Format(SaveFormatName),
    /// `{"format": "bvh", "last_s": 5}`.
    Object(SaveObject),
}

impl<'de> Deserialize<'de> for SaveCommand {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Save;
        impl<'de> Visitor<'de> for Save {
            type Value = SaveCommand;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("\"bvh\", \"csv\" or {\"format\", \"last_s\"}")
            }
            fn visit_str<E: serde::de::Error>(self, text: &str) -> Result<SaveCommand, E> {
                SaveFormatName::deserialize(serde::de::value::StrDeserializer::<E>::new(text))
                    .map(SaveCommand::Format)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<SaveCommand, A::Error> {
                SaveObject::deserialize(serde::de::value::MapAccessDeserializer::new(map))
                    .map(SaveCommand::Object)
            }
        }
        deserializer.deserialize_any(Save)
    }
}

/// One `command(json)` object. Every key is optional; [`App::command`]
/// applies them in the order of these fields. `null` counts as absent except
/// for `compare` (leaves the comparison) and `narrow` (follow the width).
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(
    feature = "schema",
    schemars(
        title = "gaitlab command",
        description = "One window.gaitlab.command(json) object (docs/app.md)."
    )
)]
#[serde(deny_unknown_fields)]
pub struct Command {
    /// `ik`, `poda` or `physics`: loads the matching creature.
    pub engine: Option<EngineName>,
    /// A bundled preset's name.
    pub preset: Option<String>,
    /// A whole preset file's text (gaitlab-preset/1).
    pub preset_json: Option<String>,
    /// The ground under the figure (the preset's `scenario.terrain`, as the
    /// Terrain panel builds it: `{"kind": "stairs", "rise_m": 0.05, …}`,
    /// `{"kind": "flat"}` for the floor); the walk starts again on it and
    /// the link carries it.
    pub terrain: Option<gaitlab_core::terrain::Terrain>,
    /// The PODA or physics gait's name.
    pub gait: Option<String>,
    /// PODA cycle period P, seconds (each gait edit keeps eq. 7–8 true).
    pub period_s: Option<f64>,
    /// PODA duty factor β.
    pub duty_factor: Option<f64>,
    /// PODA body speed, or the physics controllers' desired speed, m/s.
    pub speed_mps: Option<f64>,
    /// PODA stroke, metres.
    pub stroke_m: Option<f64>,
    /// PODA leg force, newtons.
    pub leg_force_n: Option<f64>,
    /// The physics controllers' hop height, metres.
    pub hop_height_m: Option<f64>,
    /// The physics creature's dynamic scale L (Table 1), as the panel's
    /// "Scale L" slider: the creature starts again at that size.
    pub physics_scale: Option<f64>,
    /// Put a box this many metres ahead of the kangaroo, which jumps it
    /// (the panel's "Place a box 3 m ahead"), [1, 20].
    pub obstacle_ahead_m: Option<f64>,
    /// Push the physics creature now: change its trunk's horizontal
    /// velocity by `[x, z]` m/s (world; z is forward at heading 0), each
    /// within ±10 (`run --push`; `state().physics.pushes` tells whether it
    /// recovered).
    pub push_mps: Option<[f64; 2]>,
    /// The physics creature's path: waypoints `[x, z]`, metres, followed
    /// from the first (the panel's waypoint editor); `[]` clears it.
    pub waypoints: Option<Vec<[f64; 2]>>,
    /// One physics controller gain.
    #[serde(default, deserialize_with = "object")]
    pub gain: Option<GainCommand>,
    /// Physics controller gains by name (applied in name order).
    pub gains: Option<BTreeMap<String, f64>>,
    /// PODA leg phases, one per leg, in cycles.
    pub phases: Option<Vec<f64>>,
    /// PODA step height, metres.
    pub step_height_m: Option<f64>,
    /// PODA transfer curve keys, `[[along, height], …]`.
    pub transfer_keys: Option<Vec<[f64; 2]>>,
    /// The PODA body path.
    pub path: Option<gaitlab_core::preset::PathSpec>,
    /// A PODA leg joint's eq. 6 center.
    #[serde(default, deserialize_with = "object")]
    pub center: Option<CenterCommand>,
    /// The thesis script.
    pub mode: Option<ModeName>,
    /// The IK method.
    pub method: Option<MethodName>,
    /// The side-by-side IK comparison: an object starts or changes it, `false` leaves.
    #[serde(default, deserialize_with = "present")]
    pub compare: Option<CompareValue>,
    /// Pause (true) or run.
    pub paused: Option<bool>,
    /// Same as `paused`.
    pub pause: Option<bool>,
    /// true: back to time 0.
    pub reset: Option<bool>,
    /// true: one frame forward.
    pub step: Option<bool>,
    /// true: pause and run one IK iteration (the first of the next frame,
    /// or the next of a frame already opened; the frame's last iteration
    /// closes it). The IK engine's thesis script only.
    pub iterate: Option<bool>,
    /// Hold, let go of or pin an effector's target in every figure on
    /// screen (the 3-D view's grab and pull).
    #[serde(default, deserialize_with = "object")]
    pub drag_target: Option<crate::grab::DragTargetCommand>,
    /// Every pinned target at once: effector name → where, `[x, y, z]` in
    /// the root's frame, metres (`state().pinned_targets`; `{}` unpins all).
    pub pinned_targets: Option<std::collections::BTreeMap<String, [f64; 3]>>,
    /// Playback rate, simulated seconds per wall second, [0.1, 2].
    pub playback_rate: Option<f64>,
    /// Pause and step back this many seconds of simulated time, [0, 10]
    /// (to the oldest stored frame at most); the history scrubber.
    pub step_back_s: Option<f64>,
    /// Pause and go to this frame of the stored history (clamped to it).
    pub rewind_to_frame: Option<u64>,
    /// DLS damping λ, metres, (0, 10] (`scenario.ik.lambda`'s range).
    pub lambda: Option<f64>,
    /// SDLS γmax, radians, (0, π].
    pub gamma_max: Option<f64>,
    /// Step clamp, radians, (0, π]: pinv's (She 2006 §4.4.2), and every
    /// method's with `clamp_every_method`.
    pub max_step: Option<f64>,
    /// The lab's addition: the step clamp on transpose and DLS too (She 2006
    /// §4.4.2 clamps pinv only).
    pub clamp_every_method: Option<bool>,
    /// Buss's target clamp, metres, [0, 10]: each effector's error is cut
    /// to this length before the solve (the lab's addition; 0 off).
    pub target_clamp_m: Option<f64>,
    /// The transpose method's α: `thesis` (§4.4.1) or `buss` (twice it).
    pub transpose_alpha: Option<TransposeAlphaName>,
    /// `true`: measure the running thesis motion's λ trade-off (DLS at
    /// λ = 0.01 … 1 m, 10 s each; `state().ik.lambda_tradeoff`).
    pub measure_lambda_tradeoff: Option<bool>,
    /// Null-space gain, [0, 10].
    pub null_space_gain: Option<f64>,
    /// Keep joints inside their limits.
    pub enforce_limits: Option<bool>,
    /// Solves per IK iteration while joints hit their limits, 1 to 16: 1
    /// clamps each joint to its limits (She 2006 §6.1.1.1); more re-solve
    /// without the clamped joints (the lab's addition).
    pub limit_passes: Option<usize>,
    /// She 2006 §3.2's control way: `effectors` (the Jacobian at the end
    /// effectors, which move towards the targets; the default) or `targets`
    /// (the Jacobian at the targets: targets move towards the end effectors).
    pub jacobian_at: Option<JacobianAtName>,
    /// The walking direction, degrees, [-180, 180].
    pub heading_deg: Option<f64>,
    /// Show the plots.
    pub plots: Option<bool>,
    /// The joints the plots show, by name.
    pub plot_joints: Option<Vec<String>>,
    /// Record the motion take (on/off).
    pub record: Option<bool>,
    /// Seconds the panel's saves write (0: all).
    pub last_s: Option<f64>,
    /// Download the take (or its last seconds).
    pub save: Option<SaveCommand>,
    /// The video recording's size.
    pub video_size: Option<VideoSizeName>,
    /// Record video (on/off).
    pub record_video: Option<bool>,
    /// The colours.
    pub theme: Option<ThemeName>,
    /// Force the phone layout on (true) or off (false); null follows the width.
    #[serde(default, deserialize_with = "present")]
    pub narrow: Option<Option<bool>>,
    /// Open or close the help window.
    pub help: Option<bool>,
    /// Open or close the Jacobian panel's section (IK engine).
    pub jacobian_panel: Option<bool>,
    /// A teacher's lesson (note, hidden panels, pinned plots); `false` leaves it.
    #[serde(default, deserialize_with = "present")]
    pub lesson: Option<crate::off_or::OffOr<crate::lesson::Lesson>>,
    /// Open or close the lesson's note.
    pub lesson_note_open: Option<bool>,
    /// `false`: stop following the target recording (back to the creature's
    /// own motion). Recordings load by file (Load file…, or a drop).
    pub track: Option<bool>,
    /// View flags.
    #[serde(default, deserialize_with = "object")]
    pub views: Option<ViewsCommand>,
    /// The orbit camera.
    #[serde(default, deserialize_with = "object")]
    pub camera: Option<CameraCommand>,
    /// Open or close the preset editor.
    pub editor_open: Option<bool>,
    /// The preset editor's text.
    pub editor_text: Option<String>,
    /// true: the editor's text back to the creature's preset.
    pub editor_revert: Option<bool>,
    /// true: load the editor's text (a bad preset is an error; the creature stays).
    pub editor_apply: Option<bool>,
    /// true: download the creature's preset file.
    pub download_preset: Option<bool>,
    /// `true`: run the preset as its paper alone — every lab addition of its
    /// engine off (`state().lab_additions` then `[]`), as a custom preset.
    pub paper_alone: Option<bool>,
    /// Show the Share row's link field (as "Copy link", without the clipboard).
    pub show_link: Option<bool>,
}

fn range(key: &str, x: f64, lo: f64, hi: f64) -> Result<f64, String> {
    if !(lo..=hi).contains(&x) {
        return Err(format!("{key}: {x} is outside [{lo}, {hi}]"));
    }
    Ok(x)
}

impl Command {
    /// Reads a command from its JSON text, whole: a wrong type or an unknown
    /// key anywhere refuses it before anything applies.
    ///
    /// # Errors
    /// `key: reason`, e.g. `gain.value: expected a number`, `launch: unknown command`.
    pub fn parse(json: &str) -> Result<Self, String> {
        if json.len() > MAX_COMMAND_BYTES {
            return Err(format!(
                "command is larger than {} KiB",
                MAX_COMMAND_BYTES / 1024
            ));
        }
        let value: serde_json::Value =
            serde_json::from_str(json).map_err(|e| format!("command is not JSON: {e}"))?;
        if !value.is_object() {
            return Err("command must be a JSON object".to_owned());
        }
        from_value("", value)
    }
}

impl App {
    /// Applies a JSON command object, e.g. `{"mode":"run","method":"dls"}`
    /// (the keys are [`Command`]'s; docs/app.md lists them). The command is
    /// read whole first: a wrong type or an unknown key refuses it and nothing
    /// applies. Then keys apply in [`Command`]'s field order; the first value
    /// out of range (or a name the creature lacks) stops the command with an
    /// error naming its key, and what came before it stays applied.
    ///
    /// # Errors
    /// A readable `key: reason` text.
    pub fn command(&mut self, json: &str) -> Result<(), String> {
        let command = Command::parse(json)?;
        self.apply_command(&command)
    }

    /// Applies a typed command in [`Command`]'s field order (see [`App::command`]).
    ///
    /// # Errors
    /// The first key whose value the lab refuses, as `key: reason`.
    pub fn apply_command(&mut self, c: &Command) -> Result<(), String> {
        if let Some(engine) = c.engine {
            self.set_engine(engine.0)?;
        }
        if let Some(name) = &c.preset {
            self.set_preset(name)?;
        }
        if let Some(json) = &c.preset_json {
            self.set_custom_preset(json)?;
        }
        if let Some(terrain) = &c.terrain {
            self.set_terrain(terrain).map_err(|e| {
                if e.starts_with("terrain") {
                    e
                } else {
                    format!("terrain: {e}")
                }
            })?;
        }
        if let Some(name) = &c.gait {
            self.set_gait(name)?;
        }
        for (key, value) in [
            ("period_s", c.period_s),
            ("duty_factor", c.duty_factor),
            ("speed_mps", c.speed_mps),
            ("stroke_m", c.stroke_m),
            ("leg_force_n", c.leg_force_n),
            ("hop_height_m", c.hop_height_m),
        ] {
            if let Some(value) = value {
                self.edit_gait(key, value)?;
            }
        }
        // The panel's errors name its controls; the command's name its keys.
        if let Some(scale) = c.physics_scale {
            self.set_physics_scale(scale)
                .map_err(|e| e.replacen("scale:", "physics_scale:", 1))?;
        }
        if let Some(distance) = c.obstacle_ahead_m {
            self.place_obstacle(distance)
                .map_err(|e| e.replacen("obstacle:", "obstacle_ahead_m:", 1))?;
        }
        if let Some(dv) = c.push_mps {
            self.push(dv)
                .map_err(|e| e.replacen("push:", "push_mps:", 1))?;
        }
        if let Some(points) = &c.waypoints {
            self.set_waypoints(points)?;
        }
        if let Some(gain) = &c.gain {
            self.set_gain(&gain.name, gain.value)?;
        }
        for (name, &value) in c.gains.iter().flatten() {
            self.set_gain(name, value)?;
        }
        for (leg, &phase) in c.phases.iter().flatten().enumerate() {
            self.edit_gait_shape(GaitShapeEdit::Phase { leg, phase })?;
        }
        if let Some(height) = c.step_height_m {
            self.edit_gait_shape(GaitShapeEdit::StepHeight(height))?;
        }
        if let Some(keys) = &c.transfer_keys {
            self.edit_gait_shape(GaitShapeEdit::TransferKeys(keys))?;
        }
        if let Some(spec) = &c.path {
            self.set_path(spec)?;
        }
        if let Some(center) = &c.center {
            self.set_center(&center.joint, center.center, center.gain)?;
        }
        if let Some(mode) = c.mode {
            self.set_mode(mode.0);
        }
        if let Some(method) = c.method {
            self.set_method(method.0);
        }
        if let Some(compare) = &c.compare {
            self.apply_compare_command(compare)?;
        }
        for paused in [c.paused, c.pause].into_iter().flatten() {
            self.set_paused(paused);
        }
        if let Some(rate) = c.playback_rate {
            let rate = range("playback_rate", rate, 0.1, 2.0)?;
            self.playback.set_rate(rate);
        }
        if c.reset == Some(true) {
            self.reset();
        }
        if c.step == Some(true) {
            self.single_step();
        }
        if c.iterate == Some(true) {
            self.step_iteration().map_err(|e| format!("iterate: {e}"))?;
        }
        if let Some(drag) = &c.drag_target {
            self.drag_target(drag)?;
        }
        if let Some(pins) = &c.pinned_targets {
            self.set_pinned_targets(pins)?;
        }
        if let Some(seconds) = c.step_back_s {
            let seconds = range("step_back_s", seconds, 0.0, crate::app::rewind::REWIND_S)?;
            let frames = (seconds / self.frame_seconds()).round() as u64;
            self.step_back(frames)?;
        }
        if let Some(frame) = c.rewind_to_frame {
            self.rewind_to(frame)?;
        }
        self.apply_ik_command(c)?;
        if let Some(x) = c.heading_deg {
            let heading =
                gaitlab_core::params::row(gaitlab_core::params::SCENARIO_PARAMS, "heading_deg")
                    .check_command("heading_deg", x)?;
            self.set_heading_deg(heading);
        }
        if let Some(plots) = c.plots {
            self.session.settings.plots = plots;
        }
        if let Some(names) = &c.plot_joints {
            self.set_plot_joints(names)?;
        }
        match c.record {
            Some(true) => self.start_recording(),
            Some(false) => self.stop_recording(),
            None => {}
        }
        if let Some(x) = c.last_s {
            self.session.settings.export_last_s =
                range("last_s", x, 0.0, gaitlab_engine::MAX_TAKE_S)?;
        }
        match &c.save {
            Some(SaveCommand::Format(format)) => self.save_take_as_set(format.0.name())?,
            Some(SaveCommand::Object(save)) => {
                let last_s = match save.last_s {
                    Some(x) => Some(range("save.last_s", x, 0.0, gaitlab_engine::MAX_TAKE_S)?)
                        .filter(|&s| s > 0.0),
                    None => None,
                };
                self.save_take(save.format.0.name(), last_s)?;
            }
            None => {}
        }
        if let Some(size) = c.video_size {
            self.session.settings.video_size = size.0;
        }
        if let Some(on) = c.record_video {
            self.set_video_recording(on);
        }
        if let Some(theme) = c.theme {
            self.session.settings.theme = theme.0;
        }
        if let Some(narrow) = c.narrow {
            self.layout.narrow_override = narrow;
        }
        if let Some(help) = c.help {
            self.layout.help_open = help;
        }
        if let Some(open) = c.jacobian_panel {
            self.jacobian.open_request = Some(open);
        }
        if let Some(lesson) = &c.lesson {
            self.set_lesson(
                match lesson {
                    crate::off_or::OffOr::Off => None,
                    crate::off_or::OffOr::On(lesson) => Some(lesson.clone()),
                },
                &crate::ui::panels::hideable_titles(),
            )?;
        }
        match c.track {
            Some(false) => self.stop_tracking()?,
            Some(true) => {
                return Err(
                    "track: true is not a recording; load a target CSV with Load file… or drop one"
                        .to_owned(),
                );
            }
            None => {}
        }
        if let Some(open) = c.lesson_note_open {
            self.layout.lesson_note_open = open && self.session.lesson.is_some();
        }
        if let Some(views) = &c.views {
            let view = &mut self.session.settings.view;
            for (slot, value) in [
                (&mut view.world_axes, views.world_axes),
                (&mut view.joint_axes, views.joint_axes),
                (&mut view.targets, views.targets),
                (&mut view.perspective, views.perspective),
                (&mut view.follow, views.follow),
                (&mut view.grid, views.grid),
                (&mut view.shadow, views.shadow),
                (&mut view.ellipsoids, views.ellipsoids),
                (&mut view.reach_shells, views.reach_shells),
            ] {
                if let Some(value) = value {
                    *slot = value;
                }
            }
        }
        if let Some(camera) = &c.camera {
            super::camera::apply_camera(
                &mut self.lab.camera,
                &mut self.lab.session.settings.view,
                camera,
            )?;
        }
        if let Some(open) = c.editor_open {
            self.set_editor_open(open);
        }
        if let Some(text) = &c.editor_text {
            self.set_editor_text(text);
        }
        if c.editor_revert == Some(true) {
            self.editor_revert();
        }
        if c.editor_apply == Some(true) {
            self.editor_apply()?;
        }
        if c.download_preset == Some(true) {
            self.download_preset();
        }
        if c.paper_alone == Some(true) {
            self.run_paper_alone()?;
        }
        if let Some(show) = c.show_link {
            self.show_link(show)?;
        }
        Ok(())
    }

    /// The IK solver options of a command (`lambda` … `jacobian_at`),
    /// applied to the solver once when any is set.
    fn apply_ik_command(&mut self, c: &Command) -> Result<(), String> {
        let mut changed = false;
        let table = |key: &str| {
            gaitlab_core::params::row(gaitlab_core::ik::IK_PARAMS, &format!("scenario.ik.{key}"))
        };
        for (key, value) in [
            ("lambda", c.lambda),
            ("gamma_max", c.gamma_max),
            ("max_step", c.max_step),
            ("null_space_gain", c.null_space_gain),
            ("target_clamp_m", c.target_clamp_m),
        ] {
            let Some(x) = value else { continue };
            let x = table(key).check_command(key, x)?;
            let ik = &mut self.session.settings.ik;
            match key {
                "lambda" => ik.lambda = x,
                "gamma_max" => ik.gamma_max = x,
                "max_step" => ik.max_step = x,
                "target_clamp_m" => ik.target_clamp_m = x,
                _ => ik.null_space_gain = x,
            }
            changed = true;
        }
        if let Some(on) = c.enforce_limits {
            self.session.settings.ik.enforce_limits = on;
            changed = true;
        }
        if let Some(passes) = c.limit_passes {
            table("limit_passes")
                .check_integer("limit_passes", passes)
                .map_err(|e| format!("limit_passes: {passes}: {}", e.reason))?;
            self.session.settings.ik.limit_passes = passes;
            changed = true;
        }
        if let Some(way) = c.jacobian_at {
            self.session.settings.ik.jacobian_at = way.0;
            changed = true;
        }
        if let Some(on) = c.clamp_every_method {
            self.session.settings.ik.clamp_every_method = on;
            changed = true;
        }
        if let Some(alpha) = c.transpose_alpha {
            self.session.settings.ik.transpose_alpha = alpha.0;
            changed = true;
        }
        if changed {
            self.apply_ik_options();
        }
        if c.measure_lambda_tradeoff == Some(true) {
            self.measure_lambda_tradeoff()?;
        }
        Ok(())
    }
}
