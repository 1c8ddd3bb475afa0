//! Quadruped pacing (Raibert 1990, "Trotting, pacing, and bounding by a
//! quadruped robot", reference 13 of Raibert & Hodgins 1991; the paper's
//! "Gaits": quadruped gaits as *virtual biped gaits*). The pace pairs the
//! lateral legs — front-left with rear-left, front-right with rear-right —
//! as virtual legs, and runs the trot's state machine on them: Figure 4 for
//! each pair, eq. 2's thrust on its flight, eq. 3's placement of each foot
//! about its hip, eq. 4's posture through the stance pair's hips.
//!
//! Its parameters are the trot's ([`QuadrupedRunParams`]), with the pace's
//! own defaults here; a preset changes them under
//! `scenario.physics.controller_by_gait.pace`.

use crate::control::gaits::trot::{GaitTuning, QuadrupedRunParams};

pub mod build;

/// The pace's two virtual legs, lateral pairs of leg indices (front-left
/// 0, front-right 1, rear-left 2, rear-right 3): the left legs, the right legs.
pub const PACE_PAIRS: [[usize; 2]; 2] = [[0, 2], [1, 3]];

/// The pace's own parameters at scale 1: the trot's controller with
/// gains tuned for the pace by the paper's laws alone (`gaitlab tune
/// raibert-quadruped --gait pace`, three rounds of CMA-ES on falls, speed
/// and the paper's friction at 1.0–2.3 m/s; docs/physics.md, "The pace").
/// Its stance pair stands on one side, so the roll servo of eq. 4 works
/// harder than the trot's and the leg springs are stiffer.
#[must_use]
pub fn pace_params() -> QuadrupedRunParams {
    let d = QuadrupedRunParams::default();
    QuadrupedRunParams {
        trot: GaitTuning {
            leg_stiffness: 14_776.0,
            leg_damping: 225.5,
            placement_gain_s: 0.033_56,
            pitch_kp: 1804.0,
            pitch_kv: 79.0,
            roll_kp: 1407.0,
            roll_kv: 362.3,
            landing_rest_m: -0.007_3,
            stance_s: 0.035_46,
            // Eq. 2 alone (the integrator off) on these gains, tuned with
            // the integrator: 0.06 m asked runs −51 / −42 / −9 % at 1.3 /
            // 1.6 / 2.0 m/s; the bundled quadruped carries gains tuned for
            // eq. 2 (docs/physics.md, "Eq. 2 as written").
            eq2_hop_m: 0.06,
            ..d.trot
        },
        swing_kp: 884.0,
        swing_kv: 9.8,
        ..d
    }
}
