//! What one IK iteration saw and did (errors, step size, clamps, rank), for any method.

/// What one iteration saw and did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct IkStatus {
    /// Largest effector position error before the step, metres.
    pub max_error_m: f64,
    /// Root-mean-square effector position error before the step, metres.
    pub rms_error_m: f64,
    /// Largest absolute joint change applied, radians (or metres).
    pub max_step: f64,
    /// Joints held at a limit in this iteration.
    pub clamped_joints: usize,
    /// Numerical rank of the (weighted) Jacobian; 0 for the transpose method.
    pub rank: usize,
    /// Linear solves this iteration: 1, plus one per clamp-and-re-solve pass.
    pub solves: usize,
    /// Whether the linear algebra failed (non-finite input); no step was taken.
    pub failed: bool,
}
