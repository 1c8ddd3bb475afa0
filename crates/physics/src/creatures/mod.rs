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
pub use quadruped::{LEG_LENGTH_M as QUADRUPED_LEG_M, quadruped};
