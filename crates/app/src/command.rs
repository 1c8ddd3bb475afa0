//! The JS state API (DESIGN.md "Browser"): `state()` as one JSON object and
//! `command(json)` applying the same changes a person can make in the panels.
//! Commands are plain data; nothing in them is evaluated.

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::thesis::ThesisMode;
use serde_json::{Map, Value, json};

use crate::lab::{GaitShapeEdit, Lab};
use crate::settings::VideoSize;
use crate::theme::Theme;
use crate::view::ViewOptions;

/// Longest command text accepted, bytes (a custom preset rides in `preset_json`).
pub const MAX_COMMAND_BYTES: usize = 300 * 1024;

fn number(key: &str, value: &Value, lo: f64, hi: f64) -> Result<f64, String> {
    let x = value
        .as_f64()
        .ok_or_else(|| format!("{key}: expected a number"))?;
    if !(lo..=hi).contains(&x) {
        return Err(format!("{key}: {x} is outside [{lo}, {hi}]"));
    }
    Ok(x)
}

fn flag(key: &str, value: &Value) -> Result<bool, String> {
    value
        .as_bool()
        .ok_or_else(|| format!("{key}: expected true or false"))
}

fn text<'a>(key: &str, value: &'a Value) -> Result<&'a str, String> {
    value
        .as_str()
        .ok_or_else(|| format!("{key}: expected a string"))
}

fn apply_views(views: &mut ViewOptions, value: &Value) -> Result<(), String> {
    let object = value.as_object().ok_or("views: expected an object")?;
    for (key, value) in object {
        let path = format!("views.{key}");
        let slot = match key.as_str() {
            "world_axes" => &mut views.world_axes,
            "joint_axes" => &mut views.joint_axes,
            "targets" => &mut views.targets,
            "perspective" => &mut views.perspective,
            "follow" => &mut views.follow,
            "grid" => &mut views.grid,
            "shadow" => &mut views.shadow,
            _ => return Err(format!("{path}: unknown view option")),
        };
        *slot = flag(&path, value)?;
    }
    Ok(())
}

