//! [`Scene::fill`]: the figure as primitives from a skeleton's forward
//! kinematics (She 2006 §6.2's view options): bones and joint spheres,
//! effectors, blob shadows and contact marks, IK targets with their error
//! segments, joint rotation (or sliding) axes and the world axes.

use gaitlab_core::ik::Targets;
use gaitlab_core::{Kinematics, Skeleton};
use glam::{DVec3, Vec3};

use super::frame::{Scene, TargetRanges};
use super::palette::{
    CENTRE_COLOR, EFFECTOR_COLOR, ERROR_COLOR, PRISMATIC_AXIS_COLOR, REVOLUTE_AXIS_COLOR,
    TARGET_COLOR, TARGET_OUT_OF_REACH_COLOR, WORLD_AXIS_COLORS, shade, side_color,
};
use super::primitives::{Capsule, GroundMark, Segment, Sphere};
use super::sizes::{
    COINCIDENT, CONTACT_DARKNESS, CONTACT_HEIGHT, GROUND_Y, JOINT_SPHERE_SCALE, MIN_BONE_RADIUS,
    SHADOW_DARKNESS, SHADOW_FADE_HEIGHT, WORLD_AXIS_LENGTH,
};
use crate::view::ViewOptions;

fn f32_point(p: DVec3) -> Vec3 {
    p.as_vec3()
}

