//! The control panels, after She 2006 §6.2's workbench: Method (with λ, γmax
//! and the step clamp), Motion, Motion control (wounded, moving forward), View,
//! Object transformation, Speed, Target positions, Recording, and the Reset /
//! Pause / Step buttons; plus a preset picker and the live error plot.

use gaitlab_core::ik::Method;
use gaitlab_core::preset::bundled_names;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_motion::validate_params;

use crate::lab::Lab;
use crate::settings::VideoSize;
use crate::theme::Theme;

/// Human labels of the methods, in the thesis' order.
pub(crate) fn method_label(method: Method) -> &'static str {
    match method {
        Method::Transpose => "Jacobian transpose",
        Method::Pinv => "Pseudoinverse",
        Method::Dls => "Damped least squares",
        Method::Sdls => "Selectively damped LS",
        Method::Ccd => "Cyclic coordinate descent",
    }
}

/// What each method does, for its tooltip.
fn method_hint(method: Method) -> &'static str {
    match method {
        Method::Transpose => "Δθ = α Jᵀ e: cheap, never singular, slow to converge",
        Method::Pinv => "Δθ = J⁺ e: fastest convergence, oscillates near singular poses",
        Method::Dls => "Δθ = Jᵀ (J Jᵀ + λ² I)⁻¹ e: damped by λ, stable near singularities",
        Method::Sdls => "Selectively damped least squares: each singular direction clamped by γmax",
        Method::Ccd => {
            "Cyclic coordinate descent: turns one joint at a time to aim the effector at its target; no Jacobian"
        }
    }
}

fn mode_label(mode: ThesisMode) -> &'static str {
    match mode {
        ThesisMode::Walk => "Walking",
        ThesisMode::Run => "Running",
        ThesisMode::WoundedWalk => "Wounded walking",
        ThesisMode::WoundedRun => "Wounded running",
    }
}

/// The engine selector: She 2006's IK tracking or PODA's gait synthesis
/// (switching loads the matching creature).
pub fn engine(ui: &mut egui::Ui, lab: &mut Lab) {
    use gaitlab_core::preset::Engine;
    let mut engine = lab.engine();
    ui.horizontal(|ui| {
        ui.label("Engine");
        ui.radio_value(&mut engine, Engine::Ik, "IK (She 2006)")
            .on_hover_text("Sinusoidal effector targets tracked by Jacobian IK (She 2006)");
        ui.radio_value(&mut engine, Engine::Poda, "PODA gaits")
            .on_hover_text("Gait synthesis from period, duty factor and phases (Girard & Maciejewski 1985)");
        ui.radio_value(&mut engine, Engine::Physics, "Physics")
            .on_hover_text("Simulated runners under hopping, speed and posture control (Raibert & Hodgins 1991)");
    });
    if engine != lab.engine()
        && let Err(error) = lab.set_engine(engine)
    {
        lab.report_error(error);
    }
}

/// The preset picker.
pub fn preset(ui: &mut egui::Ui, lab: &mut Lab) {
    let current = lab.creature().name.clone();
    let mut chosen = None;
    egui::ComboBox::from_label("Preset")
        .selected_text(current.as_str())
        .show_ui(ui, |ui| {
            for name in bundled_names() {
                if ui
                    .selectable_label(name == current, name)
                    .on_hover_text("Load this bundled creature with its own scenario")
                    .clicked()
                {
                    chosen = Some(name);
                }
            }
        })
        .response
        .on_hover_text("The creature and its scenario (bundled presets)");
    if let Some(name) = chosen
        && name != current
        && let Err(error) = lab.set_preset(name)
    {
        lab.report_error(error);
    }
}

