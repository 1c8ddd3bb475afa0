//! gaitlab-physics: the dynamic engine of Raibert & Hodgins 1991, "Animation
//! of Dynamic Legged Locomotion" — creatures modelled as trees of rigid bodies
//! whose every motion comes from integrating equations of motion while
//! controllers apply actuator forces.
//!
//! Stages, after MuJoCo's immutable-model / mutable-data split: a [`Model`]
//! (bodies, joints, inertias) and its [`Data`] (state and workspace);
//! [`kinematics`](kinematics::kinematics) → [`forward_dynamics`](aba::forward_dynamics)
//! (O(n), articulated-body algorithm) → [`integrate`](integrate::integrate)
//! (semi-implicit Euler). [`crba`] and [`rnea`] are the independent O(n³) path.
//!
//! Conventions: SI units, world y up; spatial vectors `[angular; linear]` in
//! body coordinates (see [`spatial`]).

pub mod aba;
pub mod crba;
pub mod data;
pub mod integrate;
pub mod kinematics;
pub mod model;
pub mod rnea;
pub mod spatial;

pub use aba::{DynamicsError, forward_dynamics};
pub use data::Data;
pub use model::{Body, GRAVITY_MPS2, Joint, Model, ModelError};
pub use spatial::{Force, Inertia, Motion, ParentLink};
pub mod creature;
pub mod creatures;
pub use creature::{Creature, Leg, Species};
pub mod actuator;
pub mod energy;
pub mod ground;
pub mod sim;
pub use sim::{BlowUp, ControlInput, Controller, Drive, Sim, SimOptions};
pub mod control;
pub mod driver;
pub mod metrics;
pub mod preset;
pub use driver::PhysicsDriver;
pub mod mjcf;
pub mod step_bench;
pub mod table2;
