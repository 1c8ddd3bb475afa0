//! The states of Figure 4's finite state machine, entered on the sensory
//! events the paper lists beneath each state name, and the stance part of
//! the cycle (loading → compression → thrust → unloading) that every gait's
//! (virtual) leg runs. What counts as a touchdown or a lift-off, and the
//! thresholds of each event, are the gait's: it senses them, this module
//! moves the state.

/// One state of the running cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Phase {
    /// Entered when the active leg leaves the ground: legs swap roles, the
    /// new active leg lengthens and is positioned for landing.
    #[default]
    Flight,
    /// Entered when the active leg touches the ground: hip torque zeroed.
    Loading,
    /// Entered when the active leg's spring shortens: pitch servoed by the hip.
    Compression,
    /// Entered when the spring lengthens: the leg extends (thrust).
    Thrust,
    /// Entered when the spring nears full length: the leg shortens, hip limp.
    Unloading,
}

impl Phase {
    /// Every state in cycle order.
    pub const ALL: [Phase; 5] = [
        Phase::Flight,
        Phase::Loading,
        Phase::Compression,
        Phase::Thrust,
        Phase::Unloading,
    ];

    /// The paper's name for the state.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Phase::Flight => "flight",
            Phase::Loading => "loading",
            Phase::Compression => "compression",
            Phase::Thrust => "thrust",
            Phase::Unloading => "unloading",
        }
    }

    /// The state's position in the cycle (0–4), for plots.
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }
}

/// The sensory events of one (virtual) leg in stance, as its gait senses them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StanceEvents {
    /// The leg spring has shortened: Loading → Compression.
    pub shortened: bool,
    /// The leg spring lengthens again: Compression → Thrust.
    pub lengthening: bool,
    /// The leg spring is near full length: Thrust → Unloading.
    pub extended: bool,
}

impl Phase {
    /// The state after `self` on `events` (Figure 4), one step at most:
    /// Loading, Compression and Thrust move on their event; Flight and
    /// Unloading stay (touchdown and lift-off are the gait's to sense).
    #[must_use]
    pub fn after(self, events: StanceEvents) -> Phase {
        match self {
            Phase::Loading if events.shortened => Phase::Compression,
            Phase::Compression if events.lengthening => Phase::Thrust,
            Phase::Thrust if events.extended => Phase::Unloading,
            other => other,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::control::laws::phase::{Phase, StanceEvents};

    const ALL_EVENTS: StanceEvents = StanceEvents {
        shortened: true,
        lengthening: true,
        extended: true,
    };

    #[test]
    fn the_stance_moves_one_state_per_event_in_figure_4s_order() {
        // With every event sensed at once, each call moves one state on.
        let mut phase = Phase::Loading;
        let mut seen = vec![phase];
        for _ in 0..4 {
            phase = phase.after(ALL_EVENTS);
            seen.push(phase);
        }
        assert_eq!(
            seen,
            [
                Phase::Loading,
                Phase::Compression,
                Phase::Thrust,
                Phase::Unloading,
                Phase::Unloading
            ]
        );
        // Touchdown is the gait's to sense: flight stays flight.
        assert_eq!(Phase::Flight.after(ALL_EVENTS), Phase::Flight);
    }

    #[test]
    fn each_state_waits_for_its_own_event() {
        let only = |shortened, lengthening, extended| StanceEvents {
            shortened,
            lengthening,
            extended,
        };
        // Each state moves on its own event only (Loading waits for the
        // spring to shorten, not for the others, and so on).
        let cases = [
            (Phase::Loading, only(false, true, true), Phase::Loading),
            (Phase::Loading, only(true, false, false), Phase::Compression),
            (
                Phase::Compression,
                only(true, false, true),
                Phase::Compression,
            ),
            (Phase::Compression, only(false, true, false), Phase::Thrust),
            (Phase::Thrust, only(true, true, false), Phase::Thrust),
            (Phase::Thrust, only(false, false, true), Phase::Unloading),
        ];
        for (from, events, to) in cases {
            assert_eq!(from.after(events), to, "{from:?} on {events:?}");
        }
    }
}
