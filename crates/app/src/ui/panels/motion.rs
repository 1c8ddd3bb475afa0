//! The IK engine's Motion, Speed and Target positions panels, after She 2006
//! §6.2's workbench: the motion (§5.2), the target script (gaitlab's or the
//! §5.2.2 listing), the wounded weights and their form (§5.1.1), moving
//! forward, the posture pull (the lab's addition), step frequency, slowdown,
//! speed and the targets.

use gaitlab_core::preset::thesis::{
    ListingTarget, TargetScript, ThesisMode, ThesisParams, WoundForm,
};
use gaitlab_engine::DriverKind;
use gaitlab_engine::catalog::check_thesis_params;

use super::panel::Panel;
use crate::app::App;
use crate::param_widgets::{self as widgets, Param, key};

/// The Motion panel.
pub struct MotionPanel;

impl Panel for MotionPanel {
    fn title(&self) -> &'static str {
        "Motion"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().kind() == DriverKind::Thesis
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        motion(ui, lab);
    }
}

/// The Speed and Target positions panels.
pub struct SpeedAndTargetsPanel;

impl Panel for SpeedAndTargetsPanel {
    fn title(&self) -> &'static str {
        "Speed"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().kind() == DriverKind::Thesis
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        speed_and_targets(ui, lab);
    }
}

/// Human label of a thesis motion.
fn mode_label(mode: ThesisMode) -> &'static str {
    match mode {
        ThesisMode::Walk => "Walking",
        ThesisMode::Run => "Running",
        ThesisMode::WoundedWalk => "Wounded walking",
        ThesisMode::WoundedRun => "Wounded running",
    }
}

/// Human label and hover text of a target script.
fn script_label(script: TargetScript) -> (&'static str, &'static str) {
    match script {
        TargetScript::Lab => (
            "gaitlab script",
            "The lab's own targets: foot strokes within reach with a foot lift, hands \
             swinging in front, a bouncing root. Not in the thesis",
        ),
        TargetScript::Listing => (
            "She 2006 listing (§5.2.2)",
            "The thesis' code: only z moves, sinusoidally; feet at x = ±0.35 m, hands at \
             ±0.8 m. Walking the feet are within reach and the hands are not; running none are",
        ),
    }
}

/// Human label and hover text of a wound form.
fn wound_label(form: WoundForm) -> (&'static str, &'static str) {
    match form {
        WoundForm::Step => (
            "on the IK step",
            "The weight scales the joint's IK step each iteration; the other joints \
             make up for it. The lab's reading",
        ),
        WoundForm::Angle => (
            "on the angle shown (§5.1.1)",
            "The thesis: θ shown = w·θ (or θ + w) before the angles are mapped onto the \
             body; the IK keeps its own angles",
        ),
    }
}

