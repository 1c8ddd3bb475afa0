//! The sparse joint transforms (`dynamics/sparse.rs`) against the dense
//! products of `ParentLink`: the same bits for every joint kind and every
//! zero pattern of the joint's offset, and the shape each joint is given.

use gaitlab_physics::dynamics::kinematics::joint_link;
use gaitlab_physics::dynamics::model::RotShape;
use gaitlab_physics::dynamics::sparse::{
    force_to_parent, inertia_to_parent, motion_to_child, then,
};
use gaitlab_physics::{Body, Force, Inertia, Joint, Motion, ParentLink};
use glam::{DMat3, DVec3};

/// Equal bit for bit, or both zero (the one difference allowed).
fn same(x: f64, y: f64) -> bool {
    x.to_bits() == y.to_bits() || (x == 0.0 && y == 0.0)
}

fn same_mat(x: &DMat3, y: &DMat3) -> bool {
    x.to_cols_array()
        .iter()
        .zip(y.to_cols_array())
        .all(|(&p, q)| same(p, q))
}

fn same_vec(x: DVec3, y: DVec3) -> bool {
    x.to_array()
        .iter()
        .zip(y.to_array())
        .all(|(&p, q)| same(p, q))
}

/// A full articulated-like inertia with no zero entry.
fn dense_inertia(seed: f64) -> Inertia {
    let m = |o: f64| {
        DMat3::from_cols_array(&[
            1.3 + o,
            0.21 * o,
            -0.17,
            0.21 * o,
            0.9,
            0.11 + o,
            -0.17,
            0.11 + o,
            2.1,
        ])
    };
    let b = DMat3::from_cols_array(&[0.3, -0.7, 0.05, 0.12, -0.4, 0.33, -0.6, 0.08, 0.27 + seed]);
    Inertia {
        a: m(seed),
        b,
        c: m(0.5 * seed) * 3.0,
    }
}

/// Every joint a creature uses, at every zero pattern of its position:
/// the shaped products give the dense products' bits.
#[test]
fn shaped_products_match_the_dense_ones_bit_for_bit() {
    let joints = [
        Joint::Revolute(DVec3::X),
        Joint::Revolute(DVec3::Y),
        Joint::Revolute(DVec3::Z),
        Joint::Revolute(DVec3::NEG_X),
        Joint::Prismatic(DVec3::NEG_Y),
        Joint::Prismatic(DVec3::Z),
    ];
    let mut checked = 0;
    for joint in joints {
        for zeros in 0..8u8 {
            let c = |bit: u8, v: f64| if zeros & bit != 0 { 0.0 } else { v };
            let body = Body {
                name: "b".into(),
                parent: Some(0),
                joint,
                placement: ParentLink {
                    rot: DMat3::IDENTITY,
                    pos: DVec3::new(c(1, 0.072), c(2, -0.2), c(4, 0.31)),
                },
                mass: 1.0,
                com: DVec3::ZERO,
                inertia_com: DMat3::IDENTITY,
            };
            let shape = body.link_shape();
            assert_ne!(shape, RotShape::General, "{joint:?}");
            for q in [0.0, 0.37, -1.9, 2.8] {
                let link = joint_link(&body.placement, &body.joint, q);
                // The link as the dense formula forms it (no identity left out).
                let p = body.placement;
                let dense = match joint {
                    Joint::Revolute(axis) => ParentLink {
                        rot: p.rot * DMat3::from_axis_angle(axis, q),
                        pos: p.pos,
                    },
                    _ => ParentLink {
                        rot: p.rot,
                        pos: p.pos + p.rot * (joint.subspace().linear * q),
                    },
                };
                assert!(same_mat(&link.rot, &dense.rot) && same_vec(link.pos, dense.pos));
                let i = dense_inertia(q);
                let got = inertia_to_parent(&link, shape, &i);
                let want = dense.inertia_to_parent(&i);
                assert!(same_mat(&got.a, &want.a), "{joint:?} {zeros} {q}: a");
                assert!(same_mat(&got.b, &want.b), "{joint:?} {zeros} {q}: b");
                assert!(same_mat(&got.c, &want.c), "{joint:?} {zeros} {q}: c");
                let m = Motion::new(DVec3::new(0.3, -1.2, 0.8), DVec3::new(1.5, 0.2, -0.4));
                let (gm, wm) = (motion_to_child(&link, shape, m), dense.motion_to_child(m));
                assert!(same_vec(gm.angular, wm.angular) && same_vec(gm.linear, wm.linear));
                let f = Force::new(DVec3::new(-2.0, 0.7, 0.1), DVec3::new(3.0, -9.0, 1.1));
                let (gf, wf) = (force_to_parent(&link, shape, f), dense.force_to_parent(f));
                assert!(same_vec(gf.moment, wf.moment) && same_vec(gf.force, wf.force));
                let parent = ParentLink {
                    rot: DMat3::from_axis_angle(DVec3::new(0.6, 0.0, 0.8), 0.9),
                    pos: DVec3::new(0.1, 0.9, -0.3),
                };
                let (gt, wt) = (then(&parent, &link, shape), parent.then(&dense));
                assert!(same_mat(&gt.rot, &wt.rot) && same_vec(gt.pos, wt.pos));
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 6 * 8 * 4);
}

#[test]
fn shapes_follow_joint_and_placement() {
    let body = |joint, rot| Body {
        name: "b".into(),
        parent: Some(0),
        joint,
        placement: ParentLink {
            rot,
            pos: DVec3::ZERO,
        },
        mass: 0.0,
        com: DVec3::ZERO,
        inertia_com: DMat3::ZERO,
    };
    let id = DMat3::IDENTITY;
    let turned = DMat3::from_axis_angle(DVec3::Z, 0.1);
    assert_eq!(
        body(Joint::Revolute(DVec3::Y), id).link_shape(),
        RotShape::About(1)
    );
    assert_eq!(
        body(Joint::Revolute(DVec3::NEG_Z), id).link_shape(),
        RotShape::About(2)
    );
    assert_eq!(
        body(Joint::Prismatic(DVec3::NEG_Y), id).link_shape(),
        RotShape::Identity
    );
    let tilted = DVec3::new(0.6, 0.8, 0.0);
    assert_eq!(
        body(Joint::Revolute(tilted), id).link_shape(),
        RotShape::General
    );
    assert_eq!(
        body(Joint::Revolute(DVec3::X), turned).link_shape(),
        RotShape::General
    );
    assert_eq!(
        body(Joint::Prismatic(DVec3::X), turned).link_shape(),
        RotShape::General
    );
    assert_eq!(body(Joint::Free, id).link_shape(), RotShape::General);
}
