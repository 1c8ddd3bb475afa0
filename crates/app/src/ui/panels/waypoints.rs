//! The waypoint editor of a physics creature (Raibert & Hodgins 1991,
//! Figure 2: the animator gives "the path along which to travel"; the
//! creatures follow "simple paths"): a top-down view of the ground where a
//! click adds a waypoint, the creature's place and track, and ready-made
//! paths. The steering aims at each waypoint in turn.

use glam::DVec2;

use super::ground_view::GroundView;
use super::panel::Panel;
use crate::app::App;

/// The waypoint editor.
pub struct WaypointsPanel;

impl Panel for WaypointsPanel {
    fn title(&self) -> &'static str {
        "Path (waypoints)"
    }

    fn shown_for(&self, lab: &App) -> bool {
        lab.driver()
            .physics_route()
            .is_some_and(|route| route.steerable)
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        waypoints(ui, lab);
    }
}

/// Side of the square top-down view, points.
const VIEW_SIZE: f32 = 250.0;

/// A square of side `side_m` starting at `at`, turning left: four corners
/// and back to the start.
#[must_use]
pub fn square(at: DVec2, side_m: f64) -> Vec<[f64; 2]> {
    [(0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0), (0.0, 0.0)]
        .iter()
        .map(|&(x, z)| [at.x + x * side_m, at.y + z * side_m])
        .collect()
}

fn waypoints(ui: &mut egui::Ui, lab: &mut App) {
    let Some(route) = lab.driver().physics_route() else {
        return;
    };
    // Waypoints are metres at scale 1; the creature's place too.
    let body = route.body_m;
    let mut points = route.waypoints;
    let next = route.next_waypoint;
    let mut changed = false;
    ui.collapsing("Path (waypoints)", |ui| {
        ui.horizontal(|ui| {
            if ui
                .button("Square 8 m")
                .on_hover_text("Four waypoints on an 8 m square, turning left from here")
                .clicked()
            {
                points = square(body, 8.0);
                changed = true;
            }
            if ui
                .button("Clear")
                .on_hover_text("No path: the creature keeps its heading")
                .clicked()
            {
                points.clear();
                changed = true;
            }
        });
        let framed = points.iter().map(|&p| DVec2::from(p)).chain([body]);
        let (view, response) =
            GroundView::allocate(ui, VIEW_SIZE, egui::Sense::click(), framed, 3.0);
        let painter = ui.painter_at(view.rect);
        let visuals = ui.visuals();
        painter.rect_filled(view.rect, 2.0, visuals.extreme_bg_color);
        view.draw_scale(&painter, visuals);
        let mut line: Vec<egui::Pos2> = vec![view.to_screen(body)];
        line.extend(
            points
                .iter()
                .skip(next)
                .map(|&p| view.to_screen(DVec2::from(p))),
        );
        painter.add(egui::Shape::line(
            line,
            egui::Stroke::new(1.5, visuals.selection.bg_fill),
        ));
        for (k, &p) in points.iter().enumerate() {
            let at = view.to_screen(DVec2::from(p));
            let color = if k < next {
                visuals.weak_text_color()
            } else {
                visuals.strong_text_color()
            };
            painter.circle_stroke(at, 5.0, egui::Stroke::new(1.5, color));
            painter.text(
                at + egui::vec2(7.0, -7.0),
                egui::Align2::LEFT_BOTTOM,
                k.to_string(),
                egui::FontId::proportional(11.0),
                color,
            );
        }
        painter.circle_filled(view.to_screen(body), 4.0, visuals.warn_fg_color);
        if let Some(at) = response
            .clicked()
            .then(|| response.interact_pointer_pos())
            .flatten()
        {
            let p = view.to_ground(at);
            points.push([p.x, p.y]);
            changed = true;
        }
        response.on_hover_text("Click to add a waypoint; the creature steers to each in turn");
        ui.weak(format!(
            "{} waypoints, {} reached",
            points.len(),
            next.min(points.len())
        ));
    });
    if changed && let Err(error) = lab.set_waypoints(&points) {
        lab.report_error(error);
    }
}