/// Motion and motion-control panels.
fn motion(ui: &mut egui::Ui, lab: &mut App) {
    ui.collapsing("Motion", |ui| {
        let mut mode = lab.session.settings.mode;
        for m in ThesisMode::ALL {
            ui.radio_value(&mut mode, m, mode_label(m))
                .on_hover_text("The thesis motion the targets follow");
        }
        if mode != lab.session.settings.mode {
            lab.set_mode(mode);
        }
        let Some(thesis) = lab.driver().thesis_readout() else {
            return;
        };
        let mut params = thesis.params;
        let mut changed = false;
        Param::new(key::SCRIPT).hover(ui.label("Targets:"), "Where the targets come from");
        for script in TargetScript::ALL {
            let (label, tip) = script_label(script);
            changed |= widgets::marked(ui, script == TargetScript::Lab, |ui| {
                ui.radio_value(&mut params.script, script, label)
            })
            .on_hover_text(tip)
            .changed();
        }
        changed |= widgets::add(
            ui,
            Param::new(key::MOVING_FORWARD),
            egui::Checkbox::new(&mut params.moving_forward, "Moving forward"),
            "Move the body forward at the motion's speed (off: walk on the spot)",
        )
        .changed();
        let posture = Param::new(key::POSTURE_GAIN);
        changed |= widgets::add(
            ui,
            posture,
            egui::Slider::new(&mut params.posture_gain, posture.range())
                .text(posture.text("Posture pull")),
            "Not in the thesis: before each frame's IK every joint moves this fraction of its \
             joint gain toward its centre angle (0 = off, the thesis; unitless, 0 to 1)",
        )
        .changed();
        if !params.wounded.is_empty() {
            Param::new(key::WOUND_FORM).hover(
                ui.label("Wounded weights act:"),
                "On the IK's step or on the angle shown",
            );
            for form in WoundForm::ALL {
                let (label, tip) = wound_label(form);
                changed |= widgets::marked(ui, form == WoundForm::Step, |ui| {
                    ui.radio_value(&mut params.wound_form, form, label)
                })
                .on_hover_text(tip)
                .changed();
            }
            ui.label("Wounded joints (multiply weight):");
            let weight = Param::new(key::WOUNDED).band(0.0..=2.0);
            for wounded in &mut params.wounded {
                changed |= widgets::add(
                    ui,
                    weight,
                    egui::Slider::new(&mut wounded.multiply, weight.range())
                        .text(wounded.joint.as_str()),
                    "Weight of this wounded joint in the wounded motions, 0 to 10 (0 stiff, \
                     1 normal, unitless; the slider covers 0 to 2)",
                )
                .changed();
            }
        }
        if changed {
            apply_params(lab, params);
        }
    });
}

fn apply_params(lab: &mut App, params: ThesisParams) {
    let result = check_thesis_params(&params).and_then(|()| lab.set_params(params));
    if let Err(error) = result {
        lab.report_error(error);
    }
}

/// Speed and target-position panels: the thesis' step frequency, slowdown and
/// speed, and the targets of the script in use.
fn speed_and_targets(ui: &mut egui::Ui, lab: &mut App) {
    let Some(thesis) = lab.driver().thesis_readout() else {
        return;
    };
    let mut params = thesis.params;
    let script_speed = thesis.script_speed_mps;
    let running = lab.session.settings.mode.running();
    let mut changed = false;
    ui.collapsing("Speed", |ui| {
        let cycle = Param::new(cycle_key(params.script, running)).band(0.2..=3.0);
        let frequency = match (params.script, running) {
            (TargetScript::Lab, false) => &mut params.walk.frequency_hz,
            (TargetScript::Lab, true) => &mut params.run.frequency_hz,
            (TargetScript::Listing, false) => &mut params.listing.walk.frequency_hz,
            (TargetScript::Listing, true) => &mut params.listing.run.frequency_hz,
        };
        changed |= widgets::add(
            ui,
            cycle,
            egui::Slider::new(frequency, cycle.range()).text("Step frequency (Hz)"),
            "Cycles per second of the target sinusoids, hertz",
        )
        .changed();
        let slowdown = Param::new(key::SLOWDOWN).band(1.0..=20.0);
        changed |= widgets::add(
            ui,
            slowdown,
            egui::Slider::new(&mut params.slowdown, slowdown.range())
                .text(slowdown.text("Slowdown")),
            "Divides the motion's frequency and speed (1 = real time, unitless)",
        )
        .changed();
        let speed_param = Param::new(key::THESIS_SPEED).band(0.0..=6.0);
        let mut matched = params.speed_mps.is_none();
        if widgets::add(
            ui,
            speed_param,
            egui::Checkbox::new(&mut matched, "Speed matched to stride"),
            "Body speed follows stride length × step frequency, so the feet do not slide",
        )
        .changed()
        {
            params.speed_mps = if matched { None } else { Some(script_speed) };
            changed = true;
        }
        if let Some(speed) = params.speed_mps.as_mut() {
            changed |= widgets::add(
                ui,
                speed_param,
                egui::Slider::new(speed, speed_param.range()).text(speed_param.text("Speed")),
                "Forward body speed, metres per second",
            )
            .changed();
        }
    });
    ui.collapsing("Target positions", |ui| match params.script {
        TargetScript::Lab => changed |= lab_targets(ui, &mut params, running),
        TargetScript::Listing => changed |= listing_targets(ui, &mut params, running),
    });
    if changed {
        apply_params(lab, params);
    }
}

