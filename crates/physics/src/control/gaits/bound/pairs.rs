//! The bound's two virtual legs (Raibert & Hodgins 1991, Figure 4 on the
//! front and the rear pair): each pair lands, compresses, thrusts and lifts
//! off on its own events; eq. 2's thrust, one value for both pairs, is
//! regulated on each stride's total flight and trimmed per pair on the
//! gathered and extended flights (Table 2).

use super::gallop_legs::LegCycle;
use crate::control::gaits::bound::params::QuadrupedBoundParams;
use crate::control::laws::phase::Phase;
use crate::control::laws::scale::Scale;

/// One pair's state machine (Figure 4).
#[derive(Clone, Copy, Debug)]
pub(super) struct PairState {
    pub phase: Phase,
    /// Whether the other pair touched down since this pair's lift-off.
    pub armed: bool,
    pub touchdown_s: f64,
    pub liftoff_s: f64,
    /// Measured stance duration (s), T_s of eq. 3.
    pub stance_s: f64,
    /// Each leg's stance rest (m).
    pub rest: [f64; 2],
    /// Whether each leg has touched in this stance.
    pub touched: [bool; 2],
    /// Each leg's own stance (the gallop with a lag).
    pub legs: [LegCycle; 2],
}

impl PairState {
    /// A pair in flight, not armed, its stance guessed from `params` at
    /// dynamic scale `scale`.
    pub fn in_flight(params: &QuadrupedBoundParams, scale: f64) -> Self {
        Self {
            phase: Phase::Flight,
            armed: false,
            touchdown_s: 0.0,
            liftoff_s: f64::NEG_INFINITY,
            stance_s: params.stance_s * Scale::new(scale).time(),
            rest: [params.landing_rest_m * scale; 2],
            touched: [false; 2],
            legs: [LegCycle::default(); 2],
        }
    }

    /// The state leg `side`'s stance follows: its own with `own_legs` (the
    /// gallop with a lag), else the pair's.
    pub fn leg_phase(&self, side: usize, own_legs: bool) -> Phase {
        if own_legs {
            self.legs[side].phase
        } else {
            self.phase
        }
    }
}
