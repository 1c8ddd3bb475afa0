//! The `state()` API (DESIGN.md "Browser", docs/app.md): the typed [`State`]
//! — preset, engine, mode, gait, methods, engine figures, per-view errors and
//! run metrics, settings, layout, recording, last error — and the one place
//! that reads the lab's fields for it ([`State::of`]).

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{JacobianAt, TransposeAlpha};
use gaitlab_core::skeleton::Scope;
use serde::Serialize;

use gaitlab_engine::status::{PhysicsState, PodaState};

use super::camera::CameraState;
use crate::app::App;
use crate::view::ViewOptions;

/// One of the lab's additions in force (`lab_additions`).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct LabAdditionState {
    /// The addition's name (`clamp_every_method`, `speed_trim`, …).
    pub name: &'static str,
    /// What it is and where the paper differs, one line.
    pub reason: &'static str,
}

/// One effector's IK error in `views[0].effectors`.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct EffectorState {
    /// The effector's name.
    pub name: String,
    /// This frame's distance from its target, metres.
    pub error_m: Option<f64>,
    /// Mean since the last reset, metres.
    pub mean_error_m: Option<f64>,
    /// Largest since the last reset, metres.
    pub max_error_m: Option<f64>,
    /// How far this frame's target lies beyond the limb's reach, metres
    /// (negative: within reach; see docs/ik-metrics.md).
    pub out_of_reach_m: Option<f64>,
    /// Where the effector is, world `[x, y, z]` metres.
    pub position_m: [f64; 3],
    /// Where its target is, world metres (null without targets).
    pub target_m: Option<[f64; 3]>,
    /// The target on screen, `[x, y]` points (null off screen or without one).
    pub target_pt: Option<[f32; 2]>,
    /// The effector on screen, `[x, y]` points (null off screen).
    pub position_pt: Option<[f32; 2]>,
    /// Where the limb's reach is measured from (its first joint), world
    /// metres: a target farther than the limb's length from it is out of reach.
    pub reach_anchor_m: [f64; 3],
    /// Whether the target is held (by the hand, `drag_target` or a pin).
    pub held: bool,
    /// Whether the target is pinned.
    pub pinned: bool,
    /// The semi-axes σ₁ ≥ σ₂ ≥ σ₃ of the effector's manipulability
    /// ellipsoid (its limb's block of J Jᵀ, drawn by `views.ellipsoids`),
    /// metres per radian: σ₃ falls toward 0 as the limb straightens.
    pub manipulability_m_per_rad: Option<[f64; 3]>,
}

/// `views[0]`: the single view's method, errors, box on screen and run metrics.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct ViewState {
    /// The IK method's name.
    pub method: &'static str,
    /// Per-effector errors.
    pub effectors: Vec<EffectorState>,
    /// The figure's projected box in the page, `[x, y, width, height]` px.
    pub creature_box_px: Option<[f32; 4]>,
    /// `gaitlab run --json`'s figures for the run since the last reset.
    #[cfg_attr(feature = "schema", schemars(with = "serde_json::Value"))]
    pub metrics: gaitlab_engine::RunMetrics,
}

/// `ik`: the solver options.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct IkState {
    /// DLS damping λ.
    pub lambda: f64,
    /// SDLS γmax, radians.
    pub gamma_max: f64,
    /// Step clamp, radians: pinv's, and every method's with `clamp_every_method`.
    pub max_step: f64,
    /// The lab's addition: the step clamp on transpose and DLS too.
    pub clamp_every_method: bool,
    /// The lab's addition: Buss's target clamp, metres (0 off).
    pub target_clamp_m: f64,
    /// The transpose method's α: `thesis` (She 2006 §4.4.1) or `buss`.
    pub transpose_alpha: TransposeAlpha,
    /// Null-space gain.
    pub null_space_gain: f64,
    /// Joints kept inside their limits.
    pub enforce_limits: bool,
    /// Solves per IK iteration while joints hit their limits: 1 clamps (She
    /// 2006 §6.1.1.1), more re-solve without the clamped joints (the lab's).
    pub limit_passes: usize,
    /// She 2006 §3.2's control way: `effectors` or `targets` (where the
    /// Jacobian is taken).
    pub jacobian_at: JacobianAt,
    /// The last measured λ trade-off (`measure_lambda_tradeoff`), if any.
    pub lambda_tradeoff: Option<crate::lambda_tradeoff::LambdaTradeoff>,
}