/// The table's row of the walking or running cycle of `script`: the lab
/// script's (`scenario.thesis.walk`, `.run`) or §5.2.2's listing.
fn cycle_key(script: TargetScript, running: bool) -> &'static str {
    match (script, running) {
        (TargetScript::Lab, false) => key::WALK,
        (TargetScript::Lab, true) => key::RUN,
        (TargetScript::Listing, _) => key::LISTING,
    }
}

/// One row of x, y, z drag values in metres of the table's row `param`
/// (with the lab tag after the label when it is the lab's); whether any changed.
fn vector_row(
    ui: &mut egui::Ui,
    param: Param,
    label: &str,
    what: &str,
    vector: &mut glam::DVec3,
) -> bool {
    let mut changed = false;
    let param = param.band(-2.0..=2.0);
    ui.horizontal(|ui| {
        ui.label(label);
        if param.is_lab() {
            widgets::lab_mark(ui);
        }
        for (axis, component) in [
            ("x", &mut vector.x),
            ("y", &mut vector.y),
            ("z", &mut vector.z),
        ] {
            changed |= ui
                .add(
                    egui::DragValue::new(component)
                        .speed(0.005)
                        .range(param.range())
                        .suffix(" m"),
                )
                .on_hover_ui(|ui| {
                    param.tooltip(
                        ui,
                        &format!("{label} {what}, {axis} coordinate in metres (drag to change)"),
                    );
                })
                .changed();
        }
    });
    changed
}

/// The lab script's front/back extremes and step height.
fn lab_targets(ui: &mut egui::Ui, params: &mut ThesisParams, running: bool) -> bool {
    let shape = if running {
        &mut params.run
    } else {
        &mut params.walk
    };
    let param = Param::new(cycle_key(TargetScript::Lab, running));
    let mut changed = false;
    for (label, vector) in [
        ("Front foot", &mut shape.front_foot),
        ("Back foot", &mut shape.back_foot),
        ("Front hand", &mut shape.front_hand),
        ("Back hand", &mut shape.back_hand),
    ] {
        changed |= vector_row(ui, param, label, "extreme", vector);
    }
    let lift = param.band(0.0..=0.4);
    changed |= widgets::add(
        ui,
        lift,
        egui::Slider::new(&mut shape.step_height_m, lift.range()).text("Step height (m)"),
        "Highest lift of a swinging foot, metres",
    )
    .changed();
    changed
}

/// The listing's centre and amplitude of each target, relative to the root.
fn listing_targets(ui: &mut egui::Ui, params: &mut ThesisParams, running: bool) -> bool {
    let cycle = if running {
        &mut params.listing.run
    } else {
        &mut params.listing.walk
    };
    let mut changed = false;
    ui.label("centre + amplitude · sin(ωT), metres from the root (x left, y up, z forward)");
    let targets: [(&str, &mut ListingTarget); 4] = [
        ("Left foot", &mut cycle.left_foot),
        ("Right foot", &mut cycle.right_foot),
        ("Left hand", &mut cycle.left_hand),
        ("Right hand", &mut cycle.right_hand),
    ];
    let param = Param::new(key::LISTING);
    for (label, target) in targets {
        changed |= vector_row(ui, param, label, "centre", &mut target.center);
        changed |= vector_row(
            ui,
            param,
            "   amplitude",
            "sine amplitude",
            &mut target.amplitude,
        );
    }
    let root = param.band(0.5..=1.5);
    changed |= widgets::add(
        ui,
        root,
        egui::Slider::new(&mut cycle.root_height_m, root.range()).text("Root height (m)"),
        "Height of the root, the targets' origin, above the ground, metres",
    )
    .changed();
    changed
}
