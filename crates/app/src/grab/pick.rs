//! Picking in the 3-D view for grab and pull: the screen point nearest the
//! pointer among a pane's targets and effectors, and the world point under
//! the pointer on the drag plane (through the grabbed point, facing the
//! camera).

use egui::{Pos2, Rect};
use glam::{DVec3, Vec3};

use crate::render::Camera;
use crate::render::viewport::screen_point;

/// How near a target or effector on screen a press must land to pick it,
/// points (about a fingertip).
pub const PICK_RADIUS_PT: f32 = 28.0;

/// One pickable point: an effector's index and where it is, world metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pickable {
    /// The effector.
    pub effector: usize,
    /// The point (its target, or the effector itself), world metres.
    pub at: DVec3,
}

/// Points whose screen distances from the pointer differ by less than this
/// overlap: the one nearer the camera (drawn in front) is picked, points.
pub const OVERLAP_PT: f32 = 8.0;

/// The pickable point nearest `pointer` within [`PICK_RADIUS_PT`] in the
/// pane `rect`, and its screen position. Where points overlap on screen
/// (within [`OVERLAP_PT`] of the nearest), the one nearest the camera wins:
/// seen from the side, the hand in front, not the one behind it.
#[must_use]
pub fn nearest(
    camera: &Camera,
    rect: Rect,
    points: &[Pickable],
    pointer: Pos2,
) -> Option<(Pickable, Pos2)> {
    if !rect.contains(pointer) {
        return None;
    }
    let on_screen = || {
        points
            .iter()
            .filter_map(|p| Some((*p, screen_point(camera, rect, p.at.as_vec3())?)))
            .map(|(p, at)| (p, at, at.distance(pointer)))
            .filter(|(_, _, d)| *d <= PICK_RADIUS_PT)
    };
    let best = on_screen().map(|(_, _, d)| d).min_by(f32::total_cmp)?;
    let eye = camera.eye().as_dvec3();
    on_screen()
        .filter(|(_, _, d)| *d < best + OVERLAP_PT)
        .min_by(|a, b| a.0.at.distance(eye).total_cmp(&b.0.at.distance(eye)))
        .map(|(p, at, _)| (p, at))
}

/// The world ray under the screen point `at` in the pane `rect`: its origin
/// on the near plane and its unit direction.
#[must_use]
pub fn ray(camera: &Camera, rect: Rect, at: Pos2) -> Option<(Vec3, Vec3)> {
    if rect.width() <= 0.0 || rect.height() <= 0.0 {
        return None;
    }
    let inverse = camera
        .view_projection(rect.width() / rect.height())
        .inverse();
    let x = (at.x - rect.center().x) / (0.5 * rect.width());
    let y = -(at.y - rect.center().y) / (0.5 * rect.height());
    let near = inverse.project_point3(Vec3::new(x, y, 0.0));
    let far = inverse.project_point3(Vec3::new(x, y, 1.0));
    let direction = (far - near).normalize_or_zero();
    (near.is_finite() && direction != Vec3::ZERO).then_some((near, direction))
}

/// Where the pointer at `at` meets the plane through `through` that faces
/// the camera, world metres.
#[must_use]
pub fn on_drag_plane(camera: &Camera, rect: Rect, at: Pos2, through: DVec3) -> Option<DVec3> {
    let (origin, direction) = ray(camera, rect, at)?;
    let normal = camera.forward().as_dvec3();
    let (origin, direction) = (origin.as_dvec3(), direction.as_dvec3());
    let facing = direction.dot(normal);
    if facing.abs() < 1e-6 {
        return None;
    }
    let t = (through - origin).dot(normal) / facing;
    let point = origin + direction * t;
    point.is_finite().then_some(point)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A point seen on screen and put back on the drag plane through it is
    /// itself, and a drag of the pointer moves it within the plane facing
    /// the camera, in perspective and orthographic views.
    #[test]
    fn the_drag_plane_returns_the_point_under_the_pointer() {
        let rect = Rect::from_min_size(Pos2::new(10.0, 20.0), egui::vec2(800.0, 500.0));
        for perspective in [true, false] {
            let camera = Camera {
                perspective,
                ..Camera::default()
            };
            let p = DVec3::new(0.2, 0.9, -0.3);
            let at = screen_point(&camera, rect, p.as_vec3()).expect("in view");
            let back = on_drag_plane(&camera, rect, at, p).expect("on the plane");
            assert!(back.distance(p) < 1e-4, "{perspective}: {back} vs {p}");
            let moved =
                on_drag_plane(&camera, rect, at + egui::vec2(40.0, 0.0), p).expect("on the plane");
            let along = (moved - p).dot(camera.forward().as_dvec3());
            assert!(along.abs() < 1e-4, "stays on the plane: {along}");
            assert!(moved.distance(p) > 0.01, "moves");
            // Screen right is the camera's right.
            assert!((moved - p).dot(camera.right().as_dvec3()) > 0.0);
            let picked = nearest(
                &camera,
                rect,
                &[Pickable { effector: 3, at: p }],
                at + egui::vec2(5.0, 5.0),
            );
            assert_eq!(picked.map(|(q, _)| q.effector), Some(3));
            assert!(
                nearest(
                    &camera,
                    rect,
                    &[Pickable { effector: 3, at: p }],
                    at + egui::vec2(60.0, 0.0)
                )
                .is_none()
            );
        }
    }

    /// Two points on one line of sight: the one nearer the camera is picked
    /// even when the pointer lands a little nearer the other's screen point;
    /// apart on screen, the nearer on screen is picked.
    #[test]
    fn overlapping_points_pick_the_one_in_front() {
        let rect = Rect::from_min_size(Pos2::ZERO, egui::vec2(800.0, 500.0));
        let camera = Camera::default();
        let eye = camera.eye().as_dvec3();
        let front = DVec3::new(0.1, 0.8, 0.0);
        let behind = front + (front - eye).normalize() * 0.5;
        let points = [
            Pickable {
                effector: 1,
                at: behind,
            },
            Pickable {
                effector: 2,
                at: front,
            },
        ];
        let at_behind = screen_point(&camera, rect, behind.as_vec3()).expect("in view");
        let at_front = screen_point(&camera, rect, front.as_vec3()).expect("in view");
        assert!(at_behind.distance(at_front) < 1.0, "one line of sight");
        let picked = nearest(&camera, rect, &points, at_behind + egui::vec2(3.0, 0.0));
        assert_eq!(picked.map(|(p, _)| p.effector), Some(2));
        // Side by side on screen, 20 pt apart: the one under the pointer.
        let beside = [
            Pickable {
                effector: 1,
                at: behind,
            },
            Pickable {
                effector: 2,
                at: front + camera.right().as_dvec3() * 0.3,
            },
        ];
        let picked = nearest(&camera, rect, &beside, at_behind);
        assert_eq!(picked.map(|(p, _)| p.effector), Some(1));
    }
}
