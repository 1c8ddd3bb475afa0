//! Forward dynamics in O(n): Featherstone's articulated-body algorithm
//! (Featherstone 2008 §7.3, with the floating base of §9.3). The paper's
//! equations of motion came from a symbolic O(n) Kane's-method generator
//! (Raibert & Hodgins 1991, "Modeling"); this computes the same accelerations.
//!
//! Reads `q`, `qd`, `tau`, `external` and the base state; runs
//! [`kinematics`](crate::dynamics::kinematics::kinematics); writes `qdd`,
//! `base_acceleration` and every body's `acceleration`.

use crate::dynamics::data::Data;
use crate::dynamics::inertia_solve;
use crate::dynamics::model::{Joint, Model};
use crate::dynamics::sparse;
use crate::dynamics::spatial::{Force, Inertia, Motion};

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
    body_gravity(model.gravity, &model.bodies()[i], &data.world[i].rot)
}

/// Gravity `g` (world, m/s²) on `body`, whose axes in the world are `rot`.
fn body_gravity(g: glam::DVec3, body: &crate::dynamics::model::Body, rot: &glam::DMat3) -> Force {
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
pub fn accelerations(model: &Model, data: &mut Data) -> Result<(), DynamicsError> {
    // Every per-body array sliced to the body count once, so the passes
    // index them without a bounds check per use.
    let bodies = model.bodies();
    let n = bodies.len();
    let inertias = &model.inertias()[..n];
    let shapes = &model.link_shapes()[..n];
    let dofs = &model.dofs()[..n];
    let last_children = &model.last_children()[..n];
    let world = &data.world[..n];
    let link = &data.link[..n];
    let velocity = &data.velocity[..n];
    let velocity_product = &data.velocity_product[..n];
    let external = &data.external[..n];
    let art_inertia = &mut data.art_inertia[..n];
    let art_bias = &mut data.art_bias[..n];
    let u_force = &mut data.u_force[..n];
    let d_of = &mut data.d[..n];
    let u_of = &mut data.u[..n];
    let acceleration = &mut data.acceleration[..n];
    // Pass 1: bias forces. A body's articulated inertia starts as its rigid
    // inertia; a leaf's stays the model's (read in place, not copied), and
    // a body with children gets its own at its first child's turn in pass 2.
    for i in 0..n {
        art_bias[i] = if bodies[i].mass > 0.0 {
            let v = velocity[i];
            v.cross_force(inertias[i].mul(v))
                - external[i]
                - body_gravity(model.gravity, &bodies[i], &world[i].rot)
        } else {
            // A massless link (a gimbal's inner axis) carries no momentum or weight.
            Force::ZERO - external[i]
        };
    }
    // Pass 2: articulated inertias, leaves to root.
    for &i in model.by_depth().iter().rev() {
        let Some(k) = dofs[i] else { continue };
        let joint = bodies[i].joint;
        let s = joint.subspace();
        let ia = articulated(inertias, art_inertia, last_children, i);
        let uf = match joint {
            Joint::Revolute(axis) => ia.mul_angular(axis),
            Joint::Prismatic(axis) => ia.mul_linear(axis),
            Joint::Free => ia.mul(s),
        };
        let d = s.dot(uf);
        if !(d > 1e-14 && d.is_finite()) {
            return Err(DynamicsError {
                body: bodies[i].name.clone(),
            });
        }
        let u = data.tau[k] - s.dot(art_bias[i]);
        u_force[i] = uf;
        d_of[i] = d;
        u_of[i] = u;
        if let Some(p) = bodies[i].parent {
            let ia_child = ia.minus_outer(uf, d);
            let pa_child = art_bias[i] + ia_child.mul(velocity_product[i]) + uf.scale(u / d);
            let to_parent = sparse::inertia_to_parent(&link[i], shapes[i], &ia_child);
            let bias_to_parent = sparse::force_to_parent(&link[i], shapes[i], pa_child);
            if last_children[p] == Some(i) {
                // The parent's first child: its rigid inertia plus this one.
                art_inertia[p].set_sum(&inertias[p], &to_parent);
            } else {
                art_inertia[p] += to_parent;
            }
            art_bias[p] += bias_to_parent;
        }
    }
    // Pass 3: accelerations, root to leaves.
    for &i in model.by_depth() {
        match dofs[i] {
            None => {
                let ia = articulated(inertias, art_inertia, last_children, i);
                let a = inertia_solve::solve(ia, art_bias[i].scale(-1.0)).ok_or_else(|| {
                    DynamicsError {
                        body: bodies[i].name.clone(),
                    }
                })?;
                data.base_acceleration = a;
                acceleration[i] = a;
            }
            Some(k) => {
                let parent_acc = match bodies[i].parent {
                    Some(p) => sparse::motion_to_child(&link[i], shapes[i], acceleration[p]),
                    None => Motion::ZERO,
                };
                let a = parent_acc + velocity_product[i];
                let qdd = (u_of[i] - a.dot(u_force[i])) / d_of[i];
                data.qdd[k] = qdd;
                acceleration[i] = a + bodies[i].joint.subspace().scale(qdd);
            }
        }
    }
    Ok(())
}

/// Body `i`'s articulated inertia once pass 2 has reached it: a leaf's is
/// its rigid inertia, in the model.
fn articulated<'a>(
    inertias: &'a [Inertia],
    art_inertia: &'a [Inertia],
    last_children: &[Option<usize>],
    i: usize,
) -> &'a Inertia {
    if last_children[i].is_some() {
        &art_inertia[i]
    } else {
        &inertias[i]
    }
}
