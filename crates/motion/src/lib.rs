//! gaitlab-motion: kinematic drivers — She 2006 §5.2's sinusoidal target
//! scripts for walking, running and their wounded variants ([`ThesisScript`],
//! [`ThesisDriver`]), and recorded-target tracking ([`TrackDriver`]).
//!
//! Every driver implements [`gaitlab_core::driver::Driver`]: advance by `dt`,
//! read the [`Pose`](gaitlab_core::Pose), the targets and the IK metrics.

mod error;
pub mod held;
mod ik_stage;
pub use ik_stage::IterationRecord;
pub mod poda;
mod script;
pub mod stretch;
mod thesis_driver;
mod track;

pub use error::DriverError;
pub use poda::PodaDriver;
pub use script::{Limb, ScriptSample, ThesisScript};
pub use thesis_driver::{IterationStep, MAX_ITERATIONS_PER_FRAME, ThesisDriver, validate_params};
pub use track::{FnTargets, TargetSource, TrackDriver, TrackOptions};
