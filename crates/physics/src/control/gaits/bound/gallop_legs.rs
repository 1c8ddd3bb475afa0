//! The gallop's legs within a pair (Raibert & Hodgins 1991, "Gaits": "a
//! single support phase, a double support phase, and then a second single
//! support phase"): with `gallop_lag_s` above 0 the second leg of a pair
//! lengthens for landing only that long after the pair's first touchdown,
//! and each leg runs Figure 4's stance on its own spring, so the leg that
//! landed first also thrusts and lifts off first.
//!
//! With `gallop_lag_s` 0 (files made before it) both legs follow the pair's
//! one stance, and the second leg's only separation is its shorter landing
//! rest, which the trunk's roll can take up (docs/physics.md, "The virtual
//! legs' unison").

use crate::control::laws::phase::{Phase, StanceEvents};
use crate::control::laws::scale::Scale;

/// One leg's own stance within its pair (the gallop with a lag).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct LegCycle {
    /// The leg's Figure-4 state.
    pub phase: Phase,
    /// When the leg last touched down (s).
    touchdown_s: f64,
}

/// What one leg's stance reads at a control call.
pub(super) struct LegSense {
    /// Whether the foot touches the ground.
    pub touching: bool,
    /// The spring's length past its stance rest (m).
    pub q_m: f64,
    /// The spring's rate (m/s).
    pub qd_mps: f64,
    /// The length past rest at which the thrust ends (m).
    pub extended_m: f64,
    /// Now (s).
    pub time_s: f64,
    /// The dynamic scale L.
    pub l: f64,
}

/// Seconds (× √L) after touchdown within which a foot that leaves the
/// ground is still landing: it bounced off at impact.
pub(super) const BOUNCE_S: f64 = 0.01;

/// Figure 4's stance events as the bound senses them on a spring `q_m` past
/// its stance rest moving at `qd_mps`, `since_s` after touchdown: shortened
/// once it compresses past 2 mm (× L) or 15 ms (× √L) have passed,
/// lengthening once it stops shortening, extended at `extended_m`. The
/// pair's machine reads it on the pair's mean spring, a galloping leg on
/// its own.
pub(super) fn spring_events(
    q_m: f64,
    qd_mps: f64,
    since_s: f64,
    extended_m: f64,
    l: f64,
) -> StanceEvents {
    StanceEvents {
        shortened: (qd_mps < 0.0 && q_m < -0.002 * l) || since_s > 0.015 * Scale::new(l).time(),
        lengthening: qd_mps >= 0.0,
        extended: q_m >= extended_m,
    }
}

impl LegCycle {
    /// Advance on the leg's own events; the pair in flight puts every leg
    /// in flight.
    pub fn advance(&mut self, pair: Phase, sense: &LegSense) {
        let l = sense.l;
        let since = sense.time_s - self.touchdown_s;
        self.phase = match (pair, self.phase) {
            (Phase::Flight, _) => Phase::Flight,
            (_, Phase::Flight) if sense.touching => {
                self.touchdown_s = sense.time_s;
                Phase::Loading
            }
            (_, Phase::Flight) => Phase::Flight,
            // A foot bouncing off at impact is still landing.
            (_, Phase::Loading) if !sense.touching && since > BOUNCE_S * Scale::new(l).time() => {
                Phase::Flight
            }
            (_, Phase::Loading) if !sense.touching => Phase::Loading,
            (_, _) if !sense.touching => Phase::Flight,
            (_, stance) => stance.after(spring_events(
                sense.q_m,
                sense.qd_mps,
                since,
                sense.extended_m,
                l,
            )),
        };
    }
}

/// Eq. 1's rest for a leg that has touched in this stance, by its state:
/// the stance rest, lengthened by the thrust in Thrust, short in Unloading
/// and once the foot has left.
pub(super) fn stance_rest(phase: Phase, touching: bool, rest: f64, thrust: f64, short: f64) -> f64 {
    match phase {
        Phase::Thrust => rest + thrust,
        Phase::Unloading => short,
        _ if !touching && phase != Phase::Loading => short,
        _ => rest,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sense(touching: bool, q_m: f64, qd_mps: f64, time_s: f64) -> LegSense {
        LegSense {
            touching,
            q_m,
            qd_mps,
            extended_m: 0.02,
            time_s,
            l: 1.0,
        }
    }

    #[test]
    fn a_leg_runs_figure_4_on_its_own_spring_and_lifts_off_alone() {
        let mut leg = LegCycle::default();
        // The pair is in stance but this foot is still up: it waits.
        leg.advance(Phase::Loading, &sense(false, 0.0, 0.0, 0.0));
        assert_eq!(leg.phase, Phase::Flight);
        let steps = [
            (sense(true, 0.0, -0.5, 0.010), Phase::Loading),
            (sense(true, -0.01, -0.5, 0.012), Phase::Compression),
            (sense(true, -0.03, 0.1, 0.040), Phase::Thrust),
            (sense(true, 0.021, 0.4, 0.070), Phase::Unloading),
            (sense(false, 0.03, 0.4, 0.080), Phase::Flight),
        ];
        for (s, want) in steps {
            leg.advance(Phase::Thrust, &s);
            assert_eq!(leg.phase, want, "at {} s", s.time_s);
        }
        // A bounce within 10 ms of touchdown is still landing.
        leg.advance(Phase::Thrust, &sense(true, 0.0, -0.5, 0.100));
        leg.advance(Phase::Thrust, &sense(false, 0.0, -0.5, 0.105));
        assert_eq!(leg.phase, Phase::Loading);
        // The pair's flight ends every leg's stance.
        leg.advance(Phase::Flight, &sense(true, 0.0, 0.0, 0.106));
        assert_eq!(leg.phase, Phase::Flight);
    }

    #[test]
    fn the_rest_follows_the_legs_state() {
        let (rest, thrust, short) = (-0.08, 0.03, -0.28);
        // (state, touching, rest asked)
        let cases = [
            (Phase::Loading, false, rest),
            (Phase::Compression, true, rest),
            (Phase::Thrust, true, rest + thrust),
            (Phase::Unloading, true, short),
            (Phase::Flight, false, short),
            (Phase::Compression, false, short),
        ];
        for (phase, touching, want) in cases {
            let got = stance_rest(phase, touching, rest, thrust, short);
            assert_eq!(got, want, "{phase:?}, touching {touching}");
        }
    }
}
