//! A top-down view of the ground for the path editors (PODA's body path,
//! the physics creatures' waypoints): a square that frames the given points
//! with a margin, x to the right and z up the panel, in metres, with a scale
//! bar and the axes named (issue 21 item 3: the path editor had no scale).

use glam::DVec2;

use crate::plot_scale::round_step;

/// `x` with the decimals a 1, 2 or 5 × 10ⁿ needs (0.05, 0.5, 2, 20).
fn tick_text(x: f64) -> String {
    let decimals = (-x.log10().floor()).clamp(0.0, 4.0) as usize;
    format!("{x:.decimals$}")
}

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

    /// The length of the scale bar, metres: a 1, 2 or 5 × 10ⁿ about a fifth
    /// of the view's width.
    #[must_use]
    pub fn scale_bar_m(&self) -> f64 {
        round_step(f64::from(self.rect.width()) / self.scale / 5.0)
    }

    /// Draws the scale bar in the bottom-left corner and the axes' names
    /// ("seen from above: x right, z up") in the top-left one.
    pub fn draw_scale(&self, painter: &egui::Painter, visuals: &egui::Visuals) {
        let length_m = self.scale_bar_m();
        let stroke = egui::Stroke::new(1.5, visuals.text_color());
        let font = egui::FontId::proportional(12.0);
        let start = self.rect.left_bottom() + egui::vec2(8.0, -10.0);
        let end = start + egui::vec2((length_m * self.scale) as f32, 0.0);
        painter.line_segment([start, end], stroke);
        for at in [start, end] {
            painter.line_segment(
                [at - egui::vec2(0.0, 4.0), at + egui::vec2(0.0, 4.0)],
                stroke,
            );
        }
        painter.text(
            end + egui::vec2(6.0, 0.0),
            egui::Align2::LEFT_CENTER,
            format!("{} m", tick_text(length_m)),
            font.clone(),
            visuals.text_color(),
        );
        painter.text(
            self.rect.left_top() + egui::vec2(6.0, 4.0),
            egui::Align2::LEFT_TOP,
            "seen from above: x right, z up",
            font,
            visuals.weak_text_color(),
        );
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

    #[test]
    fn the_scale_bar_is_a_round_fifth_of_the_view() {
        let ctx = egui::Context::default();
        let mut lengths = Vec::new();
        let mut output = ctx.run_ui(egui::RawInput::default(), |ui| {
            for half_m in [0.3, 2.0, 13.0] {
                let points = [DVec2::new(-half_m, 0.0), DVec2::new(half_m, 0.0)];
                let (view, _) = GroundView::allocate(ui, 200.0, egui::Sense::hover(), points, 0.1);
                lengths.push((
                    view.scale_bar_m(),
                    f64::from(view.rect.width()) / view.scale,
                ));
            }
        });
        output.textures_delta.clear();
        for (bar, width) in lengths {
            let mantissa = bar / 10f64.powf(bar.log10().floor());
            assert!(
                [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-9),
                "{bar}"
            );
            assert!(
                bar >= width / 5.0 && bar <= 2.5 * width / 5.0,
                "{bar} m for {width} m"
            );
        }
        assert_eq!(tick_text(0.05), "0.05");
        assert_eq!(tick_text(2.0), "2");
    }
}
