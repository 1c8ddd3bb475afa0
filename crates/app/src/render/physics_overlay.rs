//! What the physics engine adds to the view (Raibert & Hodgins 1991,
//! Figure 1): the trunk drawn as its equivalent-inertia body — a capsule along
//! the long axis of the uniform box with the trunk's mass and principal
//! moments (Table 3 gives masses and inertias, not shapes) — and the boxes on
//! the ground as wireframes.

use glam::{DVec3, Vec3};

use super::scene::{Capsule, Scene, Segment};

/// The trunk's colour.
pub const TRUNK_COLOR: [f32; 4] = [0.55, 0.58, 0.66, 1.0];
/// Obstacle edges.
pub const OBSTACLE_COLOR: [f32; 4] = [0.85, 0.45, 0.20, 0.95];

fn f32_point(p: DVec3) -> Vec3 {
    Vec3::new(p.x as f32, p.y as f32, p.z as f32)
}

impl Scene {
    /// Adds a trunk capsule from `a` to `b` of `radius` (world, metres) and the
    /// edges of each box `(min corner, max corner)`. Non-finite input is skipped.
    pub fn add_physics_overlay(
        &mut self,
        trunk: Option<(DVec3, DVec3, f64)>,
        boxes: impl Iterator<Item = (DVec3, DVec3)>,
    ) {
        let frame = self.frame_mut();
        if let Some((a, b, radius)) = trunk
            && a.is_finite()
            && b.is_finite()
            && radius.is_finite()
        {
            frame.capsules.push(Capsule::new(
                f32_point(a),
                f32_point(b),
                radius as f32,
                TRUNK_COLOR,
            ));
            // The trunk is part of the figure the camera frames.
            let pad = DVec3::splat(radius.abs());
            frame.include(a.min(b) - pad);
            frame.include(a.max(b) + pad);
        }
        for (lo, hi) in boxes.filter(|(lo, hi)| lo.is_finite() && hi.is_finite()) {
            let corner = |i: usize| {
                Vec3::new(
                    if i & 1 == 0 { lo.x } else { hi.x } as f32,
                    if i & 2 == 0 { lo.y } else { hi.y } as f32,
                    if i & 4 == 0 { lo.z } else { hi.z } as f32,
                )
            };
            for i in 0..8 {
                for bit in [1, 2, 4] {
                    if i & bit == 0 {
                        frame.segments.push(Segment::new(
                            corner(i),
                            corner(i | bit),
                            2.0,
                            OBSTACLE_COLOR,
                        ));
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlay_adds_the_trunk_and_twelve_edges_per_box() {
        let mut scene = Scene::new();
        let before = (scene.capsules().len(), scene.segments().len());
        scene.add_physics_overlay(
            Some((DVec3::ZERO, DVec3::X, 0.1)),
            [
                (DVec3::ZERO, DVec3::ONE),
                (DVec3::splat(f64::NAN), DVec3::ONE),
            ]
            .into_iter(),
        );
        assert_eq!(scene.capsules().len(), before.0 + 1);
        assert_eq!(scene.segments().len(), before.1 + 12);
        // The trunk, with its radius, is in the box the camera frames; the
        // obstacles are not.
        let bounds = scene.bounds().expect("bounds");
        assert!(
            (bounds.min - DVec3::splat(-0.1)).length() < 1e-12,
            "{bounds:?}"
        );
        assert!(
            (bounds.max - DVec3::new(1.1, 0.1, 0.1)).length() < 1e-12,
            "{bounds:?}"
        );
    }
}