/// Method panel: the four IK methods and their parameters.
pub fn method(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.collapsing("Method", |ui| {
        let mut method = lab.settings.method;
        for m in Method::ALL {
            ui.radio_value(&mut method, m, method_label(m))
                .on_hover_text(method_hint(m));
        }
        if method != lab.settings.method {
            lab.set_method(method);
        }
        let ik = &mut lab.settings.ik;
        let mut changed = false;
        changed |= ui
            .add(
                egui::Slider::new(&mut ik.lambda, 0.001..=1.0)
                    .logarithmic(true)
                    .text("DLS λ (m)"),
            )
            .on_hover_text("Damping λ of damped least squares, metres: larger is smoother but lags the targets")
            .changed();
        let mut gamma_deg = ik.gamma_max.to_degrees();
        if ui
            .add(egui::Slider::new(&mut gamma_deg, 1.0..=180.0).text("SDLS γmax (°)"))
            .on_hover_text("Largest joint change SDLS allows per singular direction, degrees")
            .changed()
        {
            ik.gamma_max = gamma_deg.to_radians();
            changed = true;
        }
        let mut step_deg = ik.max_step.to_degrees();
        if ui
            .add(egui::Slider::new(&mut step_deg, 0.5..=90.0).text("Step clamp (°)"))
            .on_hover_text("Largest change of any joint per IK iteration, degrees")
            .changed()
        {
            ik.max_step = step_deg.to_radians();
            changed = true;
        }
        changed |= ui
            .add(egui::Slider::new(&mut ik.null_space_gain, 0.0..=2.0).text("Center pull (PODA)"))
            .on_hover_text(
                "Gain of the null-space term pulling joints to their center angles (pinv, DLS)",
            )
            .changed();
        changed |= ui
            .checkbox(&mut ik.enforce_limits, "Joint limits")
            .on_hover_text("Clamp every joint to its limits after each IK iteration")
            .changed();
        if changed {
            lab.apply_ik_options();
        }
    });
}

/// Motion and motion-control panels.
pub fn motion(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.collapsing("Motion", |ui| {
        let mut mode = lab.settings.mode;
        for m in ThesisMode::ALL {
            ui.radio_value(&mut mode, m, mode_label(m))
                .on_hover_text("The thesis motion the targets follow");
        }
        if mode != lab.settings.mode {
            lab.set_mode(mode);
        }
        let Some(thesis) = lab.driver().thesis() else {
            return;
        };
        let mut params = thesis.params().clone();
        let mut changed = ui
            .checkbox(&mut params.moving_forward, "Moving forward")
            .on_hover_text("Move the body forward at the motion's speed (off: walk on the spot)")
            .changed();
        if !params.wounded.is_empty() {
            ui.label("Wounded joints (multiply weight):");
            for wounded in &mut params.wounded {
                changed |= ui
                    .add(
                        egui::Slider::new(&mut wounded.multiply, 0.0..=2.0)
                            .text(wounded.joint.as_str()),
                    )
                    .on_hover_text(
                        "Weight multiplier of this wounded joint (0 stiff, 1 normal, × unitless)",
                    )
                    .changed();
            }
        }
        if changed {
            apply_params(lab, params);
        }
    });
}

fn apply_params(lab: &mut Lab, params: gaitlab_core::preset::thesis::ThesisParams) {
    let result = validate_params(&params)
        .map_err(|e| e.to_string())
        .and_then(|()| lab.set_params(params));
    if let Err(error) = result {
        lab.report_error(error);
    }
}

