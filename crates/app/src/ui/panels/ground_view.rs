//! A top-down view of the ground for the path editors (PODA's body path,
//! the physics creatures' waypoints): a square that frames the given points
//! with a margin, x to the right and z up the panel, in metres.

use glam::DVec2;

/// Where the ground lies in a square of the panel.
pub struct GroundView {
    /// The square on screen.
    pub rect: egui::Rect,
    centre: DVec2,
    /// Screen points per metre.
    pub scale: f64,
}

impl GroundView {
    /// A `size`-point square allocated in `ui` with `sense`, framing every
    /// point of `points` (m) with at least `min_half_m` either side of
    /// their middle.
    pub fn allocate(
        ui: &mut egui::Ui,
        size: f32,
        sense: egui::Sense,
        points: impl IntoIterator<Item = DVec2>,
        min_half_m: f64,
    ) -> (Self, egui::Response) {
        let (rect, response) = ui.allocate_exact_size(egui::vec2(size, size), sense);
        let mut points = points.into_iter();
        let first = points.next().unwrap_or(DVec2::ZERO);
        let (min, max) = points.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p)));
        let centre = 0.5 * (min + max);
        let half = (0.5 * (max - min).max_element()).max(min_half_m) * 1.15;
        let view = Self {
            rect,
            centre,
            scale: f64::from(size) / (2.0 * half),
        };
        (view, response)
    }

    /// The screen point of ground point `p` (m).
    #[must_use]
    pub fn to_screen(&self, p: DVec2) -> egui::Pos2 {
        egui::pos2(
            self.rect.center().x + ((p.x - self.centre.x) * self.scale) as f32,
            self.rect.center().y - ((p.y - self.centre.y) * self.scale) as f32,
        )
    }

    /// The ground point (m) under screen point `at`.
    #[must_use]
    pub fn to_ground(&self, at: egui::Pos2) -> DVec2 {
        DVec2::new(
            self.centre.x + f64::from(at.x - self.rect.center().x) / self.scale,
            self.centre.y - f64::from(at.y - self.rect.center().y) / self.scale,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn screen_and_ground_are_inverse_and_frame_the_points() {
        let mut checked = false;
        egui::__run_test_ui(|ui| {
            let points = [DVec2::new(-1.0, 0.0), DVec2::new(3.0, 2.0)];
            let (view, _) = GroundView::allocate(ui, 200.0, egui::Sense::hover(), points, 0.5);
            for p in points {
                let at = view.to_screen(p);
                assert!(view.rect.contains(at), "{p} framed");
                assert!((view.to_ground(at) - p).length() < 1e-4);
            }
            // z up the panel.
            assert!(view.to_screen(points[1]).y < view.to_screen(points[0]).y);
            checked = true;
        });
        assert!(checked);
    }
}
