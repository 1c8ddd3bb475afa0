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
#[inline(always)]
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
    // Every per-body array sliced to the body count once (no bounds check
    // per use).
    let bodies = model.bodies();
    let n = bodies.len();
    let shapes = &model.link_shapes()[..n];
    let dofs = &model.dofs()[..n];
    let link_of = &mut data.link[..n];
    let world_of = &mut data.world[..n];
    let velocity_of = &mut data.velocity[..n];
    let velocity_product = &mut data.velocity_product[..n];
    for &i in model.by_depth() {
        let body = &bodies[i];
        let shape = shapes[i];
        let Some(k) = dofs[i] else {
            // The free root: its frame and velocity are the base state.
            let link = ParentLink {
                rot: DMat3::from_quat(data.base_orientation.normalize()),
                pos: data.base_position,
            };
            link_of[i] = link;
            world_of[i] = link;
            velocity_of[i] = data.base_velocity;
            velocity_product[i] = Motion::ZERO;
            continue;
        };
        let link = joint_link(&body.placement, &body.joint, data.q[k]);
        let vel_joint = body.joint.subspace().scale(data.qd[k]);
        link_of[i] = link;
        let (world, velocity) = match body.parent {
            None => (link, vel_joint),
            Some(p) => (
                sparse::then(&world_of[p], &link, shape),
                sparse::motion_to_child(&link, shape, velocity_of[p]) + vel_joint,
            ),
        };
        world_of[i] = world;
        velocity_of[i] = velocity;
        velocity_product[i] = velocity.cross_motion(vel_joint);
    }
}
