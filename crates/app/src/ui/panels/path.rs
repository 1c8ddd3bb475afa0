//! The body-path editor (Girard & Maciejewski 1985, "Horizontal Control": the
//! animator designs the body's path as a Catmull-Rom or B-spline on the
//! ground): a top-down view of the path, its control points to drag, the
//! body's place on it, and ready-made paths.

use gaitlab_core::preset::{PathKindSpec, PathSpec};
use gaitlab_engine::DriverKind;
use glam::DVec2;

use super::ground_view::GroundView;
use super::panel::Panel;
use crate::app::App;

/// The body-path editor.
pub struct PathPanel;

impl Panel for PathPanel {
    fn title(&self) -> &'static str {
        "Path"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver().kind() == DriverKind::Poda
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        path(ui, lab);
    }
}

/// Side of the square top-down view, points.
const VIEW_SIZE: f32 = 250.0;
/// Radius of a control point's handle, points.
const HANDLE_RADIUS: f32 = 5.0;

/// Ready-made paths: a straight line, a circle of radius 2 m, an S-curve.
fn preset_path(name: &str, start: DVec2) -> PathSpec {
    let points: Vec<[f64; 2]> = match name {
        "circle" => (0..12)
            .map(|k| {
                let a = f64::from(k) / 12.0 * std::f64::consts::TAU;
                [start.x + 2.0 - 2.0 * a.cos(), start.y + 2.0 * a.sin()]
            })
            .collect(),
        "s-curve" => vec![
            [start.x, start.y],
            [start.x, start.y + 2.0],
            [start.x + 1.5, start.y + 4.0],
            [start.x + 1.5, start.y + 6.0],
            [start.x, start.y + 8.0],
            [start.x, start.y + 10.0],
        ],
        _ => vec![[start.x, start.y], [start.x, start.y + 20.0]],
    };
    PathSpec {
        kind: PathKindSpec::CatmullRom,
        closed: name == "circle",
        speeds_mps: None,
        points,
    }
}

/// The path panel (shown for PODA creatures).
fn path(ui: &mut egui::Ui, lab: &mut App) {
    if lab.driver().kind() != DriverKind::Poda {
        return;
    }
    // Filled only while the panel is open: the edited path.
    let mut edited: Option<PathSpec> = None;
    ui.collapsing("Body path", |ui| {
        // Read only while the panel is open: the path sampled along its length.
        let Some(path) = lab.driver().poda_path() else {
            return;
        };
        let mut spec = path.spec;
        let mut changed = false;
        let body = path.body;
        ui.horizontal(|ui| {
            for (label, name) in [
                ("Straight", "straight"),
                ("Circle", "circle"),
                ("S-curve", "s-curve"),
            ] {
                if ui
                    .button(label)
                    .on_hover_text("Replace the body path with this shape, starting at the body")
                    .clicked()
                {
                    spec = preset_path(name, body);
                    changed = true;
                }
            }
        });
        ui.horizontal(|ui| {
            changed |= ui
                .radio_value(&mut spec.kind, PathKindSpec::CatmullRom, "Catmull-Rom")
                .on_hover_text("Spline through every control point")
                .changed();
            changed |= ui
                .radio_value(&mut spec.kind, PathKindSpec::BSpline, "B-spline")
                .on_hover_text("Smoother spline near (not through) the control points")
                .changed();
        });
        changed |= top_down(ui, &mut spec, &path.samples, (body, path.closest));
        let (now, most) = (path.error_m, path.error_max_m);
        ui.label(format!(
            "Body off its path: {:.0} mm now, {:.0} mm at most",
            now * 1e3,
            most * 1e3
        ))
        .on_hover_text(if path.turn_within_reach {
            "The body turns no tighter than its legs reach and waits for nothing: on a \
             bend its legs cannot take it cuts the corner (the lab's reading of the \
             paper's horizontal control, scenario.poda.turn_within_reach), and the feet stay planted."
        } else {
            "turn_within_reach is off: the body follows the path as eq. 14–15's leg forces \
             allow, and on bends tighter than the legs reach the planted feet are dragged."
        });
        ui.weak("Drag the control points; the body joins the new path where it is closest.");
        if changed {
            edited = Some(spec);
        }
    });
    if let Some(spec) = edited
        && let Err(error) = lab.set_path(&spec)
    {
        lab.report_error(error);
    }
}

/// Draws the path from above and lets the control points be dragged; true
/// when a point moved.
/// `body` is the body's ground position and the path point closest to it.
fn top_down(
    ui: &mut egui::Ui,
    spec: &mut PathSpec,
    samples: &[DVec2],
    (body, closest): (DVec2, DVec2),
) -> bool {
    // The points, the samples and the body, framed.
    let framed = samples
        .iter()
        .copied()
        .chain(spec.points.iter().map(|&p| DVec2::from(p)))
        .chain([body]);
    let (view, _) = GroundView::allocate(ui, VIEW_SIZE, egui::Sense::hover(), framed, 0.5);
    let painter = ui.painter_at(view.rect);
    let visuals = ui.visuals();
    painter.rect_filled(view.rect, 2.0, visuals.extreme_bg_color);
    view.draw_scale(&painter, visuals);
    let scale = view.scale;
    let to_screen = |p: DVec2| view.to_screen(p);
    let line: Vec<egui::Pos2> = samples.iter().map(|&p| to_screen(p)).collect();
    painter.add(egui::Shape::line(
        line,
        egui::Stroke::new(2.0, visuals.selection.bg_fill),
    ));
    if (closest - body).length() > 0.01 {
        // How far the body is off its path: a line to the closest point.
        painter.line_segment(
            [to_screen(body), to_screen(closest)],
            egui::Stroke::new(1.5, visuals.warn_fg_color),
        );
    }
    painter.circle_filled(to_screen(body), 4.0, visuals.warn_fg_color);
    painter.text(
        to_screen(body) + egui::vec2(7.0, -7.0),
        egui::Align2::LEFT_BOTTOM,
        "body",
        egui::FontId::proportional(12.0),
        visuals.warn_fg_color,
    );
    let mut moved = false;
    for (k, point) in spec.points.iter_mut().enumerate() {
        let at = to_screen(DVec2::from(*point));
        let handle = egui::Rect::from_center_size(at, egui::vec2(4.0, 4.0) * HANDLE_RADIUS);
        let response = ui
            .interact(
                handle,
                ui.scope_id().with(("path-point", k)),
                egui::Sense::drag(),
            )
            .on_hover_text(format!(
                "Control point {k} at x {:.2} m, z {:.2} m: drag to move it",
                point[0], point[1]
            ));
        if response.dragged() {
            let delta = response.drag_delta();
            point[0] += f64::from(delta.x) / scale;
            point[1] -= f64::from(delta.y) / scale;
            moved = true;
        }
        let color = if response.hovered() || response.dragged() {
            visuals.strong_text_color()
        } else {
            visuals.text_color()
        };
        painter.circle_stroke(at, HANDLE_RADIUS, egui::Stroke::new(1.5, color));
    }
    moved
}
