//! The IK engine's panels, after She 2006 §6.2's workbench: Method (with λ,
//! γmax and the step clamp), Motion and motion control (wounded, moving
//! forward), Speed and Target positions.

use gaitlab_core::ik::{JacobianAt, Method};
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_motion::validate_params;

use super::panel::Panel;
use crate::lab::Lab;

/// The Method panel (hidden while a comparison runs: each view has its own).
pub struct MethodPanel;

impl Panel for MethodPanel {
    fn title(&self) -> &'static str {
        "Method"
    }

    fn shown_for(&self, lab: &Lab) -> bool {
        lab.driver().thesis().is_some() && lab.comparison().is_none()
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        method(ui, lab);
    }
}

/// The Motion panel.
pub struct MotionPanel;

impl Panel for MotionPanel {
    fn title(&self) -> &'static str {
        "Motion"
    }

    fn shown_for(&self, lab: &Lab) -> bool {
        lab.driver().thesis().is_some()
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        motion(ui, lab);
    }
}

/// The Speed and Target positions panels.
pub struct SpeedAndTargetsPanel;

impl Panel for SpeedAndTargetsPanel {
    fn title(&self) -> &'static str {
        "Speed"
    }

    fn shown_for(&self, lab: &Lab) -> bool {
        lab.driver().thesis().is_some()
    }

    fn ui(&self, lab: &mut Lab, ui: &mut egui::Ui) {
        speed_and_targets(ui, lab);
    }
}

/// Human labels of the methods, in the thesis' order.
fn method_label(method: Method) -> &'static str {
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

/// Labels of She 2006 §3.2's two control ways.
fn jacobian_at_label(way: JacobianAt) -> &'static str {
    match way {
        JacobianAt::Effectors => "Effectors to targets",
        JacobianAt::Targets => "Targets to effectors",
    }
}

/// What each control way does, for its tooltip.
fn jacobian_at_hint(way: JacobianAt) -> &'static str {
    match way {
        JacobianAt::Effectors => {
            "Jacobian at the end effectors, columns v × (s − p): the end effectors move towards the targets (the usual way)"
        }
        JacobianAt::Targets => {
            "Jacobian at the targets, columns v × (t − p) (Buss's Jtarget): the targets move towards the end effectors; the error is still t − s"
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

/// Method panel: the four IK methods and their parameters.
fn method(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.collapsing("Method", |ui| {
        let mut method = lab.session.settings.method;
        for m in Method::ALL {
            ui.radio_value(&mut method, m, method_label(m))
                .on_hover_text(method_hint(m));
        }
        if method != lab.session.settings.method {
            lab.set_method(method);
        }
        let ik = &mut lab.session.settings.ik;
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
        ui.label("She 2006 §3.2 control way:")
            .on_hover_text("Where the Jacobian is taken (no effect on CCD)");
        for way in JacobianAt::ALL {
            changed |= ui
                .radio_value(&mut ik.jacobian_at, way, jacobian_at_label(way))
                .on_hover_text(jacobian_at_hint(way))
                .changed();
        }
        if changed {
            lab.apply_ik_options();
        }
    });
}

/// Motion and motion-control panels.
fn motion(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.collapsing("Motion", |ui| {
        let mut mode = lab.session.settings.mode;
        for m in ThesisMode::ALL {
            ui.radio_value(&mut mode, m, mode_label(m))
                .on_hover_text("The thesis motion the targets follow");
        }
        if mode != lab.session.settings.mode {
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
fn speed_and_targets(ui: &mut egui::Ui, lab: &mut Lab) {
    let Some(thesis) = lab.driver().thesis() else {
        return;
    };
    let mut params = thesis.params().clone();
    let script_speed = thesis.script().speed_mps();
    let running = lab.session.settings.mode.running();
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