/// `editor`: the preset editor.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct EditorState {
    /// Whether it is open.
    pub open: bool,
    /// Whether its text differs from the creature's preset.
    pub dirty: bool,
    /// The last apply's error.
    pub error: Option<String>,
    /// That error as the editor shows it: the joint named after its index,
    /// serde's type words put plainly.
    pub message: Option<String>,
    /// The editor line it stands on (1-based).
    pub line: Option<usize>,
}

/// `recording`: the motion take.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct RecordingState {
    /// Whether it records.
    pub active: bool,
    /// Frames in the take.
    pub frames: usize,
    /// Seconds in the take.
    pub seconds: f64,
    /// Seconds the panel's saves write (0: all).
    pub last_s: f64,
}

/// `layout`: the page layout.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct LayoutState {
    /// The phone layout.
    pub narrow: bool,
    /// Whether the phone layout's controls are open.
    pub controls_open: bool,
    /// The controls button's rectangle, points.
    pub controls_button_pt: [f32; 4],
    /// The physics creature's trunk on screen, points `[x, y]`: a drag
    /// from there pushes it (`null`: no physics creature in the view).
    pub trunk_pt: Option<[f32; 2]>,
    /// Whether the phone layout's plots drawer is open.
    pub plots_open: bool,
    /// Whether the help window is open.
    pub help_open: bool,
    /// Whether the lesson's note window is open.
    pub lesson_note_open: bool,
    /// The titles of the control panels drawn, top to bottom (the lesson's
    /// hidden ones left out).
    pub panels_shown: Vec<&'static str>,
    /// The phone layout's interactive widgets measured in the last frame (0 wide).
    pub touch_targets_checked: usize,
    /// Those under 44 CSS px wide or tall, `[x, y, w, h]` (points).
    pub small_touch_targets_pt: Vec<[f32; 4]>,
    /// The phone layout's plots button's rectangle, points.
    pub plots_button_pt: [f32; 4],
    /// Where the Help button, the playback-rate slider and the preset combo
    /// box were drawn, points `[x, y, w, h]` (zeros where not drawn).
    pub widgets_pt: crate::lab::layout::WidgetRects,
    /// Whether a popup (a combo box's list) is open.
    pub popup_open: bool,
    /// Clicks the preset combo box has taken since the page opened.
    pub preset_combo_clicks: u32,
    /// The open preset menu's entries by preset name, points `[x, y, w, h]`
    /// (empty while it is closed).
    pub preset_menu_pt: crate::lab::layout::MenuRects,
    /// The single view's figure on screen, points `[x, y, w, h]` (`null` in
    /// a comparison or where a corner is behind the eye).
    pub figure_pt: Option<[f32; 4]>,
    /// The single 3-D view's rectangle, points `[x, y, w, h]`.
    pub view_pt: [f32; 4],
}

/// `terrain`: the ground under the figure (issue 45).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct TerrainState {
    /// `flat`, `plane`, `stairs`, `height_field` or `rough`.
    pub kind: &'static str,
    /// The preset's `scenario.terrain` as the `terrain` command takes it
    /// (`null` for a height field, whose grid can be large: the preset
    /// carries it).
    #[cfg_attr(feature = "schema", schemars(with = "Option<serde_json::Value>"))]
    pub spec: Option<serde_json::Value>,
    /// Triangles the 3-D view draws for it (0 on the floor).
    pub triangles_drawn: usize,
    /// PODA footholds moved off an unacceptable spot since the restart.
    pub footholds_moved: u64,
    /// The body's root, world metres `[x, y, z]`.
    pub root_m: [f64; 3],
    /// The ground's height under the root, metres.
    pub ground_under_root_m: f64,
}

/// `track`: the target recording the figure follows.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct TrackState {
    /// The file's name.
    pub file: String,
    /// Data rows.
    pub rows: usize,
    /// Effectors (one target each per row).
    pub effectors: usize,
    /// From the first row's time to the last's, seconds.
    pub duration_s: f64,
}

/// `video`: the video recording.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct VideoState {
    /// Whether it records.
    pub recording: bool,
    /// Frames encoded.
    pub frames: u64,
    /// The encoder's name.
    pub encoder: &'static str,
    /// Frames skipped.
    pub skipped: u64,
    /// Seconds recorded.
    pub seconds: f64,
    /// The frame size's name.
    pub size: &'static str,
}

