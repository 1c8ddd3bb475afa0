//! Framing: [`Camera::frame_for`] fits a figure's whole box, with a margin, to
//! a view of any aspect ratio (a tall phone view backs off further for the
//! width), keeping the viewing direction.

use glam::Vec3;

use super::orbit::{Camera, MIN_DISTANCE};
use crate::render::scene::Bounds;

/// Framing fills at most this share of the view's half width and half height
/// with the figure's box, leaving the rest as a margin.
pub const FRAME_FILL: f32 = 0.8;
/// Framing grows the figure's box by this much on every side, metres (bone and
/// joint radii are not in the box).
pub const FRAME_PAD_M: f32 = 0.06;
/// Follow mode backs off when the figure's box comes past this share of the
/// view's half width or half height ([`Camera::keep_in_view`]).
pub const KEEP_FILL: f32 = 0.95;

impl Camera {
    /// Keeps the eye out of the figure (issue 21 item 7: a pinch went inside
    /// the mesh): the distance to the target stays at least the half
    /// diagonal of `bounds`, grown by [`FRAME_PAD_M`], so with the target on
    /// the figure the eye stays outside its box. Returns whether it moved.
    pub fn keep_outside(&mut self, bounds: &Bounds) -> bool {
        let half = (bounds.max - bounds.min).as_vec3() * 0.5 + Vec3::splat(FRAME_PAD_M);
        let nearest = half.length().max(MIN_DISTANCE);
        if nearest.is_finite() && self.distance < nearest {
            self.distance = nearest;
            return true;
        }
        false
    }

    /// Frames `bounds` for a view of aspect ratio 1 (see [`Self::frame_for`]).
    pub fn frame(&mut self, bounds: &Bounds) {
        self.frame_for(bounds, 1.0);
    }

    /// Places the target at the centre of `bounds` and, keeping the viewing
    /// direction (raised if the eye would go under the ground), backs off until
    /// every corner of the box, grown by [`FRAME_PAD_M`], lies within
    /// [`FRAME_FILL`] of the view's half height and half width for a view of
    /// width / height `aspect` (a tall phone view needs more distance for the
    /// width). Clears the pan offset, follow mode's velocity and the mark of a
    /// person's zoom.
    pub fn frame_for(&mut self, bounds: &Bounds, aspect: f32) {
        let centre = bounds.centre().as_vec3();
        if !centre.is_finite() {
            return;
        }
        self.target = centre;
        self.follow_offset = Vec3::ZERO;
        self.follow_velocity = Vec3::ZERO;
        self.framed = true;
        self.zoomed = false;
        // The lowest pitch depends on the distance: settle the two together.
        for _ in 0..3 {
            if let Some(distance) = self.fit_distance(bounds, aspect, FRAME_FILL) {
                self.distance = distance;
            }
            self.constrain();
        }
    }

    /// Follow mode's wider view: while the person has not zoomed since the
    /// last framing, backs off to [`FRAME_FILL`] when a corner of `bounds`
    /// (grown by [`FRAME_PAD_M`]) comes past [`KEEP_FILL`] of the view's half
    /// width or height (a running creature's legs reach further than the
    /// standing pose framing saw). Never comes closer. Returns whether it moved.
    pub fn keep_in_view(&mut self, bounds: &Bounds, aspect: f32) -> bool {
        if self.zoomed {
            return false;
        }
        match (
            self.fit_distance(bounds, aspect, KEEP_FILL),
            self.fit_distance(bounds, aspect, FRAME_FILL),
        ) {
            (Some(needed), Some(wider)) if self.distance < needed => {
                self.distance = wider;
                self.constrain();
                true
            }
            _ => false,
        }
    }

