//! PODA (Girard & Maciejewski 1985): kinematic locomotion for any number of
//! legs — the gait model (eq. 7–9), named gaits, Catmull-Rom splines for foot
//! transfer trajectories and body paths, and per-leg pseudoinverse IK with
//! null-space center angles (eq. 5–6), which key leg positions may change
//! along the transfer.

pub mod body_track;
pub mod driver;
pub mod gait;
pub mod gait_by_speed;
pub mod gait_metrics;
pub mod gaits;
pub mod ground_pose;
pub mod key_centers;
pub mod leg_cycles;
pub mod leg_ik;
pub mod path;
pub mod spline;
pub mod stability;
pub mod surge;
pub mod transition;

pub use body_track::{BodyDynamics, BodyState, BodyTrack};
pub use driver::PodaDriver;
pub use gait::{Derived, GaitError, GaitParams, LegPhase};
pub use gait_metrics::{GaitMetrics, LegMetrics};
pub use gaits::{gait_names, named_gait};
pub use ground_pose::GroundPose;
pub use leg_ik::{LegIk, LegIkOptions};
pub use path::{BodyPath, PathError, PathKind, PathSample};
