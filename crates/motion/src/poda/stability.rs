//! Static stability of a walk (issue 21 item 3; the criterion Girard &
//! Maciejewski's gait design assumes for slow walks, after McGhee's
//! support-polygon rule): the support polygon is the convex hull of the feet
//! on the ground, seen from above; the body is statically stable while its
//! centre projects inside it, and the stability margin is that point's
//! distance to the polygon's nearest edge (negative outside, and for fewer
//! than three feet, which span no area). Measured every frame and summed over
//! the last gait period.

use std::collections::VecDeque;

use glam::DVec2;

/// Frames kept for the trailing window before the buffer would grow.
const WINDOW_FRAMES: usize = 4096;

/// The support polygon of `feet` (ground points, x and z) into `hull`, as a
/// convex hull in counter-clockwise order (Andrew's monotone chain); fewer
/// than three distinct points stay as they are. Sorts `feet` in place.
pub fn support_polygon(feet: &mut [DVec2], hull: &mut Vec<DVec2>) {
    hull.clear();
    // Unstable: sorts in place without a buffer (called every frame).
    feet.sort_unstable_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let cross = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    for &p in feet.iter() {
        while hull.len() >= 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
            hull.pop();
        }
        if hull
            .last()
            .is_none_or(|&q| (q - p).length_squared() > 1e-18)
        {
            hull.push(p);
        }
    }
    let lower = hull.len() + 1;
    for &p in feet.iter().rev().skip(1) {
        while hull.len() >= lower && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
            hull.pop();
        }
        hull.push(p);
    }
    // The last point pushed is the first (the chain closes on it).
    if hull.len() > 2 {
        hull.pop();
    }
    hull.dedup_by(|a, b| (*a - *b).length_squared() < 1e-18);
}

/// The static stability margin of `centre` over the convex polygon `hull`
/// (counter-clockwise), metres: the distance to the nearest edge, positive
/// inside, negative outside; for a polygon of fewer than three corners, minus
/// the distance to it (a line or a point of support has no inside).
#[must_use]
pub fn stability_margin_m(hull: &[DVec2], centre: DVec2) -> f64 {
    match hull.len() {
        0 => f64::NEG_INFINITY,
        1 => -(centre - hull[0]).length(),
        2 => -distance_to_segment(centre, hull[0], hull[1]),
        n => {
            let mut inside = true;
            let mut nearest = f64::INFINITY;
            for i in 0..n {
                let (a, b) = (hull[i], hull[(i + 1) % n]);
                inside &= (b - a).perp_dot(centre - a) >= 0.0;
                nearest = nearest.min(distance_to_segment(centre, a, b));
            }
            if inside { nearest } else { -nearest }
        }
    }
}

fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let along = if ab.length_squared() > 0.0 {
        ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * along)).length()
}

/// This frame's stability and its share over the last gait period.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StabilityReport {
    /// Feet on the ground now.
    pub feet_down: usize,
    /// The margin now, metres (negative: the centre is outside the support
    /// polygon, or fewer than three feet are down); `None` in flight.
    pub margin_m: Option<f64>,
    /// Share of the last gait period's time the body stood statically
    /// unstable with at least one foot down (0–1).
    pub unstable_share: f64,
}

/// Measures static stability frame by frame; keeps its buffers.
#[derive(Clone, Debug)]
pub struct StabilityMeter {
    feet: Vec<DVec2>,
    hull: Vec<DVec2>,
    /// `(frame end s, frame length s, unstable)` over the trailing window.
    frames: VecDeque<(f64, f64, bool)>,
    unstable_s: f64,
    window_total_s: f64,
    report: StabilityReport,
}

impl Default for StabilityMeter {
    fn default() -> Self {
        Self {
            feet: Vec::with_capacity(16),
            hull: Vec::with_capacity(32),
            frames: VecDeque::with_capacity(WINDOW_FRAMES),
            unstable_s: 0.0,
            window_total_s: 0.0,
            report: StabilityReport::default(),
        }
    }
}

impl StabilityMeter {
    /// Forgets every frame.
    pub fn clear(&mut self) {
        self.frames.clear();
        self.unstable_s = 0.0;
        self.window_total_s = 0.0;
        self.report = StabilityReport::default();
    }

    /// Records the frame `[t_prev, t]`: the ground points of the feet down,
    /// the body's centre on the ground, and the gait period `window_s` the
    /// share is taken over.
    pub fn record(
        &mut self,
        t_prev: f64,
        t: f64,
        feet_down: impl Iterator<Item = DVec2>,
        centre: DVec2,
        window_s: f64,
    ) {
        self.feet.clear();
        self.feet.extend(feet_down);
        support_polygon(&mut self.feet, &mut self.hull);
        let margin = (!self.feet.is_empty()).then(|| stability_margin_m(&self.hull, centre));
        let unstable = margin.is_some_and(|m| m < 0.0);
        let dt = (t - t_prev).max(0.0);
        if self.frames.len() == WINDOW_FRAMES {
            self.forget_oldest();
        }
        self.frames.push_back((t, dt, unstable));
        self.window_total_s += dt;
        if unstable {
            self.unstable_s += dt;
        }
        while self
            .frames
            .front()
            .is_some_and(|&(end, _, _)| end <= t - window_s)
        {
            self.forget_oldest();
        }
        self.report = StabilityReport {
            feet_down: self.feet.len(),
            margin_m: margin,
            unstable_share: if self.window_total_s > 0.0 {
                (self.unstable_s / self.window_total_s).clamp(0.0, 1.0)
            } else {
                0.0
            },
        };
    }