    /// The least distance, along the present viewing direction from the
    /// present target, at which every corner of `bounds` grown by
    /// [`FRAME_PAD_M`] lies within `fill` of the half width and half height
    /// of a view of width / height `aspect`; `None` for a box that is not finite.
    fn fit_distance(&self, bounds: &Bounds, aspect: f32, fill: f32) -> Option<f32> {
        let pad = Vec3::splat(FRAME_PAD_M);
        let (lo, hi) = (bounds.min.as_vec3() - pad, bounds.max.as_vec3() + pad);
        if !lo.is_finite() || !hi.is_finite() {
            return None;
        }
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        let tan_y = fill * (0.5 * self.fov_y).tan();
        let tan_x = tan_y * aspect;
        let (right, up, back) = (self.right(), self.up(), self.back());
        let mut distance = MIN_DISTANCE;
        for corner in 0..8 {
            let pick = |bit: i32, lo: f32, hi: f32| if corner & bit == 0 { lo } else { hi };
            let offset = Vec3::new(
                pick(1, lo.x, hi.x),
                pick(2, lo.y, hi.y),
                pick(4, lo.z, hi.z),
            ) - self.target;
            // A point `depth` nearer the eye than the target shows within
            // the view when its sideways offsets fit at distance − depth.
            let depth = offset.dot(back);
            distance = distance
                .max(depth + offset.dot(right).abs() / tan_x)
                .max(depth + offset.dot(up).abs() / tan_y);
        }
        distance.is_finite().then_some(distance)
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::render::camera::projection::ndc;

    #[test]
    fn framing_fits_the_box_to_the_aspect_ratio() {
        let bounds = Bounds {
            min: DVec3::new(-0.4, 0.0, -1.2),
            max: DVec3::new(0.4, 1.1, 1.0),
        };
        for aspect in [0.46_f32, 1.0, 1.6, 2.4] {
            for perspective in [true, false] {
                let mut camera = Camera {
                    perspective,
                    ..Camera::default()
                };
                camera.frame_for(&bounds, aspect);
                let mut widest = 0.0_f32;
                // The box as framing grows it.
                let (lo, hi) = (
                    bounds.min - DVec3::splat(f64::from(FRAME_PAD_M)),
                    bounds.max + DVec3::splat(f64::from(FRAME_PAD_M)),
                );
                for corner in 0..8 {
                    let pick = |bit: i32, lo: f64, hi: f64| if corner & bit == 0 { lo } else { hi };
                    let p = Vec3::new(
                        pick(1, lo.x, hi.x) as f32,
                        pick(2, lo.y, hi.y) as f32,
                        pick(4, lo.z, hi.z) as f32,
                    );
                    let p = ndc(&camera, aspect, p);
                    assert!(
                        p.x.abs() <= FRAME_FILL + 1e-4 && p.y.abs() <= FRAME_FILL + 1e-4,
                        "aspect {aspect}: {p} outside the framed part of the view"
                    );
                    widest = widest.max(p.x.abs()).max(p.y.abs());
                }
                // And, in perspective, it backs off no further than needed.
                assert!(
                    !perspective || widest > 0.95 * FRAME_FILL,
                    "aspect {aspect}: only {widest} used"
                );
            }
        }
        // A tall view backs off further than a wide one.
        let (mut tall, mut wide) = (Camera::default(), Camera::default());
        tall.frame_for(&bounds, 0.46);
        wide.frame_for(&bounds, 1.6);
        assert!(tall.distance > 1.5 * wide.distance);
    }

    #[test]
    fn framing_fits_the_figure() {
        let mut camera = Camera::default();
        let bounds = Bounds {
            min: DVec3::new(-0.3, 0.0, -0.2),
            max: DVec3::new(0.3, 1.8, 0.2),
        };
        camera.frame(&bounds);
        assert!(camera.framed);
        assert!((camera.target - Vec3::new(0.0, 0.9, 0.0)).length() < 1e-6);
        for corner in [bounds.min, bounds.max] {
            let p = ndc(&camera, 1.0, corner.as_vec3());
            assert!(p.x.abs() < 1.0 && p.y.abs() < 1.0, "{p} is off screen");
        }
    }

    #[test]
    fn a_pinch_stops_outside_the_figure() {
        let bounds = Bounds {
            min: DVec3::new(-0.3, 0.0, -0.2),
            max: DVec3::new(0.3, 1.8, 0.2),
        };
        let mut camera = Camera::default();
        camera.frame(&bounds);
        // Pinch far in: the eye stops at the box's half diagonal (padded) from the target.
        camera.zoom(1e6);
        assert!(camera.keep_outside(&bounds));
        let half = (bounds.max - bounds.min).as_vec3() * 0.5 + Vec3::splat(FRAME_PAD_M);
        assert!(
            (camera.distance - half.length()).abs() < 1e-6,
            "{}",
            camera.distance
        );
        // With the target at the box's centre, the eye is outside the box.
        let eye = camera.eye();
        let inside = (eye - bounds.centre().as_vec3())
            .abs()
            .cmplt(half - Vec3::splat(FRAME_PAD_M));
        assert!(!inside.all(), "eye {eye} inside the figure's box");
        // Farther than that, nothing changes.
        camera.zoom(0.5);
        let far = camera.distance;
        assert!(!camera.keep_outside(&bounds));
        assert_eq!(camera.distance, far);
    }

    #[test]
    fn follow_widens_the_view_for_a_figure_that_outgrows_it_unless_zoomed() {
        let standing = Bounds {
            min: DVec3::new(-0.3, 0.0, -0.5),
            max: DVec3::new(0.3, 0.8, 0.5),
        };
        let mut camera = Camera::default();
        camera.frame_for(&standing, 1.4);
        let framed = camera.distance;
        // Within the view: nothing moves.
        assert!(!camera.keep_in_view(&standing, 1.4));
        assert_eq!(camera.distance, framed);
        // Legs reaching 0.5 m further each way: it backs off until every
        // corner is back within FRAME_FILL, and never comes closer after.
        let running = Bounds {
            min: DVec3::new(-0.5, 0.0, -1.0),
            max: DVec3::new(0.5, 0.9, 1.0),
        };
        assert!(camera.keep_in_view(&running, 1.4));
        assert!(camera.distance > framed);
        let (lo, hi) = (
            running.min - DVec3::splat(f64::from(FRAME_PAD_M)),
            running.max + DVec3::splat(f64::from(FRAME_PAD_M)),
        );
        for corner in 0..8 {
            let pick = |bit: i32, lo: f64, hi: f64| if corner & bit == 0 { lo } else { hi };
            let p = ndc(
                &camera,
                1.4,
                Vec3::new(
                    pick(1, lo.x, hi.x) as f32,
                    pick(2, lo.y, hi.y) as f32,
                    pick(4, lo.z, hi.z) as f32,
                ),
            );
            assert!(
                p.x.abs() <= FRAME_FILL + 1e-3 && p.y.abs() <= FRAME_FILL + 1e-3,
                "{p}"
            );
        }
        let wide = camera.distance;
        assert!(!camera.keep_in_view(&standing, 1.4));
        assert_eq!(camera.distance, wide);
        // After a person's zoom the distance is theirs.
        let mut zoomed = Camera::default();
        zoomed.frame_for(&standing, 1.4);
        zoomed.zoom(1.5);
        let theirs = zoomed.distance;
        assert!(!zoomed.keep_in_view(&running, 1.4));
        assert_eq!(zoomed.distance, theirs);
        // Framing again hands the distance back to the camera.
        zoomed.frame_for(&standing, 1.4);
        assert!(zoomed.keep_in_view(&running, 1.4));
    }
}
