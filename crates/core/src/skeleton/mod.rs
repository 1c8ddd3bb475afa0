//! Articulated figures as trees of 1-DOF joints (She 2006 §3.1–3.2) and their
//! construction from Denavit–Hartenberg parameters (PODA, "Modeling Articulated Figures").

mod dh;
mod effector;
mod joint;
mod manipulability;
mod reach;
mod tree;

pub use dh::{DhJoint, DhLimb};
pub use effector::Effector;
pub use joint::{Joint, JointKind};
pub use manipulability::{Ellipsoid, Scope};
pub use reach::Limb;
pub use tree::{AxisKind, JointShape, Skeleton, SkeletonError, TaskBlock};
