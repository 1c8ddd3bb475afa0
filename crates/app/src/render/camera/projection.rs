//! The camera's projection (She 2006 §6.2's "perspective" view option):
//! world → view → clip matrices in wgpu's clip space, perspective or an
//! orthographic view of the same apparent size at the target, clip planes
//! and the distance over which the ground grid fades.

use glam::camera::rh::proj::directx;
use glam::{Mat4, Vec3};

use super::orbit::Camera;

impl Camera {
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
}

/// Normalised device coordinates of `p` seen through `camera` in a view of
/// width / height `aspect` (for tests).
#[cfg(test)]
pub(super) fn ndc(camera: &Camera, aspect: f32, p: Vec3) -> Vec3 {
    let clip = camera.view_projection(aspect) * p.extend(1.0);
    clip.truncate() / clip.w
}

#[cfg(test)]
mod tests {
    use glam::{Vec2, Vec4};

    use super::*;

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
}
