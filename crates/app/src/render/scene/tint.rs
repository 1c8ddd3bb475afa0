//! The comparison's overlay (issue 21 item 1): several figures of one
//! skeleton drawn as one scene, so the methods can be told apart where they
//! part. For each bone the figures fall into groups that hold it in the same
//! place (both ends within [`AGREE_RADII`] of its radius of the group's
//! first): a group of one draws the bone in its figure's colour, a larger
//! group draws it once, striped in its figures' colours, so every figure
//! stays visible where the methods agree and none hides another. Joints
//! group the same way (a shared joint is grey). The targets, the axes and the
//! ground marks are drawn once, from the first figure (the figures of a
//! comparison chase the same targets); each figure's error segments keep its
//! colour.

use super::frame::{Scene, SceneFrame};
use super::palette::{CENTRE_COLOR, LEFT_COLOR, RIGHT_COLOR, shade};
use super::primitives::{Capsule, Segment, Sphere};

/// Figures agree on a bone or joint when its ends lie within this share of
/// its radius of each other: closer than that they would overlap on screen.
pub const AGREE_RADII: f32 = 0.5;

/// Most figures an overlay groups (a comparison has 2 or 4); later ones are left out.
pub const MAX_FIGURES: usize = 8;

/// Stripes per figure along a bone a group shares.
const STRIPES_PER_FIGURE: usize = 2;

/// How the overlay shades a figure's colour by the side a part was on: the
/// figure's right side darker than its left and centre line, so its legs
/// stay apart in one colour.
fn side_shade(original: [f32; 4]) -> f32 {
    if original == RIGHT_COLOR {
        0.7
    } else if original == LEFT_COLOR {
        1.0
    } else {
        0.88
    }
}

fn near(a: [f32; 3], b: [f32; 3], tolerance_m: f32) -> bool {
    glam::Vec3::from(a).distance(glam::Vec3::from(b)) <= tolerance_m
}

/// Groups of figures by agreement: `group[k]` is the index of the first
/// figure figure `k` agrees with (itself when none before it).
fn groups(count: usize, agree: impl Fn(usize, usize) -> bool) -> [usize; MAX_FIGURES] {
    let mut group = [0; MAX_FIGURES];
    for k in 0..count.min(MAX_FIGURES) {
        group[k] = (0..k).find(|&j| group[j] == j && agree(j, k)).unwrap_or(k);
    }
    group
}