impl Scene {
    /// Rebuilds the primitives for one pose.
    ///
    /// - `kin` must be the forward kinematics of `skeleton` (joints or
    ///   effectors missing from it are skipped, never indexed out of bounds);
    /// - `root` is the root position, where the bones of root-attached joints start;
    /// - `targets` are drawn (red spheres and error segments) when `view.targets` is on;
    /// - rotation axes, world axes and ground marks follow `view.joint_axes`,
    ///   `view.world_axes` and `view.shadow`.
    ///
    /// Non-finite positions (a simulation that blew up) draw nothing.
    pub fn fill(
        &mut self,
        skeleton: &Skeleton,
        kin: &Kinematics,
        root: DVec3,
        targets: Option<&Targets>,
        view: &ViewOptions,
    ) {
        let frame = self.frame_mut();
        frame.clear();
        if let Some(terrain) = frame.terrain.clone() {
            frame.segments.extend_from_slice(&terrain.edges);
        }
        frame.include(root);
        let joints = skeleton.joints();

        // Bones and joint spheres.
        for (j, joint) in joints.iter().enumerate() {
            let Some(&to) = kin.joint_position.get(j) else {
                continue;
            };
            let from = match joint.parent {
                Some(p) => kin.joint_position.get(p).copied().unwrap_or(root),
                None => root,
            };
            frame.include(to);
            if !to.is_finite() || !from.is_finite() {
                continue;
            }
            let color = side_color(&joint.name);
            let radius = (joint.size as f32).max(MIN_BONE_RADIUS);
            if to.distance(from) > COINCIDENT {
                frame
                    .capsules
                    .push(Capsule::new(f32_point(from), f32_point(to), radius, color));
            } else if joint.parent.is_some() {
                // Same place as the parent joint: its sphere is already there.
                continue;
            }
            frame.spheres.push(Sphere::new(
                f32_point(to),
                radius * JOINT_SPHERE_SCALE,
                shade(color, 0.82),
            ));
        }

        // Effector bones and spheres.
        for (e, effector) in skeleton.effectors().iter().enumerate() {
            let (Some(&at), Some(&from)) = (
                kin.effector_position.get(e),
                kin.joint_position.get(effector.joint),
            ) else {
                continue;
            };
            frame.include(at);
            if !at.is_finite() || !from.is_finite() {
                continue;
            }
            let size = joints
                .get(effector.joint)
                .map_or(0.0, |joint| joint.size as f32);
            // No wider than half the bone to it is long: a short tip on a
            // big joint (the hexapod's head_tip) stays a marker, not a ball
            // hiding the creature (issue 43 item 4).
            let reach = effector.offset.length() as f32;
            let size = if reach > 0.0 {
                size.min(0.5 * reach)
            } else {
                size
            };
            let radius = size.max(MIN_BONE_RADIUS);
            let name_color = side_color(&effector.name);
            let color = if name_color == CENTRE_COLOR {
                joints
                    .get(effector.joint)
                    .map_or(CENTRE_COLOR, |joint| side_color(&joint.name))
            } else {
                name_color
            };
            if at.distance(from) > COINCIDENT {
                frame
                    .capsules
                    .push(Capsule::new(f32_point(from), f32_point(at), radius, color));
            }
            frame.spheres.push(Sphere::new(
                f32_point(at),
                (radius * 1.15).max(0.015),
                EFFECTOR_COLOR,
            ));
        }

        // Blob shadows of the bones (joint spheres sit on bone ends and would
        // add nothing under the Min blend), skipping those too high to show.
        if view.shadow {
            let ground = f64::from(GROUND_Y);
            for capsule in &frame.capsules {
                let height = (capsule.a[1].min(capsule.b[1]) - capsule.radius - GROUND_Y).max(0.0);
                if height < SHADOW_FADE_HEIGHT {
                    frame.ground_marks.push(GroundMark::new(
                        [capsule.a[0], capsule.a[2]],
                        [capsule.b[0], capsule.b[2]],
                        capsule.radius,
                        height,
                        SHADOW_DARKNESS,
                    ));
                }
            }
            for (e, effector) in skeleton.effectors().iter().enumerate() {
                let Some(&at) = kin.effector_position.get(e) else {
                    continue;
                };
                let size = joints.get(effector.joint).map_or(0.0, |joint| joint.size);
                let radius = size.max(f64::from(MIN_BONE_RADIUS)) * 1.15;
                if at.is_finite() && at.y - ground < radius + f64::from(CONTACT_HEIGHT) {
                    let foot = [at.x as f32, at.z as f32];
                    frame.ground_marks.push(GroundMark::new(
                        foot,
                        foot,
                        (radius as f32 * 1.8).max(0.03),
                        0.0,
                        CONTACT_DARKNESS,
                    ));
                }
            }
        }

        // Targets and error segments.
        let (spheres_from, segments_from) = (frame.spheres.len(), frame.segments.len());
        if view.targets
            && let Some(targets) = targets
        {
            for (e, effector) in skeleton.effectors().iter().enumerate() {
                let Some(&target) = targets.position.get(e) else {
                    continue;
                };
                if !target.is_finite() {
                    continue;
                }
                let size = joints
                    .get(effector.joint)
                    .map_or(0.0, |joint| joint.size as f32);
                let radius = (size * 0.75).clamp(0.012, 0.04);
                let beyond = skeleton.limbs().get(e).map_or(0.0, |limb| {
                    limb.out_of_reach_m(&kin.joint_anchor, &kin.joint_position, target)
                });
                let color = if beyond > 0.0 {
                    TARGET_OUT_OF_REACH_COLOR
                } else {
                    TARGET_COLOR
                };
                frame
                    .spheres
                    .push(Sphere::new(f32_point(target), radius, color));
                // A drawn target is part of what framing must show: an
                // unreachable one (she-2006's hands) lies outside the figure.
                frame.include(target);
                if let Some(&at) = kin.effector_position.get(e)
                    && at.is_finite()
                    && at.distance(target) > 1e-4
                {
                    frame.segments.push(Segment::new(
                        f32_point(at),
                        f32_point(target),
                        2.0,
                        ERROR_COLOR,
                    ));
                }
            }
        }

        frame.targets = TargetRanges {
            spheres: spheres_from..frame.spheres.len(),
            segments: segments_from..frame.segments.len(),
        };

        // Joint rotation (or sliding) axes.
        if view.joint_axes {
            for (j, joint) in joints.iter().enumerate() {
                let (Some(&at), Some(&axis)) = (kin.joint_position.get(j), kin.joint_axis.get(j))
                else {
                    continue;
                };
                if !at.is_finite() || !axis.is_finite() || axis.length_squared() < 1e-12 {
                    continue;
                }
                let half = (joint.size * 2.5).max(0.04);
                let color = match joint.kind {
                    gaitlab_core::JointKind::Revolute => REVOLUTE_AXIS_COLOR,
                    gaitlab_core::JointKind::Prismatic => PRISMATIC_AXIS_COLOR,
                };
                frame.segments.push(Segment::new(
                    f32_point(at - axis * half),
                    f32_point(at + axis * half),
                    2.0,
                    color,
                ));
            }
        }

        // Manipulability ellipsoids and reach shells.
        if view.ellipsoids || view.reach_shells {
            super::reach::push_reach(frame, skeleton, kin, view.ellipsoids, view.reach_shells);
        }

        // World axes at the origin.
        if view.world_axes {
            for (axis, color) in [Vec3::X, Vec3::Y, Vec3::Z]
                .into_iter()
                .zip(WORLD_AXIS_COLORS)
            {
                frame.segments.push(Segment::new(
                    Vec3::ZERO,
                    axis * WORLD_AXIS_LENGTH,
                    2.5,
                    color,
                ));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use gaitlab_core::{Effector, Joint, Pose, RootTransform};

    use super::*;
    use crate::render::scene::{LEFT_COLOR, RIGHT_COLOR};

    /// A root-attached hip, a left and a right leg of one revolute joint each,
    /// with a foot effector at the end of each leg.
    fn legs() -> Skeleton {
        let hip = Joint::revolute("pelvis", None, DVec3::ZERO, DVec3::X);
        let left = Joint::revolute("left_hip", Some(0), DVec3::new(0.1, -0.05, 0.0), DVec3::X);
        let right = Joint::revolute("right_hip", Some(0), DVec3::new(-0.1, -0.05, 0.0), DVec3::X);
        let effector = |name: &str, joint| Effector {
            name: name.to_owned(),
            joint,
            offset: DVec3::new(0.0, -0.8, 0.0),
            orientation: false,
        };
        Skeleton::new(
            vec![hip, left, right],
            vec![effector("left_foot", 1), effector("right_foot", 2)],
        )
        .expect("valid skeleton")
    }

    fn pose(skeleton: &Skeleton) -> (Kinematics, DVec3) {
        let root = DVec3::new(0.0, 0.9, 0.0);
        let pose = Pose {
            root: RootTransform {
                position: root,
                ..RootTransform::default()
            },
            joints: vec![0.0, 0.3, -0.2],
        };
        (Kinematics::of(skeleton, &pose), root)
    }

    fn v(p: [f32; 3]) -> DVec3 {
        Vec3::from_array(p).as_dvec3()
    }

    #[test]
    fn counts_for_a_small_skeleton() {
        let skeleton = legs();
        let (kin, root) = pose(&skeleton);
        let mut scene = Scene::new();
        scene.fill(&skeleton, &kin, root, None, &ViewOptions::figure_only());
        // The pelvis sits on the root: no bone, but a sphere. Two hip bones and
        // two foot bones; spheres for the three joints and two effectors.
        assert_eq!(scene.capsules().len(), 4, "{:?}", scene.capsules());
        assert_eq!(scene.spheres().len(), 5);
        assert!(scene.segments().is_empty());
        assert!(scene.ground_marks().is_empty());

        let all = ViewOptions {
            world_axes: true,
            joint_axes: true,
            targets: true,
            shadow: true,
            ..ViewOptions::figure_only()
        };
        let mut targets = Targets::at(&kin);
        targets.position[0].z += 0.1;
        scene.fill(&skeleton, &kin, root, Some(&targets), &all);
        assert_eq!(scene.capsules().len(), 4);
        // + one red sphere per target.
        assert_eq!(scene.spheres().len(), 7);
        // One error segment (the other target is reached), three rotation axes, three world axes.
        assert_eq!(scene.segments().len(), 1 + 3 + 3);
        // A shadow per bone; the feet are 0.85 m up: no contact marks.
        assert_eq!(scene.ground_marks().len(), 4);
    }

    #[test]
    fn positions_match_the_kinematics() {
        let skeleton = legs();
        let (kin, root) = pose(&skeleton);
        let mut scene = Scene::new();
        let view = ViewOptions {
            targets: true,
            ..ViewOptions::figure_only()
        };
        let mut targets = Targets::at(&kin);
        targets.position[1] += DVec3::new(0.05, 0.02, -0.03);
        scene.fill(&skeleton, &kin, root, Some(&targets), &view);

        let close = |a: DVec3, b: DVec3| a.distance(b) < 1e-6;
        // Hip bones run from the pelvis to each hip joint.
        let left = &scene.capsules()[0];
        assert!(close(v(left.a), kin.joint_position[0]));
        assert!(close(v(left.b), kin.joint_position[1]));
        assert_eq!(left.color, LEFT_COLOR);
        assert_eq!(left.radius, skeleton.joints()[1].size as f32);
        let right = &scene.capsules()[1];
        assert!(close(v(right.b), kin.joint_position[2]));
        assert_eq!(right.color, RIGHT_COLOR);
        // Foot bones run from the leg joints to the effectors.
        assert!(close(v(scene.capsules()[2].a), kin.joint_position[1]));
        assert!(close(v(scene.capsules()[2].b), kin.effector_position[0]));
        assert!(close(v(scene.capsules()[3].b), kin.effector_position[1]));
        // The pelvis sphere sits on the root.
        assert!(close(v(scene.spheres()[0].centre), root));
        // The target sphere and the error segment.
        let target = scene.spheres().last().expect("target sphere");
        assert_eq!(target.color, TARGET_COLOR);
        assert!(close(v(target.centre), targets.position[1]));
        let error = &scene.segments()[0];
        assert!(close(v(error.a), kin.effector_position[1]));
        assert!(close(v(error.b), targets.position[1]));
        // A target beyond the limb's reach (the leg: hip joint to foot) is
        // drawn in the out-of-reach colour; the reachable one stays red.
        targets.position[1] = kin.joint_anchor[2] + DVec3::new(0.0, -5.0, 0.0);
        scene.fill(&skeleton, &kin, root, Some(&targets), &view);
        let far = scene.spheres().last().expect("target sphere");
        assert_eq!(far.color, TARGET_OUT_OF_REACH_COLOR);
        assert_eq!(
            scene.spheres()[scene.spheres().len() - 2].color,
            TARGET_COLOR
        );
        // The bounds hold the root and the feet.
        let bounds = scene.bounds().expect("bounds");
        for p in kin.effector_position.iter().chain([&root]) {
            assert!(p.cmpge(bounds.min - 1e-9).all() && p.cmple(bounds.max + 1e-9).all());
        }
        assert!(close(
            scene.centre().expect("centre"),
            0.5 * (bounds.min + bounds.max)
        ));
    }

    #[test]
    fn disabled_options_add_nothing() {
        let skeleton = legs();
        let (kin, root) = pose(&skeleton);
        let targets = Targets::at(&kin);
        let mut scene = Scene::new();
        scene.fill(
            &skeleton,
            &kin,
            root,
            Some(&targets),
            &ViewOptions::figure_only(),
        );
        assert!(scene.segments().is_empty(), "no axes, no error segments");
        assert!(scene.ground_marks().is_empty(), "no shadows");
        assert!(
            scene.spheres().iter().all(|s| s.color != TARGET_COLOR),
            "no target spheres"
        );
    }

    #[test]
    fn feet_on_the_ground_leave_contact_marks() {
        let skeleton = legs();
        let root = DVec3::new(0.0, 0.85, 0.0);
        let pose = Pose {
            root: RootTransform {
                position: root,
                ..RootTransform::default()
            },
            joints: vec![0.0; 3],
        };
        let kin = Kinematics::of(&skeleton, &pose);
        assert!(kin.effector_position[0].y.abs() < 1e-9, "feet at y = 0");
        let mut scene = Scene::new();
        let view = ViewOptions {
            shadow: true,
            ..ViewOptions::figure_only()
        };
        scene.fill(&skeleton, &kin, root, None, &view);
        let contacts = scene
            .ground_marks()
            .iter()
            .filter(|mark| mark.darkness == CONTACT_DARKNESS)
            .count();
        assert_eq!(contacts, 2);
    }

    #[test]
    fn refill_reuses_the_allocation_once_the_renderer_let_go() {
        let skeleton = legs();
        let (kin, root) = pose(&skeleton);
        let mut scene = Scene::new();
        let view = ViewOptions::default();
        scene.fill(&skeleton, &kin, root, None, &view);
        let before = scene.capsules().as_ptr();
        let drawn = Arc::clone(scene.frame());
        drop(drawn);
        scene.fill(&skeleton, &kin, root, None, &view);
        assert_eq!(scene.capsules().as_ptr(), before);
        // While the renderer still holds a frame, fill copies instead.
        let held = Arc::clone(scene.frame());
        scene.fill(&skeleton, &kin, root, None, &view);
        assert_eq!(held.capsules, scene.capsules());
        assert!(!Arc::ptr_eq(&held, scene.frame()));
    }

    #[test]
    fn non_finite_positions_draw_nothing_and_keep_finite_bounds() {
        let skeleton = legs();
        let (mut kin, root) = pose(&skeleton);
        kin.joint_position[1] = DVec3::NAN;
        kin.effector_position[0] = DVec3::NAN;
        let mut scene = Scene::new();
        scene.fill(&skeleton, &kin, root, None, &ViewOptions::default());
        // Only the right hip bone and the right foot bone remain.
        assert_eq!(scene.capsules().len(), 2);
        let bounds = scene.bounds().expect("bounds");
        assert!(bounds.min.is_finite() && bounds.max.is_finite());
    }
}
