//! Camera gestures: [`gestures`] reads egui's pointer, wheel and touch input
//! into a [`CameraInput`] (orbit drag, pan drag, pinch or wheel zoom, double
//! click to re-frame), and [`Camera::apply`] turns it into orbit, pan and zoom
//! moves within the camera's limits. Input deltas are in egui points.

use glam::Vec3;

use super::orbit::{Camera, MAX_DISTANCE, MIN_DISTANCE};

/// Orbit speed, radians per point dragged.
pub const ORBIT_RADIANS_PER_POINT: f32 = 0.008;
/// Wheel zoom: the distance shrinks by `exp(ZOOM_PER_POINT · points scrolled)`.
pub const ZOOM_PER_POINT: f32 = 0.0015;

/// One frame's camera gestures, in points.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CameraInput {
    /// Orbit drag (primary button).
    pub orbit: glam::Vec2,
    /// Pan drag (secondary / middle button, shift + primary, two-finger move).
    pub pan: glam::Vec2,
    /// Multiplicative zoom: > 1 comes closer (pinch spread, ctrl + wheel).
    pub zoom: f32,
    /// Wheel / trackpad scroll, points (positive y: content moves down = zoom in).
    pub scroll: f32,
    /// Re-frame the figure (double click).
    pub reframe: bool,
}

impl Camera {
    /// Turns the camera about its target by a drag of `delta` points: dragging
    /// right turns the figure to the right, dragging down looks from higher up.
    pub fn orbit(&mut self, delta: glam::Vec2) {
        self.yaw = (self.yaw - delta.x * ORBIT_RADIANS_PER_POINT).rem_euclid(std::f32::consts::TAU);
        self.pitch += delta.y * ORBIT_RADIANS_PER_POINT;
        self.constrain();
    }

    /// Moves the target in the screen plane so the scene follows a drag of
    /// `delta` points in a viewport `viewport_height` points tall.
    pub fn pan(&mut self, delta: glam::Vec2, viewport_height: f32) {
        if viewport_height.is_nan() || viewport_height <= 0.0 {
            return;
        }
        let metres_per_point = 2.0 * self.half_height_at_target() / viewport_height;
        let shift = (self.up() * delta.y - self.right() * delta.x) * metres_per_point;
        if shift.is_finite() {
            self.target += shift;
            self.follow_offset += Vec3::new(shift.x, 0.0, shift.z);
            self.constrain();
        }
    }

    /// Zooms by `factor` (> 1 comes closer), keeping the distance within limits.
    pub fn zoom(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance / factor).clamp(MIN_DISTANCE, MAX_DISTANCE);
            self.zoomed = true;
            self.constrain();
        }
    }

    /// Applies one frame's gestures; `viewport_height` in points scales panning.
    /// Returns whether the camera moved.
    pub fn apply(&mut self, input: &CameraInput, viewport_height: f32) -> bool {
        let before = *self;
        if input.orbit != glam::Vec2::ZERO {
            self.orbit(input.orbit);
        }
        if input.pan != glam::Vec2::ZERO {
            self.pan(input.pan, viewport_height);
        }
        if input.zoom != 1.0 && input.zoom > 0.0 {
            self.zoom(input.zoom);
        }
        if input.scroll != 0.0 {
            self.zoom((input.scroll * ZOOM_PER_POINT).exp());
        }
        if input.reframe {
            self.home();
        }
        *self != before
    }

    /// Reads the gestures aimed at the view `response` (which must sense
    /// click-and-drag) and applies them. Returns whether the camera moved.
    pub fn handle_input(&mut self, response: &egui::Response) -> bool {
        let input = gestures(response);
        self.apply(&input, response.rect.height())
    }
}