/// `state()`: the whole lab as one JSON object.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(
    feature = "schema",
    schemars(
        title = "gaitlab state",
        description = "The object window.gaitlab.state() returns (docs/app.md)."
    )
)]
pub struct State {
    /// The creature's preset name.
    pub preset: String,
    /// Whether it came from a preset file rather than the bundled list.
    pub custom_preset: bool,
    /// `ik`, `poda` or `physics`.
    pub engine: &'static str,
    /// The lab's additions to the paper in force for the running preset,
    /// each with why (`[]`: the paper alone; the `paper_alone` command
    /// turns them off).
    pub lab_additions: Vec<LabAdditionState>,
    /// The thesis script.
    pub mode: &'static str,
    /// The PODA or physics gait.
    pub gait: Option<String>,
    /// The physics figures (physics engine).
    pub physics: Option<PhysicsState>,
    /// The PODA figures (PODA engine).
    pub poda: Option<PodaState>,
    /// The ground under the figure.
    pub terrain: TerrainState,
    /// The IK method.
    pub method: &'static str,
    /// The method of each view.
    pub methods: Vec<&'static str>,
    /// The comparison's configuration and metrics, or null.
    #[cfg_attr(feature = "schema", schemars(with = "Option<serde_json::Value>"))]
    pub compare: serde_json::Value,
    /// Whether time stands still.
    pub paused: bool,
    /// Playback rate, simulated seconds per wall second.
    pub playback_rate: f64,
    /// The history scrubber: the frame shown, how far back one can go, and
    /// whether frames simulated again matched the stored poses.
    pub rewind: crate::app::rewind::RewindState,
    /// Frames since the last reset.
    pub frame: u64,
    /// Simulated time, seconds.
    pub time_s: f64,
    /// Frames per second drawn.
    pub fps: f64,
    /// Simulation time per frame, µs.
    pub sim_us_per_frame: f64,
    /// The wasm memory's size (browser only).
    pub wasm_memory_bytes: Option<f64>,
    /// Live heap bytes (browser only).
    pub wasm_heap_live_bytes: Option<usize>,
    /// Peak heap bytes (browser only).
    pub wasm_heap_peak_bytes: Option<usize>,
    /// The 3-D view's rectangle, `[x, y, width, height]` px.
    pub view_rect_px: [f32; 4],
    /// The skeleton's joint count.
    pub joints: usize,
    /// The views (one; a comparison's are in `compare`).
    pub views: [ViewState; 1],
    /// View flags.
    pub view_options: ViewOptions,
    /// Solver options.
    pub ik: IkState,
    /// Whether the plots show.
    pub plots: bool,
    /// The preset editor.
    pub editor: EditorState,
    /// The walking direction, degrees.
    pub heading_deg: f64,
    /// The graphics backend.
    pub backend: Option<String>,
    /// The orbit camera.
    pub camera: CameraState,
    /// The plotted joints' names.
    pub plot_joints: Vec<String>,
    /// The motion take.
    pub recording: RecordingState,
    /// `system`, `light` or `dark`.
    pub theme: &'static str,
    /// Whether the dark colours show.
    pub dark: bool,
    /// The page layout.
    pub layout: LayoutState,
    /// The video recording.
    pub video: VideoState,
    /// The last error shown.
    pub last_error: Option<String>,
    /// The target recording the figure follows, or null.
    pub track: Option<TrackState>,
    /// The teacher's lesson: note, hidden panels, pinned plots; null without one.
    pub lesson: Option<crate::lesson::Lesson>,
    /// The note shown about the running preset: the deprecated values it
    /// uses, which still run as it was made.
    pub notice: Option<String>,
    /// The Jacobian panel's figures: each view's singular values, condition
    /// number and gains, and the last frame's iterations (null outside the
    /// IK engine's script).
    pub jacobian: Option<crate::jacobian::JacobianState>,
    /// The pinned targets: effector name → where, in the root's frame,
    /// metres (`pinned_targets` takes the same; empty without pins).
    pub pinned_targets: std::collections::BTreeMap<String, [f64; 3]>,
}

