//! Shared helpers for the core integration tests: a deterministic random
//! source and small skeletons with known geometry.
#![allow(dead_code)]

use gaitlab_core::{Effector, Joint, Kinematics, Pose, RootTransform, Skeleton};
use glam::DVec3;

/// A small deterministic random generator (PCG-style LCG), so tests are repeatable.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    pub fn vec3(&mut self, scale: f64) -> DVec3 {
        DVec3::new(
            self.range(-scale, scale),
            self.range(-scale, scale),
            self.range(-scale, scale),
        )
    }
    pub fn unit_vec3(&mut self) -> DVec3 {
        loop {
            let v = self.vec3(1.0);
            if v.length_squared() > 0.01 && v.length_squared() <= 1.0 {
                return v.normalize();
            }
        }
    }
}

/// Planar arm in the x–y plane: revolute joints about z, links along x.
pub fn planar_arm(lengths: &[f64]) -> Skeleton {
    let mut joints = Vec::new();
    let mut offset = DVec3::ZERO;
    for (i, &length) in lengths.iter().enumerate() {
        let parent = i.checked_sub(1);
        joints.push(Joint::revolute(&format!("j{i}"), parent, offset, DVec3::Z));
        offset = DVec3::new(length, 0.0, 0.0);
    }
    let effector = Effector {
        name: "tip".into(),
        joint: lengths.len() - 1,
        offset,
        orientation: false,
    };
    Skeleton::new(joints, vec![effector]).expect("valid arm")
}

/// A random tree of `n` joints (mixed revolute / prismatic, random axes, frames
/// and offsets) with `k` effectors on leaves or random joints, limits ±`limit`.
pub fn random_tree(
    rng: &mut Rng,
    n: usize,
    k: usize,
    limit: Option<f64>,
    orientation: bool,
) -> Skeleton {
    let mut joints = Vec::new();
    for i in 0..n {
        let parent = if i == 0 {
            None
        } else {
            Some((rng.unit() * i as f64) as usize)
        };
        let axis = rng.unit_vec3();
        let offset = rng.vec3(0.3);
        let mut joint = if rng.unit() < 0.15 && i > 0 {
            Joint::prismatic(&format!("j{i}"), parent, offset, axis)
        } else {
            Joint::revolute(&format!("j{i}"), parent, offset, axis)
        };
        joint.frame = glam::DMat3::from_axis_angle(rng.unit_vec3(), rng.range(-1.0, 1.0));
        if let Some(limit) = limit {
            joint.limits = Some((-limit, limit));
        }
        joints.push(joint);
    }
    let effectors = (0..k)
        .map(|e| Effector {
            name: format!("e{e}"),
            joint: n - 1 - (e * 7919) % n.max(1),
            offset: rng.vec3(0.2),
            orientation: orientation && e == 0,
        })
        .collect();
    Skeleton::new(joints, effectors).expect("valid random tree")
}

/// Position of effector 0 of `skeleton` at joint `values`, root at the origin, metres.
pub fn tip(skeleton: &Skeleton, values: &[f64]) -> DVec3 {
    Kinematics::of(
        skeleton,
        &Pose {
            root: RootTransform::default(),
            joints: values.to_vec(),
        },
    )
    .effector_position[0]
}
