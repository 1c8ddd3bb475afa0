//! What the 3-D view draws, in world metres: bones as capsules, joints,
//! effectors and targets as spheres, line segments (She 2006 §6.2's view
//! options: error segments, rotation axes, world axes) and the marks the figure
//! leaves on the ground (blob shadows and foot contacts).
//!
//! [`Scene::fill`] rebuilds everything from a skeleton's forward kinematics
//! once per frame. The lists live in one [`SceneFrame`] behind an [`Arc`]: the
//! renderer takes a cheap clone of the `Arc` for the frame it draws, and once
//! that frame is on screen the next `fill` reuses the same allocations (no
//! per-frame allocation after warm-up). Should a drawn frame still be held
//! when `fill` runs, `fill` copies it once instead of waiting.
//!
//! # Conventions
//! - World frame of gaitlab-core: metres, y up, ground plane at y = [`GROUND_Y`].
//! - Positions are `f32` (what the GPU reads); the kinematics are `f64`.
//! - Colours are sRGB-encoded RGBA in `[0, 1]` (like egui's `Color32`), not linear.
//! - Primitive types are `#[repr(C)]` and [`bytemuck::Pod`]: the GPU instance
//!   buffers are byte copies of the lists.

use std::sync::Arc;

use bytemuck::{Pod, Zeroable};
use gaitlab_core::ik::Targets;
use gaitlab_core::{Kinematics, Skeleton};
use glam::{DVec3, Vec3};

use crate::view::ViewOptions;

/// Height of the ground plane, world metres.
pub const GROUND_Y: f32 = 0.0;

/// Colour of bones and joints on the figure's centre line (sRGB).
pub const CENTRE_COLOR: [f32; 4] = [0.80, 0.81, 0.84, 1.0];
/// Colour of bones and joints whose name starts with `left` (sRGB).
pub const LEFT_COLOR: [f32; 4] = [0.36, 0.60, 0.96, 1.0];
/// Colour of bones and joints whose name starts with `right` (sRGB).
pub const RIGHT_COLOR: [f32; 4] = [0.96, 0.52, 0.34, 1.0];
/// Colour of end effectors (sRGB).
pub const EFFECTOR_COLOR: [f32; 4] = [0.98, 0.80, 0.26, 1.0];
/// Colour of IK targets (sRGB).
pub const TARGET_COLOR: [f32; 4] = [0.93, 0.16, 0.14, 1.0];
/// Colour of the segment from an effector to its target (sRGB).
pub const ERROR_COLOR: [f32; 4] = [1.0, 0.33, 0.28, 1.0];
/// Colour of a revolute joint's rotation axis (sRGB).
pub const REVOLUTE_AXIS_COLOR: [f32; 4] = [0.96, 0.86, 0.22, 1.0];
/// Colour of a prismatic joint's sliding axis (sRGB).
pub const PRISMATIC_AXIS_COLOR: [f32; 4] = [0.25, 0.90, 0.90, 1.0];
/// Colours of the world x, y and z axes (sRGB).
pub const WORLD_AXIS_COLORS: [[f32; 4]; 3] = [
    [0.92, 0.22, 0.20, 1.0],
    [0.32, 0.86, 0.32, 1.0],
    [0.26, 0.48, 1.0, 1.0],
];

/// Length of each world axis, metres.
pub const WORLD_AXIS_LENGTH: f32 = 0.5;
/// Joint spheres are this much wider than the bone ending at the joint.
pub const JOINT_SPHERE_SCALE: f32 = 1.3;
/// Bones with a `size` of zero are drawn this thin, metres.
pub const MIN_BONE_RADIUS: f32 = 0.006;
/// Effectors nearer the ground than this (plus their radius) leave a contact mark, metres.
pub const CONTACT_HEIGHT: f32 = 0.02;

/// Darkness of a blob shadow at its centre (before fading with height).
pub const SHADOW_DARKNESS: f32 = 0.55;
/// Casters this high above the ground (or higher) cast no shadow, metres;
/// below it shadows fade linearly with height.
pub const SHADOW_FADE_HEIGHT: f32 = 2.0;
/// Darkness of a foot's contact mark.
pub const CONTACT_DARKNESS: f32 = 0.75;

/// Points closer than this are one point (zero-length bones are skipped), metres.
const COINCIDENT: f64 = 1e-6;

