//! gaitlab-physics: the dynamic engine of Raibert & Hodgins 1991, "Animation
//! of Dynamic Legged Locomotion" — creatures modelled as trees of rigid bodies
//! whose every motion comes from integrating equations of motion while
//! controllers apply actuator forces.
//!
//! The folders follow the pipeline, each using only those above it:
//!
//! - [`dynamics`]: spatial algebra, after MuJoCo's immutable-model /
//!   mutable-data split a [`Model`] (bodies, joints, inertias) and its
//!   [`Data`] (state and workspace);
//!   [`kinematics`](dynamics::kinematics::kinematics) →
//!   [`forward_dynamics`] (O(n),
//!   articulated-body algorithm) →
//!   [`integrate`](dynamics::integrate::integrate) (semi-implicit Euler);
//!   [`crba`](dynamics::crba) and [`rnea`](dynamics::rnea), the independent
//!   O(n³) path; [`energy`](dynamics::energy).
//! - [`creatures`]: the Table-3 models, each a [`PhysicalCreature`] (a model
//!   plus where its legs, feet and tail are).
//! - [`world`]: [`actuator`](world::actuator)s, [`ground`](world::ground)
//!   contact and the fixed-step [`Sim`] loop with its blow-up guard.
//! - [`control`]: the paper's control parts and, composed from them, a
//!   [`Controller`] per gait ([`gait_controller`](control::gaits::controller)).
//! - [`engine`]: the [`PhysicsDriver`] that runs a preset's creature
//!   ([`preset`](engine::preset)) for the app and the CLI, with the Table-2
//!   figures of [`metrics`](engine::metrics) and [`table2`](engine::table2),
//!   and the MuJoCo export ([`mjcf`](engine::mjcf)).
//!
//! Conventions: SI units, world y up; spatial vectors `[angular; linear]` in
//! body coordinates (see [`spatial`](dynamics::spatial)).

pub mod control;
pub mod creatures;
pub mod dynamics;
pub mod engine;
pub mod world;

pub use creatures::{Leg, PhysicalCreature, Species};
pub use dynamics::aba::{DynamicsError, forward_dynamics};
pub use dynamics::data::Data;
pub use dynamics::model::{Body, GRAVITY_MPS2, Joint, Model, ModelError};
pub use dynamics::spatial::{Force, Inertia, Motion, ParentLink};
pub use engine::driver::PhysicsDriver;
pub use world::sim::{BlowUp, ControlInput, Controller, Drive, Sim, SimOptions};
