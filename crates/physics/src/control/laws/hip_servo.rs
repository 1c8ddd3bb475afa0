//! Hip servos shared by the running controllers: eq. 5's linear servo on a
//! leg's hip joints, used to position legs for landing and swing them
//! (Raibert & Hodgins 1991, Figure 4's "position active leg for landing").

use crate::world::sim::Drive;

/// Servo each hip joint to its target (eq. 5) with gains `kp`, `kv` and
/// torque limit `max`.
pub fn set_hip(drives: &mut [Drive], hip: &[usize], targets: [f64; 2], kp: f64, kv: f64, max: f64) {
    for (&j, &t) in hip.iter().zip(&targets) {
        drives[j].servo(kp, kv, t);
        drives[j].spring.max_force = max;
    }
}

/// Figure 4's zero hip torque on a hip's joints `hip`, their angles now
/// (`q`, rad, indexed by joint) kept in `previous` as the servo's last targets.
pub fn release(drives: &mut [Drive], hip: &[usize], q: &[f64], previous: &mut [f64; 2]) {
    for (&j, prev) in hip.iter().zip(previous.iter_mut()) {
        drives[j].torque(0.0);
        *prev = q[j];
    }
}

/// Figure 4's zero hip torque on a ball hip's roll and pitch; its yaw joint
/// keeps the leg's own orientation (gains `ykp` N·m/rad, `ykv` N·m·s/rad).
pub fn zero_hip(drives: &mut [Drive], hip: &[usize], ykp: f64, ykv: f64) {
    for &j in &hip[..2] {
        drives[j].torque(0.0);
    }
    drives[hip[2]].servo(ykp, ykv, 0.0);
}

/// Largest hip servo targets (rad): roll, pitch.
pub const HIP_TARGET_LIMIT: [f64; 2] = [0.8, 1.3];

/// Hip servo gains and torque limit.
#[derive(Clone, Copy)]
pub struct HipServo {
    /// Stiffness (N·m/rad).
    pub kp: f64,
    /// Damping (N·m·s/rad).
    pub kv: f64,
    /// Torque limit (N·m).
    pub max: f64,
    /// Time since the last call (s).
    pub dt: f64,
}

impl HipServo {
    /// Servo the hip joints to `targets` (eq. 5) with the targets' rate as
    /// velocity feed-forward (`previous` holds last call's targets).
    pub fn set(
        &self,
        drives: &mut [Drive],
        hip: &[usize],
        targets: [f64; 2],
        previous: &mut [f64; 2],
    ) {
        for ((&j, (&t, &lim)), prev) in hip
            .iter()
            .zip(targets.iter().zip(&HIP_TARGET_LIMIT))
            .zip(previous.iter_mut())
        {
            let t = t.clamp(-lim, lim);
            let rate = if self.dt > 0.0 {
                ((t - *prev) / self.dt).clamp(-20.0, 20.0)
            } else {
                0.0
            };
            *prev = t;
            drives[j].servo(self.kp, self.kv, t + self.kv / self.kp * rate);
            drives[j].spring.max_force = self.max;
        }
    }
}
