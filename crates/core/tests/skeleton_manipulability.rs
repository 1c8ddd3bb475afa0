//! Manipulability ellipsoids (issue 44 item 3): on a planar 2-link arm σ₁σ₂
//! is the Jacobian's determinant l₁l₂|sin q₂| and the ellipsoid flattens to a
//! segment as the arm straightens; on the bundled human, in random poses, the
//! semi-axes equal an independent SVD of the same 3×k block of the geometric
//! Jacobian (`fill_jacobian`'s rows and the limb's columns) to 1e-9, and
//! J_ℓ J_ℓᵀ aᵢ = σᵢ² aᵢ for each axis.

use gaitlab_core::jacobian::fill_jacobian;
use gaitlab_core::preset;
use gaitlab_core::skeleton::Scope;
use gaitlab_core::{Effector, Joint, Kinematics, RootTransform, Skeleton};
use glam::DVec3;
use nalgebra::DMatrix;

fn two_link() -> Skeleton {
    let joints = vec![
        Joint::revolute("shoulder", None, DVec3::new(0.0, 1.0, 0.0), DVec3::Z),
        Joint::revolute("elbow", Some(0), DVec3::new(0.5, 0.0, 0.0), DVec3::Z),
    ];
    let hand = Effector {
        name: "hand".to_owned(),
        joint: 1,
        offset: DVec3::new(0.3, 0.0, 0.0),
        orientation: false,
    };
    Skeleton::new(joints, vec![hand]).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_planar_arm_has_its_determinant_and_flattens_when_straight() {
    let skeleton = two_link();
    let mut kin = Kinematics::new(&skeleton);
    for q2 in [1.2_f64, 0.5, 0.1, 0.01, 0.0] {
        kin.update(&skeleton, &RootTransform::default(), &[0.4, q2]);
        let ellipsoid = skeleton
            .manipulability(&kin, 0, Scope::Limb)
            .expect("an effector");
        let [s1, s2, s3] = ellipsoid.sigma;
        // No motion out of the arm's plane.
        assert!(s3 < 1e-12, "σ₃ {s3}");
        assert!(ellipsoid.axes[2].dot(DVec3::Z).abs() > 1.0 - 1e-9);
        let det = 0.5 * 0.3 * gaitlab_core::trig::sin_cos(q2).0.abs();
        assert!(
            (s1 * s2 - det).abs() < 1e-12,
            "q2 {q2}: {} vs {det}",
            s1 * s2
        );
        assert!(s1 >= s2 && s2 >= s3);
        if q2 == 0.0 {
            // Straight: the arm cannot move along itself.
            assert!(s2 < 1e-9, "σ₂ {s2}");
            let along = (ellipsoid.centre - DVec3::new(0.0, 1.0, 0.0)).normalize();
            assert!(ellipsoid.axes[0].dot(along).abs() < 1e-9);
        }
    }
}

/// xorshift in [−1, 1).
fn next(state: &mut u64) -> f64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

#[test]
fn the_human_ellipsoids_equal_an_svd_of_the_jacobian_block() {
    let creature = preset::load_bundled("human")
        .expect("human is bundled")
        .expect("human.json is valid");
    let skeleton = &creature.skeleton;
    let mut kin = Kinematics::new(skeleton);
    let mut jacobian = DMatrix::zeros(0, 0);
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut checked = 0;
    for _ in 0..20 {
        let angles: Vec<f64> = (0..skeleton.joint_count())
            .map(|_| 0.8 * next(&mut state))
            .collect();
        kin.update(skeleton, &RootTransform::default(), &angles);
        fill_jacobian(skeleton, &kin, &mut jacobian);
        for e in 0..skeleton.effector_count() {
            let row = 3 * e; // the human's effectors have no orientation rows
            for scope in [Scope::Limb, Scope::Chain] {
                let columns: Vec<usize> = match scope {
                    Scope::Limb => skeleton.limb(e).joints.clone(),
                    Scope::Chain => skeleton.chain(e).to_vec(),
                };
                let block =
                    DMatrix::from_fn(3, columns.len(), |r, c| jacobian[(row + r, columns[c])]);
                let mut svd: Vec<f64> = block.singular_values().iter().copied().collect();
                svd.sort_by(|a, b| b.total_cmp(a));
                svd.resize(3, 0.0);
                let ellipsoid = skeleton
                    .manipulability(&kin, e, scope)
                    .expect("an effector");
                let gram = &block * block.transpose();
                for (i, &sigma) in svd.iter().enumerate() {
                    assert!(
                        (ellipsoid.sigma[i] - sigma).abs() < 1e-9,
                        "effector {e} {scope:?}: σ{i} {} vs SVD {sigma}",
                        ellipsoid.sigma[i]
                    );
                    let a = ellipsoid.axes[i];
                    let a = nalgebra::DVector::from_vec(vec![a.x, a.y, a.z]);
                    let residual = (&gram * &a - &a * sigma.powi(2)).norm();
                    assert!(residual < 1e-9, "effector {e} axis {i}: {residual}");
                    for k in 0..i {
                        assert!(ellipsoid.axes[i].dot(ellipsoid.axes[k]).abs() < 1e-9);
                    }
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 20 * 4 * 2 * 3);
}
