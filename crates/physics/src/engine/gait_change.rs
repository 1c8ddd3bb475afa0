//! A gait change as it took effect (Raibert & Hodgins 1991, "Gaits": the
//! quadruped "changes gait"): when the new gait's controller took over —
//! at a flight, by the paper's take-over, or at once from the gait's own
//! start by the lab's `switch_to_start` — which can be later than the switch
//! was asked for.

/// How the new gait was entered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Entry {
    /// The paper's take-over at the next flight, from the state found.
    TakeOver,
    /// The lab's entry at the gait's own start (`switch_to_start`).
    OwnStart,
}

impl Entry {
    /// Its name in `--json` (`take_over`, `own_start`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Entry::TakeOver => "take_over",
            Entry::OwnStart => "own_start",
        }
    }
}

/// One gait change that took effect.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaitChange {
    /// Seconds into the whole run.
    pub at_s: f64,
    /// The gait that ran before.
    pub from: &'static str,
    /// The gait that runs since.
    pub to: &'static str,
    /// How it was entered.
    pub entry: Entry,
}

/// The most changes a run keeps (one a second for a long run is plenty).
pub const MAX_GAIT_CHANGES: usize = 256;
