//! The paper's three models (Table 3), built at any dynamic scale L (Table 1:
//! lengths ×L, masses ×L³, moments of inertia ×L⁵).

mod biped;
mod build;
mod kangaroo;
mod quadruped;

pub use biped::biped;
pub use kangaroo::kangaroo;
pub use quadruped::quadruped;