/// Speed and target-position panels: the thesis' step frequency, slowdown and
/// speed, and the front/back extremes of the feet and hands.
pub fn speed_and_targets(ui: &mut egui::Ui, lab: &mut Lab) {
    let Some(thesis) = lab.driver().thesis() else {
        return;
    };
    let mut params = thesis.params().clone();
    let script_speed = thesis.script().speed_mps();
    let running = lab.settings.mode.running();
    let mut changed = false;
    ui.collapsing("Speed", |ui| {
        let shape = if running {
            &mut params.run
        } else {
            &mut params.walk
        };
        changed |= ui
            .add(egui::Slider::new(&mut shape.frequency_hz, 0.2..=3.0).text("Step frequency (Hz)"))
            .on_hover_text("Steps per second of the target sinusoids, hertz")
            .changed();
        changed |= ui
            .add(egui::Slider::new(&mut params.slowdown, 1.0..=20.0).text("Slowdown"))
            .on_hover_text("Divides the motion's frequency and speed (1 = real time, unitless)")
            .changed();
        let mut matched = params.speed_mps.is_none();
        if ui
            .checkbox(&mut matched, "Speed matched to stride")
            .on_hover_text(
                "Body speed follows stride length × step frequency, so the feet do not slide",
            )
            .changed()
        {
            params.speed_mps = if matched { None } else { Some(script_speed) };
            changed = true;
        }
        if let Some(speed) = params.speed_mps.as_mut() {
            changed |= ui
                .add(egui::Slider::new(speed, 0.0..=6.0).text("Speed (m/s)"))
                .on_hover_text("Forward body speed, metres per second")
                .changed();
        }
    });
    ui.collapsing("Target positions", |ui| {
        let shape = if running {
            &mut params.run
        } else {
            &mut params.walk
        };
        for (label, vector) in [
            ("Front foot", &mut shape.front_foot),
            ("Back foot", &mut shape.back_foot),
            ("Front hand", &mut shape.front_hand),
            ("Back hand", &mut shape.back_hand),
        ] {
            ui.horizontal(|ui| {
                ui.label(label);
                for (axis, component) in [
                    ("x", &mut vector.x),
                    ("y", &mut vector.y),
                    ("z", &mut vector.z),
                ] {
                    changed |= ui
                        .add(
                            egui::DragValue::new(component)
                                .speed(0.005)
                                .range(-2.0..=2.0)
                                .suffix(" m"),
                        )
                        .on_hover_text(format!(
                            "{label} extreme, {axis} coordinate in metres (drag to change)"
                        ))
                        .changed();
                }
            });
        }
        changed |= ui
            .add(egui::Slider::new(&mut shape.step_height_m, 0.0..=0.4).text("Step height (m)"))
            .on_hover_text("Highest lift of a swinging foot, metres")
            .changed();
    });
    if changed {
        apply_params(lab, params);
    }
}

/// View and object-transformation panels.
pub fn view(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.collapsing("View", |ui| {
        let view = &mut lab.settings.view;
        ui.checkbox(&mut view.world_axes, "Axes")
            .on_hover_text("World x (red), y (green), z (blue) axes at the origin, 1 m long");
        ui.checkbox(&mut view.perspective, "Perspective")
            .on_hover_text("Perspective projection (off: orthographic)");
        ui.checkbox(&mut view.joint_axes, "Rotation axes")
            .on_hover_text("Each joint's rotation axis as a short segment");
        ui.checkbox(&mut view.targets, "Draw targets")
            .on_hover_text(
                "Targets, footholds and the error segment from each effector to its target",
            );
        ui.checkbox(&mut view.grid, "Ground grid")
            .on_hover_text("Ground grid lines, 1 m apart");
        ui.checkbox(&mut view.shadow, "Shadow")
            .on_hover_text("The figure's shadow and foot contact marks on the ground");
        ui.checkbox(&mut view.follow, "Follow the figure")
            .on_hover_text("Keep the camera centred on the figure as it moves");
        ui.checkbox(&mut lab.settings.plots, "Plots")
            .on_hover_text("Show the live error and joint-angle plots (hidden on phones)");
        theme(ui, lab);
    });
    ui.collapsing("Object transformation", |ui| {
        let mut heading = lab.settings.heading_deg;
        if ui
            .add(egui::Slider::new(&mut heading, -180.0..=180.0).text("Heading (°)"))
            .on_hover_text(
                "Direction the figure faces, degrees about the vertical axis (restarts the motion)",
            )
            .changed()
        {
            lab.set_heading_deg(heading);
        }
    });
}

