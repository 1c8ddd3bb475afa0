//! Forward dynamics in O(n): Featherstone's articulated-body algorithm
//! (Featherstone 2008 §7.3, with the floating base of §9.3). The paper's
//! equations of motion came from a symbolic O(n) Kane's-method generator
//! (Raibert & Hodgins 1991, "Modeling"); this computes the same accelerations.
//!
//! Reads `q`, `qd`, `tau`, `external` and the base state; runs
//! [`kinematics`](crate::dynamics::kinematics::kinematics); writes `qdd`,
//! `base_acceleration` and every body's `acceleration`.

use crate::dynamics::data::Data;
use crate::dynamics::model::Model;
use crate::dynamics::sparse;
use crate::dynamics::spatial::{Force, Motion};

/// Why the dynamics could not be solved.
#[derive(Clone, Debug, PartialEq)]
pub struct DynamicsError {
    /// The body whose articulated inertia was singular.
    pub body: String,
}

impl std::fmt::Display for DynamicsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "singular articulated inertia at body {}", self.body)
    }
}

impl std::error::Error for DynamicsError {}

/// Gravity on body `i` as a spatial force in body coordinates.
pub(crate) fn gravity_force(model: &Model, data: &Data, i: usize) -> Force {
    let body = &model.bodies()[i];
    let rot = &data.world[i].rot;
    let g = model.gravity;
    let g_body = if g.x == 0.0 && g.z == 0.0 {
        // Vertical gravity: only the world-vertical row of the rotation
        // contributes (the same bits as the full product).
        glam::DVec3::new(rot.x_axis.y, rot.y_axis.y, rot.z_axis.y) * g.y
    } else {
        rot.transpose() * g
    };
    Force::at_point(body.com, g_body * body.mass)
}

/// Run kinematics, then compute the accelerations of every joint and of the base.
///
/// # Errors
/// [`DynamicsError`] when a joint drives no inertia (a massless chain end) or
/// the base's articulated inertia is singular; `data` keeps its last state.
pub fn forward_dynamics(model: &Model, data: &mut Data) -> Result<(), DynamicsError> {
    crate::dynamics::kinematics::kinematics(model, data);
    accelerations(model, data)
}

/// The accelerations, with the kinematics of the current state already run.
///
/// # Errors
/// As [`forward_dynamics`].
#[expect(
    clippy::needless_range_loop,
    reason = "body indices address several parallel arrays, as in Featherstone's pseudocode"
)]
pub fn accelerations(model: &Model, data: &mut Data) -> Result<(), DynamicsError> {
    let bodies = model.bodies();
    // Pass 1: rigid-body inertias and bias forces.
    for i in 0..bodies.len() {
        data.art_inertia[i] = *model.inertia(i);
        let inertia = &data.art_inertia[i];
        data.art_bias[i] = if bodies[i].mass > 0.0 {
            let v = data.velocity[i];
            v.cross_force(inertia.mul(v)) - data.external[i] - gravity_force(model, data, i)
        } else {
            // A massless link (a gimbal's inner axis) carries no momentum or weight.
            Force::ZERO - data.external[i]
        };
    }
    // Pass 2: articulated inertias, leaves to root.
    for i in (0..bodies.len()).rev() {
        let Some(k) = model.dof_of(i) else { continue };
        let s = bodies[i].joint.subspace();
        let ia = &data.art_inertia[i];
        let u_force = match bodies[i].joint {
            crate::dynamics::model::Joint::Revolute(axis) => ia.mul_angular(axis),
            crate::dynamics::model::Joint::Prismatic(axis) => ia.mul_linear(axis),
            crate::dynamics::model::Joint::Free => ia.mul(s),
        };
        let d = s.dot(u_force);
        if !(d > 1e-14 && d.is_finite()) {
            return Err(DynamicsError {
                body: bodies[i].name.clone(),
            });
        }
        let u = data.tau[k] - s.dot(data.art_bias[i]);
        data.u_force[i] = u_force;
        data.d[i] = d;
        data.u[i] = u;
        if let Some(p) = bodies[i].parent {
            let ia_child = ia.minus_outer(u_force, d);
            let pa_child =
                data.art_bias[i] + ia_child.mul(data.velocity_product[i]) + u_force.scale(u / d);
            let link = &data.link[i];
            let shape = model.link_shape(i);
            let to_parent = sparse::inertia_to_parent(link, shape, &ia_child);
            let bias_to_parent = sparse::force_to_parent(link, shape, pa_child);
            data.art_inertia[p] += to_parent;
            data.art_bias[p] += bias_to_parent;
        }
    }
    // Pass 3: accelerations, root to leaves.
    for i in 0..bodies.len() {
        match model.dof_of(i) {
            None => {
                let a = data.art_inertia[i]
                    .solve(data.art_bias[i].scale(-1.0))
                    .ok_or_else(|| DynamicsError {
                        body: bodies[i].name.clone(),
                    })?;
                data.base_acceleration = a;
                data.acceleration[i] = a;
            }
            Some(k) => {
                let parent_acc = match bodies[i].parent {
                    Some(p) => sparse::motion_to_child(
                        &data.link[i],
                        model.link_shape(i),
                        data.acceleration[p],
                    ),
                    None => Motion::ZERO,
                };
                let a = parent_acc + data.velocity_product[i];
                let qdd = (data.u[i] - a.dot(data.u_force[i])) / data.d[i];
                data.qdd[k] = qdd;
                data.acceleration[i] = a + bodies[i].joint.subspace().scale(qdd);
            }
        }
    }
    Ok(())
}
