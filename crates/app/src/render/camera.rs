//! The 3-D view's orbit camera: it circles a target point at a distance, with
//! perspective or orthographic projection of the same apparent size at the
//! target (She 2006 §6.2's "perspective" view option), orbit / pan / zoom from
//! mouse and touch, framing that fits a figure's whole box to the view's
//! aspect ratio, and a follow mode that keeps a walking or running figure in
//! view at any speed.
//!
//! # Conventions
//! - World frame of gaitlab-core: metres, y up, x right, z forward.
//! - `yaw` turns about +y; at `yaw = 0` the camera sits on +z looking toward −z
//!   (it faces a figure walking along +z). `pitch > 0` looks down from above.
//! - Matrices are glam's column-major `Mat4` acting on column vectors, which is
//!   WGSL's `mat4x4<f32>` layout; clip space is wgpu's: x, y in [−1, 1], y up,
//!   depth z in [0, 1] (near → 0).
//! - Input deltas are in egui points.

use glam::camera::rh::proj::directx;
use glam::{Mat4, Vec3};

use super::scene::{Bounds, GROUND_Y};

/// Closest the camera may come to its target, metres.
pub const MIN_DISTANCE: f32 = 0.1;
/// Farthest the camera may go from its target, metres.
pub const MAX_DISTANCE: f32 = 200.0;
/// Largest |pitch|, radians (just short of straight up or down, where yaw is undefined).
pub const PITCH_LIMIT: f32 = 1.50;
/// Lowest the eye may go above the ground, metres: an eye at the ground plane
/// would slice it with the near plane, and under it the ground hides the figure.
pub const MIN_EYE_HEIGHT: f32 = 0.05;
/// Orbit speed, radians per point dragged.
pub const ORBIT_RADIANS_PER_POINT: f32 = 0.008;
/// Wheel zoom: the distance shrinks by `exp(ZOOM_PER_POINT · points scrolled)`.
pub const ZOOM_PER_POINT: f32 = 0.0015;
/// Follow mode's natural frequency, rad/s: a critically damped tracker of this
/// frequency closes a gap to the figure in about `4 / FOLLOW_RATE` seconds and,
/// since it learns the figure's velocity, trails a figure at constant speed by
/// nothing at all (a plain ease would trail it by `speed / rate`).
pub const FOLLOW_RATE: f32 = 4.0;
/// Follow mode jumps to the figure instead of easing when it is farther than
/// this many camera distances away (a reset, or many frames stepped at once):
/// it is out of view then, and easing would only sweep the view across the
/// ground (and overshoot).
pub const FOLLOW_JUMP_DISTANCES: f32 = 1.0;
/// Framing fills at most this share of the view's half width and half height
/// with the figure's box, leaving the rest as a margin.
pub const FRAME_FILL: f32 = 0.8;
/// Framing grows the figure's box by this much on every side, metres (bone and
/// joint radii are not in the box).
pub const FRAME_PAD_M: f32 = 0.06;