impl State {
    /// The lab's state (the one place that reads the lab's fields for `state()`).
    #[must_use]
    pub fn of(lab: &App) -> Self {
        let skeleton = &lab.session.creature.skeleton;
        let report = lab.stage.driver.ik_report();
        let metrics = lab.stage.driver.ik_metrics();
        let targets = lab.stage.driver.targets();
        let held = lab.stage.driver.held_targets();
        let effectors = skeleton
            .effectors()
            .iter()
            .enumerate()
            .map(|(e, effector)| EffectorState {
                name: effector.name.clone(),
                error_m: report.and_then(|r| r.effector_error_m.get(e).copied()),
                mean_error_m: metrics.and_then(|m| m.mean_error_m(e)),
                max_error_m: metrics.and_then(|m| m.max_error_m(e)),
                out_of_reach_m: report.and_then(|r| r.out_of_reach_m.get(e).copied()),
                position_m: lab
                    .stage
                    .driver
                    .effector_positions()
                    .get(e)
                    .map_or([f64::NAN; 3], |p| p.to_array()),
                target_m: targets
                    .and_then(|t| t.position.get(e))
                    .map(|p| p.to_array()),
                target_pt: lab.layout.target_pt.get(e).copied().flatten(),
                position_pt: lab.layout.effector_pt.get(e).copied().flatten(),
                reach_anchor_m: skeleton
                    .limb(e)
                    .anchor(
                        &lab.stage.kinematics.joint_anchor,
                        &lab.stage.kinematics.joint_position,
                    )
                    .to_array(),
                held: held.is_some_and(|h| h.held_at(e).is_some()),
                pinned: held.is_some_and(|h| h.is_pinned(e)),
                manipulability_m_per_rad: skeleton
                    .manipulability(&lab.stage.kinematics, e, Scope::Limb)
                    .map(|m| m.sigma),
            })
            .collect();
        let settings = &lab.session.settings;
        Self {
            preset: lab.session.creature.name.clone(),
            custom_preset: lab.session.custom_preset.is_some(),
            lab_additions: lab
                .driver()
                .lab_additions()
                .iter()
                .map(|a| LabAdditionState {
                    name: a.name,
                    reason: a.reason,
                })
                .collect(),
            engine: lab.session.creature.scenario.engine.name(),
            mode: settings.mode.name(),
            gait: lab.stage.driver.gait_name().map(str::to_owned),
            physics: lab.stage.driver.physics_state(),
            poda: lab
                .stage
                .driver
                .poda_state(&lab.gait_derived, crate::ui::panels::UNSTABLE_WARNING_SHARE),
            terrain: terrain_state(lab),
            method: settings.method.name(),
            methods: lab.compare.as_ref().map_or_else(
                || vec![settings.method.name()],
                |c| c.config.views.iter().map(|m| m.name()).collect(),
            ),
            compare: lab.compare_state(),
            paused: lab.playback.paused,
            playback_rate: lab.playback.rate(),
            rewind: lab.rewind_state(),
            frame: lab.stage.frame,
            time_s: lab.stage.driver.time(),
            fps: lab.playback.fps,
            sim_us_per_frame: lab.playback.sim_us_per_frame,
            wasm_memory_bytes: crate::memory::wasm_memory_bytes(),
            wasm_heap_live_bytes: crate::memory::wasm_heap_bytes().map(|(live, _)| live),
            wasm_heap_peak_bytes: crate::memory::wasm_heap_bytes().map(|(_, peak)| peak),
            view_rect_px: lab.layout.view_rect_px,
            joints: skeleton.joint_count(),
            views: [ViewState {
                method: settings.method.name(),
                effectors,
                creature_box_px: crate::render::viewport::figure_box(
                    &lab.stage.scene,
                    &lab.camera,
                    lab.layout.view_rect_px,
                ),
                metrics: run_metrics(lab),
            }],
            view_options: settings.view.clone(),
            ik: IkState {
                lambda: settings.ik.lambda,
                gamma_max: settings.ik.gamma_max,
                max_step: settings.ik.max_step,
                clamp_every_method: settings.ik.clamp_every_method,
                target_clamp_m: settings.ik.target_clamp_m,
                transpose_alpha: settings.ik.transpose_alpha,
                null_space_gain: settings.ik.null_space_gain,
                enforce_limits: settings.ik.enforce_limits,
                limit_passes: settings.ik.limit_passes,
                jacobian_at: settings.ik.jacobian_at,
                lambda_tradeoff: lab.lambda_tradeoff.clone(),
            },
            plots: settings.plots,
            editor: EditorState {
                open: lab.editor.open,
                dirty: lab.editor.dirty(),
                error: lab.editor.error.clone(),
                message: lab.editor.problem.as_ref().map(|p| p.message.clone()),
                line: lab.editor.problem.as_ref().and_then(|p| p.line),
            },
            heading_deg: settings.heading_deg,
            backend: lab.backend.clone(),
            camera: CameraState::of(&lab.camera, &settings.view),
            plot_joints: lab
                .plots
                .joints
                .iter()
                .map(|&j| skeleton.joints()[j].name.clone())
                .collect(),
            recording: RecordingState {
                active: lab.take.recording(),
                frames: lab.take.take().map_or(0, gaitlab_engine::Take::frames),
                seconds: lab.take.take().map_or(0.0, gaitlab_engine::Take::seconds),
                last_s: settings.export_last_s,
            },
            theme: settings.theme.name(),
            dark: lab.layout.dark_mode,
            layout: LayoutState {
                narrow: lab.layout.narrow,
                controls_open: lab.layout.controls_open,
                controls_button_pt: lab.layout.controls_button_pt,
                trunk_pt: lab.layout.trunk_pt,
                plots_open: lab.layout.plots_open,
                help_open: lab.layout.help_open,
                lesson_note_open: lab.layout.lesson_note_open,
                panels_shown: lab.layout.panels_shown.clone(),
                touch_targets_checked: lab.layout.touch_targets_checked,
                small_touch_targets_pt: lab.layout.small_touch_targets_pt.clone(),
                plots_button_pt: lab.layout.plots_button_pt,
                widgets_pt: lab.layout.widgets_pt,
                popup_open: lab.layout.popup_open,
                preset_combo_clicks: lab.layout.preset_combo_clicks,
                preset_menu_pt: lab.layout.preset_menu_pt.clone(),
                figure_pt: lab.layout.figure_pt,
                view_pt: lab.layout.view_pt,
            },
            video: VideoState {
                recording: lab.video.recording,
                frames: lab.video.frames,
                encoder: lab.video.encoder,
                skipped: lab.video.skipped,
                seconds: lab.video.seconds,
                size: settings.video_size.name(),
            },
            last_error: lab.session.last_error.clone(),
            lesson: lab.session.lesson.clone(),
            track: lab.tracking().map(|t| TrackState {
                file: t.name.clone(),
                rows: t.targets.row_count(),
                effectors: t.targets.effector_count(),
                duration_s: t.targets.end_time() - t.targets.start_time(),
            }),
            notice: lab.session.notice.clone(),
            pinned_targets: lab.pinned_targets(),
            jacobian: lab.driver().ik_solver().map(|_| {
                let views = lab.comparison().map_or(1, |c| c.views().len());
                crate::jacobian::JacobianState::of(lab.jacobian(), views)
            }),
        }
    }
}

