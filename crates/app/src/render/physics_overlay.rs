//! What the physics engine adds to the view (Raibert & Hodgins 1991,
//! Figure 1): the trunk drawn as its equivalent-inertia body — a capsule along
//! the long axis of the uniform box with the trunk's mass and principal
//! moments (Table 3 gives masses and inertias, not shapes) — the boxes on
//! the ground, and the last push as an arrow over the trunk. A box is drawn
//! as the box it is (issue 43 item 4): its edges and its faces hatched, as
//! wide as the creature is long where the simulated box is wider (the
//! planar kangaroo's spans 20 m across), and the camera frames one within
//! [`FRAMED_BOX_M`] of the trunk with the creature, so it shows before the
//! jump.

use glam::{DVec3, Vec3};

use super::scene::{Capsule, Scene, Segment};

/// The trunk's colour.
pub const TRUNK_COLOR: [f32; 4] = [0.55, 0.58, 0.66, 1.0];
/// Obstacle edges.
pub const OBSTACLE_COLOR: [f32; 4] = [0.85, 0.45, 0.20, 0.95];
/// Obstacle faces' hatching.
const OBSTACLE_HATCH_COLOR: [f32; 4] = [0.85, 0.45, 0.20, 0.45];
/// Spacing of a face's hatching lines, metres.
const HATCH_SPACING_M: f64 = 0.04;
/// Most hatching lines on one face.
const MAX_HATCH_LINES: usize = 16;
/// Half the drawn width of a box cut to a small creature, at least, metres.
const MIN_BOX_HALF_WIDTH_M: f64 = 0.3;
/// A box whose nearest point lies within this of the trunk's centre
/// (horizontally, metres) is framed with the creature.
pub const FRAMED_BOX_M: f64 = 4.0;
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
        // The creature's box (its figure and trunk) before any obstacle.
        let creature = frame.bounds;
        for (mut lo, mut hi) in boxes.filter(|(lo, hi)| lo.is_finite() && hi.is_finite()) {
            if let Some(creature) = creature {
                // Across the creature's path no wider than the creature is
                // long (a box past that is drawn cut there).
                let centre = creature.centre();
                let extent = creature.max - creature.min;
                let half = (0.5 * extent.x.max(extent.z)).max(MIN_BOX_HALF_WIDTH_M);
                lo.x = lo.x.max(centre.x - half);
                hi.x = hi.x.min(centre.x + half);
                let nearest = DVec3::new(
                    centre.x.clamp(lo.x, hi.x),
                    centre.y,
                    centre.z.clamp(lo.z, hi.z),
                );
                if nearest.distance(centre) <= FRAMED_BOX_M {
                    frame.include(lo);
                    frame.include(hi);
                }
            }
            if lo.x > hi.x || lo.z > hi.z {
                continue;
            }
            add_box(&mut frame.segments, lo, hi);
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

/// A box from `lo` to `hi`: its twelve edges, and its four sides and top
/// hatched with lines [`HATCH_SPACING_M`] apart (at most
/// [`MAX_HATCH_LINES`] a face) so it reads as solid.
fn add_box(segments: &mut Vec<Segment>, lo: DVec3, hi: DVec3) {
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
                segments.push(Segment::new(
                    corner(i),
                    corner(i | bit),
                    2.0,
                    OBSTACLE_COLOR,
                ));
            }
        }
    }
    let lines = |span: f64| ((span / HATCH_SPACING_M) as usize).clamp(1, MAX_HATCH_LINES);
    let mut hatch = |a: DVec3, b: DVec3| {
        segments.push(Segment::new(
            f32_point(a),
            f32_point(b),
            1.0,
            OBSTACLE_HATCH_COLOR,
        ));
    };
    // Level lines round the four sides, from the ground up.
    let n = lines(hi.y - lo.y);
    for k in 1..n {
        let y = lo.y + (hi.y - lo.y) * k as f64 / n as f64;
        let c = [
            DVec3::new(lo.x, y, lo.z),
            DVec3::new(hi.x, y, lo.z),
            DVec3::new(hi.x, y, hi.z),
            DVec3::new(lo.x, y, hi.z),
        ];
        for j in 0..4 {
            hatch(c[j], c[(j + 1) % 4]);
        }
    }
    // The top, across its width.
    let n = lines(hi.z - lo.z);
    for k in 1..n {
        let z = lo.z + (hi.z - lo.z) * k as f64 / n as f64;
        hatch(DVec3::new(lo.x, hi.y, z), DVec3::new(hi.x, hi.y, z));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlay_adds_the_trunk_and_each_box_cut_to_the_creature_and_hatched() {
        let mut scene = Scene::new();
        let before = (scene.capsules().len(), scene.segments().len());
        let (a, b) = (DVec3::new(0.0, 0.5, 0.0), DVec3::new(0.0, 0.5, 1.0));
        // The kangaroo's boxes span 20 m across: one 1 m ahead, one 20 m.
        let near = (DVec3::new(-10.0, 0.0, 2.0), DVec3::new(10.0, 0.2, 2.3));
        let far = (DVec3::new(-10.0, 0.0, 21.0), DVec3::new(10.0, 0.2, 21.3));
        scene.add_physics_overlay(
            Some((a, b, 0.1)),
            [near, (DVec3::splat(f64::NAN), DVec3::ONE), far].into_iter(),
        );
        assert_eq!(scene.capsules().len(), before.0 + 1);
        let added = &scene.segments()[before.1..];
        // Two boxes of 12 edges and hatching each; the NaN one is skipped.
        let edges = added.iter().filter(|s| s.color == OBSTACLE_COLOR).count();
        assert_eq!(edges, 24);
        assert!(added.len() > 2 * 12 + 2 * 8, "hatched: {}", added.len());
        // Cut to the creature's length (1.2 m with the trunk's radius) across.
        assert!(
            added
                .iter()
                .all(|s| s.a[0].abs() <= 0.6 + 1e-6 && s.b[0].abs() <= 0.6 + 1e-6)
        );
        // The trunk and the near box are in the box the camera frames; the
        // far box is not.
        let bounds = scene.bounds().expect("bounds");
        assert!(
            (bounds.min - DVec3::new(-0.6, 0.0, -0.1)).length() < 1e-12,
            "{bounds:?}"
        );
        assert!(
            (bounds.max - DVec3::new(0.6, 0.6, 2.3)).length() < 1e-12,
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
