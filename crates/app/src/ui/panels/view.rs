//! The View and Object transformation panels: what the 3-D view draws, the
//! colour theme, and the figure's heading.

use super::panel::Panel;
use crate::app::App;
use crate::param_widgets::{self as widgets, Param, key};
use crate::theme::Theme;

/// The View and Object transformation panels.
pub struct ViewPanel;

impl Panel for ViewPanel {
    fn title(&self) -> &'static str {
        "View"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        view(ui, lab);
    }
}

/// View and object-transformation panels.
fn view(ui: &mut egui::Ui, lab: &mut App) {
    ui.collapsing("View", |ui| {
        if ui
            .button("Home view")
            .on_hover_text(
                "Frame the figure from a three-quarter view above it (key H; a double-click \
                 on the view does the same)",
            )
            .clicked()
        {
            lab.camera.home();
        }
        let view = &mut lab.session.settings.view;
        ui.checkbox(&mut view.world_axes, "Axes")
            .on_hover_text("World x (red), y (green), z (blue) axes at the origin, 1 m long");
        ui.checkbox(&mut view.perspective, "Perspective")
            .on_hover_text("Perspective projection (off: orthographic)");
        ui.checkbox(&mut view.joint_axes, "Rotation axes")
            .on_hover_text("Each joint's rotation axis as a short segment");
        ui.checkbox(&mut view.targets, "Draw targets")
            .on_hover_text(
                "Targets (red; orange when beyond the limb's reach), footholds and the error \
                 segment from each effector to its target",
            );
        ui.checkbox(&mut view.ellipsoids, "Reach ellipsoids")
            .on_hover_text(
                "Each effector's manipulability ellipsoid: how far a joint step of 0.15 rad \
                 moves it in each direction (from its limb's Jacobian); it flattens to a disc \
                 as the limb straightens",
            );
        ui.checkbox(&mut view.reach_shells, "Reach shells")
            .on_hover_text(
                "Each limb's reach: the sphere of its full extension around its first joint; \
                 a target outside it is out of reach (orange)",
            );
        ui.checkbox(&mut view.grid, "Ground grid")
            .on_hover_text("Ground grid lines, 1 m apart");
        ui.checkbox(&mut view.shadow, "Shadow")
            .on_hover_text("The figure's shadow and foot contact marks on the ground");
        ui.checkbox(&mut view.follow, "Follow the figure")
            .on_hover_text("Keep the camera centred on the figure as it moves");
        ui.checkbox(&mut lab.session.settings.plots, "Plots")
            .on_hover_text("Show the live error and joint-angle plots (hidden on phones)");
        theme(ui, lab);
    });
    ui.collapsing("Object transformation", |ui| {
        let mut heading = lab.session.settings.heading_deg;
        let param = Param::new(key::HEADING).in_degrees();
        if widgets::add(
            ui,
            param,
            egui::Slider::new(&mut heading, param.range()).text(param.text("Heading")),
            "Direction the figure faces, degrees about the vertical axis (restarts the motion)",
        )
        .changed()
        {
            lab.set_heading_deg(heading);
        }
    });
}

/// The colour scheme: system, light or dark (the panels and the 3-D view).
fn theme(ui: &mut egui::Ui, lab: &mut App) {
    ui.horizontal(|ui| {
        ui.label("Theme");
        for theme in Theme::ALL {
            ui.radio_value(&mut lab.session.settings.theme, theme, theme.label())
                .on_hover_text(match theme {
                    Theme::System => "Follow the system's light or dark preference",
                    Theme::Light => "Light panels and a light 3-D view",
                    Theme::Dark => "Dark panels and a dark 3-D view",
                });
        }
    });
}
