//! Jacobian inverse kinematics (She 2006 §4.4: transpose, pseudoinverse, DLS,
//! SDLS) with PODA's null-space "center angles and gains" (eq. 6), joint limits
//! and the thesis' per-joint "wounded" weights (§5.1.1); plus cyclic
//! coordinate descent as a non-Jacobian contrast.

mod ccd;
mod dls;
mod eigen;
mod nullspace;
mod options;
mod params;
mod pinv;
mod sdls;
mod solver;
mod spectrum;
mod status;
mod svd;
mod targets;
mod transpose;

pub use eigen::{NoConvergence, SymmetricEigen};
pub use options::{IkOptions, JacobianAt, JointWeight, Method, TransposeAlpha};
pub use params::{IK_PARAMS, check_ik_options};
pub use solver::IkSolver;
pub use spectrum::{Direction, GainLaw, Spectrum, ZERO_SIGMA_RELATIVE};
pub use status::IkStatus;
pub use svd::ThinSvd;
pub use targets::Targets;
