//! Semi-implicit (symplectic) Euler integration — Raibert & Hodgins 1991
//! integrated "using Euler's method, with time steps of about 0.0004 s".
//! Velocities are advanced with the new accelerations first, then positions
//! with the new velocities; the base orientation by the exponential map.
//!
//! Reads `qdd` and `base_acceleration` (run the dynamics first); writes
//! `q`, `qd` and the base state.

use glam::DQuat;

use crate::dynamics::data::Data;
use crate::dynamics::model::Model;

/// Advance the state by `dt` seconds.
pub fn integrate(model: &Model, data: &mut Data, dt: f64) {
    let n = model.joint_count();
    for ((q, qd), qdd) in data.q[..n]
        .iter_mut()
        .zip(&mut data.qd[..n])
        .zip(&data.qdd[..n])
    {
        *qd += qdd * dt;
        *q += *qd * dt;
    }
    if model.free_base() {
        let a = data.base_acceleration;
        data.base_velocity.angular += a.angular * dt;
        data.base_velocity.linear += a.linear * dt;
        let v = data.base_velocity;
        let rot = data.base_orientation;
        data.base_position += rot * (v.linear * dt);
        let turn = v.angular * dt;
        let angle = turn.length();
        if angle > 0.0 {
            let delta = DQuat::from_axis_angle(turn / angle, angle);
            data.base_orientation = (rot * delta).normalize();
        }
    }
}
