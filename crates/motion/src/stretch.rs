//! The "singularity" scenario for comparing IK methods (She 2006 §4.4.2–4.4.5:
//! the pseudoinverse is unstable near singular configurations, damped and
//! selectively damped least squares are not): every scripted limb's target is
//! pulled along the limb's rest direction to a distance that oscillates slowly
//! around the limb's full reach, so the limb spends its time fully stretched —
//! the configuration where the Jacobian loses rank.

use gaitlab_core::portable::Portable;
use gaitlab_core::{Kinematics, Skeleton};
use glam::DVec3;

/// Options of the stretch. Every field has a default that shows pinv's
/// oscillation clearly on the bundled IK creatures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StretchOptions {
    /// Mean target distance from the limb's base, as a fraction of its reach. Default 1.0.
    pub mean_reach: f64,
    /// Half the swing of the target distance, a fraction of the reach. Default 0.08.
    pub amplitude: f64,
    /// Period of the swing, seconds. Default 4.
    pub period_s: f64,
}

impl Default for StretchOptions {
    fn default() -> Self {
        Self {
            mean_reach: 1.0,
            amplitude: 0.08,
            period_s: 4.0,
        }
    }
}

/// Where one limb starts and how far it reaches, in the root's frame at rest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LimbReach {
    /// The limb's first joint: the first on the effector's chain that moves no
    /// other effector.
    pub base_joint: usize,
    /// The base joint's position relative to the root at rest, metres.
    pub base_m: DVec3,
    /// Unit direction from the base to the effector at rest.
    pub direction: DVec3,
    /// Sum of the limb's segment lengths from the base to the effector, metres
    /// (its reach when fully stretched).
    pub reach_m: f64,
}

impl LimbReach {
    /// The reach of effector `effector`, from the rest kinematics `rest`
    /// (computed with the root at the origin, unrotated). `None` when the
    /// effector is out of range or sits on its base joint.
    #[must_use]
    pub fn of(skeleton: &Skeleton, rest: &Kinematics, effector: usize) -> Option<Self> {
        if effector >= skeleton.effector_count() {
            return None;
        }
        let chain = skeleton.chain(effector);
        let shared = |j: usize| {
            (0..skeleton.effector_count())
                .any(|other| other != effector && skeleton.chain(other).contains(&j))
        };
        let start = chain.iter().position(|&j| !shared(j))?;
        let limb = &chain[start..];
        let base_joint = limb[0];
        let base_m = rest.joint_position[base_joint];
        let tip = rest.effector_position[effector];
        let mut reach_m = 0.0;
        let mut previous = base_m;
        for &j in &limb[1..] {
            reach_m += previous.distance(rest.joint_position[j]);
            previous = rest.joint_position[j];
        }
        reach_m += previous.distance(tip);
        let direction = (tip - base_m).try_normalize()?;
        (reach_m > 0.0).then_some(Self {
            base_joint,
            base_m,
            direction,
            reach_m,
        })
    }

    /// The stretched target at time `t_s`, relative to the root, metres.
    #[must_use]
    pub fn target(&self, options: &StretchOptions, t_s: f64) -> DVec3 {
        let swing = if options.period_s > 0.0 {
            (std::f64::consts::TAU * t_s / options.period_s).psin()
        } else {
            0.0
        };
        let distance = self.reach_m * (options.mean_reach + options.amplitude * swing);
        self.base_m + self.direction * distance
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gaitlab_core::preset::load_bundled;
    use gaitlab_core::{Pose, RootTransform};

    #[test]
    fn the_human_legs_reach_about_their_length_and_point_down() {
        let Some(Ok(creature)) = load_bundled("human") else {
            panic!("human preset")
        };
        let skeleton = &creature.skeleton;
        let rest = Kinematics::of(
            skeleton,
            &Pose {
                root: RootTransform::default(),
                joints: skeleton.rest_values(),
            },
        );
        let foot = skeleton
            .effectors()
            .iter()
            .position(|e| e.name.contains("foot"))
            .unwrap_or(0);
        let Some(limb) = LimbReach::of(skeleton, &rest, foot) else {
            panic!("a limb")
        };
        println!("{limb:?}");
        assert!((0.6..1.2).contains(&limb.reach_m), "{}", limb.reach_m);
        assert!(limb.direction.y < -0.8, "{:?}", limb.direction);
        let options = StretchOptions::default();
        let far = limb.target(&options, 1.0).distance(limb.base_m);
        assert!((far / limb.reach_m - 1.08).abs() < 1e-9);
    }
}