impl Scene {
    /// Refills this scene with `figures` (each a scene of the same skeleton
    /// and its sRGB colour) drawn over one another, as the module docs say.
    /// Reuses the allocations; `figures` is walked several times. Figures
    /// whose lists do not match the first's in length (not one skeleton)
    /// are drawn whole, each in its colour.
    pub fn fill_overlay<'a, I>(&mut self, figures: I)
    where
        I: Iterator<Item = (&'a Scene, [f32; 4])> + Clone,
    {
        let frame = self.frame_mut();
        frame.clear();
        let figures = figures.take(MAX_FIGURES);
        let Some((first, _)) = figures.clone().next() else {
            return;
        };
        let first = first.frame();
        let count = figures.clone().count();
        let scene = |k: usize| figures.clone().nth(k).map(|(s, c)| (&**s.frame(), c));
        let matching = figures.clone().all(|(s, _)| {
            s.capsules().len() == first.capsules.len() && s.spheres().len() == first.spheres.len()
        });
        if !matching {
            for (s, colour) in figures.clone() {
                for bone in s.capsules() {
                    let mut bone = *bone;
                    bone.color = shade(colour, side_shade(bone.color));
                    frame.capsules.push(bone);
                }
            }
        } else {
            for (i, bone) in first.capsules.iter().enumerate() {
                let tolerance = AGREE_RADII * bone.radius;
                let bone_of = |k: usize| scene(k).map(|(f, c)| (f.capsules[i], c));
                let group = groups(count, |j, k| match (bone_of(j), bone_of(k)) {
                    (Some((a, _)), Some((b, _))) => {
                        near(a.a, b.a, tolerance) && near(a.b, b.b, tolerance)
                    }
                    _ => false,
                });
                for leader in (0..count).filter(|&k| group[k] == k) {
                    let Some((own, _)) = bone_of(leader) else {
                        continue;
                    };
                    let colours = (0..count)
                        .filter(|&k| group[k] == leader)
                        .filter_map(|k| bone_of(k).map(|(_, c)| c));
                    stripes(frame, &own, colours);
                }
            }
        }
        joints(frame, first, matching, count, &scene);
        for (k, (s, colour)) in figures.enumerate() {
            segments_and_marks(frame, s.frame(), k, colour);
        }
    }
}

/// `bone` cut into [`STRIPES_PER_FIGURE`] pieces per colour of `colours`,
/// coloured in turn (one colour: the bone whole in it).
fn stripes(
    frame: &mut SceneFrame,
    bone: &Capsule,
    colours: impl Iterator<Item = [f32; 4]> + Clone,
) {
    let shading = side_shade(bone.color);
    let members = colours.clone().count();
    if members <= 1 {
        if let Some(colour) = colours.clone().next() {
            let mut whole = *bone;
            whole.color = shade(colour, shading);
            frame.capsules.push(whole);
        }
        return;
    }
    let pieces = STRIPES_PER_FIGURE * members;
    let (a, b) = (glam::Vec3::from(bone.a), glam::Vec3::from(bone.b));
    for (j, colour) in colours.cycle().take(pieces).enumerate() {
        let from = a.lerp(b, j as f32 / pieces as f32);
        let to = a.lerp(b, (j + 1) as f32 / pieces as f32);
        frame
            .capsules
            .push(Capsule::new(from, to, bone.radius, shade(colour, shading)));
    }
}

/// The joint and effector spheres, grouped as the bones are: a group of one
/// in its figure's colour, a larger group once in grey. The targets come
/// from the first figure only.
fn joints<'a>(
    frame: &mut SceneFrame,
    first: &SceneFrame,
    matching: bool,
    count: usize,
    scene: &impl Fn(usize) -> Option<(&'a SceneFrame, [f32; 4])>,
) {
    let targets = &first.targets.spheres;
    let mut target_range = frame.spheres.len()..frame.spheres.len();
    for (i, ball) in first.spheres.iter().enumerate() {
        if targets.contains(&i) {
            if i == targets.start {
                target_range.start = frame.spheres.len();
            }
            frame.spheres.push(*ball);
            target_range.end = frame.spheres.len();
            continue;
        }
        if !matching {
            continue;
        }
        let tolerance = AGREE_RADII * ball.radius;
        let ball_of = |k: usize| scene(k).map(|(f, c)| (f.spheres[i], c));
        let group = groups(count, |j, k| match (ball_of(j), ball_of(k)) {
            (Some((a, _)), Some((b, _))) => near(a.centre, b.centre, tolerance),
            _ => false,
        });
        for leader in (0..count).filter(|&k| group[k] == k) {
            let Some((own, colour)) = ball_of(leader) else {
                continue;
            };
            let shared = (0..count).filter(|&k| group[k] == leader).count() > 1;
            let colour = if shared { CENTRE_COLOR } else { colour };
            frame.spheres.push(Sphere {
                color: shade(colour, 0.9),
                ..own
            });
        }
    }
    if !matching {
        // Not one skeleton: every figure's own joints (the targets are the first's).
        for k in 0..count {
            let Some((own, colour)) = scene(k) else {
                continue;
            };
            for (i, ball) in own.spheres.iter().enumerate() {
                if !own.targets.spheres.contains(&i) {
                    frame.spheres.push(Sphere {
                        color: shade(colour, 0.9),
                        ..*ball
                    });
                }
            }
        }
    }
    frame.targets.spheres = target_range;
}

/// Figure `k`'s error segments in its colour; the first figure's other
/// segments (axes) and ground marks; every figure's box.
fn segments_and_marks(frame: &mut SceneFrame, source: &SceneFrame, k: usize, colour: [f32; 4]) {
    let errors = &source.targets.segments;
    for (i, segment) in source.segments.iter().enumerate() {
        if errors.contains(&i) {
            frame.segments.push(Segment::new(
                segment.a.into(),
                segment.b.into(),
                segment.width,
                colour,
            ));
        } else if k == 0 {
            frame.segments.push(*segment);
        }
    }
    if k == 0 {
        frame.ground_marks.extend_from_slice(&source.ground_marks);
    }
    if let Some(bounds) = source.bounds {
        frame.include(bounds.min);
        frame.include(bounds.max);
    }
}

#[cfg(test)]
mod tests {
    use glam::{DVec3, Vec3};

    use super::*;
    use crate::render::scene::frame::TargetRanges;
    use crate::render::scene::primitives::GroundMark;
    use crate::render::scene::{EFFECTOR_COLOR, TARGET_COLOR};