impl Lab {
    /// Applies a JSON command object, e.g. `{"mode":"run","method":"dls"}`.
    /// Keys: `engine` (`ik`, `poda` or `physics`: loads the matching creature),
    /// `preset`, `preset_json`, `gait`, `period_s`, `duty_factor`,
    /// `speed_mps`, `stroke_m` (PODA gait values; each edit keeps eq. 7–8 true;
    /// `speed_mps` and `hop_height_m` are also the physics controllers' desired
    /// speed and hop height), `gain` (`{"name", "value"}`: a physics controller gain),
    /// `phases`, `step_height_m`, `transfer_keys` (PODA gait shape),
    /// `center` (`{"joint", "center", "gain"}`: a PODA leg joint's eq. 6 center),
    /// `path` (`{"kind", "points": [[x, z], …], "closed"}`: the PODA body path),
    /// `mode`, `method`, `compare` (an object of `views`, `scenario`,
    /// `options`, or `false`: the side-by-side IK comparison, see
    /// [`crate::compare`]), `paused` (or `pause`),
    /// `reset`, `step`, `lambda`, `gamma_max`, `max_step`, `null_space_gain`,
    /// `enforce_limits`, `heading_deg`, `plots`, `plot_joints` (joint names),
    /// `record` (motion take on/off), `last_s` (seconds the panel's saves
    /// write, 0 all), `save` (`"bvh"` or `"csv"`, or `{"format", "last_s"}`:
    /// download the take or its last seconds), `video_size`, `record_video`
    /// (on/off), `theme` (`system`, `light`, `dark`), `narrow` (true/false
    /// forces the phone layout on or off, null follows the width), `views`
    /// (an object of view flags), `camera` (see [`crate::camera_state`]),
    /// `editor_open`, `editor_text`, `editor_revert`, `editor_apply` (the
    /// preset editor; a bad preset is an error and the creature stays),
    /// `download_preset`, `show_link` (the Share row's link field as "Copy
    /// link" shows it, without the clipboard); `gains` (an object
    /// `{name: value}`) goes with `gain`.
    /// Keys apply in that order; the first bad key stops the command with an
    /// error naming it, and what came before it stays applied.
    ///
    /// # Errors
    /// A readable `key: reason` text.
    pub fn command(&mut self, json: &str) -> Result<(), String> {
        if json.len() > MAX_COMMAND_BYTES {
            return Err(format!(
                "command is larger than {} KiB",
                MAX_COMMAND_BYTES / 1024
            ));
        }
        let value: Value =
            serde_json::from_str(json).map_err(|e| format!("command is not JSON: {e}"))?;
        let object: &Map<String, Value> =
            value.as_object().ok_or("command must be a JSON object")?;
        const KNOWN: &[&str] = &[
            "compare",
            "hop_height_m",
            "gain",
            "engine",
            "preset",
            "preset_json",
            "gait",
            "path",
            "center",
            "phases",
            "step_height_m",
            "transfer_keys",
            "period_s",
            "duty_factor",
            "speed_mps",
            "stroke_m",
            "leg_force_n",
            "mode",
            "method",
            "paused",
            "pause",
            "reset",
            "step",
            "lambda",
            "gamma_max",
            "max_step",
            "null_space_gain",
            "enforce_limits",
            "heading_deg",
            "plots",
            "plot_joints",
            "record",
            "save",
            "record_video",
            "video_size",
            "views",
            "camera",
            "gains",
            "editor_open",
            "editor_text",
            "editor_apply",
            "editor_revert",
            "download_preset",
            "last_s",
            "theme",
            "narrow",
            "show_link",
        ];
        if let Some(unknown) = object.keys().find(|k| !KNOWN.contains(&k.as_str())) {
            return Err(format!("{unknown}: unknown command"));
        }
        let get = |key: &str| object.get(key);
        if let Some(v) = get("engine") {
            let name = text("engine", v)?;
            let engine = gaitlab_core::preset::Engine::parse(name)
                .ok_or_else(|| format!("engine: unknown engine {name:?} (ik, poda, physics)"))?;
            self.set_engine(engine)?;
        }
        if let Some(v) = get("preset") {
            self.set_preset(text("preset", v)?)?;
        }
        if let Some(v) = get("preset_json") {
            self.set_custom_preset(text("preset_json", v)?)?;
        }
        if let Some(v) = get("gait") {
            self.set_gait(text("gait", v)?)?;
        }
        for key in [
            "period_s",
            "duty_factor",
            "speed_mps",
            "stroke_m",
            "leg_force_n",
            "hop_height_m",
        ] {
            if let Some(v) = get(key) {
                let value = v
                    .as_f64()
                    .ok_or_else(|| format!("{key}: expected a number"))?;
                self.edit_gait(key, value)?;
            }
        }
        if let Some(v) = get("gain") {
            let name = text("gain.name", v.get("name").ok_or("gain.name: missing")?)?;
            let value = v
                .get("value")
                .and_then(Value::as_f64)
                .ok_or("gain.value: expected a number")?;
            self.set_gain(name, value)?;
        }
        if let Some(v) = get("gains") {
            let gains = v
                .as_object()
                .ok_or("gains: expected an object of gain values by name")?;
            for (name, value) in gains {
                let value = value
                    .as_f64()
                    .ok_or_else(|| format!("gains.{name}: expected a number"))?;
                self.set_gain(name, value)?;
            }
        }
        if let Some(v) = get("phases") {
            let phases = v.as_array().ok_or("phases: expected an array of numbers")?;
            for (leg, phase) in phases.iter().enumerate() {
                let phase = phase
                    .as_f64()
                    .ok_or_else(|| format!("phases[{leg}]: expected a number"))?;
                self.edit_gait_shape(GaitShapeEdit::Phase { leg, phase })?;
            }
        }
        if let Some(v) = get("step_height_m") {
            let height = v.as_f64().ok_or("step_height_m: expected a number")?;
            self.edit_gait_shape(GaitShapeEdit::StepHeight(height))?;
        }
        if let Some(v) = get("transfer_keys") {
            let keys: Vec<[f64; 2]> = serde_json::from_value(v.clone())
                .map_err(|_| "transfer_keys: expected [[along, height], …]".to_owned())?;
            self.edit_gait_shape(GaitShapeEdit::TransferKeys(&keys))?;
        }
        if let Some(v) = get("path") {
            let spec: gaitlab_core::preset::PathSpec =
                serde_json::from_value(v.clone()).map_err(|e| format!("path: {e}"))?;
            self.set_path(&spec)?;
        }
        if let Some(v) = get("center") {
            let field = |key: &str| v.get(key).ok_or(format!("center.{key}: missing"));
            let joint = text("center.joint", field("joint")?)?;
            let center = field("center")?
                .as_f64()
                .ok_or("center.center: expected a number")?;
            let gain = field("gain")?
                .as_f64()
                .ok_or("center.gain: expected a number")?;
            self.set_center(joint, center, gain)?;
        }
        if let Some(v) = get("mode") {
            let name = text("mode", v)?;
            let mode = ThesisMode::parse(name).ok_or_else(|| {
                format!("mode: unknown mode {name:?} (walk, run, wounded-walk, wounded-run)")
            })?;
            self.set_mode(mode);
        }
        if let Some(v) = get("method") {
            let name = text("method", v)?;
            let method = Method::parse(name).ok_or_else(|| {
                format!("method: unknown method {name:?} (transpose, pinv, dls, sdls, ccd)")
            })?;
            self.set_method(method);
        }
        if let Some(v) = get("compare") {
            self.apply_compare_command(v)?;
        }
        for key in ["paused", "pause"] {
            if let Some(v) = get(key) {
                self.set_paused(flag(key, v)?);
            }
        }
        if let Some(v) = get("reset")
            && flag("reset", v)?
        {
            self.reset();
        }
        if let Some(v) = get("step")
            && flag("step", v)?
        {
            self.single_step();
        }
        let mut ik_changed = false;
        for (key, lo, hi) in [
            ("lambda", 1e-6, 10.0),
            ("gamma_max", 1e-3, std::f64::consts::PI),
            ("max_step", 1e-3, std::f64::consts::PI),
            ("null_space_gain", 0.0, 10.0),
        ] {
            if let Some(v) = get(key) {
                let x = number(key, v, lo, hi)?;
                let ik = &mut self.session.settings.ik;
                match key {
                    "lambda" => ik.lambda = x,
                    "gamma_max" => ik.gamma_max = x,
                    "max_step" => ik.max_step = x,
                    _ => ik.null_space_gain = x,
                }
                ik_changed = true;
            }
        }
        if let Some(v) = get("enforce_limits") {
            self.session.settings.ik.enforce_limits = flag("enforce_limits", v)?;
            ik_changed = true;
        }
        if ik_changed {
            self.apply_ik_options();
        }
        if let Some(v) = get("heading_deg") {
            self.set_heading_deg(number("heading_deg", v, -180.0, 180.0)?);
        }
        if let Some(v) = get("plots") {
            self.session.settings.plots = flag("plots", v)?;
        }
        if let Some(v) = get("plot_joints") {
            let names = v
                .as_array()
                .ok_or("plot_joints: expected an array of joint names")?
                .iter()
                .enumerate()
                .map(|(i, name)| text(&format!("plot_joints[{i}]"), name).map(str::to_owned))
                .collect::<Result<Vec<_>, _>>()?;
            self.set_plot_joints(&names)?;
        }
        if let Some(v) = get("record") {
            if flag("record", v)? {
                self.start_recording();
            } else {
                self.stop_recording();
            }
        }
        if let Some(v) = get("last_s") {
            self.session.settings.export_last_s =
                number("last_s", v, 0.0, gaitlab_engine::MAX_TAKE_S)?;
        }
        if let Some(v) = get("save") {
            self.apply_save(v)?;
        }
        if let Some(v) = get("video_size") {
            let name = text("video_size", v)?;
            self.session.settings.video_size = VideoSize::parse(name).ok_or_else(|| {
                format!("video_size: unknown size {name:?} (view, p360, p720, p1080)")
            })?;
        }
        if let Some(v) = get("record_video") {
            self.set_video_recording(flag("record_video", v)?);
        }
        if let Some(v) = get("theme") {
            let name = text("theme", v)?;
            self.session.settings.theme = Theme::parse(name)
                .ok_or_else(|| format!("theme: unknown theme {name:?} (system, light, dark)"))?;
        }
        if let Some(v) = get("narrow") {
            self.layout.narrow_override = match v {
                Value::Null => None,
                v => Some(flag("narrow", v)?),
            };
        }
        if let Some(v) = get("views") {
            let mut views = self.session.settings.view.clone();
            apply_views(&mut views, v)?;
            self.session.settings.view = views;
        }
        if let Some(v) = get("camera") {
            crate::camera_state::apply_camera(
                &mut self.camera,
                &mut self.session.settings.view,
                v,
            )?;
        }
        if let Some(v) = get("editor_open") {
            self.set_editor_open(flag("editor_open", v)?);
        }
        if let Some(v) = get("editor_text") {
            self.set_editor_text(text("editor_text", v)?);
        }
        if let Some(v) = get("editor_revert")
            && flag("editor_revert", v)?
        {
            self.editor_revert();
        }
        if let Some(v) = get("editor_apply")
            && flag("editor_apply", v)?
        {
            self.editor_apply()?;
        }
        if let Some(v) = get("download_preset")
            && flag("download_preset", v)?
        {
            self.download_preset();
        }
        if let Some(v) = get("show_link") {
            self.show_link(flag("show_link", v)?)?;
        }
        Ok(())
    }

