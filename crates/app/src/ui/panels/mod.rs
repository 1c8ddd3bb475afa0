//! The control panels, one file per group.

pub mod compare;
pub mod gait;
pub mod ik;
pub mod path;
pub mod physics;
pub mod share;