/// Recording panel (She 2006 §6.2): a motion take saved as BVH or CSV, and a
/// video of the 3-D view at a chosen frame size (in the browser).
pub fn recording(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.collapsing("Recording", |ui| {
        ui.horizontal(|ui| {
            if lab.recording() {
                if ui
                    .button("Stop motion")
                    .on_hover_text("Stop recording; the take stays available to save")
                    .clicked()
                {
                    lab.stop_recording();
                }
            } else if ui
                .button("Record motion")
                .on_hover_text("Record every animation frame: pose, effectors and targets")
                .clicked()
            {
                lab.start_recording();
            }
            if let Some(take) = lab.take() {
                ui.label(format!(
                    "{} frames · {:.1} s",
                    take.frames(),
                    take.seconds()
                ));
            }
        });
        let has_take = lab.take().is_some_and(|t| t.frames() > 0);
        ui.horizontal(|ui| {
            ui.label("Save the last");
            ui.add(
                egui::DragValue::new(&mut lab.settings.export_last_s)
                    .range(0.0..=gaitlab_engine::MAX_TAKE_S)
                    .speed(0.1)
                    .max_decimals(2)
                    .suffix(" s"),
            )
            .on_hover_text("Seconds at the end of the take that Save BVH / Save CSV write, in seconds of animation; 0 saves the whole take");
        });
        ui.horizontal(|ui| {
            for (label, format, hint) in [
                (
                    "Save BVH",
                    "bvh",
                    "Motion capture file for Blender, Maya and friends",
                ),
                (
                    "Save CSV",
                    "csv",
                    "Time, root, joint values, effectors and targets",
                ),
            ] {
                if ui
                    .add_enabled(has_take, egui::Button::new(label))
                    .on_hover_text(hint)
                    .clicked()
                    && let Err(error) = lab.save_take_as_set(format)
                {
                    lab.report_error(error);
                }
            }
        });
        ui.separator();
        let mut size = lab.settings.video_size;
        egui::ComboBox::from_label("Video frame size")
            .selected_text(size.label())
            .show_ui(ui, |ui| {
                for s in VideoSize::ALL {
                    ui.selectable_value(&mut size, s, s.label())
                        .on_hover_text("Width × height of the recorded video, pixels");
                }
            })
            .response
            .on_hover_text("Frame size of the WebM video, pixels (View size: the 3-D view as shown)");
        lab.settings.video_size = size;
        let video_supported = cfg!(target_arch = "wasm32");
        ui.add_enabled_ui(video_supported, |ui| {
            if lab.video_recording() {
                if ui
                    .button("Stop video")
                    .on_hover_text("Stop the video and download it as a WebM file")
                    .clicked()
                {
                    lab.set_video_recording(false);
                }
            } else if ui
                .button("Record video")
                .on_hover_text("Record the 3-D view as a WebM video")
                .clicked()
            {
                lab.set_video_recording(true);
            }
        });
    });
}

/// Reset / Pause / Step, with the keyboard shortcuts (space, R, .).
pub fn buttons(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.horizontal(|ui| {
        if ui
            .button("Reset")
            .on_hover_text("Back to time 0 and the rest pose (key R)")
            .clicked()
        {
            lab.reset();
        }
        let label = if lab.paused() { "Play" } else { "Pause" };
        if ui
            .button(label)
            .on_hover_text("Pause or resume the animation (space bar)")
            .clicked()
        {
            lab.set_paused(!lab.paused());
        }
        if ui
            .button("Step")
            .on_hover_text("Pause and advance exactly one animation frame (key .)")
            .clicked()
        {
            lab.set_paused(true);
            lab.single_step();
        }
    });
}

/// The colour scheme: system, light or dark (the panels and the 3-D view).
pub fn theme(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.horizontal(|ui| {
        ui.label("Theme");
        for theme in Theme::ALL {
            ui.radio_value(&mut lab.settings.theme, theme, theme.label())
                .on_hover_text(match theme {
                    Theme::System => "Follow the system's light or dark preference",
                    Theme::Light => "Light panels and a light 3-D view",
                    Theme::Dark => "Dark panels and a dark 3-D view",
                });
        }
    });
}