    /// `save`: `"bvh"` / `"csv"` (the last [`Settings::export_last_s`]
    /// seconds, all for 0) or `{"format": "bvh", "last_s": 5}`.
    ///
    /// [`Settings::export_last_s`]: crate::Settings::export_last_s
    fn apply_save(&mut self, value: &Value) -> Result<(), String> {
        if let Some(format) = value.as_str() {
            return self.save_take_as_set(format);
        }
        let object = value
            .as_object()
            .ok_or("save: expected \"bvh\", \"csv\" or {\"format\", \"last_s\"}")?;
        if let Some(key) = object
            .keys()
            .find(|k| !["format", "last_s"].contains(&k.as_str()))
        {
            return Err(format!("save.{key}: unknown key (format, last_s)"));
        }
        let format = text(
            "save.format",
            object.get("format").ok_or("save.format: missing")?,
        )?;
        let last_s = match object.get("last_s") {
            None | Some(Value::Null) => None,
            Some(v) => Some(number("save.last_s", v, 0.0, gaitlab_engine::MAX_TAKE_S)?)
                .filter(|&s| s > 0.0),
        };
        self.save_take(format, last_s)
    }

    /// The state as one JSON object: preset, engine, mode, gait, method(s),
    /// paused, frame, fps, per-view error metrics, last error.
    #[must_use]
    pub fn state_json(&self) -> String {
        let skeleton = &self.session.creature.skeleton;
        let report = self.stage.driver.ik_report();
        let metrics = self.stage.driver.ik_metrics();
        let effectors: Vec<Value> = skeleton
            .effectors()
            .iter()
            .enumerate()
            .map(|(e, effector)| {
                json!({
                    "name": effector.name,
                    "error_m": report.and_then(|r| r.effector_error_m.get(e).copied()),
                    "mean_error_m": metrics.and_then(|m| m.mean_error_m(e)),
                    "max_error_m": metrics.and_then(|m| m.max_error_m(e)),
                })
            })
            .collect();
        json!({
            "preset": self.session.creature.name,
            "custom_preset": self.session.custom_preset.is_some(),
            "engine": self.session.creature.scenario.engine.name(),
            "mode": self.session.settings.mode.name(),
            "gait": self
                .stage.driver
                .poda()
                .map(gaitlab_motion::PodaDriver::gait_name)
                .or_else(|| self.stage.driver.physics().map(gaitlab_physics::PhysicsDriver::gait)),
            "physics": self.stage.driver.physics().map(|driver| {
                let s = driver.summary();
                let probe = driver.probe();
                json!({
                    "model": driver.params().model.name(),
                    "scale": driver.params().scale,
                    "phase": driver.phase_name(),
                    "speed_desired_mps": driver.params().speed_mps,
                    "hop_height_m": driver.params().hop_height_m,
                    "heading_deg": driver.heading().to_degrees(),
                    "waypoint": driver.waypoint(),
                    "speed_mean_mps": s.speed_mean_mps,
                    "fell": s.fell,
                    "resets": driver.resets(),
                    "height_m": probe.height_m,
                    "pitch_deg": probe.pitch_deg,
                    "roll_deg": probe.roll_deg,
                    "stride_length_m": s.stride_length_m,
                    "stride_duration_s": s.stride_duration_s,
                    "flight_duration_s": s.flight_duration_s,
                    "stance_duration_s": s.stance_duration_s,
                    "friction_needed_max": s.friction_needed_max,
                    "steps": driver.sim().steps,
                    "gains": driver
                        .gains()
                        .iter()
                        .map(|g| (g.name.to_owned(), Value::from(g.value)))
                        .collect::<Map<String, Value>>(),
                })
            }),
            "poda": self.stage.driver.poda().map(|driver| {
                let gait = driver.gait();
                json!({
                    "period_s": gait.period_s(),
                    "duty_factor": gait.duty_factor(),
                    "speed_mps": gait.speed_mps(),
                    "stroke_m": gait.stroke_m(),
                    "leg_force_n": driver.leg_force_n(),
                    "support_s": gait.support_s(),
                    "transfer_s": gait.transfer_s(),
                    "phases": gait.phases(),
                    "step_height_m": driver.params().step_height_m,
                    "transfer_keys": driver.params().transfer_keys,
                    "path": driver.path().to_spec(),
                    "blending": gait.is_blending(),
                    "legs": driver.leg_names().collect::<Vec<_>>(),
                    "foot_slip_max_m": driver.metrics().foot_slip_max_m(),
                    "derived": self.gait_derived,
                })
            }),
            "method": self.session.settings.method.name(),
            "methods": self.compare.as_ref().map_or_else(
                || vec![self.session.settings.method.name()],
                |c| c.config.views.iter().map(|m| m.name()).collect(),
            ),
            "compare": self.compare_state(),
            "paused": self.playback.paused,
            "frame": self.stage.frame,
            "time_s": self.stage.driver.time(),
            "fps": self.playback.fps,
            "sim_us_per_frame": self.playback.sim_us_per_frame,
            "wasm_memory_bytes": crate::memory::wasm_memory_bytes(),
            "wasm_heap_live_bytes": crate::memory::wasm_heap_bytes().map(|(live, _)| live),
            "wasm_heap_peak_bytes": crate::memory::wasm_heap_bytes().map(|(_, peak)| peak),
            "view_rect_px": self.layout.view_rect_px,
            "joints": skeleton.joint_count(),
            "views": [{
                "method": self.session.settings.method.name(),
                "effectors": effectors,
                "creature_box_px": crate::render::viewport::figure_box(
                    &self.stage.scene, &self.camera, self.layout.view_rect_px),
                "metrics": self.run_metrics(),
            }],
            "view_options": self.session.settings.view,
            "ik": {
                "lambda": self.session.settings.ik.lambda,
                "gamma_max": self.session.settings.ik.gamma_max,
                "max_step": self.session.settings.ik.max_step,
                "null_space_gain": self.session.settings.ik.null_space_gain,
                "enforce_limits": self.session.settings.ik.enforce_limits,
            },
            "plots": self.session.settings.plots,
            "editor": {
                "open": self.editor.open,
                "dirty": self.editor.dirty(),
                "error": self.editor.error,
            },
            "heading_deg": self.session.settings.heading_deg,
            "backend": self.backend,
            "camera": crate::camera_state::camera_json(&self.camera, &self.session.settings.view),
            "plot_joints": self
                .plots.joints
                .iter()
                .map(|&j| skeleton.joints()[j].name.as_str())
                .collect::<Vec<_>>(),
            "recording": {
                "active": self.take.recording(),
                "frames": self.take.take().map_or(0, gaitlab_engine::Take::frames),
                "seconds": self.take.take().map_or(0.0, gaitlab_engine::Take::seconds),
                "last_s": self.session.settings.export_last_s,
            },
            "theme": self.session.settings.theme.name(),
            "dark": self.layout.dark_mode,
            "layout": {
                "narrow": self.layout.narrow,
                "controls_open": self.layout.controls_open,
                "controls_button_pt": self.layout.controls_button_pt,
            },
            "video": {
                "recording": self.video.recording,
                "frames": self.video.frames,
                "encoder": self.video.encoder,
                "skipped": self.video.skipped,
                "seconds": self.video.seconds,
                "size": self.session.settings.video_size.name(),
            },
            "last_error": self.session.last_error,
        })
        .to_string()
    }

    /// The figures `gaitlab run --json` prints, for the run since the last
    /// reset: the engine layer's one metrics type. Wall-time fields come from
    /// the page's smoothed time per frame; `within_limits` is the current pose's.
    fn run_metrics(&self) -> gaitlab_engine::RunMetrics {
        let frames = usize::try_from(self.stage.frame).unwrap_or(usize::MAX);
        let step_ms = self.playback.sim_us_per_frame * self.stage.frame as f64 / 1e3;
        let within_limits = gaitlab_engine::metrics::pose_within_limits(
            self.stage.driver.skeleton(),
            self.stage.driver.pose(),
        );
        let timing = gaitlab_engine::Timing {
            frames,
            step_ms,
            wall_ms: step_ms,
            within_limits,
        };
        gaitlab_engine::RunMetrics::of(&self.session.creature.name, &self.stage.driver, &timing)
            .with_fps(1.0 / self.frame_seconds())
    }
}