/// A bone: a capsule from `a` to `b` (`a == b` makes it a sphere).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Capsule {
    /// Start point (the parent joint), world metres.
    pub a: [f32; 3],
    /// Radius, metres.
    pub radius: f32,
    /// End point (the child joint or effector), world metres.
    pub b: [f32; 3],
    padding: f32,
    /// sRGB colour.
    pub color: [f32; 4],
}

impl Capsule {
    /// A capsule from `a` to `b` with `radius` and sRGB `color`.
    #[must_use]
    pub fn new(a: Vec3, b: Vec3, radius: f32, color: [f32; 4]) -> Self {
        Self {
            a: a.to_array(),
            radius,
            b: b.to_array(),
            padding: 0.0,
            color,
        }
    }
}

impl From<&Sphere> for Capsule {
    /// The sphere as a capsule of zero length (the renderer draws both with one pipeline).
    fn from(sphere: &Sphere) -> Self {
        Self {
            a: sphere.centre,
            radius: sphere.radius,
            b: sphere.centre,
            padding: 0.0,
            color: sphere.color,
        }
    }
}

/// A sphere: a joint, an effector or a target.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Sphere {
    /// Centre, world metres.
    pub centre: [f32; 3],
    /// Radius, metres.
    pub radius: f32,
    /// sRGB colour.
    pub color: [f32; 4],
}

impl Sphere {
    /// A sphere at `centre` with `radius` and sRGB `color`.
    #[must_use]
    pub fn new(centre: Vec3, radius: f32, color: [f32; 4]) -> Self {
        Self {
            centre: centre.to_array(),
            radius,
            color,
        }
    }
}

/// A line segment of constant screen width.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Segment {
    /// Start, world metres.
    pub a: [f32; 3],
    /// Width on screen, points (not pixels).
    pub width: f32,
    /// End, world metres.
    pub b: [f32; 3],
    padding: f32,
    /// sRGB colour; alpha blends.
    pub color: [f32; 4],
}

impl Segment {
    /// A segment from `a` to `b`, `width` points wide.
    #[must_use]
    pub fn new(a: Vec3, b: Vec3, width: f32, color: [f32; 4]) -> Self {
        Self {
            a: a.to_array(),
            width,
            b: b.to_array(),
            padding: 0.0,
            color,
        }
    }
}

/// A soft dark mark on the ground: the blob shadow of a capsule or sphere
/// seen from straight above, or a foot's contact mark.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GroundMark {
    /// Ground position (x, z) of one end, metres.
    pub a: [f32; 2],
    /// Ground position (x, z) of the other end, metres.
    pub b: [f32; 2],
    /// Radius of the caster, metres.
    pub radius: f32,
    /// Height of the caster's lowest end above the ground, metres (the shadow
    /// softens and fades with it).
    pub height: f32,
    /// Darkness at the centre, 0 (none) to 1 (black).
    pub darkness: f32,
    padding: f32,
}

impl GroundMark {
    /// A mark from ground point `a` to `b` (x, z).
    #[must_use]
    pub fn new(a: [f32; 2], b: [f32; 2], radius: f32, height: f32, darkness: f32) -> Self {
        Self {
            a,
            b,
            radius,
            height,
            darkness,
            padding: 0.0,
        }
    }
}

/// An axis-aligned box, world metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Smallest x, y, z.
    pub min: DVec3,
    /// Largest x, y, z.
    pub max: DVec3,
}

impl Bounds {
    /// The box around one point.
    #[must_use]
    pub fn point(p: DVec3) -> Self {
        Self { min: p, max: p }
    }

    /// Grows the box to hold `p`.
    pub fn include(&mut self, p: DVec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    /// Centre of the box.
    #[must_use]
    pub fn centre(&self) -> DVec3 {
        0.5 * (self.min + self.max)
    }

    /// Half the diagonal: the radius of the sphere around the box.
    #[must_use]
    pub fn radius(&self) -> f64 {
        0.5 * (self.max - self.min).length()
    }
}

/// One frame's primitives. Read it through [`Scene`]; the renderer holds an
/// `Arc` of it while drawing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneFrame {
    /// Bones: one per joint (from its parent, or from the root) and one per
    /// effector (from its joint), skipping zero-length ones.
    pub capsules: Vec<Capsule>,
    /// Joints, effectors and (when shown) targets.
    pub spheres: Vec<Sphere>,
    /// Error segments, rotation axes and world axes, as enabled.
    pub segments: Vec<Segment>,
    /// Blob shadows of the bones and contact marks of the feet (when shadows are on).
    pub ground_marks: Vec<GroundMark>,
    /// Box around the root, the joints and the effectors (not the targets)
    /// and the physics trunk; `None` before the first fill or when no
    /// position is finite.
    pub bounds: Option<Bounds>,
}