    fn forget_oldest(&mut self) {
        if let Some((_, dt, unstable)) = self.frames.pop_front() {
            self.window_total_s -= dt;
            if unstable {
                self.unstable_s -= dt;
            }
        }
    }

    /// The latest frame's report.
    #[must_use]
    pub fn report(&self) -> StabilityReport {
        self.report
    }

    /// The support polygon of the latest frame (ground x, z), counter-clockwise.
    #[must_use]
    pub fn polygon(&self) -> &[DVec2] {
        &self.hull
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hull_of(points: &[[f64; 2]]) -> Vec<DVec2> {
        let mut feet: Vec<DVec2> = points.iter().map(|&[x, z]| DVec2::new(x, z)).collect();
        let mut hull = Vec::new();
        support_polygon(&mut feet, &mut hull);
        hull
    }

    #[test]
    fn the_hull_of_a_square_with_a_point_inside_is_the_square() {
        let hull = hull_of(&[[0.0, 0.0], [1.0, 0.0], [0.5, 0.5], [1.0, 1.0], [0.0, 1.0]]);
        assert_eq!(hull.len(), 4, "{hull:?}");
        // Counter-clockwise: positive area.
        let area: f64 = (0..4)
            .map(|i| hull[i].perp_dot(hull[(i + 1) % 4]))
            .sum::<f64>()
            / 2.0;
        assert!((area - 1.0).abs() < 1e-12, "{area}");
    }

    #[test]
    fn three_feet_in_a_row_and_a_foot_opposite_make_a_triangle() {
        // The hexapod's five feet down: three on the left, in a line.
        let hull = hull_of(&[
            [-0.246, 1.04],
            [-0.246, 0.586],
            [0.246, 0.666],
            [0.246, 0.893],
            [-0.246, 0.813],
        ]);
        assert_eq!(hull.len(), 4, "{hull:?}");
        assert!(!hull.contains(&DVec2::new(-0.246, 0.813)), "{hull:?}");
        let margin = stability_margin_m(&hull, DVec2::new(0.0, 0.837));
        assert!(margin > 0.0, "the centre is inside: {margin}");
    }

    #[test]
    fn the_margin_is_the_distance_to_the_nearest_edge_signed() {
        let hull = hull_of(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        let margin = |x, z| stability_margin_m(&hull, DVec2::new(x, z));
        assert!((margin(0.5, 0.5) - 0.5).abs() < 1e-12);
        assert!((margin(0.9, 0.5) - 0.1).abs() < 1e-12);
        assert!((margin(1.3, 0.5) + 0.3).abs() < 1e-12);
        // Two feet: a line has no inside, so the centre on it has margin 0,
        // off it a negative margin.
        let line = hull_of(&[[0.0, 0.0], [1.0, 0.0]]);
        assert_eq!(stability_margin_m(&line, DVec2::new(0.5, 0.0)), 0.0);
        assert!((stability_margin_m(&line, DVec2::new(0.5, 0.2)) + 0.2).abs() < 1e-12);
    }

    #[test]
    fn the_unstable_share_counts_the_last_window_only() {
        let mut meter = StabilityMeter::default();
        let square =
            [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|[x, z]| DVec2::new(x, z));
        let two = [DVec2::new(-1.0, 0.5), DVec2::new(1.0, 0.5)];
        let dt = 0.01;
        // 1 s on four feet, then 0.25 s on two; the window is 1 s.
        for k in 0..100 {
            let t = f64::from(k + 1) * dt;
            meter.record(t - dt, t, square.iter().copied(), DVec2::ZERO, 1.0);
        }
        assert_eq!(meter.report().unstable_share, 0.0);
        assert_eq!(meter.report().feet_down, 4);
        for k in 100..125 {
            let t = f64::from(k + 1) * dt;
            meter.record(t - dt, t, two.iter().copied(), DVec2::ZERO, 1.0);
        }
        let report = meter.report();
        assert_eq!(report.feet_down, 2);
        assert!((report.margin_m.unwrap_or(0.0) + 0.5).abs() < 1e-12);
        assert!((report.unstable_share - 0.25).abs() < 0.02, "{report:?}");
        // In flight there is no margin and nothing counts as unstable.
        meter.record(1.25, 1.26, std::iter::empty(), DVec2::ZERO, 1.0);
        assert_eq!(meter.report().margin_m, None);
    }
}
