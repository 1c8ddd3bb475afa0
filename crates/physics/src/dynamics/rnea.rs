//! Inverse dynamics: the recursive Newton–Euler algorithm (Featherstone 2008
//! §5.3). With zero accelerations it gives the bias forces `C(q, q̇)` that,
//! with [`crate::dynamics::crba`]'s mass matrix, make the O(n³) forward-dynamics path the
//! articulated-body algorithm is checked against.
//!
//! Generalized vectors are ordered `[base ω (3), base v (3), joints…]` for a
//! free base (body coordinates), `[joints…]` otherwise.

use crate::dynamics::aba::gravity_force;
use crate::dynamics::data::Data;
use crate::dynamics::model::Model;
use crate::dynamics::spatial::{Force, Motion};

/// The generalized forces that produce the generalized accelerations `accel`
/// (length `model.nv()`) at the current state, with `data.external` and
/// gravity acting. Runs kinematics; overwrites `data.acceleration`.
#[must_use]
pub fn inverse_dynamics(model: &Model, data: &mut Data, accel: &[f64]) -> Vec<f64> {
    crate::dynamics::kinematics::kinematics(model, data);
    let bodies = model.bodies();
    let base = if model.free_base() { 6 } else { 0 };
    let mut forces = vec![Force::ZERO; bodies.len()];
    for i in 0..bodies.len() {
        let a = match model.dof_of(i) {
            None => Motion::new(
                glam::DVec3::new(accel[0], accel[1], accel[2]),
                glam::DVec3::new(accel[3], accel[4], accel[5]),
            ),
            Some(k) => {
                let parent = match bodies[i].parent {
                    Some(p) => data.link[i].motion_to_child(data.acceleration[p]),
                    None => Motion::ZERO,
                };
                parent
                    + data.velocity_product[i]
                    + bodies[i].joint.subspace().scale(accel[base + k])
            }
        };
        data.acceleration[i] = a;
        let inertia = bodies[i].spatial_inertia();
        let v = data.velocity[i];
        forces[i] = inertia.mul(a) + v.cross_force(inertia.mul(v))
            - data.external[i]
            - gravity_force(model, data, i);
    }
    let mut tau = vec![0.0; model.nv()];
    for i in (0..bodies.len()).rev() {
        match model.dof_of(i) {
            None => {
                let f = forces[i];
                tau[..6].copy_from_slice(&[
                    f.moment.x, f.moment.y, f.moment.z, f.force.x, f.force.y, f.force.z,
                ]);
            }
            Some(k) => tau[base + k] = bodies[i].joint.subspace().dot(forces[i]),
        }
        if let Some(p) = bodies[i].parent {
            let up = data.link[i].force_to_parent(forces[i]);
            forces[p] += up;
        }
    }
    tau
}
