//! What a gait controller reads of its creature once, when it is made
//! (Raibert & Hodgins 1991, "Dynamic Scaling" and eq. 3): Table 1's factors
//! for the creature's L and each leg's hip-to-foot length at full extension,
//! so every gait places its feet by the creature's own legs.

use crate::control::laws::scale::Scale;
use crate::creatures::PhysicalCreature;

/// The scale and the leg lengths of a creature with `N` legs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyPlan<const N: usize> {
    /// Table 1's factors for the creature's L.
    pub scale: Scale,
    /// Each leg's hip-to-foot length at full extension (m, scaled); 0 for
    /// a leg the creature lacks.
    pub leg_m: [f64; N],
}

impl<const N: usize> BodyPlan<N> {
    /// The plan of `creature`.
    #[must_use]
    pub fn of(creature: &PhysicalCreature) -> Self {
        Self {
            scale: Scale::new(creature.scale),
            leg_m: std::array::from_fn(|i| creature.leg_length_m(i)),
        }
    }
}
