//! An edit of the PODA gait's shape (Girard & Maciejewski 1985: a leg's
//! relative phase, eq. 9; the transfer trajectory's height and key positions).

/// An edit of the PODA gait's shape (see [`crate::App::edit_gait_shape`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GaitShapeEdit<'a> {
    /// Relative phase of one leg, a fraction of the period.
    Phase {
        /// Leg index.
        leg: usize,
        /// New relative phase.
        phase: f64,
    },
    /// Highest point of the transfer trajectory, metres.
    StepHeight(f64),
    /// Key leg positions `[along, height]` of the transfer trajectory.
    TransferKeys(&'a [[f64; 2]]),
}
