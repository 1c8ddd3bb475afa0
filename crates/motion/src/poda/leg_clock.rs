//! The clock the legs run on (Girard & Maciejewski 1985, eq. 9 and
//! "Vertical Control"): eq. 9 on the gait's values for every leg from a
//! restart until the gait changes; from then each leg's own cycles
//! ([`LegCycles`]), which take a change on at each leg's mid-stance,
//! starting from eq. 9 on the gait the legs ran with.

use super::gait::{GaitParams, LegPhase};
use super::leg_cycles::{LegCycle, LegCycles};

/// Eq. 9 or the legs' own cycles, and the steady gait the cycles start from.
#[derive(Clone, Debug)]
pub struct LegClock {
    /// Whether the legs run on [`LegCycles`].
    by_cycles: bool,
    /// The gait eq. 9 ran with since the last restart (the cycles start from it).
    steady: GaitParams,
    /// The legs' own cycles, in use from the first gait change after a
    /// restart.
    cycles: LegCycles,
}

impl LegClock {
    /// Eq. 9 on `gait`.
    #[must_use]
    pub fn new(gait: &GaitParams) -> Self {
        Self {
            by_cycles: false,
            steady: gait.clone(),
            cycles: LegCycles::default(),
        }
    }

    /// A restart: eq. 9 on `gait` again.
    pub fn restart(&mut self, gait: &GaitParams) {
        self.by_cycles = false;
        self.steady.clone_from(gait);
    }

    /// From `t_s` on the legs run on their own cycles, starting from eq. 9
    /// on the steady gait; whether they started now (false when they
    /// already ran on them).
    pub fn start_cycles(&mut self, t_s: f64) -> bool {
        if self.by_cycles {
            return false;
        }
        self.cycles.start(&self.steady, t_s);
        self.by_cycles = true;
        true
    }

    /// Whether the legs run on their own cycles.
    #[must_use]
    pub fn by_cycles(&self) -> bool {
        self.by_cycles
    }

    /// The gait eq. 9 ran with since the last restart.
    #[must_use]
    pub fn steady(&self) -> &GaitParams {
        &self.steady
    }

    /// The legs' own cycles (meaningful while [`LegClock::by_cycles`]).
    #[must_use]
    pub fn cycles(&self) -> &LegCycles {
        &self.cycles
    }

    /// Moves the legs' cycles to `t_s` ([`LegCycles::advance_to`]).
    pub fn advance_to(&mut self, t_s: f64, gait: &GaitParams) {
        self.cycles.advance_to(t_s, gait);
    }

    /// Leg `i`'s state at `t_s`: its own cycles after a change, eq. 9 before.
    #[must_use]
    pub fn leg_phase(&self, i: usize, t_s: f64, gait: &GaitParams) -> Option<LegPhase> {
        if self.by_cycles {
            self.cycles.leg_phase(i, t_s, gait)
        } else {
            gait.leg_phase(i, t_s)
        }
    }

    /// Leg `i`'s own cycle holding `t_s`; `None` on eq. 9.
    #[must_use]
    pub fn cycle_at(&self, i: usize, t_s: f64, gait: &GaitParams) -> Option<LegCycle> {
        if self.by_cycles {
            self.cycles.cycle_at(i, t_s, gait)
        } else {
            None
        }
    }

    /// Leg `i`'s latest mid-stance at or before `t_s`, seconds.
    #[must_use]
    pub fn mid_stance_s(&self, i: usize, t_s: f64, gait: &GaitParams) -> Option<f64> {
        if self.by_cycles {
            return self.cycles.mid_stance_s(i, t_s, gait);
        }
        let half = 0.5 * gait.support_s();
        let phase = gait.leg_phase(i, t_s)?;
        Some(t_s - (phase.state_s - half).rem_euclid(gait.period_s()))
    }

    /// Whether some leg has not yet taken on `gait`'s values at `t_s`.
    #[must_use]
    pub fn is_shifting(&self, t_s: f64, gait: &GaitParams) -> bool {
        self.by_cycles && !self.cycles.is_steady(t_s, gait)
    }

    /// How far past `t_s` the `legs` legs' footholds are already planned,
    /// seconds: to their next mid-stances (eq. 11's f₁).
    #[must_use]
    pub fn planned_ahead_s(&self, t_s: f64, gait: &GaitParams, legs: usize) -> f64 {
        let steady = gait.transfer_s() + 0.5 * gait.support_s();
        if !self.by_cycles {
            return steady;
        }
        (0..legs)
            .filter_map(|i| self.cycles.cycle_at(i, t_s, gait))
            .map(|c| c.end_s() - t_s)
            .fold(steady, f64::max)
    }
}
