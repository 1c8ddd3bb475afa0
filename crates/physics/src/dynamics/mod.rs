//! Rigid-body dynamics: a creature as a tree of rigid bodies and the
//! equations of motion that move it (Raibert & Hodgins 1991, "Modeling";
//! Featherstone 2008).
//!
//! [`spatial`] algebra and its [`sparse`] forms for coordinate-axis joints;
//! the immutable [`model`] and its mutable [`data`]; [`kinematics`] →
//! [`aba`] (forward dynamics, O(n); the base's 6×6 solve in
//! [`inertia_solve`]) → [`integrate`]; [`crba`] and [`rnea`],
//! the independent O(n³) path; [`energy`] and momentum, what the
//! tests hold the others to. Knows nothing of legs, ground or control.

pub mod aba;
pub mod crba;
pub mod data;
pub mod energy;
pub mod inertia_solve;
pub mod integrate;
pub mod kinematics;
pub mod model;
pub mod rnea;
pub mod sparse;
pub mod spatial;
