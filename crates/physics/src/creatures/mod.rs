//! Creatures: the paper's three models (Table 3), built at any
//! dynamic scale L (Table 1: lengths ×L, masses ×L³, moments of inertia ×L⁵),
//! each a [`PhysicalCreature`]: a dynamics model plus where its legs are.

mod biped;
mod build;
mod kangaroo;
mod physical_creature;
mod quadruped;

pub use biped::{LEG_LENGTH_M as BIPED_LEG_M, biped};
pub use kangaroo::kangaroo;
pub use physical_creature::{Leg, PhysicalCreature, Species};
pub use quadruped::{
    LEG_LENGTH_M as QUADRUPED_LEG_M, TRUNK_INERTIA_LITERAL_KGM2, TRUNK_INERTIA_TENTH_KGM2,
    quadruped, quadruped_with_trunk,
};

#[cfg(test)]
mod tests {
    use super::{BIPED_LEG_M, QUADRUPED_LEG_M, biped, quadruped};

    #[test]
    fn leg_lengths_are_the_models_hip_to_foot_at_full_length() {
        let built = [(biped(1.0), BIPED_LEG_M), (quadruped(1.0), QUADRUPED_LEG_M)];
        for (creature, want) in built {
            for got in creature.expect("model builds").leg_lengths_m() {
                assert_eq!(got, want, "bit for bit at scale 1");
            }
        }
        for got in biped(2.0).expect("model builds").leg_lengths_m() {
            assert!((got - 2.0 * BIPED_LEG_M).abs() < 1e-12);
        }
    }
}
