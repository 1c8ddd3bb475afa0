//! The constant that centres eq. 12–13's vertical superposition (Girard &
//! Maciejewski 1985, "Vertical Control"): averaged over every leg's support
//! phase the body stands at its standing height, so the legs reach the
//! ground however high the flights are. On eq. 9 it is computed once per
//! restart (the gait cannot change without one, or without the legs going
//! over to their own cycles); on the legs' own cycles over their coming
//! supports while a change is taken on, and once when they are steady.

use super::gait::GaitParams;
use super::leg_clock::LegClock;
use super::transition::{SAMPLES, eq9_centre_and_range_m};

/// The vertical centre and when it is due.
#[derive(Clone, Copy, Debug)]
pub struct VerticalCentre {
    centre_m: f64,
    /// Eq. 9's centre is due (after a restart).
    due: bool,
    /// The centre holds for the cycles' steady gait.
    steady: bool,
}

impl Default for VerticalCentre {
    fn default() -> Self {
        Self {
            centre_m: 0.0,
            due: true,
            steady: false,
        }
    }
}

impl VerticalCentre {
    /// The centre at `t_s`, metres, for `gait` on `clock`, gravity `g_mps2`.
    pub fn value_m(&mut self, clock: &LegClock, gait: &GaitParams, t_s: f64, g_mps2: f64) -> f64 {
        if clock.by_cycles() {
            // While a change is taken on, over the legs' own coming supports;
            // once they are steady, once.
            let cycles = clock.cycles();
            let steady = cycles.is_steady(t_s, gait);
            if !(steady && self.steady) {
                let g_n = gait.gravity_share_mps2(g_mps2);
                self.centre_m = cycles.vertical_centre_m(t_s, gait, g_n, SAMPLES);
                self.steady = steady;
            }
            return self.centre_m;
        }
        if self.due {
            self.centre_m = eq9_centre_and_range_m(gait, t_s, g_mps2).0;
            self.due = false;
        }
        self.centre_m
    }

    /// A restart: eq. 9's centre is due.
    pub fn restart(&mut self) {
        self.due = true;
        self.steady = false;
    }

    /// The legs went over to their own cycles.
    pub fn cycles_started(&mut self) {
        self.steady = false;
    }
}
