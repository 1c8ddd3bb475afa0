//! PODA (Girard & Maciejewski 1985): kinematic locomotion for any number of
//! legs — the gait model (eq. 7–9), named gaits, Catmull-Rom splines for foot
//! transfer trajectories and body paths, and per-leg pseudoinverse IK with
//! null-space center angles (eq. 5–6), which key leg positions may change
//! along the transfer, holding the foot's orientation as well as its
//! position (eq. 2) where a leg has six joints or more. The driver
//! ([`PodaDriver`]) is a fixed model (`model.rs`), a changing state
//! (`state.rs`) and the stages of `stages/` as functions of the two; live
//! edits reach the stages as events (`edits.rs`).

pub mod body_track;
pub mod driver;
mod edits;
pub mod foot_orientation;
pub mod gait;
pub mod gait_by_speed;
mod gait_edit;
pub mod gait_metrics;
pub mod gaits;
pub mod ground_pose;
pub mod key_centers;
mod leg_clock;
pub mod leg_cycles;
pub mod leg_ik;
mod measure;
mod model;
pub mod path;
mod speed_gait;
pub mod spline;
pub mod stability;
mod stages;
mod start;
mod state;
pub mod surge;
pub mod terrain_feet;
pub mod terrain_fit;
pub mod transition;
mod vertical_centre;

pub use body_track::{BodyDynamics, BodyState, BodyTrack};
pub use driver::PodaDriver;
pub use gait::{Derived, GaitError, GaitParams, LegPhase};
pub use gait_metrics::{GaitMetrics, LegMetrics};
pub use gaits::{gait_names, named_gait};
pub use ground_pose::GroundPose;
pub use leg_ik::{LegIk, LegIkOptions};
pub use path::{BodyPath, PathError, PathKind, PathSample};