impl SceneFrame {
    fn clear(&mut self) {
        self.capsules.clear();
        self.spheres.clear();
        self.segments.clear();
        self.ground_marks.clear();
        self.bounds = None;
    }

    /// Grows [`Self::bounds`] to hold `p` (non-finite points are skipped).
    pub(crate) fn include(&mut self, p: DVec3) {
        if !p.is_finite() {
            return;
        }
        match &mut self.bounds {
            Some(bounds) => bounds.include(p),
            None => self.bounds = Some(Bounds::point(p)),
        }
    }
}

/// The figure as drawable primitives, rebuilt each frame by [`Scene::fill`].
#[derive(Clone, Debug, Default)]
pub struct Scene {
    frame: Arc<SceneFrame>,
}

/// Whether `name` starts with `prefix`, ignoring ASCII case.
fn starts_with_ignore_case(name: &str, prefix: &str) -> bool {
    name.as_bytes()
        .get(..prefix.len())
        .is_some_and(|head| head.eq_ignore_ascii_case(prefix.as_bytes()))
}

/// Colour by side: names starting with `left` / `right` (any case: `left_knee`,
/// `LeftUpLeg`) are the figure's left / right.
fn side_color(name: &str) -> [f32; 4] {
    if starts_with_ignore_case(name, "left") {
        LEFT_COLOR
    } else if starts_with_ignore_case(name, "right") {
        RIGHT_COLOR
    } else {
        CENTRE_COLOR
    }
}

/// `color` with its RGB scaled by `factor` (alpha kept).
fn shade(color: [f32; 4], factor: f32) -> [f32; 4] {
    [
        color[0] * factor,
        color[1] * factor,
        color[2] * factor,
        color[3],
    ]
}

fn f32_point(p: DVec3) -> Vec3 {
    p.as_vec3()
}

impl From<SceneFrame> for Scene {
    /// A scene showing hand-made primitives.
    fn from(frame: SceneFrame) -> Self {
        Self {
            frame: Arc::new(frame),
        }
    }
}

impl Scene {
    /// An empty scene.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

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
        let frame = Arc::make_mut(&mut self.frame);
        frame.clear();
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
                frame
                    .spheres
                    .push(Sphere::new(f32_point(target), radius, TARGET_COLOR));
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

    /// The primitives, for adding overlays after [`Scene::fill`] (copied
    /// first if the renderer still holds the previous frame).
    pub(crate) fn frame_mut(&mut self) -> &mut SceneFrame {
        Arc::make_mut(&mut self.frame)
    }

    /// The primitives of the last fill, shared with the renderer.
    #[must_use]
    pub fn frame(&self) -> &Arc<SceneFrame> {
        &self.frame
    }

    /// Bones.
    #[must_use]
    pub fn capsules(&self) -> &[Capsule] {
        &self.frame.capsules
    }

    /// Joints, effectors and targets.
    #[must_use]
    pub fn spheres(&self) -> &[Sphere] {
        &self.frame.spheres
    }

    /// Error segments and axes.
    #[must_use]
    pub fn segments(&self) -> &[Segment] {
        &self.frame.segments
    }

    /// Shadows and contact marks on the ground.
    #[must_use]
    pub fn ground_marks(&self) -> &[GroundMark] {
        &self.frame.ground_marks
    }

    /// Box around the figure (root, joints, effectors).
    #[must_use]
    pub fn bounds(&self) -> Option<Bounds> {
        self.frame.bounds
    }

    /// Centre of the figure's box: what the camera follows.
    #[must_use]
    pub fn centre(&self) -> Option<DVec3> {
        self.frame.bounds.map(|bounds| bounds.centre())
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::{Effector, Joint, Pose, RootTransform};

    use super::*;

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

    #[test]
    fn side_from_name() {
        assert_eq!(side_color("left_knee"), LEFT_COLOR);
        assert_eq!(side_color("LeftUpLeg"), LEFT_COLOR);
        assert_eq!(side_color("right_ankle"), RIGHT_COLOR);
        assert_eq!(side_color("spine"), CENTRE_COLOR);
        assert_eq!(side_color("é"), CENTRE_COLOR);
    }
}
