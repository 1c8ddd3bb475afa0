//! Position and velocity kinematics: each body's frame in its parent and in
//! the world, and its spatial velocity (Featherstone 2008 §4.4, the first pass
//! of the recursive algorithms).
//!
//! Reads `q`, `qd` and the base state; writes `link`, `world`, `velocity`.

use glam::DMat3;

use crate::dynamics::data::Data;
use crate::dynamics::model::{Joint, Model};
use crate::dynamics::sparse;
use crate::dynamics::spatial::{Motion, ParentLink};

/// The joint's frame in its parent for coordinate `q` (an unrotated
/// placement's identity product left out: the same bits).
#[must_use]
pub fn joint_link(placement: &ParentLink, joint: &Joint, q: f64) -> ParentLink {
    let unrotated = placement.rot == DMat3::IDENTITY;
    match *joint {
        Joint::Free => *placement,
        Joint::Revolute(axis) => ParentLink {
            rot: if unrotated {
                DMat3::from_axis_angle(axis, q)
            } else {
                placement.rot * DMat3::from_axis_angle(axis, q)
            },
            pos: placement.pos,
        },
        Joint::Prismatic(axis) => ParentLink {
            rot: placement.rot,
            pos: placement.pos
                + if unrotated {
                    axis * q
                } else {
                    placement.rot * (axis * q)
                },
        },
    }
}

/// Run the kinematics pass.
pub fn kinematics(model: &Model, data: &mut Data) {
    for (i, body) in model.bodies().iter().enumerate() {
        let shape = model.link_shape(i);
        let (link, vel_joint) = match model.dof_of(i) {
            None => (
                ParentLink {
                    rot: DMat3::from_quat(data.base_orientation.normalize()),
                    pos: data.base_position,
                },
                data.base_velocity,
            ),
            Some(k) => {
                let l = joint_link(&body.placement, &body.joint, data.q[k]);
                (l, body.joint.subspace().scale(data.qd[k]))
            }
        };
        data.link[i] = link;
        let (world, velocity) = match (model.dof_of(i), body.parent) {
            (None, _) => (link, vel_joint),
            (Some(_), None) => (link, vel_joint),
            (Some(_), Some(p)) => (
                sparse::then(&data.world[p], &link, shape),
                sparse::motion_to_child(&link, shape, data.velocity[p]) + vel_joint,
            ),
        };
        data.world[i] = world;
        data.velocity[i] = velocity;
        data.velocity_product[i] = match model.dof_of(i) {
            None => Motion::ZERO,
            Some(_) => velocity.cross_motion(vel_joint),
        };
    }
}
