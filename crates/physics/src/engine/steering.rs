//! Steering a running creature along a path (Raibert & Hodgins 1991 §2: the
//! control regulates "speed and direction of travel"; the creatures follow
//! "simple paths"): the desired heading given to the speed and placement
//! control turns toward its goal at a bounded rate, and with waypoints the goal
//! is the next waypoint until the centre of mass comes within reach of it. The
//! rate and the reach are the lab's choices; the paper gives neither.

use gaitlab_core::portable::Portable;
use gaitlab_core::preset::PhysicsParams;
use glam::DVec3;

use crate::control::laws::scale::Scale;

/// How fast the desired heading turns (rad/s at scale 1, ×1/√L).
pub const TURN_RATE_RAD_S: f64 = 0.5;

/// A waypoint counts as reached within this distance (m at scale 1).
pub const WAYPOINT_RADIUS_M: f64 = 0.75;

/// The desired heading and the waypoint being steered to.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Steering {
    /// The desired heading as it turns toward its goal (rad about +y).
    pub heading: f64,
    /// Where the heading is turning to (rad).
    pub heading_goal: f64,
    /// The next waypoint of `PhysicsParams::waypoints`.
    pub waypoint: usize,
}

impl Steering {
    /// One frame of `dt` seconds: aim at the next of `params.waypoints`
    /// (`com` gives the centre of mass, m, read only when there is one), then
    /// turn the heading toward its goal. Returns the new heading when it moved.
    pub fn steer(
        &mut self,
        com: impl FnOnce() -> DVec3,
        params: &PhysicsParams,
        dt: f64,
    ) -> Option<f64> {
        let l = params.scale;
        if let Some(&[x, z]) = params.waypoints.get(self.waypoint) {
            let com = com();
            let to = DVec3::new(x * l - com.x, 0.0, z * l - com.z);
            if to.length() < WAYPOINT_RADIUS_M * l {
                self.waypoint += 1;
            } else {
                self.heading_goal = to.x.patan2(to.z);
            }
        }
        let error = (self.heading_goal - self.heading + std::f64::consts::PI)
            .rem_euclid(std::f64::consts::TAU)
            - std::f64::consts::PI;
        let step = TURN_RATE_RAD_S / Scale::new(l).time() * dt;
        if error.abs() > 1e-12 {
            self.heading += error.clamp(-step, step);
            Some(self.heading)
        } else {
            None
        }
    }
}
