//! Follow mode: [`Camera::follow`] keeps a walking or running figure in view
//! at any speed with a critically damped tracker that learns the figure's
//! velocity, and jumps to a figure that got far out of view.

use glam::Vec3;

use super::orbit::Camera;

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

impl Camera {
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
}

impl Camera {
    /// Follow mode on ground that is not flat: eases the target up or down
    /// with the ground's height under the figure (`ground_m`, metres), at
    /// [`FOLLOW_RATE`], so a climb stays framed while the figure's own
    /// bobbing never moves the camera. On the floor (`ground_m` always 0)
    /// it does nothing.
    pub fn follow_ground(&mut self, ground_m: f32, dt: f32) {
        if !ground_m.is_finite() || dt.is_nan() || dt <= 0.0 {
            return;
        }
        let k = 1.0 - (-FOLLOW_RATE * dt.min(0.1)).exp();
        let next = self.ground_m + (ground_m - self.ground_m) * k;
        self.target.y += next - self.ground_m;
        self.ground_m = next;
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec2;

    use super::*;

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
    fn follow_rises_with_the_ground_under_a_climbing_figure() {
        let mut camera = Camera::default();
        let start = camera.target.y;
        let dt = 1.0 / 60.0;
        // Up 1 m of stairs over 5 s, then level for 2 s.
        for frame in 0..420 {
            let ground = (frame as f32 * dt / 5.0).min(1.0);
            camera.follow_ground(ground, dt);
        }
        assert!(
            (camera.target.y - start - 1.0).abs() < 1e-3,
            "target {} after a 1 m climb from {start}",
            camera.target.y
        );
        camera.follow_ground(f32::NAN, dt);
        assert!(camera.target.y.is_finite());
    }

    #[test]
    fn follow_jumps_to_a_figure_far_out_of_view() {
        let mut camera = Camera::default();
        let far = Vec3::new(0.0, 0.5, 40.0);
        camera.follow(far, 1.0 / 60.0);
        assert!((camera.target.z - 40.0).abs() < 1e-4, "{}", camera.target);
        assert_eq!(camera.follow_velocity, Vec3::ZERO);
    }
}
