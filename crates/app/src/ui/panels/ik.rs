//! The IK engine's Method panel, after She 2006 §6.2's workbench: the four
//! methods (and CCD) with λ, γmax and the step clamp.

use gaitlab_core::ik::{JacobianAt, Method, TransposeAlpha};

use super::panel::Panel;
use crate::app::App;
use crate::param_widgets::{self as widgets, Param, key};

/// The Method panel (hidden while a comparison runs: each view has its own).
pub struct MethodPanel;

impl Panel for MethodPanel {
    fn title(&self) -> &'static str {
        "Method"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().is_ik() && lab.comparison().is_none()
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        method(ui, lab);
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
        Method::Transpose => "Δθ = α Jᵀ e: no inverse, a step along the error's gradient",
        Method::Pinv => {
            "Δθ = J⁺ e: the least-norm step; its gain 1/σ grows without bound near singular poses"
        }
        Method::Dls => "Δθ = Jᵀ (J Jᵀ + λ² I)⁻¹ e: each direction damped by λ, gain at most 1/(2λ)",
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

fn transpose_alpha_label(alpha: TransposeAlpha) -> &'static str {
    match alpha {
        TransposeAlpha::Thesis => "§4.4.1",
        TransposeAlpha::Buss => "Buss",
    }
}

fn transpose_alpha_hint(alpha: TransposeAlpha) -> &'static str {
    match alpha {
        TransposeAlpha::Thesis => {
            "α = Δs·Δt / (2|Δt|²) with Δs = e and Δt = JJᵀe, as She 2006 §4.4.1 prints it"
        }
        TransposeAlpha::Buss => {
            "The lab's: Buss's α = ⟨e, JJᵀe⟩/‖JJᵀe‖², twice the thesis' (the α that brings JΔθ closest to e)"
        }
    }
}

/// Method panel: the four IK methods and their parameters.
fn method(ui: &mut egui::Ui, lab: &mut App) {
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
        let lambda = Param::new(key::LAMBDA).band(0.001..=1.0);
        changed |= widgets::add(
            ui,
            lambda,
            egui::Slider::new(&mut ik.lambda, lambda.range())
                .logarithmic(true)
                .text(lambda.text("DLS λ")),
            "Damping λ of damped least squares, metres: larger is smoother but lags the targets",
        )
        .changed();
        let gamma = Param::new(key::GAMMA_MAX).in_degrees().band(1.0..=180.0);
        let mut gamma_deg = ik.gamma_max.to_degrees();
        if widgets::add(
            ui,
            gamma,
            egui::Slider::new(&mut gamma_deg, gamma.range()).text(gamma.text("SDLS γmax")),
            "Largest joint change SDLS allows per singular direction, degrees",
        )
        .changed()
        {
            ik.gamma_max = gamma_deg.to_radians();
            changed = true;
        }
        let step = Param::new(key::MAX_STEP).in_degrees().band(0.5..=90.0);
        let mut step_deg = ik.max_step.to_degrees();
        if widgets::add(
            ui,
            step,
            egui::Slider::new(&mut step_deg, step.range()).text(step.text("Step clamp")),
            "Largest change of any joint per IK iteration, degrees: pinv's, as She 2006 \
             §4.4.2 scales a pseudoinverse step that exceeds it (the thesis gives no value)",
        )
        .changed()
        {
            ik.max_step = step_deg.to_radians();
            changed = true;
        }
        changed |= widgets::add(
            ui,
            Param::new(key::CLAMP_EVERY_METHOD),
            egui::Checkbox::new(&mut ik.clamp_every_method, "Clamp transpose and DLS too"),
            "The step clamp on transpose and DLS as well as pinv, as Buss's code does; \
             §4.4.2 clamps pinv only. Files made before 2026-12-05 run with it",
        )
        .changed();
        let target_clamp = Param::new(key::TARGET_CLAMP).band(0.0..=1.0);
        changed |= widgets::add(
            ui,
            target_clamp,
            egui::Slider::new(&mut ik.target_clamp_m, target_clamp.range())
                .text(target_clamp.text("Target clamp (m, 0 off)")),
            "Buss's target clamp: each effector's error is cut to this length before every \
             method's solve, so a far target pulls no harder than one this far (his SDLS \
             uses 0.4 of his scene's units). The thesis clamps no target: 0, off",
        )
        .changed();
        ui.horizontal(|ui| {
            Param::new(key::TRANSPOSE_ALPHA).hover(
                ui.label("Transpose α:"),
                "The step length of Δθ = α Jᵀe (She 2006 §4.4.1)",
            );
            for alpha in TransposeAlpha::ALL {
                changed |= ui
                    .radio_value(&mut ik.transpose_alpha, alpha, transpose_alpha_label(alpha))
                    .on_hover_text(transpose_alpha_hint(alpha))
                    .changed();
                if alpha == TransposeAlpha::Buss {
                    widgets::lab_mark(ui);
                }
            }
        });
        let pull = Param::new(key::NULL_SPACE_GAIN).band(0.0..=2.0);
        changed |= widgets::add(
            ui,
            pull,
            egui::Slider::new(&mut ik.null_space_gain, pull.range())
                .text(pull.text("Center pull (PODA)")),
            "Gain of the null-space term pulling joints to their center angles (pinv, DLS)",
        )
        .changed();
        changed |= widgets::add(
            ui,
            Param::new(key::ENFORCE_LIMITS),
            egui::Checkbox::new(&mut ik.enforce_limits, "Joint limits"),
            "Clamp every joint to its limits after each IK iteration",
        )
        .changed();
        let passes = Param::new(key::LIMIT_PASSES);
        let enabled = ik.enforce_limits;
        changed |= widgets::control(
            ui,
            passes,
            "1: a joint past its limit takes the limit value, as She 2006 §6.1.1.1 does. \
             More (the lab's addition): solve again without the clamped joints, up to this \
             many solves per iteration, so the free joints make up the difference",
            |ui| {
                ui.add_enabled(
                    enabled,
                    egui::Slider::new(&mut ik.limit_passes, passes.count_range())
                        .text(passes.text("Limit passes")),
                )
            },
        )
        .changed();
        Param::new(key::JACOBIAN_AT).hover(
            ui.label("She 2006 §3.2 control way:"),
            "Where the Jacobian is taken (no effect on CCD)",
        );
        for way in JacobianAt::ALL {
            changed |= ui
                .radio_value(&mut ik.jacobian_at, way, jacobian_at_label(way))
                .on_hover_text(jacobian_at_hint(way))
                .changed();
        }
        if changed {
            lab.apply_ik_options();
        }
        if let Some(mode) = lab.stage.driver.thesis_mode() {
            let running = crate::lambda_tradeoff::plot::Running {
                mode,
                preset: &lab.session.creature.name,
                lambda_m: lab.session.settings.ik.lambda,
            };
            if crate::lambda_tradeoff::plot::section(ui, &running, lab.lambda_tradeoff())
                && let Err(error) = lab.measure_lambda_tradeoff()
            {
                lab.report_error(error);
            }
        }
    });
}