    /// One figure: a left bone ending `shift_m` to the side and a right bone
    /// that never moves, a joint at the origin and an effector sphere at the
    /// left bone's end, one target with its error segment, a world axis and a shadow.
    fn figure(shift_m: f32) -> Scene {
        let foot = Vec3::new(shift_m, -1.0, 0.0);
        let mut frame = SceneFrame {
            capsules: vec![
                Capsule::new(Vec3::ZERO, foot, 0.05, LEFT_COLOR),
                Capsule::new(Vec3::ZERO, Vec3::new(0.2, -1.0, 0.0), 0.05, RIGHT_COLOR),
            ],
            spheres: vec![
                Sphere::new(Vec3::ZERO, 0.06, CENTRE_COLOR),
                Sphere::new(foot, 0.06, EFFECTOR_COLOR),
                Sphere::new(Vec3::new(0.0, -1.0, 0.0), 0.03, TARGET_COLOR),
            ],
            segments: vec![
                Segment::new(foot, Vec3::new(0.0, -1.0, 0.0), 2.0, [1.0; 4]),
                Segment::new(Vec3::ZERO, Vec3::X, 2.5, [1.0, 0.0, 0.0, 1.0]),
            ],
            ground_marks: vec![GroundMark::new([0.0, 0.0], [0.2, 0.0], 0.05, 0.1, 0.5)],
            bounds: None,
            targets: TargetRanges {
                spheres: 2..3,
                segments: 0..1,
            },
            terrain: None,
        };
        frame.include(DVec3::ZERO);
        frame.include(foot.as_dvec3());
        Scene::from(frame)
    }

    #[test]
    fn figures_part_in_their_colours_and_agree_in_stripes() {
        let (a, b) = (figure(0.0), figure(0.3));
        let (orange, blue) = ([0.9, 0.6, 0.0, 1.0], [0.3, 0.7, 0.9, 1.0]);
        let mut overlay = Scene::new();
        overlay.fill_overlay([(&a, orange), (&b, blue)].into_iter());

        // The left bones part: one per figure, whole, in its colour.
        let bones = overlay.capsules();
        assert_eq!(bones[0].color, orange);
        assert_eq!(bones[1].color, blue);
        assert_eq!(bones[1].b, [0.3, -1.0, 0.0]);
        // The right bones agree: one bone in 2 × 2 stripes, colours in turn
        // (right side darker), end to end.
        let stripes = &bones[2..];
        assert_eq!(stripes.len(), STRIPES_PER_FIGURE * 2);
        assert_eq!(stripes[0].color, shade(orange, 0.7));
        assert_eq!(stripes[1].color, shade(blue, 0.7));
        assert_eq!(stripes[0].a, [0.0; 3]);
        assert_eq!(stripes[3].b, [0.2, -1.0, 0.0]);
        assert_eq!(stripes[0].b, stripes[1].a);

        // The shared joint once in grey, each effector in its colour, one target.
        let balls = overlay.spheres();
        assert_eq!(balls.len(), 1 + 2 + 1);
        assert_eq!(balls[0].color, shade(CENTRE_COLOR, 0.9));
        assert_eq!(balls[1].color, shade(orange, 0.9));
        assert_eq!(balls[2].color, shade(blue, 0.9));
        assert_eq!(balls[3].color, TARGET_COLOR);
        // Each figure's error segment in its colour; the world axis once; one shadow.
        let colours: Vec<_> = overlay.segments().iter().map(|s| s.color).collect();
        assert_eq!(colours, vec![orange, [1.0, 0.0, 0.0, 1.0], blue]);
        assert_eq!(overlay.ground_marks().len(), 1);
        // The box holds both figures.
        let bounds = overlay.bounds().expect("bounds");
        assert!((bounds.max.x - 0.3).abs() < 1e-6, "{bounds:?}");

        // Within half a radius (25 mm) agrees: all bones striped.
        let c = figure(0.02);
        overlay.fill_overlay([(&a, orange), (&c, blue)].into_iter());
        assert_eq!(overlay.capsules().len(), 2 * STRIPES_PER_FIGURE * 2);
        // Three figures, the first and third agreeing: their stripes, the second alone.
        overlay.fill_overlay([(&a, orange), (&b, blue), (&c, orange)].into_iter());
        assert_eq!(
            overlay.capsules().len(),
            2 * STRIPES_PER_FIGURE + 1 + 3 * STRIPES_PER_FIGURE
        );
        assert_eq!(groups(3, |j, k| (j + k) % 2 == 0)[..3], [0, 1, 0]);
        // One figure alone: its own colour.
        overlay.fill_overlay([(&b, blue)].into_iter());
        assert_eq!(overlay.capsules().len(), 2);
        assert_eq!(overlay.capsules()[0].color, blue);
    }
}
