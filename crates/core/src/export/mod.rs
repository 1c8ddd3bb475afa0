//! Motion export and import: BVH writer and reader (with the reader's own
//! forward kinematics), the pose CSV writer, and the effector-target CSV format
//! that `gaitlab track` reads (DESIGN.md, "Data flow" and "Contracts").
//!
//! Everything here is I/O free: writers append text to any
//! [`std::fmt::Write`] (a `String`, or an adapter over a file in the CLI), and
//! readers take `&str`. Writers stream one frame at a time and allocate nothing
//! per frame beyond the text they produce, so a long run never has to keep
//! every pose in memory.
//!
//! # Conventions
//! - Lengths are metres unless a [`BvhOptions::scale`] says otherwise; angles are
//!   radians everywhere except BVH rotation channels, which are degrees (the format's rule).
//! - BVH rotations use the channel order `Zrotation Xrotation Yrotation`, so a
//!   joint's local rotation is `Rz(z)·Rx(x)·Ry(y)` ([`euler_zxy`]).
//! - Readers never panic on any input: every problem is an error that names the
//!   line (and, for CSV, the column).

mod bvh;
mod bvh_fk;
mod bvh_reader;
mod bvh_writer;
mod csv_error;
mod pose_csv;
mod rotation;
mod target_csv;
mod target_track;
pub(crate) mod text;
mod write_error;

pub use bvh::{Bvh, BvhChannel, BvhJoint, MAX_BVH_CHANNELS_PER_JOINT, MAX_BVH_JOINTS};
pub use bvh_fk::BvhKinematics;
pub use bvh_reader::{BvhError, parse_bvh};
pub use bvh_writer::{BVH_ROOT_NAME, BvhOptions, BvhWriter, bvh_string, write_bvh};
pub use csv_error::CsvError;
pub use pose_csv::{PoseCsvColumns, PoseCsvWriter};
pub use rotation::{euler_zxy, from_euler_zxy, from_rotation_vector, rotation_vector};
pub use target_csv::{MAX_TARGET_CSV_BYTES, TargetCsvWriter, parse_target_csv, write_target_csv};
pub use target_track::{MAX_TARGET_ROWS, TargetTrack};
pub use write_error::WriteError;
