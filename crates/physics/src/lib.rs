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
//! A [`Sim`] adds [`actuator`]s, [`ground`] contact and a [`Controller`]
//! ([`control`]) on a fixed-step loop; a [`PhysicsDriver`] runs a preset's
//! creature ([`preset`], [`creatures`]) for the app and the CLI, with the
//! Table-2 figures of [`metrics`] and [`table2`].
//!
//! Conventions: SI units, world y up; spatial vectors `[angular; linear]` in
//! body coordinates (see [`spatial`]).

// Rigid-body dynamics.
pub mod aba;
pub mod crba;
pub mod data;
pub mod energy;
pub mod integrate;
pub mod kinematics;
pub mod model;
pub mod rnea;
pub mod spatial;

// The world and the loop.
pub mod actuator;
pub mod ground;
pub mod sim;

// Creatures and their control.
pub mod control;
pub mod creature;
pub mod creatures;
pub mod gait_controller;

// Front-end services: presets, the driver, figures, export, benchmarks.
pub mod driver;
pub mod metrics;
pub mod mjcf;
pub mod preset;
pub mod table2;

pub use aba::{DynamicsError, forward_dynamics};
pub use creature::{Creature, Leg, Species};
pub use data::Data;
pub use driver::PhysicsDriver;
pub use model::{Body, GRAVITY_MPS2, Joint, Model, ModelError};
pub use sim::{BlowUp, ControlInput, Controller, Drive, Sim, SimOptions};
pub use spatial::{Force, Inertia, Motion, ParentLink};
