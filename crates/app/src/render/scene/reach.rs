//! Reach in the 3-D view (issue 44 item 3): each effector's manipulability
//! ellipsoid ([`Skeleton::manipulability`], the limb's block of J Jᵀ) drawn
//! at the effector as its three principal ellipses, and each limb's reach
//! shell — the sphere of its full extension around its first joint (the
//! reach test of She 2006 §5.3) — as rings, so a target leaving it is seen
//! before it turns orange.

use gaitlab_core::skeleton::Scope;
use gaitlab_core::{Kinematics, Skeleton};
use glam::{DVec3, Vec3};

use super::frame::SceneFrame;
use super::palette::side_color;
use super::primitives::Segment;

/// The ellipsoid's scale: its semi-axes are σᵢ × this, so it is the set of
/// first-order effector displacements for joint steps of this norm,
/// radians. At 0.15 rad the she-2006 human's arm ellipsoid (σ₁ 0.64 m/rad)
/// is 0.19 m across, its leg's (σ₁ about 0.98 m/rad) 0.29 m: large enough
/// to read in four views, small enough not to hide the figure.
pub const ELLIPSOID_STEP_RAD: f64 = 0.15;

/// Segments per drawn ring.
const RING_SEGMENTS: usize = 32;

/// The ellipsoids' colour (sRGB, a little transparent).
pub const ELLIPSOID_COLOR: [f32; 4] = [0.22, 0.82, 0.72, 0.95];

/// How opaque a reach shell's rings are (its colour is its limb's side's).
const SHELL_ALPHA: f32 = 0.35;

/// Pushes the ellipse `centre + cos t · a + sin t · b` as [`RING_SEGMENTS`]
/// segments.
fn ring(frame: &mut SceneFrame, centre: DVec3, a: DVec3, b: DVec3, width: f32, color: [f32; 4]) {
    let at = |k: usize| {
        let t = std::f64::consts::TAU * k as f64 / RING_SEGMENTS as f64;
        (centre + a * t.cos() + b * t.sin()).as_vec3()
    };
    let mut last: Vec3 = at(0);
    for k in 1..=RING_SEGMENTS {
        let next = at(k);
        frame.segments.push(Segment::new(last, next, width, color));
        last = next;
    }
}

/// Draws each effector's ellipsoid (`ellipsoids`) and each limb's reach
/// shell (`shells`) for the pose `kin`. Non-finite poses draw nothing.
pub(super) fn push_reach(
    frame: &mut SceneFrame,
    skeleton: &Skeleton,
    kin: &Kinematics,
    ellipsoids: bool,
    shells: bool,
) {
    for e in 0..skeleton.effector_count() {
        if ellipsoids && let Some(ellipsoid) = skeleton.manipulability(kin, e, Scope::Limb) {
            let [a, b, c] = ellipsoid.axes;
            let [ra, rb, rc] = ellipsoid.sigma.map(|s| s * ELLIPSOID_STEP_RAD);
            let centre = ellipsoid.centre;
            ring(frame, centre, a * ra, b * rb, 1.5, ELLIPSOID_COLOR);
            ring(frame, centre, a * ra, c * rc, 1.5, ELLIPSOID_COLOR);
            ring(frame, centre, b * rb, c * rc, 1.5, ELLIPSOID_COLOR);
        }
        if shells && let Some(limb) = skeleton.limbs().get(e) {
            let Some(first) = limb.joints.first() else {
                continue;
            };
            let centre = limb.anchor(&kin.joint_anchor, &kin.joint_position);
            let r = limb.length_m;
            if !centre.is_finite() || r <= 0.0 {
                continue;
            }
            let mut color = skeleton
                .joints()
                .get(*first)
                .map_or([0.8, 0.8, 0.8, 1.0], |j| side_color(&j.name));
            color[3] = SHELL_ALPHA;
            // The equator, two meridians, and latitudes at ±45°.
            ring(frame, centre, DVec3::X * r, DVec3::Z * r, 1.0, color);
            ring(frame, centre, DVec3::X * r, DVec3::Y * r, 1.0, color);
            ring(frame, centre, DVec3::Z * r, DVec3::Y * r, 1.0, color);
            let (s, c) = std::f64::consts::FRAC_PI_4.sin_cos();
            for up in [1.0, -1.0] {
                let at = centre + DVec3::Y * (up * r * s);
                ring(frame, at, DVec3::X * r * c, DVec3::Z * r * c, 1.0, color);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::{Effector, Joint, RootTransform};

    use super::*;

    /// A planar 2-link arm, bent: its ellipsoid's rings lie at σᵢ·0.15 m from
    /// the hand along its axes and one ring is flat (σ₃ = 0); its shell's
    /// rings lie on the 0.8 m sphere around the shoulder.
    #[test]
    fn rings_lie_on_the_ellipsoid_and_the_shell() {
        let joints = vec![
            Joint::revolute("left_shoulder", None, DVec3::new(0.0, 1.0, 0.0), DVec3::Z),
            Joint::revolute("left_elbow", Some(0), DVec3::new(0.5, 0.0, 0.0), DVec3::Z),
        ];
        let hand = Effector {
            name: "left_hand".to_owned(),
            joint: 1,
            offset: DVec3::new(0.3, 0.0, 0.0),
            orientation: false,
        };
        let skeleton = Skeleton::new(joints, vec![hand]).expect("valid");
        let mut kin = Kinematics::new(&skeleton);
        kin.update(&skeleton, &RootTransform::default(), &[0.3, 1.0]);
        let mut frame = SceneFrame::default();
        push_reach(&mut frame, &skeleton, &kin, true, false);
        assert_eq!(frame.segments.len(), 3 * RING_SEGMENTS);
        let e = skeleton
            .manipulability(&kin, 0, Scope::Limb)
            .expect("effector");
        let first = frame.segments[0];
        let start = Vec3::from(first.a).as_dvec3();
        let expected = e.centre + e.axes[0] * e.sigma[0] * ELLIPSOID_STEP_RAD;
        assert!(start.distance(expected) < 1e-5, "{start} vs {expected}");
        frame.segments.clear();
        push_reach(&mut frame, &skeleton, &kin, false, true);
        assert_eq!(frame.segments.len(), 5 * RING_SEGMENTS);
        let shoulder = DVec3::new(0.0, 1.0, 0.0);
        for segment in &frame.segments {
            let r = Vec3::from(segment.a).as_dvec3().distance(shoulder);
            assert!((r - 0.8).abs() < 1e-5, "on the shell: {r}");
            assert!((segment.color[3] - SHELL_ALPHA).abs() < 1e-6);
        }
    }
}