/// The camera gestures in `response` this frame.
#[must_use]
pub fn gestures(response: &egui::Response) -> CameraInput {
    use egui::PointerButton;

    // Read the response first: its methods lock the context's input themselves.
    let primary = response.dragged_by(PointerButton::Primary);
    let secondary =
        response.dragged_by(PointerButton::Secondary) || response.dragged_by(PointerButton::Middle);
    let drag = response.drag_delta();
    let hovered = response.contains_pointer();
    let reframe = response.double_clicked();
    let (shift, touch, zoom, scroll) = response.ctx.input(|i| {
        (
            i.modifiers.shift,
            i.multi_touch(),
            i.zoom_delta(),
            i.smooth_scroll_delta.y,
        )
    });
    let drag = glam::Vec2::new(drag.x, drag.y);
    let mut input = CameraInput {
        zoom: 1.0,
        reframe,
        ..CameraInput::default()
    };
    if let Some(touch) = touch {
        // Two fingers: pinch zooms, moving pans; no orbit from the first finger.
        if hovered || primary {
            input.pan = glam::Vec2::new(touch.translation_delta.x, touch.translation_delta.y);
            input.zoom = touch.zoom_delta;
        }
        return input;
    }
    if secondary || (primary && shift) {
        input.pan = drag;
    } else if primary {
        input.orbit = drag;
    }
    if hovered {
        input.zoom = zoom;
        input.scroll = scroll;
    }
    input
}

#[cfg(test)]
mod tests {
    use glam::Vec2;

    use super::*;
    use crate::render::camera::{MIN_EYE_HEIGHT, PITCH_LIMIT};
    use crate::render::scene::GROUND_Y;

    #[test]
    fn zoom_clamps() {
        let mut camera = Camera::default();
        camera.zoom(1e9);
        assert_eq!(camera.distance, MIN_DISTANCE);
        camera.zoom(1e-9);
        assert_eq!(camera.distance, MAX_DISTANCE);
        camera.zoom(f32::NAN);
        camera.zoom(0.0);
        camera.zoom(-2.0);
        assert_eq!(camera.distance, MAX_DISTANCE);
        let mut wheel = Camera::default();
        let before = wheel.distance;
        assert!(wheel.apply(
            &CameraInput {
                scroll: 100.0,
                zoom: 1.0,
                ..CameraInput::default()
            },
            400.0
        ));
        assert!(wheel.distance < before, "scrolling up comes closer");
    }

    #[test]
    fn orbit_keeps_the_distance_and_clamps_the_pitch() {
        let mut camera = Camera::default();
        let target = camera.target;
        camera.orbit(Vec2::new(120.0, -40.0));
        assert!(((camera.eye() - camera.target).length() - camera.distance).abs() < 1e-4);
        assert_eq!(camera.target, target);
        camera.orbit(Vec2::new(0.0, 1e6));
        assert_eq!(camera.pitch, PITCH_LIMIT);
        camera.orbit(Vec2::new(0.0, -1e6));
        assert!(
            (camera.eye().y - (GROUND_Y + MIN_EYE_HEIGHT)).abs() < 1e-4,
            "the eye stops above the ground: {}",
            camera.eye()
        );
        // Raised high enough, the camera may look straight up at the figure.
        camera.target.y = 500.0;
        camera.orbit(Vec2::new(0.0, -1e6));
        assert_eq!(camera.pitch, -PITCH_LIMIT);
        // Still a valid view straight from above.
        assert!(camera.view_projection(1.0).is_finite());
    }

    #[test]
    fn pan_moves_the_target_in_the_screen_plane() {
        let mut camera = Camera::default();
        let before = camera.target;
        camera.pan(Vec2::new(50.0, -20.0), 500.0);
        let moved = camera.target - before;
        assert!(moved.length() > 0.0);
        assert!(moved.dot(camera.forward()).abs() < 1e-5);
        // Dragging right moves the scene right: the target goes left.
        assert!(moved.dot(camera.right()) < 0.0);
        // The scene under the pointer moves with it: 50 points of 500 is a tenth of the height.
        let expected = 50.0 * 2.0 * camera.half_height_at_target() / 500.0;
        assert!((moved.dot(camera.right()).abs() - expected).abs() < 1e-4);
    }

    /// A double-click returns to the home view, whatever the orbit: a
    /// three-quarter view from above, framed on the next frame.
    #[test]
    fn a_double_click_returns_to_the_home_view() {
        use crate::render::camera::{HOME_PITCH, HOME_YAW};
        let mut camera = Camera {
            framed: true,
            ..Camera::default()
        };
        camera.orbit(Vec2::new(300.0, -200.0));
        assert!((camera.pitch - HOME_PITCH).abs() > 0.1);
        camera.apply(
            &CameraInput {
                reframe: true,
                zoom: 1.0,
                ..CameraInput::default()
            },
            400.0,
        );
        assert_eq!((camera.yaw, camera.pitch), (HOME_YAW, HOME_PITCH));
        assert!(!camera.framed, "framed again on the next frame");
    }
}
