//! What the physics engine adds to the view (Raibert & Hodgins 1991,
//! Figure 1): the trunk drawn as its equivalent-inertia body — a capsule along
//! the long axis of the uniform box with the trunk's mass and principal
//! moments (Table 3 gives masses and inertias, not shapes) — the boxes on
//! the ground as wireframes, and the last push as an arrow over the trunk.

use glam::{DVec3, Vec3};

use super::scene::{Capsule, Scene, Segment};

/// The trunk's colour.
pub const TRUNK_COLOR: [f32; 4] = [0.55, 0.58, 0.66, 1.0];
/// Obstacle edges.
pub const OBSTACLE_COLOR: [f32; 4] = [0.85, 0.45, 0.20, 0.95];
/// A push's arrow.
pub const PUSH_COLOR: [f32; 4] = [0.80, 0.20, 0.75, 1.0];

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

    /// Adds a push's arrow from `tail` to `head` (world, metres): a shaft and
    /// four barbs at the head, two level and two upright, so the head shows
    /// from any camera (seen end-on, a push straight away from the camera,
    /// it is a cross over the trunk). Non-finite or zero-length input is
    /// skipped.
    pub fn add_push_arrow(&mut self, tail: DVec3, head: DVec3) {
        let along = head - tail;
        if !(tail.is_finite() && head.is_finite()) || along.length() < 1e-6 {
            return;
        }
        let frame = self.frame_mut();
        frame.segments.push(Segment::new(
            f32_point(tail),
            f32_point(head),
            4.0,
            PUSH_COLOR,
        ));
        let back = -along.normalize() * (0.25 * along.length()).min(0.15);
        let spread = back.length() * 0.6;
        let side = DVec3::Y.cross(along).normalize_or(DVec3::X) * spread;
        let up = along.cross(side).normalize_or(DVec3::Y) * spread;
        for barb in [back + side, back - side, back + up, back - up] {
            frame.segments.push(Segment::new(
                f32_point(head),
                f32_point(head + barb),
                4.0,
                PUSH_COLOR,
            ));
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

    #[test]
    fn a_push_is_a_shaft_and_four_barbs_ending_at_the_head() {
        let mut scene = Scene::new();
        let before = scene.segments().len();
        let head = DVec3::new(0.0, 0.6, 2.0);
        scene.add_push_arrow(head - DVec3::new(0.3, 0.0, 0.0), head);
        let added = &scene.segments()[before..];
        assert_eq!(added.len(), 5);
        // The shaft ends at the head; every barb starts there and points back.
        let h = f32_point(head);
        let at_head = |p: [f32; 3]| (Vec3::from(p) - h).length() < 1e-6;
        assert!(at_head(added[0].b) && added[1..].iter().all(|s| at_head(s.a)));
        assert!(added[1..].iter().all(|s| s.b[0] < h.x));
        // Two barbs level (spread along z), two upright (spread along y).
        let level = added[1..].iter().filter(|s| (s.b[1] - h.y).abs() < 1e-6);
        let upright = added[1..].iter().filter(|s| (s.b[2] - h.z).abs() < 1e-6);
        assert_eq!((level.count(), upright.count()), (2, 2));
        scene.add_push_arrow(head, head);
        scene.add_push_arrow(DVec3::splat(f64::NAN), head);
        assert_eq!(
            scene.segments().len(),
            before + 5,
            "nothing for a point or NaN"
        );
    }
}