/// The figures `gaitlab run --json` prints, for the run since the last
/// reset: the engine layer's one metrics type. Wall-time fields come from
/// the page's smoothed time per frame; `within_limits` is the current pose's.
fn run_metrics(lab: &App) -> gaitlab_engine::RunMetrics {
    let frames = usize::try_from(lab.stage.frame).unwrap_or(usize::MAX);
    let step_ms = lab.playback.sim_us_per_frame * lab.stage.frame as f64 / 1e3;
    let within_limits = gaitlab_engine::metrics::pose_within_limits(
        lab.stage.driver.skeleton(),
        lab.stage.driver.pose(),
    );
    let timing = gaitlab_engine::Timing {
        frames,
        step_ms,
        wall_ms: step_ms,
        within_limits,
    };
    gaitlab_engine::RunMetrics::of(&lab.session.creature.name, &lab.stage.driver, &timing)
        .with_fps(1.0 / lab.frame_seconds())
}

impl App {
    /// The state as one JSON object ([`State`]).
    #[must_use]
    pub fn state_json(&self) -> String {
        // Through `Value`, as the hand-built object was: f32 fields read back
        // as the same f64 numbers.
        serde_json::to_value(State::of(self)).map_or_else(
            |e| format!("{{\"last_error\":\"state: {e}\"}}"),
            |v| v.to_string(),
        )
    }
}

/// The ground under the figure, for `state().terrain`.
fn terrain_state(lab: &App) -> TerrainState {
    let terrain = lab.terrain();
    let root = lab.stage.driver.pose().root.position;
    let spec = match terrain {
        gaitlab_core::terrain::Terrain::HeightField(_) => None,
        other => serde_json::to_value(other).ok(),
    };
    TerrainState {
        kind: terrain.kind_name(),
        spec,
        triangles_drawn: lab
            .stage
            .scene
            .frame()
            .terrain
            .as_ref()
            .map_or(0, |mesh| mesh.triangles()),
        footholds_moved: lab.stage.driver.poda().map_or(0, |d| d.footholds_moved()),
        root_m: root.to_array(),
        ground_under_root_m: terrain.height_m(root.x, root.z),
    }
}
