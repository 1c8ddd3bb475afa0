//! The biped gallop's support states (Raibert & Hodgins 1991, "Gaits":
//! "the two stance legs share a single support phase"): flight, the trailing
//! leg's single support, double support, the leading leg's single support.

/// The stride's support state, from the legs' contacts as the controller
/// accepted them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GallopPhase {
    /// No leg in support.
    #[default]
    Flight,
    /// Only the trailing leg (the first to land) supports.
    TrailSupport,
    /// Both legs support.
    DoubleSupport,
    /// Only the leading leg (the last to leave) supports.
    LeadSupport,
}

impl GallopPhase {
    /// Every phase in stride order.
    pub const ALL: [GallopPhase; 4] = [
        GallopPhase::Flight,
        GallopPhase::TrailSupport,
        GallopPhase::DoubleSupport,
        GallopPhase::LeadSupport,
    ];

    /// A name for people.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            GallopPhase::Flight => "flight",
            GallopPhase::TrailSupport => "trail support",
            GallopPhase::DoubleSupport => "double support",
            GallopPhase::LeadSupport => "lead support",
        }
    }

    /// The phase's position in the stride (0–3), for plots.
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }
}
