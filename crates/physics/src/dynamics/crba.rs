//! The joint-space mass matrix by the composite-rigid-body algorithm
//! (Featherstone 2008 §6.2), and the O(n³) forward dynamics
//! `H q̈ = τ − C` it gives with [`crate::dynamics::rnea`] — the independent path the
//! O(n) articulated-body algorithm is tested against.

use nalgebra::{DMatrix, DVector};

use crate::dynamics::data::Data;
use crate::dynamics::model::Model;
use crate::dynamics::rnea::inverse_dynamics;
use crate::dynamics::spatial::{Force, Motion};

/// The motion-subspace columns of body `i` (six unit motions for the free base).
fn columns(model: &Model, i: usize) -> Vec<(usize, Motion)> {
    let base = if model.free_base() { 6 } else { 0 };
    match model.dof_of(i) {
        None => (0..6)
            .map(|c| {
                let mut e = [0.0; 6];
                e[c] = 1.0;
                (
                    c,
                    Motion::new(
                        glam::DVec3::new(e[0], e[1], e[2]),
                        glam::DVec3::new(e[3], e[4], e[5]),
                    ),
                )
            })
            .collect(),
        Some(k) => vec![(base + k, model.bodies()[i].joint.subspace())],
    }
}

/// The mass matrix `H(q)` (`nv × nv`). Runs kinematics.
#[must_use]
#[expect(
    clippy::needless_range_loop,
    reason = "body indices address several parallel arrays, as in Featherstone's pseudocode"
)]
pub fn mass_matrix(model: &Model, data: &mut Data) -> DMatrix<f64> {
    crate::dynamics::kinematics::kinematics(model, data);
    let bodies = model.bodies();
    let mut composite: Vec<_> = bodies
        .iter()
        .map(crate::dynamics::model::Body::spatial_inertia)
        .collect();
    for i in (0..bodies.len()).rev() {
        if let Some(p) = bodies[i].parent {
            let up = data.link[i].inertia_to_parent(&composite[i]);
            composite[p] += up;
        }
    }
    let nv = model.nv();
    let mut h = DMatrix::zeros(nv, nv);
    for i in 0..bodies.len() {
        for (col, s) in columns(model, i) {
            let mut f: Force = composite[i].mul(s);
            for (row, s2) in columns(model, i) {
                h[(row, col)] = s2.dot(f);
            }
            let mut j = i;
            while let Some(p) = bodies[j].parent {
                f = data.link[j].force_to_parent(f);
                j = p;
                for (row, s2) in columns(model, j) {
                    let x = s2.dot(f);
                    h[(row, col)] = x;
                    h[(col, row)] = x;
                }
            }
        }
    }
    h
}

/// Forward dynamics by `q̈ = H⁻¹ (τ − C)`: the generalized accelerations
/// (`[base…, joints…]`, see [`crate::dynamics::rnea`]), or `None` when `H` is singular.
#[must_use]
pub fn forward_dynamics_dense(model: &Model, data: &mut Data) -> Option<Vec<f64>> {
    let nv = model.nv();
    let bias = inverse_dynamics(model, data, &vec![0.0; nv]);
    let h = mass_matrix(model, data);
    let base = if model.free_base() { 6 } else { 0 };
    let rhs = DVector::from_fn(
        nv,
        |r, _| if r < base { 0.0 } else { data.tau[r - base] } - bias[r],
    );
    let x = h.cholesky()?.solve(&rhs);
    Some(x.iter().copied().collect())
}
