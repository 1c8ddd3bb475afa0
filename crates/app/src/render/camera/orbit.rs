//! The orbit camera ([`Camera`]): the point it looks at, its yaw, pitch and
//! distance, the limits that keep the eye above the ground and short of
//! vertical, and the screen basis (right, up, back) it sees the world in.

use glam::Vec3;

use crate::render::scene::GROUND_Y;

/// Closest the camera may come to its target, metres.
pub const MIN_DISTANCE: f32 = 0.1;
/// Farthest the camera may go from its target, metres.
pub const MAX_DISTANCE: f32 = 200.0;
/// Largest |pitch|, radians (just short of straight up or down, where yaw is undefined).
pub const PITCH_LIMIT: f32 = 1.50;
/// Lowest the eye may go above the ground, metres: an eye at the ground plane
/// would slice it with the near plane, and under it the ground hides the figure.
pub const MIN_EYE_HEIGHT: f32 = 0.05;

/// The home view's yaw, radians: a three-quarter view of a figure facing +z.
pub const HOME_YAW: f32 = 0.65;
/// The home view's pitch, radians (about 24°): from above, so the feet and
/// the ground ahead show (issue 43 item 4).
pub const HOME_PITCH: f32 = 0.42;

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
    /// [`crate::render::viewport::show`] frames the first figure it sees.
    pub framed: bool,
    /// Whether the person zoomed since the last framing; follow mode's
    /// [`Camera::keep_in_view`] then leaves the distance alone.
    pub zoomed: bool,
    /// The ground's height under the figure as follow mode has eased the
    /// target up or down with it ([`Camera::follow_ground`]), metres.
    pub ground_m: f32,
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            target: Vec3::new(0.0, 0.9, 0.0),
            yaw: HOME_YAW,
            pitch: HOME_PITCH,
            distance: 3.2,
            perspective: true,
            fov_y: 40_f32.to_radians(),
            follow_offset: Vec3::ZERO,
            follow_velocity: Vec3::ZERO,
            framed: false,
            zoomed: false,
            ground_m: 0.0,
        }
    }
}

impl Camera {
    /// Back to the home view: the three-quarter view from above
    /// ([`HOME_YAW`], [`HOME_PITCH`]), framing the figure on the next frame
    /// (a new preset, a double-click, the H key, *Home view*).
    pub fn home(&mut self) {
        self.yaw = HOME_YAW;
        self.pitch = HOME_PITCH;
        self.framed = false;
    }

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
}