/// An orbit camera. `Copy`, so a frame's camera travels into the paint callback.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Point the camera looks at and orbits, world metres.
    pub target: Vec3,
    /// Angle about +y, radians (0: camera on +z).
    pub yaw: f32,
    /// Elevation, radians, clamped to ±[`PITCH_LIMIT`] (positive: from above)
    /// and so the eye stays [`MIN_EYE_HEIGHT`] above the ground.
    pub pitch: f32,
    /// Distance from the eye to the target, metres, clamped to
    /// [[`MIN_DISTANCE`], [`MAX_DISTANCE`]].
    pub distance: f32,
    /// Perspective (true) or orthographic projection.
    pub perspective: bool,
    /// Vertical field of view of the perspective projection, radians. The
    /// orthographic view shows the same height at the target.
    pub fov_y: f32,
    /// Where follow mode keeps the target relative to the figure's centre
    /// (horizontal; set by panning), metres.
    pub follow_offset: Vec3,
    /// Follow mode's estimate of the figure's horizontal velocity, m/s: the
    /// feed-forward that leaves no lag at constant speed.
    pub follow_velocity: Vec3,
    /// Whether the camera has been placed around a figure; until then
    /// [`super::viewport::show`] frames the first figure it sees.
    pub framed: bool,
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            target: Vec3::new(0.0, 0.9, 0.0),
            yaw: 0.65,
            pitch: 0.22,
            distance: 3.2,
            perspective: true,
            fov_y: 40_f32.to_radians(),
            follow_offset: Vec3::ZERO,
            follow_velocity: Vec3::ZERO,
            framed: false,
        }
    }
}

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
    /// Unit vector from the target toward the eye.
    #[must_use]
    pub fn back(&self) -> Vec3 {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        Vec3::new(cp * sy, sp, cp * cy)
    }

    /// Unit viewing direction (from the eye toward the target).
    #[must_use]
    pub fn forward(&self) -> Vec3 {
        -self.back()
    }

    /// Eye position, world metres.
    #[must_use]
    pub fn eye(&self) -> Vec3 {
        self.target + self.back() * self.distance
    }

    /// Screen-right direction in the world.
    #[must_use]
    pub fn right(&self) -> Vec3 {
        self.forward().cross(Vec3::Y).normalize_or(Vec3::X)
    }

    /// Screen-up direction in the world.
    #[must_use]
    pub fn up(&self) -> Vec3 {
        self.right().cross(self.forward())
    }

    /// World → view (camera) transform, right-handed, looking down −z.
    #[must_use]
    pub fn view(&self) -> Mat4 {
        glam::camera::rh::view::look_at_mat4(self.eye(), self.target, Vec3::Y)
    }

    /// Half the height the view shows at the target's distance, metres (the
    /// orthographic half-height; matches the perspective view there).
    #[must_use]
    pub fn half_height_at_target(&self) -> f32 {
        self.distance * (0.5 * self.fov_y).tan()
    }

    /// Ground fade: the grid fades from `start` to `end` metres from the eye,
    /// and the ground quad reaches `end`.
    #[must_use]
    pub fn ground_fade(&self) -> (f32, f32) {
        let end = (self.distance * 6.0).clamp(15.0, 400.0);
        (end * 0.3, end)
    }

    /// Near and far clip distances, metres. Perspective: near scales with the
    /// distance (≥ 5 mm) and far reaches past the faded ground. Orthographic:
    /// the slab also reaches behind the eye so a close zoom clips nothing.
    #[must_use]
    pub fn clip_planes(&self) -> (f32, f32) {
        let (_, ground) = self.ground_fade();
        let far = self.distance + 1.5 * ground + 10.0;
        if self.perspective {
            ((self.distance * 0.02).clamp(0.005, 1.0), far)
        } else {
            (-(self.distance + ground), far)
        }
    }

    /// View → clip projection for a viewport of width / height `aspect`.
    #[must_use]
    pub fn projection(&self, aspect: f32) -> Mat4 {
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        let (near, far) = self.clip_planes();
        if self.perspective {
            directx::perspective(self.fov_y, aspect, near, far)
        } else {
            let h = self.half_height_at_target();
            directx::orthographic(-h * aspect, h * aspect, -h, h, near, far)
        }
    }

    /// World → clip transform (wgpu clip space, depth in [0, 1]).
    #[must_use]
    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        self.projection(aspect) * self.view()
    }

    /// Turns the camera about its target by a drag of `delta` points: dragging
    /// right turns the figure to the right, dragging down looks from higher up.
    pub fn orbit(&mut self, delta: glam::Vec2) {
        self.yaw = (self.yaw - delta.x * ORBIT_RADIANS_PER_POINT).rem_euclid(std::f32::consts::TAU);
        self.pitch += delta.y * ORBIT_RADIANS_PER_POINT;
        self.constrain();
    }

    /// Lowest pitch that keeps the eye [`MIN_EYE_HEIGHT`] above the ground.
    #[must_use]
    pub fn min_pitch(&self) -> f32 {
        let drop = (GROUND_Y + MIN_EYE_HEIGHT - self.target.y) / self.distance;
        drop.clamp(-1.0, 1.0).asin().max(-PITCH_LIMIT)
    }

    /// Clamps the distance and the pitch into their limits (eye above the
    /// ground, short of vertical).
    pub fn constrain(&mut self) {
        if !self.distance.is_finite() {
            self.distance = Self::default().distance;
        }
        self.distance = self.distance.clamp(MIN_DISTANCE, MAX_DISTANCE);
        let pitch = if self.pitch.is_finite() {
            self.pitch
        } else {
            0.0
        };
        self.pitch = pitch.clamp(self.min_pitch().min(PITCH_LIMIT), PITCH_LIMIT);
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
            self.constrain();
        }
    }

    /// Moves the target horizontally toward `centre` (plus the pan offset) over
    /// `dt` seconds; the height stays where the person put it.
    ///
    /// A critically damped tracker of natural frequency [`FOLLOW_RATE`] with
    /// the figure's velocity as feed-forward: with the gap `e` from the target
    /// to the goal, `v' = ω² e` and `target' = v + 2ω e`, so at a constant
    /// speed `v` settles on the figure's velocity and the gap on zero. Each
    /// step first moves the target by `v dt`, then corrects by the gap left
    /// (so at constant speed the target lands on this frame's goal). A goal
    /// more than [`FOLLOW_JUMP_DISTANCES`] camera distances away is jumped to.
    pub fn follow(&mut self, centre: Vec3, dt: f32) {
        if !centre.is_finite() || dt.is_nan() || dt <= 0.0 {
            return;
        }
        let horizontal = Vec3::new(1.0, 0.0, 1.0);
        let goal = centre + self.follow_offset;
        if ((goal - self.target) * horizontal).length() > FOLLOW_JUMP_DISTANCES * self.distance {
            self.target.x = goal.x;
            self.target.z = goal.z;
            return;
        }
        // Predict, then correct (stable for the clamped step, ω·dt ≤ 0.4).
        let dt = dt.min(0.1);
        let predicted = self.target + self.follow_velocity * horizontal * dt;
        let gap = (goal - predicted) * horizontal;
        let velocity = (self.follow_velocity + FOLLOW_RATE * FOLLOW_RATE * dt * gap) * horizontal;
        let target = predicted + 2.0 * FOLLOW_RATE * dt * gap;
        if target.is_finite() && velocity.is_finite() {
            self.target = target;
            self.follow_velocity = velocity;
        } else {
            self.follow_velocity = Vec3::ZERO;
        }
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
    /// width). Clears the pan offset and follow mode's velocity.
    pub fn frame_for(&mut self, bounds: &Bounds, aspect: f32) {
        let centre = bounds.centre().as_vec3();
        let half = ((bounds.max - bounds.min).as_vec3() * 0.5 + Vec3::splat(FRAME_PAD_M))
            .max(Vec3::splat(0.1));
        if !centre.is_finite() || !half.is_finite() {
            return;
        }
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        self.target = centre;
        self.follow_offset = Vec3::ZERO;
        self.follow_velocity = Vec3::ZERO;
        self.framed = true;
        let tan_y = FRAME_FILL * (0.5 * self.fov_y).tan();
        let tan_x = tan_y * aspect;
        // The lowest pitch depends on the distance: settle the two together.
        for _ in 0..3 {
            let (right, up, back) = (self.right(), self.up(), self.back());
            let mut distance = MIN_DISTANCE;
            for corner in 0..8 {
                let sign = |bit: i32| if corner & bit == 0 { -1.0 } else { 1.0 };
                let offset = half * Vec3::new(sign(1), sign(2), sign(4));
                // A point `depth` nearer the eye than the target shows within
                // the view when its sideways offsets fit at distance − depth.
                let depth = offset.dot(back);
                distance = distance
                    .max(depth + offset.dot(right).abs() / tan_x)
                    .max(depth + offset.dot(up).abs() / tan_y);
            }
            self.distance = distance;
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
            self.framed = false;
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
    use glam::{DVec3, Vec2, Vec4};

    use super::*;

    fn ndc(camera: &Camera, aspect: f32, p: Vec3) -> Vec3 {
        let clip = camera.view_projection(aspect) * p.extend(1.0);
        clip.truncate() / clip.w
    }

    #[test]
    fn the_target_projects_to_the_screen_centre() {
        for perspective in [true, false] {
            let camera = Camera {
                target: Vec3::new(0.4, 1.1, -2.0),
                yaw: 2.1,
                pitch: -0.4,
                distance: 5.0,
                perspective,
                ..Camera::default()
            };
            let p = ndc(&camera, 1.7, camera.target);
            assert!(p.x.abs() < 1e-5 && p.y.abs() < 1e-5, "{p}");
            assert!(p.z > 0.0 && p.z < 1.0, "depth {}", p.z);
        }
    }

    #[test]
    fn screen_axes_point_the_right_way() {
        // From +z looking at the origin: +x is right, +y is up, and nearer is smaller depth.
        let camera = Camera {
            target: Vec3::ZERO,
            yaw: 0.0,
            pitch: 0.0,
            ..Camera::default()
        };
        assert!(ndc(&camera, 1.0, Vec3::X * 0.3).x > 0.1);
        assert!(ndc(&camera, 1.0, Vec3::Y * 0.3).y > 0.1);
        assert!(ndc(&camera, 1.0, Vec3::Z * 0.5).z < ndc(&camera, 1.0, Vec3::ZERO).z);
        // The eye is on +z.
        assert!((camera.eye() - Vec3::new(0.0, 0.0, camera.distance)).length() < 1e-5);
    }

    #[test]
    fn orthographic_matches_perspective_at_the_target() {
        let mut camera = Camera::default();
        let probe = camera.target + camera.right() * 0.5 + camera.up() * 0.3;
        let seen = ndc(&camera, 1.5, probe);
        camera.perspective = false;
        let flat = ndc(&camera, 1.5, probe);
        assert!(
            (seen.truncate() - flat.truncate()).length() < 1e-4,
            "{seen} vs {flat}"
        );
    }

    #[test]
    fn depth_stays_in_range_across_the_ground() {
        for perspective in [true, false] {
            let camera = Camera {
                perspective,
                ..Camera::default()
            };
            let (_, end) = camera.ground_fade();
            let eye = camera.eye();
            for corner in [
                Vec2::new(1.0, 1.0),
                Vec2::new(-1.0, 1.0),
                Vec2::new(1.0, -1.0),
                Vec2::new(-1.0, -1.0),
            ] {
                let p = Vec3::new(eye.x + corner.x * end, 0.0, eye.z + corner.y * end);
                let clip: Vec4 = camera.view_projection(1.0) * p.extend(1.0);
                if clip.w > 0.0 {
                    let z = clip.z / clip.w;
                    assert!(z <= 1.0, "ground corner beyond the far plane: {z}");
                }
            }
        }
    }

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

    #[test]
    fn follow_eases_toward_the_figure_horizontally() {
        let mut camera = Camera::default();
        let height = camera.target.y;
        let centre = Vec3::new(1.0, 0.5, 3.0);
        camera.follow(centre, 1.0 / 60.0);
        assert!(
            camera.target.z > 0.0 && camera.target.z < 3.0,
            "eases, does not jump"
        );
        for _ in 0..600 {
            camera.follow(centre, 1.0 / 60.0);
        }
        assert!((camera.target.x - 1.0).abs() < 1e-3 && (camera.target.z - 3.0).abs() < 1e-3);
        assert_eq!(camera.target.y, height);
        // A pan shifts where the figure is kept.
        camera.pan(Vec2::new(100.0, 0.0), 500.0);
        let kept = camera.target;
        for _ in 0..600 {
            camera.follow(centre, 1.0 / 60.0);
        }
        assert!((camera.target.x - kept.x).abs() < 1e-3 && (camera.target.z - kept.z).abs() < 1e-3);
    }

    #[test]
    fn follow_keeps_a_running_figure_centred_at_any_speed() {
        for speed in [0.5_f32, 3.5, 12.0] {
            let mut camera = Camera::default();
            let dt = 1.0 / 60.0;
            let mut worst_late = 0.0_f32;
            for frame in 0..600 {
                let centre = Vec3::new(0.0, 0.9, speed * dt * frame as f32);
                camera.follow(centre, dt);
                if frame >= 180 {
                    worst_late = worst_late.max((centre.z - camera.target.z).abs());
                }
            }
            // A plain ease at FOLLOW_RATE would trail by speed / rate: 0.875 m at 3.5 m/s.
            assert!(
                worst_late < 1e-3,
                "{speed} m/s: trails by {worst_late} m after 3 s"
            );
        }
    }

    #[test]
    fn follow_jumps_to_a_figure_far_out_of_view() {
        let mut camera = Camera::default();
        let far = Vec3::new(0.0, 0.5, 40.0);
        camera.follow(far, 1.0 / 60.0);
        assert!((camera.target.z - 40.0).abs() < 1e-4, "{}", camera.target);
        assert_eq!(camera.follow_velocity, Vec3::ZERO);
    }

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
}
