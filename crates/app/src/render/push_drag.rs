//! Pushing the physics creature by dragging its trunk in the 3-D view
//! (issue 42's pushes; a lab experiment — Raibert & Hodgins 1991 push
//! nothing). A primary drag that starts within [`GRAB_RADIUS_PT`] of the
//! trunk on screen pushes instead of turning the camera: while it is held an
//! arrow from the trunk to the pointer shows the push to come, and on release
//! the trunk's velocity changes along the drag's direction on the ground,
//! [`MPS_PER_POINT`] per point dragged, at most [`MAX_DRAG_PUSH_MPS`].

use egui::{Color32, Pos2, Stroke};
use glam::Vec3;

use super::camera::Camera;

/// How near the trunk on screen a drag must start to grab it, points
/// (about a fingertip).
pub const GRAB_RADIUS_PT: f32 = 40.0;

/// The push per point dragged, m/s (100 points: the panel's 0.3 m/s).
pub const MPS_PER_POINT: f64 = 0.003;

/// The hardest push a drag gives, m/s.
pub const MAX_DRAG_PUSH_MPS: f64 = 1.0;

/// A shorter drag is a slip of the finger, not a push, points.
pub const MIN_DRAG_PT: f32 = 8.0;

/// A drag on the trunk: where the trunk was on screen when it was grabbed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PushDrag {
    grabbed: Option<Pos2>,
}

impl PushDrag {
    /// Whether a drag holds the trunk now (the camera stays still).
    #[must_use]
    pub fn is_held(&self) -> bool {
        self.grabbed.is_some()
    }

    /// Reads this frame's drag on the view `response`: a primary drag
    /// (no shift, one finger) that starts within [`GRAB_RADIUS_PT`] of
    /// `trunk` (the trunk on screen; `None`: nothing to grab) grabs it; its
    /// release returns the push, world `[x, z]` m/s (see [`world_push`]).
    pub fn update(
        &mut self,
        response: &egui::Response,
        trunk: Option<Pos2>,
        camera: &Camera,
        sideways: bool,
    ) -> Option<[f64; 2]> {
        let (origin, latest, shift, touches) = response.ctx.input(|i| {
            (
                i.pointer.press_origin(),
                i.pointer.latest_pos(),
                i.modifiers.shift,
                i.multi_touch().is_some(),
            )
        });
        if response.drag_started_by(egui::PointerButton::Primary)
            && !shift
            && !touches
            && let (Some(at), Some(from)) = (trunk, origin)
            && at.distance(from) <= GRAB_RADIUS_PT
        {
            self.grabbed = Some(at);
        }
        let grabbed = self.grabbed?;
        if response.dragged() && !touches {
            return None;
        }
        self.grabbed = None;
        let to = latest.or_else(|| response.interact_pointer_pos())?;
        world_push(camera, to - grabbed, sideways)
    }

    /// The arrow of a held drag, from the trunk to `pointer`, and the push it
    /// would give, drawn with `painter`.
    pub fn paint(
        &self,
        painter: &egui::Painter,
        pointer: Option<Pos2>,
        camera: &Camera,
        sideways: bool,
        color: Color32,
    ) {
        let (Some(from), Some(to)) = (self.grabbed, pointer) else {
            return;
        };
        let stroke = Stroke::new(3.0, color);
        painter.arrow(from, to - from, stroke);
        let text = world_push(camera, to - from, sideways).map_or_else(
            || "drag further to push".to_owned(),
            |[x, z]| format!("push {:.2} m/s", x.hypot(z)),
        );
        painter.text(
            to + egui::vec2(8.0, -8.0),
            egui::Align2::LEFT_BOTTOM,
            text,
            egui::FontId::proportional(14.0),
            color,
        );
    }
}

/// The push of a drag of `drag` points on screen seen through `camera`:
/// the drag's direction laid on the ground (screen right is the camera's
/// right, screen up is away from the camera), [`MPS_PER_POINT`] per point,
/// at most [`MAX_DRAG_PUSH_MPS`]; for a creature that cannot go `sideways`,
/// only its forward (+z) part. World `[x, z]` m/s; `None` for a drag shorter
/// than [`MIN_DRAG_PT`].
#[must_use]
pub fn world_push(camera: &Camera, drag: egui::Vec2, sideways: bool) -> Option<[f64; 2]> {
    let length = drag.length();
    if !length.is_finite() || length < MIN_DRAG_PT {
        return None;
    }
    let on_ground = |v: Vec3| Vec3::new(v.x, 0.0, v.z).normalize_or_zero();
    let right = on_ground(camera.right());
    let away = on_ground(camera.forward());
    let direction = (right * drag.x - away * drag.y).normalize_or_zero();
    let speed = (f64::from(length) * MPS_PER_POINT).min(MAX_DRAG_PUSH_MPS);
    let mut push = [
        f64::from(direction.x) * speed,
        f64::from(direction.z) * speed,
    ];
    if !sideways {
        push[0] = 0.0;
    }
    (push[0].hypot(push[1]) > 0.0).then_some(push)
}

#[cfg(test)]
mod tests {
    use crate::render::camera::Camera;
    use crate::render::push_drag::{MAX_DRAG_PUSH_MPS, world_push};

    /// With the camera looking along −z (yaw 0), a drag up the screen
    /// pushes along −z, away from it, and a drag right along +x, its right.
    #[test]
    fn a_drag_is_laid_on_the_ground_as_the_camera_sees_it() {
        let camera = Camera {
            yaw: 0.0,
            ..Camera::default()
        };
        let close =
            |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-6 && (a[1] - b[1]).abs() < 1e-6;
        let up = world_push(&camera, egui::vec2(0.0, -100.0), true).expect("a push");
        assert!(close(up, [0.0, -0.3]), "{up:?}");
        let right = world_push(&camera, egui::vec2(50.0, 0.0), true).expect("a push");
        assert!(close(right, [0.15, 0.0]), "{right:?}");
        let hard = world_push(&camera, egui::vec2(0.0, -1000.0), true).expect("a push");
        assert!((hard[0].hypot(hard[1]) - MAX_DRAG_PUSH_MPS).abs() < 1e-9);
        assert_eq!(world_push(&camera, egui::vec2(3.0, 2.0), true), None);
        assert_eq!(world_push(&camera, egui::vec2(f32::NAN, 0.0), true), None);
        let planar = world_push(&camera, egui::vec2(60.0, -100.0), false).expect("a push");
        assert_eq!(planar[0], 0.0);
        assert!(planar[1] < 0.0);
        assert_eq!(world_push(&camera, egui::vec2(100.0, 0.0), false), None);
    }
}
